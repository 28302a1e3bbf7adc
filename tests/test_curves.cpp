// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for mesh/curves: OBJ polylines and their errors (file and line),
// polylines from points, closest points with arc length and tangent, the
// boundary loops of a mesh, Catmull-Rom resampling.
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "geometry/curves.h"
#include "generators/generators.h"
#include "core/input_error.h"
#include "generators/smoothness_surfaces.h"
#include "tests/make_mesh.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

constexpr double kRounding = 1e-12;

using V = Eigen::Vector3d;

V E(const Vec3& x) { return {x[0], x[1], x[2]}; }
double Distance(const Vec3& a, const Vec3& b) { return (E(a) - E(b)).norm(); }

class ReadPolylinesTest : public ScratchDirTest {
 protected:
  // Expects ReadPolylines to throw an InputError for `text` at `line`
  // whose message contains `what`.
  void ExpectError(const std::string& text, int line, const std::string& what) {
    const std::string path = WriteFile("bad.obj", text);
    try {
      ReadPolylines(path);
      ADD_FAILURE() << "no error for:\n" << text;
    } catch (const InputError& error) {
      EXPECT_EQ(error.file(), path);
      EXPECT_EQ(error.line(), line) << error.what();
      EXPECT_NE(error.message().find(what), std::string::npos) << error.what();
    }
  }
};

TEST_F(ReadPolylinesTest, ReadsOpenAndClosedPolylines) {
  const std::string path = WriteFile("curves.obj",
                                     "# perimeter and a guide curve\r\n"
                                     "o curves\n"
                                     "v 0 0 0\n"
                                     "v 2 0 0\n"
                                     "v 2 3 0 1.0\n"
                                     "v 0 3 0\n"
                                     "l 1 2 3 4 1\n"
                                     "vt 0.5 0.5\n"
                                     "v 5 5 5\n"
                                     "l -1/1 -4 -4 3  # relative indices, repeat merged\n"
                                     "f 1 2 3\n");
  const std::vector<Polyline> polylines = ReadPolylines(path);
  ASSERT_EQ(polylines.size(), 2u);
  EXPECT_TRUE(polylines[0].closed);
  ASSERT_EQ(polylines[0].points.size(), 4u);
  EXPECT_EQ(polylines[0].points[2], (Vec3{2, 3, 0}));
  EXPECT_NEAR(PolylineLength(polylines[0]), 10.0, kRounding);
  EXPECT_FALSE(polylines[1].closed);
  ASSERT_EQ(polylines[1].points.size(), 3u);
  EXPECT_EQ(polylines[1].points[0], (Vec3{5, 5, 5}));
  EXPECT_EQ(polylines[1].points[1], (Vec3{2, 0, 0}));
  EXPECT_EQ(polylines[1].points[2], (Vec3{2, 3, 0}));
  EXPECT_EQ(Coordinates(polylines[1]), (std::vector<double>{5, 5, 5, 2, 0, 0, 2, 3, 0}));
}

TEST_F(ReadPolylinesTest, ErrorsNameTheLine) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 1 1 0\n";
  ExpectError(v + "l 1 0 2\n", 4, "index '0'");
  ExpectError(v + "l 1 2 4\n", 4, "out of range");
  ExpectError(v + "l 1 -4\n", 4, "out of range");
  ExpectError(v + "l 1 x\n", 4, "bad polyline index 'x'");
  ExpectError(v + "l 2\n", 4, "at least 2 distinct points");
  ExpectError(v + "l 2 2 2\n", 4, "distinct points, got 1");
  ExpectError(v + "l 1 2 1\n", 4, "at least 3 distinct points");
  ExpectError("v 0 0 0\nv nan 0 0\nl 1 2\n", 2, "non-finite");
  ExpectError("v 0 0 0\nv 1 inf 0\nl 1 2\n", 2, "non-finite");
  ExpectError("v 0 0\nl 1 2\n", 1, "malformed vertex");
  ExpectError(v + "f 1 2 3\n", 0, "no 'l' record");
  EXPECT_THROW(ReadPolylines(Path("missing.obj")), InputError);
}

TEST(MakePolyline, MergesRepeatsAndReportsWhereThePointsCameFrom) {
  const Polyline closed =
      MakePolyline({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}}, true);
  EXPECT_TRUE(closed.closed);
  EXPECT_EQ(closed.points.size(), 3u);
  EXPECT_NEAR(PolylineLength(closed), 2 + std::sqrt(2.0), kRounding);
  try {
    MakePolyline({{0, 0, 0}, {1, NAN, 0}}, false, "spec.yaml", 7, "curves.guide");
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "spec.yaml");
    EXPECT_EQ(error.line(), 7);
    EXPECT_EQ(error.key(), "curves.guide");
    EXPECT_NE(error.message().find("point 1"), std::string::npos);
  }
  EXPECT_THROW(MakePolyline({{1, 2, 3}, {1, 2, 3}}, false), InputError);
  EXPECT_THROW(MakePolyline({{0, 0, 0}, {1, 0, 0}}, true), InputError);
}

