// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Reproduces the claim of [Pellis 2019, §3.1, Fig. 7]: on finer and finer
// principal meshes of one surface, the energy E = Σ ℓ_e ‖n_f − n_f′‖ tends
// to the total absolute curvature C(Φ) = ∫ |κ1| + |κ2| dA.
//
//   ninja -C <build> pellis_fig7_torus && <build>/benchmarks/pellis_fig7_torus
//
// The paper's surface (Fig. 7d) is not public; a torus stands for it: its
// parameter lines are curvature lines, so TorusPrincipalQuads is a principal
// quad mesh, and C(Φ) = 4π²R + 8πr is known exactly (generators/smoothness_surfaces.h).
// Prints, per resolution, V, F, E, C(Φ), |E − C(Φ)|/C(Φ), E′ and the discrete
// C of §5.3. Exit 1 if the error does not decrease or the finest is > 2%.
#include <cmath>
#include <cstdio>

#include <glog/logging.h>

#include "analysis/smoothness_metrics.h"
#include "generators/smoothness_surfaces.h"
#include "benchmarks/program.h"

namespace ARCHGEO_UNITY_ID {

int Main(int argc, char** argv) {
  google::InitGoogleLogging(argv[0]);
  FLAGS_logtostderr = true;
  if (!bench::NoArguments(argc, argv)) return 2;
  constexpr double kR = 3.0, kr = 1.0;
  constexpr double kMaxFinestError = 0.02;
  const int n_u[] = {12, 24, 48, 96, 192};
  const int n_v[] = {6, 12, 24, 48, 96};
  const double c_phi = archgeo::TorusTotalAbsoluteCurvature(kR, kr);

  std::printf("Pellis 2019, Fig. 7 — E of principal meshes tends to C(Phi)\n");
  std::printf("torus R = %g, r = %g; paper: \"E tends to C(Phi) = 4 pi^2 R + 8 pi r\" = %.6f\n\n",
              kR, kr, c_phi);
  std::printf("%9s %7s %7s %12s %12s %10s %12s %12s %10s\n", "n_u x n_v", "V", "F", "E",
              "C(Phi)", "|E-C|/C", "E'", "C discrete", "|Cd-C|/C");
  double previous = INFINITY, error = INFINITY;
  bool decreasing = true;
  for (int k = 0; k < 5; ++k) {
    const archgeo::Mesh mesh = archgeo::TorusPrincipalQuads(kR, kr, n_u[k], n_v[k]);
    const archgeo::SmoothnessMetrics m = archgeo::ComputeSmoothnessMetrics(mesh);
    error = std::abs(m.E - c_phi) / c_phi;
    decreasing = decreasing && error < previous;
    previous = error;
    char size[32];
    std::snprintf(size, sizeof size, "%dx%d", n_u[k], n_v[k]);
    std::printf("%9s %7d %7d %12.6f %12.6f %9.4f%% %12.6f %12.6f %9.4f%%\n", size, m.vertices,
                m.faces, m.E, c_phi, 100 * error, m.E_prime, m.C,
                100 * std::abs(m.C - c_phi) / c_phi);
  }
  std::printf("\nerror decreasing: %s; finest error %.4f%% (limit %.0f%%)\n",
              decreasing ? "yes" : "NO", 100 * error, 100 * kMaxFinestError);
  const bool ok = decreasing && error <= kMaxFinestError;
  std::printf("%s\n", ok ? "PASS" : "FAIL");
  return ok ? 0 : 1;
}

}  // namespace ARCHGEO_UNITY_ID

ARCHGEO_BENCHMARK_PROGRAM(pellis_fig7_torus, ARCHGEO_UNITY_ID::Main);
