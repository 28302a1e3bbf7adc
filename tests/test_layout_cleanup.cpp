// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for the layout clean-ups of fields/extract.h step 6 on the branched
// pair g + i h = z^(1/2) (a +1/2 singularity at the origin, cut along the
// negative x-axis, s = −1), both levels even:
//  - without merge_valence_two the singular vertex has valence 2 (two quads
//    with a straight angle there: tests/test_field_extract.cpp);
//  - with it the vertex is gone and its two quads are one quad: no interior
//    vertex of valence 2, two valence-3 vertices (index 1/4 + 1/4 = 1/2),
//    still only quads inside, one face fewer, and every face convex (no
//    corner above 180° in its plane, so the reflex split has nothing to do);
//  - cap_angle and reflex_margin leave this regular layout unchanged.
// And on the polygon soup of fields/layout_cleanup.h, the near-slit seen on
// Concerthall's layout (two level lines leaving a singular vertex 0.3° apart;
// coordinates from that layout, in its tangent plane):
//  - RemoveNearSlits moves the two vertices beside the long side into the
//    face across it: a triangle and a heptagon, both turning as before;
//  - without it, SplitReflexCorners must not cut the hairline face along a
//    diagonal outside it (the part folded onto the other, which the PQ step
//    pushed through its neighbours: 5 intersecting face pairs).
#include <cmath>
#include <complex>
#include <functional>
#include <vector>

#include <CGAL/boost/graph/helpers.h>
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "fields/cuts.h"
#include "fields/extract.h"
#include "fields/layout_cleanup.h"
#include "fields/triangle_surfaces.h"
#include "tests/make_mesh.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using V3 = Eigen::Vector3d;

// Layout of g + i h = z^(1/2) / spacing on [−0.6, 0.9] x [−1, 1] (the origin
// a grid vertex), even rounding (α = 0 for both functions).
Extraction HalfSingularityLayout(const ExtractOptions& options) {
  const Mesh mesh = TriangulatedGrid(60, 80, [](double u, double v) -> Vec3 {
    return {-0.6 + 1.5 * u, -1.0 + 2.0 * v, 0.0};
  });
  VertexIndex origin;
  for (VertexIndex v : mesh.vertices())
    if (Pos(mesh, v).norm() < 1e-9) origin = v;
  EXPECT_TRUE(origin.is_valid());
  static CutGraph cut;  // fn.cut points here; one layout at a time
  cut = ComputeCutGraph(mesh, {origin});
  LevelSetFunctions fn;
  fn.cut = &cut;
  fn.g.assign(cut.num_wedges, NAN);
  fn.h.assign(cut.num_wedges, NAN);
  for (FaceIndex face : mesh.faces()) {
    V3 c = V3::Zero();
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(face))) c += Pos(mesh, v) / 3;
    for (HalfedgeIndex h : mesh.halfedges_around_face(mesh.halfedge(face))) {
      const V3 p = Pos(mesh, mesh.target(h));
      const std::complex<double> z =
          std::polar(std::sqrt(std::hypot(p.x(), p.y())), 0.5 * ArgNear(p, c));
      fn.g[cut.corner_wedge[h.idx()]] = z.real();
      fn.h[cut.corner_wedge[h.idx()]] = z.imag();
    }
  }
  fn.alpha_g = {0.0};
  fn.alpha_h = {0.0};
  fn.sign_g = {-1};
  fn.sign_h = {-1};
  fn.spacing_g = fn.spacing_h = 0.25;
  return ExtractQuadMesh(mesh, fn, options);
}

std::vector<double> CornerAnglesDeg(const Mesh& m, FaceIndex f) {
  std::vector<V3> p;
  for (VertexIndex v : m.vertices_around_face(m.halfedge(f))) p.push_back(Pos(m, v));
  std::vector<double> out;
  for (size_t i = 0; i < p.size(); ++i) {
    const V3 a = p[(i + p.size() - 1) % p.size()] - p[i], b = p[(i + 1) % p.size()] - p[i];
    double angle = std::atan2(b.cross(a).z(), a.dot(b)) * 180.0 / M_PI;  // plane z = 0, ccw
    if (angle < 0) angle += 360.0;
    out.push_back(angle);
  }
  return out;
}

