// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The grid lines of extracted quads (spectral/quad_relax.h): their turn at
// a vertex of valence 4 measured against the analytic angle, and the
// relaxation that straightens a kinked grid while the vertices not of
// valence 4 and the surface hold.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "spectral/quad_relax.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

// A flat (n+1) × (n+1) grid of n × n quads, unit spacing, on z = 0; the
// points of its row j and column i at i + (n + 1) j.
struct FlatGrid {
  int n;
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 4>> quads;
  explicit FlatGrid(int size) : n(size) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) points.emplace_back(i, j, 0.0);
    }
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const int a = i + (n + 1) * j;
        quads.push_back({a, a + 1, a + n + 2, a + n + 1});
      }
    }
  }
  int At(int i, int j) const { return i + (n + 1) * j; }
};

TEST(QuadRelax, AStraightGridHasNoKinkAndADisplacedVertexItsAngle) {
  FlatGrid g(4);
  EXPECT_NEAR(MeasureGridLineKinks(g.points, g.quads).max_degrees, 0.0, 1e-12);
  // The centre moved across the row through it by 0.25: the row turns by
  // 2 atan(0.25) there, the column not at all; its neighbours on the row turn
  // by atan(0.25) each.
  g.points[size_t(g.At(2, 2))].y() += 0.25;
  const GridLineKinks k = MeasureGridLineKinks(g.points, g.quads);
  EXPECT_NEAR(k.max_degrees, 2 * std::atan(0.25) * 180 / M_PI, 1e-9);
}

TEST(QuadRelax, SweepsStraightenTheLinesKeepTheBoundaryAndTheSurface) {
  FlatGrid g(8);
  // A kink like a chart boundary's: the rows bend at column 4.
  for (int j = 1; j < 8; ++j) {
    for (int i = 1; i < 8; ++i) g.points[size_t(g.At(i, j))].y() += 0.6 * std::abs(i - 4) / 4.0;
  }
  const std::vector<Eigen::Vector3d> start = g.points;
  const auto onto_plane = [](const Eigen::Vector3d& p) { return Eigen::Vector3d(p.x(), p.y(), 0); };
  const double before = MeasureGridLineKinks(g.points, g.quads).max_degrees;
  RelaxQuads(g.quads, 30, onto_plane, &g.points);
  const double after = MeasureGridLineKinks(g.points, g.quads).max_degrees;
  EXPECT_GT(before, 8.0);
  EXPECT_LT(after, 0.5 * before);
  for (int i = 0; i <= 8; ++i) {  // the boundary (not valence 4) stays
    EXPECT_EQ(g.points[size_t(g.At(i, 0))], start[size_t(g.At(i, 0))]);
  }
  for (const Eigen::Vector3d& p : g.points) EXPECT_EQ(p.z(), 0.0);
  // No sweep, no change.
  std::vector<Eigen::Vector3d> same = start;
  RelaxQuads(g.quads, 0, onto_plane, &same);
  EXPECT_EQ(same, start);
}

// A triangle chart's three quads around its centre G, with G mapped close to
// corner A: listed among the centres, G moves to the mean of its spoke
// neighbours (the midpoints, whose mean is the triangle's centroid); not
// listed, it stays like any irregular vertex.
TEST(QuadRelax, ATriangleCentreMovesToTheMiddleOfItsSpokes) {
  const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0), c(1, std::sqrt(3.0), 0);
  const Eigen::Vector3d centroid = (a + b + c) / 3;
  std::vector<Eigen::Vector3d> points = {a, b, c, (a + b) / 2, (b + c) / 2, (c + a) / 2,
                                         centroid + 0.6 * (a - centroid)};
  const std::vector<std::array<int, 4>> quads = {{0, 3, 6, 5}, {1, 4, 6, 3}, {2, 5, 6, 4}};
  const auto onto_plane = [](const Eigen::Vector3d& p) { return Eigen::Vector3d(p.x(), p.y(), 0); };
  std::vector<Eigen::Vector3d> held = points;
  RelaxQuads(quads, 40, onto_plane, &held);
  EXPECT_EQ(held, points);
  RelaxQuads(quads, 40, onto_plane, &points, {6});
  EXPECT_LT((points[6] - centroid).norm(), 1e-9);
  for (int v = 0; v < 6; ++v) EXPECT_EQ(points[size_t(v)], held[size_t(v)]);
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
