// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Isotropic remeshing [Gebreiter 2012, §3.1.2; Botsch & Kobbelt 2004]
// (geometry/isotropic_remesh.h): on a plate, a folded plate and a sphere,
// the remeshed surface stays on the input (planes exactly, boundary on its
// lines, corners and the fold's ridge kept), edges reach the target length
// and triangles are well shaped; without the feature rule the ridge is cut.
#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/validity.h"
#include "generators/smoothness_surfaces.h"
#include "geometry/isotropic_remesh.h"
#include "geometry/reference.h"
#include "io/io.h"
#include "mesh/topology.h"
#include "tests/closed_meshes.h"
#include "tests/make_mesh.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

// An n × n grid over [0, 2] × [0, 1] with jittered interior vertices and
// alternating diagonals, folded along x = 1 by `fold` (radians: the right
// half rises at that angle), so the input is uneven and the ridge is an edge
// line of the input.
Mesh FoldedPlate(int n, double fold, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  std::vector<Vec3> points;
  const double h = 1.0 / n;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= 2 * n; ++i) {
      double x = i * h, y = j * h;
      if (i > 0 && i < 2 * n && i != n) x += jitter(rng) * h;
      if (j > 0 && j < n) y += jitter(rng) * h;
      const double z = x > 1 ? (x - 1) * std::sin(fold) : 0;
      const double xx = x > 1 ? 1 + (x - 1) * std::cos(fold) : x;
      points.push_back({xx, y, z});
    }
  }
  std::vector<std::vector<int>> faces;
  const int row = 2 * n + 1;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < 2 * n; ++i) {
      const int a = j * row + i, b = a + 1, c = a + row + 1, d = a + row;
      if ((i + j) % 2) {
        faces.push_back({a, b, c});
        faces.push_back({a, c, d});
      } else {
        faces.push_back({a, b, d});
        faces.push_back({b, c, d});
      }
    }
  }
  return MakeMesh(points, faces);
}

// Mean |valence − 6| over interior vertices: the flips' target.
double ValenceDeviation(const Mesh& m) {
  double sum = 0;
  int count = 0;
  for (VertexIndex v : m.vertices()) {
    if (m.is_border(v)) continue;
    sum += std::abs(int(m.degree(v)) - 6);
    ++count;
  }
  return sum / count;
}

// The largest distance of a vertex of `mesh` from `surface`.
double FarthestFrom(const ReferenceSurface& surface, const Mesh& mesh) {
  double off = 0;
  for (VertexIndex x : mesh.vertices()) {
    const Eigen::Vector3d p = Pos(mesh, x);
    const auto c = surface.Closest({p.x(), p.y(), p.z()});
    off = std::max(off, (p - Eigen::Vector3d(c.point[0], c.point[1], c.point[2])).norm());
  }
  return off;
}

// Distance of p from the folded plate's two half-planes.
double OffFold(const Eigen::Vector3d& p, double fold) {
  const Eigen::Vector3d n(-std::sin(fold), 0, std::cos(fold));  // normal of the risen half
  const double left = std::abs(p.z()), right = std::abs((p - Eigen::Vector3d(1, 0, 0)).dot(n));
  return std::min(left, right);
}