TEST(LayoutCleanup, AValenceTwoVertexAtAHalfSingularityBecomesOneQuad) {
  const Extraction plain = HalfSingularityLayout({});
  ASSERT_TRUE(plain.ok) << plain.error;
  ASSERT_EQ(plain.irregular_interior_vertices.size(), 1u);
  ASSERT_EQ(plain.mesh.degree(plain.irregular_interior_vertices[0]), 2u);

  ExtractOptions options;
  options.merge_valence_two = true;
  const Extraction x = HalfSingularityLayout(options);
  ASSERT_TRUE(x.ok) << x.error;
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(x.mesh));
  EXPECT_EQ(x.merged_valence_two, 1);
  EXPECT_EQ(x.mesh.number_of_faces(), plain.mesh.number_of_faces() - 1);
  EXPECT_EQ(x.mesh.number_of_vertices(), plain.mesh.number_of_vertices() - 1);
  EXPECT_EQ(x.interior_valence.count(2), 0u);
  ASSERT_EQ(x.irregular_interior_vertices.size(), 2u);
  for (VertexIndex v : x.irregular_interior_vertices) EXPECT_EQ(x.mesh.degree(v), 3u);
  EXPECT_TRUE(x.irregular_interior_faces.empty());
  EXPECT_EQ(x.quads, plain.quads - 1);
  for (FaceIndex f : x.mesh.faces())
    for (double angle : CornerAnglesDeg(x.mesh, f)) EXPECT_LT(angle, 180.0) << "face " << f.idx();
}

TEST(LayoutCleanup, CapsAndReflexSplitsLeaveARegularLayoutAlone) {
  ExtractOptions options;
  options.merge_valence_two = true;
  const Extraction before = HalfSingularityLayout(options);
  options.cap_angle_deg = 160;
  options.reflex_margin_deg = 2;
  const Extraction after = HalfSingularityLayout(options);
  ASSERT_TRUE(after.ok) << after.error;
  EXPECT_EQ(after.merged_caps, 0);
  EXPECT_EQ(after.split_reflex_corners, 0);
  EXPECT_EQ(after.face_degrees, before.face_degrees);
}

// The near-slit: face 0 runs 3 → 4 → 2 → 1 → 0 with 1 and 2 (nearly) on the
// side 0–3 of face 1 (0 → 5 → 6 → 7 → 3).
std::vector<V3> SlitPoints() {
  return {V3(-0.646, -0.147, 0), V3(-0.473, -0.146, 0), V3(-0.301, -0.145, 0),
          V3(1.099, -0.131, 0),  V3(0.441, 0.006, 0),   V3(-1.508, -0.161, 0),
          V3(-0.855, -0.681, 0), V3(1.333, -0.533, 0)};
}
std::vector<std::vector<int>> SlitFaces() { return {{3, 4, 2, 1, 0}, {0, 5, 6, 7, 3}}; }

// Twice the signed area of face f in the plane z = 0 (> 0: counter-clockwise).
double SignedArea(const std::vector<V3>& p, const std::vector<int>& f) {
  double a = 0;
  for (size_t i = 0; i < f.size(); ++i) {
    const V3& u = p[f[i]];
    const V3& w = p[f[(i + 1) % f.size()]];
    a += u.x() * w.y() - w.x() * u.y();
  }
  return a;
}

TEST(LayoutCleanup, ANearSlitMovesItsVerticesIntoTheFaceAcross) {
  const std::vector<V3> p = SlitPoints();
  std::vector<std::vector<int>> faces = SlitFaces();
  int removed = 0, dropped = 0;
  RemoveNearSlits(p, 3.0, &faces, &removed, &dropped);
  EXPECT_EQ(removed, 2);
  EXPECT_EQ(dropped, 0);
  ASSERT_EQ(faces.size(), 2u);
  EXPECT_EQ(faces[0], (std::vector<int>{3, 4, 2}));
  EXPECT_EQ(faces[1], (std::vector<int>{0, 5, 6, 7, 3, 2, 1}));
  for (const auto& f : faces) EXPECT_GT(SignedArea(p, f), 0.0);

  std::vector<std::vector<int>> untouched = SlitFaces();
  RemoveNearSlits(p, 0.1, &untouched, &removed, &dropped);  // its corners are 0.3° and more
  EXPECT_EQ(untouched, SlitFaces());
}

TEST(LayoutCleanup, AReflexSplitNeverCutsAlongADiagonalOutsideTheFace) {
  const std::vector<V3> p = SlitPoints();
  std::vector<std::vector<int>> faces = SlitFaces();
  int split = 0;
  SplitReflexCorners(p, std::vector<bool>(p.size(), false), 2.0, &faces, &split);
  for (const auto& f : faces) EXPECT_GT(SignedArea(p, f), 0.0) << "a part folded over";
}

}  // namespace
}  // namespace archgeo
