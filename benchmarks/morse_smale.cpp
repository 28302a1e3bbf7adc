// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Times the Morse–Smale complex (spectral/morse_smale.h) of a function on a
// 50,000-vertex triangulated torus: the steepest paths, their rerouting, the
// cells and their check, and the quasi-dual; the function is a smooth wave
// of the positions, f = cos(6u) cos(3v) + 0.3 sin(5u + 2v) in the torus'
// angles, so the time is the complex's alone (no eigensolve).
//
//   ninja -C <build> archgeo_benchmarks && <build>/benchmarks/morse_smale
//
// Prints the counts, whether the complex is valid and the best of three
// times; exit 1 above kTargetSeconds.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "benchmarks/program.h"
#include "generators/smoothness_surfaces.h"
#include "geometry/reference.h"
#include "problems/commands/spectral.h"
#include "spectral/morse_smale.h"

namespace ARCHGEO_UNITY_ID {

int Main(int argc, char** argv) {
  if (!bench::NoArguments(argc, argv)) return 2;
  constexpr double kTargetSeconds = 0.5;
  const archgeo::SpectralMesh m =
      archgeo::SpectralArrays(archgeo::TriangulatedCopy(archgeo::TorusPrincipalQuads(3, 1, 400, 125)));
  Eigen::VectorXd f(Eigen::Index(m.points.size()));
  for (size_t i = 0; i < m.points.size(); ++i) {
    const Eigen::Vector3d& p = m.points[i];
    const double u = std::atan2(p.y(), p.x());
    const double v = std::atan2(p.z(), std::hypot(p.x(), p.y()) - 3);
    f[Eigen::Index(i)] = std::cos(6 * u) * std::cos(3 * v) + 0.3 * std::sin(5 * u + 2 * v);
  }
  double best = INFINITY;
  archgeo::MorseSmaleComplex c;
  archgeo::QuadBaseComplex dual;
  for (int run = 0; run < 3; ++run) {
    const auto start = std::chrono::steady_clock::now();
    c = archgeo::BuildMorseSmale(m.points, m.triangles, m.rings, f, {});
    dual = archgeo::QuasiDual(c, m.points);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::printf("Morse-Smale complex of a wave on a torus: %zu vertices, %zu triangles\n",
              m.points.size(), m.triangles.size());
  std::printf("max %d  min %d  saddles %d  arcs %zu  rerouted %d  unresolved %d  cells %zu  "
              "valid %s  quasi-dual %zu quads, V - E + F = %d\n",
              c.maxima, c.minima, c.saddles, c.arcs.size(), c.rerouted, c.unresolved,
              c.cells.size(), c.valid ? "yes" : "no", dual.quads.size(), dual.euler);
  std::printf("best of 3: %.3f s (target %.1f s)\n%s\n", best, kTargetSeconds,
              best <= kTargetSeconds ? "PASS" : "FAIL");
  return best <= kTargetSeconds ? 0 : 1;
}

}  // namespace ARCHGEO_UNITY_ID

ARCHGEO_BENCHMARK_PROGRAM(morse_smale, ARCHGEO_UNITY_ID::Main);