TEST(IsotropicRemesh, FlatPlateStaysOnItsPlaneAndBoundaryWithCornersAndGoodTriangles) {
  const Mesh input = FoldedPlate(12, 0, 1);
  RemeshOptions o;
  o.target_edge_length = 0.06;
  const RemeshResult r = IsotropicRemesh(input, o);
  EXPECT_EQ(r.corners, 4);
  double area = 0;
  for (FaceIndex f : r.mesh.faces()) {
    const HalfedgeIndex h = r.mesh.halfedge(f);
    const Eigen::Vector3d a = Pos(r.mesh, r.mesh.source(h)), b = Pos(r.mesh, r.mesh.target(h)),
                          c = Pos(r.mesh, r.mesh.target(r.mesh.next(h)));
    area += 0.5 * (b - a).cross(c - a).z();  // signed: no triangle flipped
  }
  EXPECT_NEAR(area, 2.0, 1e-9);
  int on_corner = 0;
  for (VertexIndex v : r.mesh.vertices()) {
    const Eigen::Vector3d p = Pos(r.mesh, v);
    EXPECT_NEAR(p.z(), 0, 1e-12);
    if (r.mesh.is_border(v)) {
      const double off = std::min({std::abs(p.x()), std::abs(p.x() - 2), std::abs(p.y()), std::abs(p.y() - 1)});
      EXPECT_LE(off, 1e-9) << p.transpose();
      on_corner += (std::abs(p.x()) < 1e-12 || std::abs(p.x() - 2) < 1e-12) &&
                   (std::abs(p.y()) < 1e-12 || std::abs(p.y() - 1) < 1e-12);
    }
  }
  EXPECT_EQ(on_corner, 4);
  const TriangleQuality q = MeasureTriangles(r.mesh);
  EXPECT_GE(q.min_angle_30_fraction, 0.99);
  EXPECT_LE(q.edge_cv, 0.12);
  EXPECT_NEAR(q.edge_mean, 0.06, 0.006);
  EXPECT_LE(ValenceDeviation(r.mesh), 0.3);  // 0.21 with the flips, 0.43 without
  // The input's edges (1/12 ≈ 0.083, jittered) are far from the target.
  EXPECT_GT(MeasureTriangles(input).edge_cv, 0.2);
}

TEST(IsotropicRemesh, FoldedPlateKeepsItsRidgeAsAFeatureAndCutsItWithout) {
  const double fold = 60 * M_PI / 180;
  const Mesh input = FoldedPlate(12, fold, 2);
  RemeshOptions o;
  o.target_edge_length = 0.07;
  o.feature_angle_degrees = 30;
  const RemeshResult kept = IsotropicRemesh(input, o);
  EXPECT_EQ(kept.feature_edges, 12);
  double worst = 0;
  for (VertexIndex v : kept.mesh.vertices()) worst = std::max(worst, OffFold(Pos(kept.mesh, v), fold));
  EXPECT_LE(worst, 1e-9);
  // Every face lies in one half: its centroid is on a plane too.
  double worst_face = 0;
  for (FaceIndex f : kept.mesh.faces()) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (VertexIndex v : CGAL::vertices_around_face(kept.mesh.halfedge(f), kept.mesh)) c += Pos(kept.mesh, v) / 3;
    worst_face = std::max(worst_face, OffFold(c, fold));
  }
  EXPECT_LE(worst_face, 1e-9);
  EXPECT_GE(MeasureTriangles(kept.mesh).min_angle_30_fraction, 0.98);
  o.feature_angle_degrees = 0;
  const RemeshResult cut = IsotropicRemesh(input, o);
  EXPECT_EQ(cut.feature_edges, 0);
  double cut_face = 0;
  for (FaceIndex f : cut.mesh.faces()) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (VertexIndex v : CGAL::vertices_around_face(cut.mesh.halfedge(f), cut.mesh)) c += Pos(cut.mesh, v) / 3;
    cut_face = std::max(cut_face, OffFold(c, fold));
  }
  EXPECT_GT(cut_face, 1e-3);  // triangles across the ridge cut the corner
}

// Sum of the lengths of the edges with both ends on the line x = 1, z = 0.
double RmLengthOnTheMidline(const Mesh& m) {
  double sum = 0;
  for (EdgeIndex e : m.edges()) {
    const Eigen::Vector3d a = Pos(m, m.source(m.halfedge(e))), b = Pos(m, m.target(m.halfedge(e)));
    if (std::abs(a.x() - 1) < 1e-9 && std::abs(b.x() - 1) < 1e-9) sum += (b - a).norm();
  }
  return sum;
}

