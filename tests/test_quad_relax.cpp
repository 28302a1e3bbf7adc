// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The grid lines of extracted quads (spectral/quad_relax.h): their turn at
// a vertex of valence 4 measured against the analytic angle, and the
// relaxation that straightens a kinked grid while the vertices not of
// valence 4 and the surface hold; folded quads unfolded
// (spectral/quad_untangle.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "spectral/quad_relax.h"
#include "spectral/quad_untangle.h"

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

// Every corner of every quad strictly convex (0° < θ < 180°) about +z.
bool QrAllConvex(const std::vector<Eigen::Vector3d>& p, const std::vector<std::array<int, 4>>& quads) {
  for (const auto& q : quads) {
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d u = p[size_t(q[size_t(k)])] - p[size_t(q[size_t((k + 3) % 4)])];
      const Eigen::Vector3d v = p[size_t(q[size_t((k + 1) % 4)])] - p[size_t(q[size_t(k)])];
      if (u.cross(v).z() <= 0) return false;  // a right turn: bent inward, or turned over
    }
  }
  return true;
}

SurfaceSample QrOntoPlane(const Eigen::Vector3d& p) {
  return {Eigen::Vector3d(p.x(), p.y(), 0), Eigen::Vector3d::UnitZ()};
}

// A 4 × 4 grid whose vertex (1, 1) is pulled to (1.7, 1.7): the quad
// between it and (2, 2) is bent inward at it. Untangling leaves every quad convex, the boundary where it was,
// and no edge under half its length as given; an unfolded grid is not
// touched.
TEST(QuadUntangle, ABentQuadIsUnfoldedAndTheBoundaryHolds) {
  FlatGrid g(4);
  g.points[size_t(g.At(1, 1))] = Eigen::Vector3d(1.7, 1.7, 0);
  ASSERT_FALSE(QrAllConvex(g.points, g.quads));
  const std::vector<Eigen::Vector3d> start = g.points;
  const UntangleResult r = UntangleQuads(g.quads, QrOntoPlane, &g.points, {}, false);
  EXPECT_EQ(r.bent_before, 1);
  EXPECT_EQ(r.bent_after, 0);
  EXPECT_GT(r.moves, 0);
  EXPECT_TRUE(QrAllConvex(g.points, g.quads));
  for (int i = 0; i <= 4; ++i) {
    for (int j : {0, 4}) {
      EXPECT_EQ(g.points[size_t(g.At(i, j))], start[size_t(g.At(i, j))]);
      EXPECT_EQ(g.points[size_t(g.At(j, i))], start[size_t(g.At(j, i))]);
    }
  }
  for (const auto& q : g.quads) {
    for (int k = 0; k < 4; ++k) {
      const size_t a = size_t(q[size_t(k)]), b = size_t(q[size_t((k + 1) % 4)]);
      EXPECT_GE((g.points[a] - g.points[b]).norm(), 0.5 * (start[a] - start[b]).norm());
    }
  }
  FlatGrid flat(4);
  const std::vector<Eigen::Vector3d> kept = flat.points;
  const UntangleResult none = UntangleQuads(flat.quads, QrOntoPlane, &flat.points, {}, false);
  EXPECT_EQ(none.bent_before, 0);
  EXPECT_EQ(none.moves, 0);
  EXPECT_EQ(flat.points, kept);
}

// The three quads round a valence-3 node G placed close to corner A of
// their triangle: the quad at A is bent inward at G. G moves (and they unfold) only when irregular
// vertices may move; otherwise nothing can and nothing does.
TEST(QuadUntangle, AnIrregularNodeMovesOnlyWhenAllowed) {
  const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0), c(1, std::sqrt(3.0), 0);
  const Eigen::Vector3d centroid = (a + b + c) / 3;
  const std::vector<Eigen::Vector3d> start = {a, b, c, (a + b) / 2, (b + c) / 2, (c + a) / 2,
                                              centroid + 0.95 * (a - centroid)};
  const std::vector<std::array<int, 4>> quads = {{0, 3, 6, 5}, {1, 4, 6, 3}, {2, 5, 6, 4}};
  ASSERT_FALSE(QrAllConvex(start, quads));
  std::vector<Eigen::Vector3d> held = start;
  const UntangleResult stay = UntangleQuads(quads, QrOntoPlane, &held, {}, false);
  EXPECT_GT(stay.bent_before, 0);
  EXPECT_EQ(stay.bent_after, stay.bent_before);
  EXPECT_EQ(held, start);
  std::vector<Eigen::Vector3d> moved = start;
  const UntangleResult r = UntangleQuads(quads, QrOntoPlane, &moved, {}, true);
  EXPECT_EQ(r.bent_after, 0);
  EXPECT_TRUE(QrAllConvex(moved, quads));
  for (int v = 0; v < 6; ++v) EXPECT_EQ(moved[size_t(v)], start[size_t(v)]);
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