TEST(PolylineLocator, ClosestPointArcLengthAndTangent) {
  // L-shape (0,0,0) → (2,0,0) → (2,3,0), closed by (2,3,0) → (0,0,0).
  const Polyline open = MakePolyline({{0, 0, 0}, {2, 0, 0}, {2, 3, 0}}, false);
  const PolylineLocator locator(open);
  EXPECT_NEAR(locator.length(), 5.0, kRounding);
  auto a = locator.Closest({1.5, -1, 2});
  EXPECT_NEAR(Distance(a.point, {1.5, 0, 0}), 0, kRounding);
  EXPECT_NEAR(a.arc_length, 1.5, kRounding);
  EXPECT_NEAR(Distance(a.tangent, {1, 0, 0}), 0, kRounding);
  EXPECT_EQ(a.segment, 0);
  EXPECT_NEAR(a.distance, std::sqrt(5.0), kRounding);
  auto b = locator.Closest({3, 2.5, 0});
  EXPECT_NEAR(b.arc_length, 4.5, kRounding);
  EXPECT_NEAR(Distance(b.tangent, {0, 1, 0}), 0, kRounding);
  EXPECT_NEAR(b.distance, 1.0, kRounding);
  auto end = locator.Closest({-1, -1, 0});  // beyond the start: p_0
  EXPECT_NEAR(end.arc_length, 0.0, kRounding);
  EXPECT_NEAR(end.distance, std::sqrt(2.0), kRounding);
  const Polyline closed = MakePolyline(open.points, true);
  const PolylineLocator loop(closed);
  const double diagonal = std::sqrt(13.0);
  EXPECT_NEAR(loop.length(), 5.0 + diagonal, kRounding);
  auto c = loop.Closest({1, 1.5, 0});  // midpoint of the closing segment
  EXPECT_EQ(c.segment, 2);
  EXPECT_NEAR(c.arc_length, 5.0 + diagonal / 2, kRounding);
  EXPECT_NEAR(Distance(c.tangent, {-2 / diagonal, -3 / diagonal, 0}), 0, kRounding);
  EXPECT_NEAR(c.distance, 0.0, kRounding);
}

TEST(BoundaryLoops, GridWithAHoleHasTwoLoopsLongestFirst) {
  // A 3 × 3 grid of unit quads without its centre quad.
  std::vector<Vec3> points;
  for (int j = 0; j <= 3; ++j) {
    for (int i = 0; i <= 3; ++i) points.push_back({double(i), double(j), 0});
  }
  std::vector<std::vector<int>> faces;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      if (i == 1 && j == 1) continue;
      const int a = j * 4 + i;
      faces.push_back({a, a + 1, a + 5, a + 4});
    }
  }
  const Mesh mesh = MakeMesh(points, faces);
  const auto loops = BoundaryLoops(mesh);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_EQ(loops[0].size(), 12u);  // outer perimeter
  EXPECT_EQ(loops[1].size(), 4u);   // the hole
  EXPECT_EQ(loops[0].front(), VertexIndex(0));
  EXPECT_EQ(loops[1].front(), VertexIndex(5));
  // Consecutive loop vertices are joined by border edges.
  for (const auto& loop : loops) {
    for (size_t k = 0; k < loop.size(); ++k) {
      const auto h = mesh.halfedge(loop[k], loop[(k + 1) % loop.size()]);
      ASSERT_NE(h, Mesh::null_halfedge());
      EXPECT_TRUE(mesh.is_border(mesh.edge(h)));
    }
  }
  EXPECT_NEAR(PolylineLength(LoopPolyline(mesh, loops[0])), 12.0, kRounding);
  EXPECT_NEAR(PolylineLength(LoopPolyline(mesh, loops[1])), 4.0, kRounding);
  EXPECT_TRUE(LoopPolyline(mesh, loops[1]).closed);
  // A closed surface has none.
  EXPECT_TRUE(BoundaryLoops(TorusPrincipalQuads(3, 1, 8, 6)).empty());
}

// Largest angle between consecutive segments of a polyline (closed: all).
double MaxTurning(const Polyline& p) {
  const size_t m = p.points.size();
  double worst = 0.0;
  for (size_t i = 0; i < m; ++i) {
    if (!p.closed && (i == 0 || i + 1 == m)) continue;
    const V a = E(p.points[i]) - E(p.points[(i + m - 1) % m]);
    const V b = E(p.points[(i + 1) % m]) - E(p.points[i]);
    worst = std::max(worst, std::atan2(a.cross(b).norm(), a.dot(b)));
  }
  return worst;
}

TEST(SampleCatmullRom, InterpolatesAndSmoothsTheTurning) {
  // Regular octagon on the unit circle: turning π/4 at every corner.
  std::vector<Vec3> octagon;
  for (int k = 0; k < 8; ++k)
    octagon.push_back({std::cos(M_PI * k / 4), std::sin(M_PI * k / 4), 0});
  const Polyline closed = MakePolyline(octagon, true);
  EXPECT_NEAR(MaxTurning(closed), M_PI / 4, kRounding);
  const Polyline fine = SampleCatmullRom(closed, 16);
  ASSERT_EQ(fine.points.size(), 8u * 16u);
  EXPECT_TRUE(fine.closed);
  for (int k = 0; k < 8; ++k) EXPECT_EQ(fine.points[16 * k], octagon[k]);  // interpolates
  // C¹: the turning spreads over the samples (≈ π/4/16 each).
  EXPECT_LT(MaxTurning(fine), M_PI / 4 / 4);
  // Open: ends kept, n − 1 segments.
  const Polyline open = MakePolyline({octagon[0], octagon[1], octagon[2], octagon[3]}, false);
  const Polyline open_fine = SampleCatmullRom(open, 5);
  ASSERT_EQ(open_fine.points.size(), 3u * 5u + 1u);
  EXPECT_EQ(open_fine.points.front(), octagon[0]);
  EXPECT_EQ(open_fine.points.back(), octagon[3]);
  EXPECT_EQ(SampleCatmullRom(open, 1).points, open.points);
}

}  // namespace
}  // namespace archgeo