// A user's feature curve on a flat plate (no dihedral features): the input
// edges along it become features and the output keeps an edge line on it,
// its whole length; without the curve, the remeshing crosses the line.
TEST(IsotropicRemesh, AUserCurveIsKeptAsAFeature) {
  const Mesh input = FoldedPlate(12, 0, 3);  // x = 1 is an edge line of the input
  RemeshOptions o;
  o.target_edge_length = 0.07;
  o.feature_angle_degrees = 0;
  o.curve_tolerance = 1e-3;
  o.feature_curves = {{Vec3{1, 0, 0}, Vec3{1, 1, 0}}, {Vec3{0.3, 0.2, 0}, Vec3{0.7, 0.45, 0}}};
  const RemeshResult kept = IsotropicRemesh(input, o);
  ASSERT_EQ(kept.curve_edges.size(), 2u);
  EXPECT_EQ(kept.curve_edges[0], 12);
  EXPECT_EQ(kept.curve_edges[1], 0);  // along no edge of the input
  EXPECT_EQ(kept.feature_edges, 12);
  EXPECT_NEAR(RmLengthOnTheMidline(kept.mesh), 1.0, 1e-9);
  o.feature_curves.clear();
  const RemeshResult free = IsotropicRemesh(input, o);
  EXPECT_LT(RmLengthOnTheMidline(free.mesh), 0.5);
}

// The unit octahedron subdivided `levels` times, its vertices on the unit sphere.
Mesh OctaSphere(int levels) {
  std::vector<Eigen::Vector3d> p;
  std::vector<std::array<int, 3>> t;
  OctahedronSphere(levels, p, t);
  std::vector<Vec3> points;
  for (const Eigen::Vector3d& x : p) points.push_back({x.x(), x.y(), x.z()});
  std::vector<std::vector<int>> faces;
  for (const auto& f : t) faces.push_back({f[0], f[1], f[2]});
  return MakeMesh(points, faces);
}

TEST(IsotropicRemesh, SphereStaysClosedOnTheInputWithEvenEdges) {
  const Mesh input = OctaSphere(4);
  RemeshOptions o;
  o.target_edge_length = 0.2;
  const RemeshResult r = IsotropicRemesh(input, o);
  const long v = long(r.mesh.number_of_vertices()), e = long(r.mesh.number_of_edges()),
             f = long(r.mesh.number_of_faces());
  EXPECT_EQ(v - e + f, 2);
  EXPECT_LE(FarthestFrom(ReferenceSurface(input), r.mesh), 1e-9);
  const TriangleQuality q = MeasureTriangles(r.mesh);
  EXPECT_GE(q.min_angle_30_fraction, 0.99);
  EXPECT_LE(q.edge_cv, 0.10);
  EXPECT_NEAR(q.edge_mean, 0.2, 0.02);
  EXPECT_LE(ValenceDeviation(r.mesh), 0.3);  // 0.19 with the flips, 0.38 without
}

// A coarse torus (10 × 5 quads, R = 3, r = 1) whose every edge bends by
// 36–72°: with features at 30° it is a net of feature chains through
// corners, as a tessellated CAD part is. Remeshed coarser than it is, every
// vertex stays on the input (a feature vertex on its own chain, not on a
// chain nearby), no two vertices meet and no triangle folds onto another:
// the output passes the validity checks on its own (no short edge, no
// self-intersection).
TEST(IsotropicRemesh, CoarseFeatureNetStaysOnItsChainsWithoutFoldsOrCoincidentVertices) {
  const Mesh input = TorusPrincipalQuads(3, 1, 10, 5);
  const ReferenceSurface surface(input);
  for (const double factor : {1.3, 1.5}) {
    SCOPED_TRACE(factor);
    RemeshOptions o;
    o.target_edge_length = factor * MeanEdgeLength(input);
    o.feature_angle_degrees = 30;
    const RemeshResult r = IsotropicRemesh(input, o);
    EXPECT_GT(r.feature_edges, 0);
    EXPECT_LE(FarthestFrom(surface, r.mesh), 1e-9);
    const Validity alone = CheckValidity(r.mesh, nullptr, ValidityLimits{}, true);
    EXPECT_TRUE(alone.valid()) << alone.Reason();
    EXPECT_GT(MeasureTriangles(r.mesh).min_angle_degrees, 5);
  }
}

