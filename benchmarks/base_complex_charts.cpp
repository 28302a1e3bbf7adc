// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Times charts + parameterisation + extraction (spectral/base_complex_charts.h)
// on a 50,000-triangle torus (TorusPrincipalQuads(3, 1, 200, 125),
// triangulated) with an 8 × 4 quad base complex: the nodes are the torus
// vertices at u = 2πi/8, v = 2πj/4 (vertex j·200 + i·25 with j·125/4
// rounded); n = 16 samples per base edge, cotangent weights.
//
//   ninja -C <build> archgeo_benchmarks && <build>/benchmarks/base_complex_charts
//
// Prints the counts and figures, the time of each step and the best of three
// totals; exit 1 above kTargetSeconds or if the output is not valid.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "benchmarks/program.h"
#include "generators/smoothness_surfaces.h"
#include "geometry/reference.h"
#include "problems/commands/spectral.h"
#include "spectral/base_complex_charts.h"

namespace ARCHGEO_UNITY_ID {

int Main(int argc, char** argv) {
  if (!bench::NoArguments(argc, argv)) return 2;
  constexpr double kTargetSeconds = 5.0;
  constexpr int kU = 200, kV = 125;
  const archgeo::SpectralMesh m =
      archgeo::SpectralArrays(archgeo::TriangulatedCopy(archgeo::TorusPrincipalQuads(3, 1, kU, kV)));
  archgeo::BaseComplex base;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 8; ++i) base.nodes.push_back(int(std::lround(j * kV / 4.0)) % kV * kU + i * kU / 8);
  }
  auto node = [](int i, int j) { return (j % 4) * 8 + i % 8; };
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 8; ++i) {
      base.faces.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)});
    }
  }
  double best = INFINITY;
  archgeo::ChartQuadsResult r;
  for (int run = 0; run < 3; ++run) {
    const auto start = std::chrono::steady_clock::now();
    r = archgeo::ChartQuads(m.points, m.triangles, base, 16, 0, archgeo::ChartWeights::kCotangent);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  const bool valid = r.flipped == 0 && r.irregular == r.expected_irregular &&
                     r.boundary_edges == 0 && r.t_junctions == 0 && r.non_manifold_edges == 0;
  std::printf("base complex charts on a torus: %zu vertices, %zu triangles; %zu base vertices, %zu "
              "quads\n",
              m.points.size(), m.triangles.size(), base.nodes.size(), base.faces.size());
  std::printf("charts %zu  flipped %d  quads %zu  irregular %zu (predicted %zu)  boundary edges %d  "
              "T-junctions %d  shared-edge mismatch %.2e\n",
              r.layout.charts.size(), r.flipped, r.quads.quads.size(), r.irregular.size(),
              r.expected_irregular.size(), r.boundary_edges, r.t_junctions,
              r.quads.shared_edge_mismatch);
  std::printf("last run: charts %.3f s, parameterisation %.3f s, extraction %.3f s\n",
              r.seconds_charts, r.seconds_parameterisation, r.seconds_extraction);
  const bool pass = valid && best <= kTargetSeconds;
  std::printf("best of 3: %.3f s (target %.1f s)\n%s\n", best, kTargetSeconds, pass ? "PASS" : "FAIL");
  return pass ? 0 : 1;
}

}  // namespace ARCHGEO_UNITY_ID

ARCHGEO_BENCHMARK_PROGRAM(base_complex_charts, ARCHGEO_UNITY_ID::Main);
