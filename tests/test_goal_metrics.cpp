// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for mesh/goal_metrics: conical residual, constant face offsets
// [Liu et al. 2006], length spreads, tributary areas and force balance, each
// against an analytic value or a theorem.
#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "generators/generators.h"
#include "analysis/goal_metrics.h"
#include "generators/smoothness_surfaces.h"
#include "tests/make_mesh.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

// Rounding on coordinates of order 1–4.
constexpr double kRounding = 1e-12;

// A closed fan of four triangles (v, w_k, w_{k+1}) around v = points[0]:
// v is interior with valence 4, every face planar.
Mesh Fan(const std::vector<Vec3>& points) {
  return MakeMesh(points, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}});
}

TEST(MeasureConical, TorusPrincipalNetIsConical) {
  // Every star of the meridian/parallel net of a surface of revolution is
  // symmetric about the meridian plane through its vertex, so ω1 = ω2 and
  // ω3 = ω4 (or the pairs swapped): conical up to rounding.
  const Mesh torus = TorusPrincipalQuads(3.0, 1.0, 24, 12);
  const ConicalMeasure m = MeasureConical(torus);
  EXPECT_EQ(m.vertices, 24 * 12);
  EXPECT_LE(m.max, kRounding);
}

TEST(MeasureConical, ParallelogramGridHasResidualFourAlphaMinusTwoPi) {
  // Planar grid spanned by a = (1, 0, 0), b = (cos α, sin α, 0): at every
  // interior vertex the angles are α, π − α, α, π − α, so
  // |(ω1 + ω3) − (ω2 + ω4)| = |4α − 2π|.
  for (double alpha : {M_PI / 3, M_PI / 2, 1.2}) {
    const Mesh grid = QuadGrid(4, 3, [alpha](double u, double v) {
      return Vec3{4 * u + 3 * v * std::cos(alpha), 3 * v * std::sin(alpha), 0.0};
    });
    const ConicalMeasure m = MeasureConical(grid);
    EXPECT_EQ(m.vertices, 3 * 2);
    EXPECT_NEAR(m.max, std::abs(4 * alpha - 2 * M_PI), kRounding) << alpha;
    EXPECT_NEAR(m.mean, std::abs(4 * alpha - 2 * M_PI), kRounding) << alpha;
  }
}

TEST(PlanesMiss, AnalyticValues) {
  // Normals e_x, e_y, e_z, (1,1,1)/√3, all at height d: by symmetry
  // q* = (a, a, a) with a = d(3 + √3)/6; the misses are |a − d| (×3) and
  // |√3 a − d| = d(3√3 − 3)/6, the larger.
  const double s = 1 / std::sqrt(3.0);
  for (double d : {1.0, 0.25}) {
    EXPECT_NEAR(PlanesMiss({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {s, s, s}}, {d, d, d, d}),
                d * (3 * std::sqrt(3.0) - 3) / 6, kRounding);
  }
  // Planes tangent to a cone of revolution (axis z, normals at polar angle
  // β): the offset planes meet at (0, 0, d / cos β).
  const double beta = 0.4;
  std::vector<Vec3> cone;
  for (double phi : {0.1, 1.7, 2.9, 4.4, 5.5}) {
    cone.push_back(
        {std::sin(beta) * std::cos(phi), std::sin(beta) * std::sin(phi), std::cos(beta)});
  }
  EXPECT_LE(PlanesMiss(cone, std::vector<double>(5, 0.3)), kRounding);
  // Parallel planes at different heights cannot meet: the miss is half the gap.
  EXPECT_NEAR(PlanesMiss({{0, 0, 1}, {0, 0, 1}}, {0.0, 1.0}), 0.5, kRounding);
}