// A tessellated CAD part (a crop of Directional's 129110__sf.obj, MPL-2.0,
// tests/data): a plate 2.5 thick with a countersunk hole, long slivers,
// remeshed at the whole part's mean edge length with features at 30°. Each
// split, collapse, flip and relaxation step turns a face by less than 90°,
// yet steps in a row turned faces over around the hole (91 intersecting face
// pairs, coincident vertices); a face must also face the input's way where
// its corners lie (the sum of the input's normals there).
TEST(IsotropicRemesh, ThinPartWithAHoleKeepsEveryFaceTheInputsWay) {
  const Mesh input = ReadMesh(std::string(ARCHGEO_SOURCE_DIR) + "/tests/data/directional_129110_sf_crop.obj");
  ASSERT_EQ(input.number_of_faces(), 375u);
  RemeshOptions o;
  o.target_edge_length = 3.0596;
  o.feature_angle_degrees = 30;
  const RemeshResult r = IsotropicRemesh(input, o);
  EXPECT_LE(FarthestFrom(ReferenceSurface(input), r.mesh), 1e-9);
  const Validity alone = CheckValidity(r.mesh, nullptr, ValidityLimits{}, true);
  EXPECT_TRUE(alone.valid()) << alone.Reason();
}

// A mesh with its input's vertex, edge and face counts is not always the
// input moved: a remeshed closed surface can have them (2V − 4 faces at the
// same vertex count). The validity checks compare faces of the same index
// only when every face has the input's vertices; here the same sphere with
// its faces listed in reverse order, whose face i is another face than the
// input's, is valid, where comparing by index would call most faces turned.
TEST(IsotropicRemesh, AMeshWithTheInputsCountsButOtherFacesIsNotComparedFaceByFace) {
  const Mesh input = OctaSphere(3);
  Mesh other;
  for (VertexIndex v : input.vertices()) other.add_vertex(input.point(v));
  std::vector<FaceIndex> faces(input.faces().begin(), input.faces().end());
  for (auto f = faces.rbegin(); f != faces.rend(); ++f) {
    std::vector<VertexIndex> corners;
    for (VertexIndex v : CGAL::vertices_around_face(input.halfedge(*f), input)) corners.push_back(v);
    other.add_face(corners);
  }
  ASSERT_EQ(other.number_of_faces(), input.number_of_faces());
  ASSERT_EQ(other.number_of_edges(), input.number_of_edges());
  EXPECT_FALSE(SameConnectivity(input, other));
  EXPECT_TRUE(SameConnectivity(input, input));
  const Validity v = CheckValidity(other, &input, ValidityLimits{}, true);
  EXPECT_TRUE(v.valid()) << v.Reason();
}

// Curvature-adaptive targets: on the unit sphere (κ = 1 everywhere) a chord
// tolerance ε asks for edges of √(6ε − 3ε²) whatever the uniform target L,
// and the triangles' centroids then lie within about 1.5 ε of the sphere
// (a centroid sinks ℓ²κ/6, an edge's midpoint ℓ²κ/8 = 0.75 ε).
TEST(IsotropicRemesh, ToleranceShrinksEdgesToTheChordDeviation) {
  const Mesh input = OctaSphere(5);
  auto deepest = [](const Mesh& m) {
    double depth = 0;
    for (FaceIndex f : m.faces()) {
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for (VertexIndex v : CGAL::vertices_around_face(m.halfedge(f), m)) c += Pos(m, v) / 3;
      depth = std::max(depth, 1 - c.norm());
    }
    return depth;
  };
  RemeshOptions o;
  o.target_edge_length = 0.5;
  const RemeshResult uniform = IsotropicRemesh(input, o);
  o.tolerance = 0.002;
  const RemeshResult adaptive = IsotropicRemesh(input, o);
  const double expected = std::sqrt(6 * o.tolerance - 3 * o.tolerance * o.tolerance);
  const TriangleQuality q = MeasureTriangles(adaptive.mesh);
  EXPECT_NEAR(q.edge_mean, expected, 0.15 * expected);
  EXPECT_GE(q.min_angle_30_fraction, 0.99);
  EXPECT_LE(deepest(adaptive.mesh), 2 * o.tolerance);
  EXPECT_GT(deepest(uniform.mesh), 5 * o.tolerance);
  EXPECT_NEAR(MeasureTriangles(uniform.mesh).edge_mean, 0.5, 0.075);
}

TEST(IsotropicRemesh, RefusesANonPositiveTarget) {
  RemeshOptions o;
  o.target_edge_length = 0;
  EXPECT_THROW(IsotropicRemesh(FoldedPlate(2, 0, 3), o), std::invalid_argument);
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
