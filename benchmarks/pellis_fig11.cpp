// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Reproduces [Pellis 2019, §3.3, Fig. 11]: for lattices inscribed in the
// paraboloid z = αx² + βy² (αβ < 0), the energy Σ ℓ ℓ* per area, as a
// function of the polar angle θ of an edge, is minimal when θ is a multiple
// of π/2, i.e. when the faces are rectangles (principal directions).
//
//   ninja -C <build> pellis_fig11 && <build>/benchmarks/pellis_fig11
//
// Measure (generators/smoothness_surfaces.h, LatticeEnergyPerArea): the rotated
// square lattice a = h(cos θ, sin θ), b = h(−sin θ, cos θ), lifted to the
// paraboloid; energy of the origin's vertex star per cell area, h → 0.
// Lifted quads are not planar unless θ = kπ/2, so the faces are triangles:
// each quad split by one diagonal, all edges (diagonals too) counted, the
// mean of the two diagonal choices ("avg", the measure tested). The single
// triangulations ("a+b", "a-b") and the quads with diagonal-cross normals
// ("quad") are printed beside it. For every (α, β) the curve is printed in
// 1° steps, its local minima are located (parabola through the neighbours)
// and compared with 0°, 90°, 180°, 270°. Exit 1 if a minimum is more than 2°
// away from those, or if fewer than 4 minima are found.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glog/logging.h>

#include "generators/smoothness_surfaces.h"
#include "benchmarks/program.h"

namespace ARCHGEO_UNITY_ID {

using archgeo::LatticeEnergyPerArea;
using archgeo::LatticeFaces;

constexpr double kMaxMinimumOffsetDegrees = 2.0;

double Radians(double degrees) { return degrees * M_PI / 180.0; }

// Distance in degrees from the nearest multiple of 90°.
double OffsetFromRightAngle(double degrees) {
  const double r = std::fmod(std::fmod(degrees, 90.0) + 90.0, 90.0);
  return std::min(r, 90.0 - r);
}

bool Curve(double alpha, double beta) {
  std::printf("\nz = %g x^2 + %g y^2   (|k1| + |k2| = %g at the origin)\n", alpha, beta,
              2 * std::abs(alpha) + 2 * std::abs(beta));
  std::printf("%6s %12s %12s %12s %12s\n", "theta", "avg", "a+b", "a-b", "quad");
  std::vector<double> avg(360);
  for (int d = 0; d < 360; ++d) {
    const double theta = Radians(d);
    avg[d] = LatticeEnergyPerArea(alpha, beta, theta, LatticeFaces::kTrianglesAveraged);
    std::printf("%6d %12.6f %12.6f %12.6f %12.6f\n", d, avg[d],
                LatticeEnergyPerArea(alpha, beta, theta, LatticeFaces::kTrianglesDiagonalAPlusB),
                LatticeEnergyPerArea(alpha, beta, theta, LatticeFaces::kTrianglesDiagonalAMinusB),
                LatticeEnergyPerArea(alpha, beta, theta, LatticeFaces::kQuads));
  }
  bool ok = true;
  int minima = 0;
  std::printf("local minima of avg (paper: at multiples of 90 degrees):\n");
  for (int d = 0; d < 360; ++d) {
    const double before = avg[(d + 359) % 360], here = avg[d], after = avg[(d + 1) % 360];
    if (!(here < before && here <= after)) continue;
    const double curvature = before - 2 * here + after;
    const double offset = curvature > 0 ? 0.5 * (before - after) / curvature : 0.0;
    const double at = d + offset;
    const double off = OffsetFromRightAngle(at);
    const bool near = off <= kMaxMinimumOffsetDegrees;
    ok = ok && near;
    ++minima;
    std::printf("  theta = %8.3f deg  E/area = %.6f  %s\n", at, here,
                near ? "ok" : "FAR FROM k*90");
  }
  double max = avg[0];
  for (double e : avg) max = std::max(max, e);
  std::printf("  %d minima; max/min = %.4f\n", minima, max / avg[0]);
  return ok && minima >= 4;
}


int Main(int argc, char** argv) {
  google::InitGoogleLogging(argv[0]);
  FLAGS_logtostderr = true;
  if (!bench::NoArguments(argc, argv)) return 2;
  std::printf("Pellis 2019, Fig. 11 — energy per area of lattices inscribed in z = a x^2 + b y^2\n");
  std::printf("paper: \"the energy is minimal if the polar angle is a multiple of pi/2, where faces "
              "are actually rectangles\"\n");
  const bool first = Curve(1.0, -0.5);
  const bool second = Curve(1.0, -1.0);
  const bool ok = first && second;
  std::printf("\n%s\n", ok ? "PASS" : "FAIL");
  return ok ? 0 : 1;
}

}  // namespace ARCHGEO_UNITY_ID

ARCHGEO_BENCHMARK_PROGRAM(pellis_fig11, ARCHGEO_UNITY_ID::Main);