TEST(MeasureFaceOffsets, TorusPrincipalNetHasConstantOffsets) {
  // Planar faces (isosceles trapezoids) and conical stars: the offset faces
  // at distance d meet at every vertex [Liu et al. 2006].
  const Mesh torus = TorusPrincipalQuads(3.0, 1.0, 24, 12);
  const FaceOffsetMeasure m0 = MeasureFaceOffsets(torus, 0.0);
  EXPECT_EQ(m0.vertices, 24 * 12);
  for (double d : {0.1, 1.0}) {
    const FaceOffsetMeasure m = MeasureFaceOffsets(torus, d * m0.mean_edge_length);
    EXPECT_LE(m.max_relative, kRounding) << d;
  }
}

TEST(MeasureFaceOffsets, AngleConditionIffOffsetsMeet) {
  // Liu et al. 2006, §3: a vertex with planar faces is conical iff
  // ω1 + ω3 = ω2 + ω4. A fan of triangles (planar) symmetric about the plane
  // x = 0 satisfies the angle condition, and its offsets meet ...
  const Vec3 v{0, 0, 0.5};
  const Mesh symmetric = Fan({v, {1, 0.2, 0}, {0, 1, 0.1}, {-1, 0.2, 0}, {0, -1.3, -0.2}});
  EXPECT_LE(MeasureConical(symmetric).max, kRounding);
  EXPECT_LE(MeasureFaceOffsets(symmetric, 0.7).max_miss, kRounding);
  // ... while moving one neighbour off the symmetric position breaks both.
  const Mesh skew = Fan({v, {1, 0.2, 0}, {0.3, 1, 0.1}, {-1, 0.2, 0}, {0, -1.3, -0.2}});
  EXPECT_GT(MeasureConical(skew).max, 1e-3);
  const double miss = MeasureFaceOffsets(skew, 0.7).max_miss;
  EXPECT_GT(miss, 1e-4);
  // Planar faces through v: the miss is linear in d and 0 at d = 0.
  EXPECT_LE(MeasureFaceOffsets(skew, 0.0).max_miss, kRounding);
  EXPECT_NEAR(MeasureFaceOffsets(skew, 1.4).max_miss, 2 * miss, kRounding);
}

TEST(LengthSpread, RectangularGrid) {
  // 3 × 1 quads over [0, 3] × [0, 2]: 6 horizontal edges of length 1 (all
  // on the boundary) and 4 vertical edges of length 2 (2 on the boundary).
  const Mesh grid = QuadGrid(3, 1, [](double u, double v) { return Vec3{3 * u, 2 * v, 0.0}; });
  const LengthSpread all = EdgeLengthSpread(grid);
  EXPECT_EQ(all.count, 10);
  EXPECT_DOUBLE_EQ(all.min, 1.0);
  EXPECT_DOUBLE_EQ(all.max, 2.0);
  EXPECT_NEAR(all.mean, 1.4, kRounding);
  EXPECT_NEAR(all.ratio, 2.0, kRounding);
  EXPECT_NEAR(all.relative_std, std::sqrt((6 * 0.16 + 4 * 0.36) / 10) / 1.4, kRounding);
  EXPECT_NEAR(all.max_relative_deviation, 0.6 / 1.4, kRounding);
  const LengthSpread boundary = BoundaryEdgeLengthSpread(grid);
  EXPECT_EQ(boundary.count, 8);
  EXPECT_NEAR(boundary.mean, 1.25, kRounding);
  EXPECT_NEAR(boundary.max_relative_deviation, 0.75 / 1.25, kRounding);
  // Equal lengths: no spread.
  const LengthSpread equal = SpreadOf({2.0, 2.0, 2.0});
  EXPECT_EQ(equal.relative_std, 0.0);
  EXPECT_EQ(equal.max_relative_deviation, 0.0);
  EXPECT_EQ(equal.ratio, 1.0);
}

TEST(TributaryAreas, FlatGridSharesEveryCellAmongItsCorners) {
  // 4 × 3 cells of 0.5 × 2: corner vertices get 1/4 cell, boundary vertices
  // 1/2, interior vertices a whole cell; the sum is the total area.
  const Mesh grid = QuadGrid(4, 3, [](double u, double v) { return Vec3{2 * u, 6 * v, 0.0}; });
  const std::vector<double> areas = TributaryAreas(grid);
  const double cell = 0.5 * 2.0;
  double total = 0.0;
  for (int j = 0; j <= 3; ++j) {
    for (int i = 0; i <= 4; ++i) {
      const int boundary_sides = (i == 0 || i == 4) + (j == 0 || j == 3);
      const double expected = boundary_sides == 2   ? cell / 4
                              : boundary_sides == 1 ? cell / 2
                                                    : cell;
      EXPECT_NEAR(areas[j * 5 + i], expected, kRounding) << i << " " << j;
      total += areas[j * 5 + i];
    }
  }
  EXPECT_NEAR(total, 12.0, kRounding);
}

TEST(MeasureForceBalance, CentreOfAThreeByThreeNet) {
  // 2 × 2 quads, spacing h, boundary fixed, zero-length springs k, load −P
  // on the centre: balanced at z = −P/(4k), the whole load unbalanced at 0.
  const double h = 2.0, k = 3.0, P = 6.0;
  auto net = [&](double z) {
    return QuadGrid(2, 2, [&](double u, double v) {
      const bool centre = std::abs(u - 0.5) < 1e-9 && std::abs(v - 0.5) < 1e-9;
      return Vec3{2 * h * u, 2 * h * v, centre ? z : 0.0};
    });
  };
  std::vector<Vec3> loads(9, Vec3{0, 0, 0});
  loads[4] = {0, 0, -P};
  std::vector<bool> fixed(9, true);
  fixed[4] = false;
  const Mesh balanced = net(-P / (4 * k));
  const std::vector<double> stiffness(balanced.num_edges(), k), zero(balanced.num_edges(), 0.0);
  const ForceBalanceMeasure at_rest = MeasureForceBalance(balanced, loads, stiffness, zero, fixed);
  EXPECT_EQ(at_rest.free_vertices, 1);
  EXPECT_NEAR(at_rest.mean_load, P, kRounding);
  EXPECT_LE(at_rest.max_relative, kRounding);
  const ForceBalanceMeasure flat = MeasureForceBalance(net(0.0), loads, stiffness, zero, fixed);
  EXPECT_NEAR(flat.max_resultant, P, kRounding);
  EXPECT_NEAR(flat.max_relative, 1.0, kRounding);
  // Length springs of rest length h in the flat net: no force; at sag z the
  // vertical resultant is 4k(s − h)(−z)/s − P with s = √(h² + z²).
  const std::vector<double> rest(balanced.num_edges(), h);
  const double z = -1.0, s = std::hypot(h, z);
  const ForceBalanceMeasure sagged = MeasureForceBalance(net(z), loads, stiffness, rest, fixed);
  EXPECT_NEAR(sagged.max_resultant, std::abs(4 * k * (s - h) * (-z) / s - P), kRounding);
}

// A square and a rectangle are convex; a dart (one corner pushed inside)
// and a bow tie (two corners swapped) are not.
TEST(NonConvexQuads, DartsAndBowTies) {
  const std::vector<Vec3> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  EXPECT_EQ(NonConvexQuads(MakeMesh(square, {{0, 1, 2, 3}})), 0);
  EXPECT_EQ(NonConvexQuads(MakeMesh({{0, 0, 0}, {3, 0, 0}, {3, 1, 0.2}, {0, 1, 0}}, {{0, 1, 2, 3}})),
            0);
  EXPECT_EQ(NonConvexQuads(MakeMesh({{0, 0, 0}, {2, 0, 0}, {0.6, 0.6, 0}, {0, 2, 0}}, {{0, 1, 2, 3}})),
            1);
  EXPECT_EQ(NonConvexQuads(MakeMesh({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2, 3}})),
            1);
  // A grid: none; the triangles of a mixed mesh are not counted.
  EXPECT_EQ(NonConvexQuads(QuadGrid(4, 3, [](double u, double v) { return Vec3{u, v, u * v}; })), 0);
  EXPECT_EQ(NonConvexQuads(MakeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}})), 0);
}

}  // namespace
}  // namespace archgeo
