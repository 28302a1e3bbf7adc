// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for fields/extract.h on level sets whose quad mesh is known:
//  - g = x, h = y on a plane patch (jittered, and grid-aligned so that levels
//    run through mesh vertices and along mesh edges): the regular grid, exact
//    counts and positions; an offset level set clips the boundary column;
//    a rotated grid has only quads inside and covers the patch exactly;
//  - a cylinder with g = angle across a seam (cut, jump α = 2π, s = +1);
//  - a sphere patch in longitude/latitude;
//  - branched pairs g + i h = z^(1/2) (index +1/2) and z^(3/2) (−1/2) across a
//    cut with s = −1: even rounding gives an irregular vertex (valence 2 or
//    6), odd rounding an irregular face (triangle/hexagon), mixed rounding the
//    configurations derived in extract.h's comments;
//  - the output is a valid, consistently oriented polygon mesh without
//    zero-length edges, and inconsistent jumps are rejected.
#include <cmath>
#include <complex>
#include <cstdio>
#include <functional>
#include <vector>

#include <CGAL/boost/graph/helpers.h>
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "fields/cuts.h"
#include "fields/extract.h"
#include "fields/face_frames.h"
#include "fields/triangle_surfaces.h"
#include "tests/make_mesh.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using V3 = Eigen::Vector3d;

Mesh Plane(int nu, int nv, double x0, double x1, double y0, double y1, double jitter) {
  TriangleGridOptions opt;
  opt.jitter = jitter;
  return TriangulatedGrid(nu, nv, [=](double u, double v) -> Vec3 {
    return {x0 + (x1 - x0) * u, y0 + (y1 - y0) * v, 0.0};
  }, opt);
}

// Per-vertex values (no cut).
LevelSetFunctions PerVertex(const Mesh& mesh, const std::function<double(const V3&)>& g,
                            const std::function<double(const V3&)>& h, double dg, double dh) {
  LevelSetFunctions fn;
  for (VertexIndex v : mesh.vertices()) {
    fn.g.push_back(g(Pos(mesh, v)));
    fn.h.push_back(h(Pos(mesh, v)));
  }
  fn.spacing_g = dg;
  fn.spacing_h = dh;
  return fn;
}

// Newell normal of a face of the output.
V3 FaceNormal(const Mesh& m, FaceIndex f) {
  V3 n = V3::Zero();
  std::vector<V3> p;
  for (VertexIndex v : m.vertices_around_face(m.halfedge(f))) p.push_back(Pos(m, v));
  for (size_t i = 0; i < p.size(); ++i) n += p[i].cross(p[(i + 1) % p.size()]);
  return 0.5 * n;
}

double MinEdge(const Mesh& m) {
  double e = INFINITY;
  for (EdgeIndex x : m.edges())
    e = std::min(e, (Pos(m, m.vertex(x, 0)) - Pos(m, m.vertex(x, 1))).norm());
  return e;
}

void ExpectValid(const Extraction& x) {
  ASSERT_TRUE(x.ok) << x.error;
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(x.mesh));
  EXPECT_EQ(x.anomalies, 0);
  EXPECT_EQ(x.duplicated_vertices, 0);
  EXPECT_EQ(x.dropped_non_disk_regions, 0);
  EXPECT_GT(MinEdge(x.mesh), 0.0);
}

TEST(Extract, AxisLevelSetsOnAPlaneGiveTheExactGrid) {
  // Jittered interior (levels cross triangles anywhere) and the plain grid
  // (levels through vertices and along edges: x = k/3).
  for (double jitter : {0.3, 0.0}) {
    const Mesh mesh = Plane(12, 12, 0.0, 4.0, 0.0, 4.0, jitter);
    const Extraction x = ExtractQuadMesh(
        mesh, PerVertex(mesh, [](const V3& p) { return p.x(); }, [](const V3& p) { return p.y(); },
                        1.0, 1.0));
    ExpectValid(x);
    EXPECT_EQ(x.mesh.number_of_faces(), 16u) << "jitter " << jitter;
    EXPECT_EQ(x.quads, 16);
    EXPECT_EQ(x.mesh.number_of_vertices(), 25u);
    for (VertexIndex v : x.mesh.vertices()) {
      const V3 p = Pos(x.mesh, v);
      EXPECT_NEAR(p.x(), std::round(p.x()), 1e-12);
      EXPECT_NEAR(p.y(), std::round(p.y()), 1e-12);
    }
    EXPECT_EQ(x.interior_valence.at(4), 9);
    EXPECT_EQ(x.valence.at(2), 4);   // corners
    EXPECT_EQ(x.valence.at(3), 12);  // boundary
    for (FaceIndex f : x.mesh.faces()) EXPECT_NEAR(FaceNormal(x.mesh, f).z(), 1.0, 1e-12);
  }
}

TEST(Extract, OffsetLevelsClipTheBoundaryColumns) {
  const Mesh mesh = Plane(12, 12, 0.0, 4.0, 0.0, 4.0, 0.3);
  const Extraction x = ExtractQuadMesh(
      mesh, PerVertex(mesh, [](const V3& p) { return p.x() + 0.5; },
                      [](const V3& p) { return p.y(); }, 1.0, 1.0));
  ExpectValid(x);
  // Levels x = 0.5 … 3.5: 5 columns (half-width at both ends) x 4 rows.
  EXPECT_EQ(x.quads, 20);
  EXPECT_EQ(x.mesh.number_of_faces(), 20u);
  EXPECT_EQ(x.mesh.number_of_vertices(), 30u);
  double area = 0.0;
  for (FaceIndex f : x.mesh.faces()) area += FaceNormal(x.mesh, f).z();
  EXPECT_NEAR(area, 16.0, 1e-10);
}

TEST(Extract, RotatedGridHasQuadsInsideAndCoversThePatch) {
  const Mesh mesh = Plane(24, 24, 0.0, 4.0, 0.0, 4.0, 0.3);
  const double c = std::cos(0.5), s = std::sin(0.5);
  const Extraction x = ExtractQuadMesh(
      mesh, PerVertex(mesh, [&](const V3& p) { return c * p.x() + s * p.y(); },
                      [&](const V3& p) { return -s * p.x() + c * p.y(); }, 0.45, 0.45));
  ExpectValid(x);
  EXPECT_TRUE(x.irregular_interior_faces.empty());
  EXPECT_TRUE(x.irregular_interior_vertices.empty());
  double area = 0.0;
  for (FaceIndex f : x.mesh.faces()) {
    const V3 n = FaceNormal(x.mesh, f);
    EXPECT_GT(n.z(), 0.0);
    area += n.z();
  }
  // The boundary is straight and its corners are kept: exact cover.
  EXPECT_NEAR(area, 16.0, 1e-9);
  // Interior vertices are crossings of the levels.
  for (VertexIndex v : x.mesh.vertices()) {
    if (x.mesh.is_border(v)) continue;
    const V3 p = Pos(x.mesh, v);
    const double g = (c * p.x() + s * p.y()) / 0.45, h = (-s * p.x() + c * p.y()) / 0.45;
    EXPECT_NEAR(g, std::round(g), 1e-9);
    EXPECT_NEAR(h, std::round(h), 1e-9);
  }
  std::printf("rotated grid: %d quads, %d triangles, %d pentagons, %d other\n", x.quads,
              x.triangles, x.pentagons, x.other_faces);
}

// Values per wedge from a function of (corner point, face centroid), which
// lets a multivalued function pick its branch on the face's side of the cut.
std::vector<double> WedgeValues(const Mesh& mesh, const CutGraph& cut,
                                const std::function<double(const V3&, const V3&)>& f) {
  std::vector<double> out(cut.num_wedges, NAN);
  for (FaceIndex face : mesh.faces()) {
    V3 c = V3::Zero();
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(face))) c += Pos(mesh, v) / 3;
    for (HalfedgeIndex h : mesh.halfedges_around_face(mesh.halfedge(face))) {
      const double value = f(Pos(mesh, mesh.target(h)), c);
      double& w = out[cut.corner_wedge[h.idx()]];
      if (!std::isnan(w)) {
        EXPECT_NEAR(w, value, 1e-9);  // one value per wedge
      }
      w = value;
    }
  }
  return out;
}

TEST(Extract, CylinderWithTheAngleAcrossASeam) {
  TriangleGridOptions opt;
  opt.closed_u = true;
  opt.jitter = 0.2;
  const Mesh mesh = TriangulatedGrid(48, 16, [](double u, double v) -> Vec3 {
    return {std::cos(2 * M_PI * u), std::sin(2 * M_PI * u), 2 * v};
  }, opt);
  const CutGraph cut = ComputeCutGraph(mesh, {});
  ASSERT_EQ(cut.chains.size(), 1u);
  // θ continued over the cut surface: the centroid angles unwrapped by a
  // breadth-first search through uncut edges, corners continued from them.
  std::vector<double> centre_angle(mesh.number_of_faces(), NAN);
  std::vector<FaceIndex> queue = {FaceIndex(0)};
  auto centroid = [&](FaceIndex f) {
    V3 c = V3::Zero();
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) c += Pos(mesh, v) / 3;
    return c;
  };
  centre_angle[0] = std::atan2(centroid(FaceIndex(0)).y(), centroid(FaceIndex(0)).x());
  for (size_t i = 0; i < queue.size(); ++i) {
    const FaceIndex f = queue[i];
    for (HalfedgeIndex h : mesh.halfedges_around_face(mesh.halfedge(f))) {
      const EdgeIndex e = mesh.edge(h);
      if (mesh.is_border(e) || cut.is_cut_edge[e.idx()]) continue;
      const FaceIndex g = mesh.face(mesh.opposite(h));
      if (!std::isnan(centre_angle[g.idx()])) continue;
      const V3 c = centroid(g);
      const double a0 = centre_angle[f.idx()];
      centre_angle[g.idx()] = a0 + std::remainder(std::atan2(c.y(), c.x()) - a0, 2 * M_PI);
      queue.push_back(g);
    }
  }
  LevelSetFunctions fn;
  fn.cut = &cut;
  fn.g.assign(cut.num_wedges, NAN);
  for (FaceIndex f : mesh.faces()) {
    const double a0 = centre_angle[f.idx()];
    for (HalfedgeIndex h : mesh.halfedges_around_face(mesh.halfedge(f))) {
      const V3 p = Pos(mesh, mesh.target(h));
      // The angle of p nearest to a0.
      const double a = a0 + std::remainder(std::atan2(p.y(), p.x()) - a0, 2 * M_PI);
      double& w = fn.g[cut.corner_wedge[h.idx()]];
      if (!std::isnan(w)) {
        EXPECT_NEAR(w, a, 1e-9);
      }
      w = a;
    }
  }
  fn.h = WedgeValues(mesh, cut, [](const V3& p, const V3&) { return p.z(); });
  // The jump across the seam: g_left − g_right at its first relation.
  const JumpRelation& r = cut.relations[0];
  fn.alpha_g = {fn.g[r.left_wedge] - fn.g[r.right_wedge]};
  fn.alpha_h = {0.0};
  fn.sign_g = {1};
  fn.sign_h = {1};
  EXPECT_NEAR(std::abs(fn.alpha_g[0]), 2 * M_PI, 1e-12);
  fn.spacing_g = 2 * M_PI / 12;
  fn.spacing_h = 0.5;
  const Extraction x = ExtractQuadMesh(mesh, fn);
  ExpectValid(x);
  EXPECT_EQ(x.quads, 48);
  EXPECT_EQ(x.mesh.number_of_faces(), 48u);
  EXPECT_EQ(x.mesh.number_of_vertices(), 60u);
  EXPECT_EQ(x.interior_valence.at(4), 36);
  EXPECT_EQ(x.valence.at(3), 24);
  // Every crossing is at an angle multiple of 30°, up to the linear
  // interpolation of the angle along a chord of angular span δ ≤ 1.4·2π/48
  // (error ≤ δ³/8 radians) — and exactly at height multiples of 0.5.
  const double delta = 1.4 * 2 * M_PI / 48;
  for (VertexIndex v : x.mesh.vertices()) {
    const V3 p = Pos(x.mesh, v);
    const double k = std::atan2(p.y(), p.x()) / (2 * M_PI / 12);
    EXPECT_NEAR(k, std::round(k), std::pow(delta, 3) / 8 / (2 * M_PI / 12));
    EXPECT_NEAR(p.z() / 0.5, std::round(p.z() / 0.5), 1e-12);
  }
  // Outward orientation kept.
  for (FaceIndex f : x.mesh.faces()) {
    V3 c = V3::Zero();
    for (VertexIndex v : x.mesh.vertices_around_face(x.mesh.halfedge(f))) c += Pos(x.mesh, v);
    EXPECT_GT(FaceNormal(x.mesh, f).dot(V3(c.x(), c.y(), 0)), 0.0);
  }
}

TEST(Extract, SpherePatchInLongitudeAndLatitude) {
  const double R = 2.0;
  TriangleGridOptions opt;
  opt.jitter = 0.25;
  // φ ∈ [0, π/2], θ ∈ [π/6, π/2] (colatitude), a 30 x 20 triangle grid.
  const Mesh mesh = TriangulatedGrid(30, 20, [&](double u, double v) -> Vec3 {
    const double phi = u * M_PI / 2, th = M_PI / 6 + v * M_PI / 3;
    return {R * std::sin(th) * std::cos(phi), R * std::sin(th) * std::sin(phi), R * std::cos(th)};
  }, opt);
  auto phi = [](const V3& p) { return std::atan2(p.y(), p.x()); };
  auto theta = [&](const V3& p) { return std::acos(std::clamp(p.z() / p.norm(), -1.0, 1.0)); };
  // Levels every 10°: 9 x 6 cells; the boundary lies on levels.
  const double step = M_PI / 18;
  const Extraction x = ExtractQuadMesh(mesh, PerVertex(mesh, phi, theta, step, step));
  ExpectValid(x);
  EXPECT_EQ(x.quads, 54);
  EXPECT_EQ(x.mesh.number_of_faces(), 54u);
  EXPECT_EQ(x.mesh.number_of_vertices(), 70u);
  EXPECT_EQ(x.interior_valence.at(4), 40);
  // Output vertices lie on the triangle mesh: within the cap height of the
  // largest circumcircle of its triangles, R − sqrt(R² − ρ²).
  double rho = 0.0;
  for (FaceIndex f : mesh.faces()) {
    std::vector<V3> p;
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) p.push_back(Pos(mesh, v));
    const double a = (p[1] - p[2]).norm(), b = (p[0] - p[2]).norm(), c = (p[0] - p[1]).norm();
    rho = std::max(rho, a * b * c / (2 * (p[1] - p[0]).cross(p[2] - p[0]).norm()));
  }
  for (VertexIndex v : x.mesh.vertices())
    EXPECT_LE(R - Pos(x.mesh, v).norm(), R - std::sqrt(R * R - rho * rho) + 1e-12);
}

// The branched pairs: g + i h = c · z^p around the origin (a vertex) with the
// cut along the negative x-axis, shifted by (sg, sh) spacings.
struct Branched {
  double p;       // 0.5: index +1/2; 1.5: index −1/2
  double shift_g, shift_h;  // 0 (even rounding) or 0.5 (odd)
};

Extraction ExtractBranched(const Branched& b, const Mesh& mesh, CutGraph* cut_out) {
  VertexIndex origin;
  for (VertexIndex v : mesh.vertices())
    if (Pos(mesh, v).norm() < 1e-9) origin = v;
  EXPECT_TRUE(origin.is_valid());
  *cut_out = ComputeCutGraph(mesh, {origin});
  const CutGraph& cut = *cut_out;
  EXPECT_EQ(cut.chains.size(), 1u);
  const double c = 1.0, spacing = 0.25;
  auto value = [&](const V3& p, const V3& centre) {
    const double r = std::hypot(p.x(), p.y());
    return std::polar(c * std::pow(r, b.p), b.p * ArgNear(p, centre));
  };
  LevelSetFunctions fn;
  fn.cut = &cut;
  fn.g = WedgeValues(mesh, cut, [&](const V3& p, const V3& q) {
    return value(p, q).real() + b.shift_g * spacing;
  });
  fn.h = WedgeValues(mesh, cut, [&](const V3& p, const V3& q) {
    return value(p, q).imag() + b.shift_h * spacing;
  });
  // g_left = α − g_right with α = 2·shift (even: 0, odd: one spacing).
  fn.alpha_g = {2 * b.shift_g * spacing};
  fn.alpha_h = {2 * b.shift_h * spacing};
  fn.sign_g = {-1};
  fn.sign_h = {-1};
  fn.spacing_g = fn.spacing_h = spacing;
  return ExtractQuadMesh(mesh, fn);
}

TEST(Extract, HalfSingularityEvenGivesAValenceTwoVertexOddAFace) {
  // [−0.6, 0.9] x [−1, 1], the origin a grid vertex (no level is tangent to
  // the boundary there).
  const Mesh mesh = Plane(60, 80, -0.6, 0.9, -1.0, 1.0, 0.0);
  CutGraph cut;
  // Even/even: the level sets g = 0 and h = 0 end at the singular vertex,
  // which has valence 2 (two quads with a straight angle there).
  Extraction x = ExtractBranched({0.5, 0.0, 0.0}, mesh, &cut);
  ExpectValid(x);
  ASSERT_EQ(x.irregular_interior_vertices.size(), 1u);
  const VertexIndex s = x.irregular_interior_vertices[0];
  EXPECT_EQ(x.mesh.degree(s), 2u);
  EXPECT_LT(Pos(x.mesh, s).norm(), 1e-12);
  EXPECT_TRUE(x.irregular_interior_faces.empty());
  std::printf("+1/2 even/even: %d quads, %d triangles, %d pentagons, %d other, %zu faces\n",
              x.quads, x.triangles, x.pentagons, x.other_faces,
              static_cast<size_t>(x.mesh.number_of_faces()));
  // Even/odd: the level g = 0 (the cut) dangles into the face around the
  // singularity, which becomes a triangle; where that level meets h = ±1/2
  // (identified across the cut) three faces meet: index 1/4 + 1/4.
  x = ExtractBranched({0.5, 0.0, 0.5}, mesh, &cut);
  ExpectValid(x);
  ASSERT_EQ(x.irregular_interior_faces.size(), 1u);
  EXPECT_EQ(x.mesh.degree(x.irregular_interior_faces[0]), 3u);
  ASSERT_EQ(x.irregular_interior_vertices.size(), 1u);
  EXPECT_EQ(x.mesh.degree(x.irregular_interior_vertices[0]), 3u);
  // Odd/odd: the face around the singularity is a 2-gon and is dropped: its
  // two vertices have valence 3 (index 1/4 each).
  x = ExtractBranched({0.5, 0.5, 0.5}, mesh, &cut);
  ExpectValid(x);
  EXPECT_TRUE(x.irregular_interior_faces.empty());
  EXPECT_GE(x.dropped_small_faces, 1);
  ASSERT_EQ(x.irregular_interior_vertices.size(), 2u);
  for (VertexIndex v : x.irregular_interior_vertices) EXPECT_EQ(x.mesh.degree(v), 3u);
}

TEST(Extract, MinusHalfSingularityEvenGivesAValenceSixVertexOddAHexagon) {
  const Mesh mesh = Plane(60, 80, -0.6, 0.9, -1.0, 1.0, 0.0);
  CutGraph cut;
  Extraction x = ExtractBranched({1.5, 0.0, 0.0}, mesh, &cut);
  ExpectValid(x);
  ASSERT_EQ(x.irregular_interior_vertices.size(), 1u);
  EXPECT_EQ(x.mesh.degree(x.irregular_interior_vertices[0]), 6u);
  EXPECT_LT(Pos(x.mesh, x.irregular_interior_vertices[0]).norm(), 1e-12);
  EXPECT_TRUE(x.irregular_interior_faces.empty());
  x = ExtractBranched({1.5, 0.5, 0.5}, mesh, &cut);
  ExpectValid(x);
  EXPECT_TRUE(x.irregular_interior_vertices.empty());
  ASSERT_EQ(x.irregular_interior_faces.size(), 1u);
  EXPECT_EQ(x.mesh.degree(x.irregular_interior_faces[0]), 6u);
  // Even/odd: the three rays of g = 0 meet at the singular vertex, a
  // valence-3 vertex between three pentagons.
  x = ExtractBranched({1.5, 0.0, 0.5}, mesh, &cut);
  ExpectValid(x);
  ASSERT_EQ(x.irregular_interior_vertices.size(), 1u);
  EXPECT_EQ(x.mesh.degree(x.irregular_interior_vertices[0]), 3u);
  ASSERT_EQ(x.irregular_interior_faces.size(), 3u);
  for (FaceIndex f : x.irregular_interior_faces) EXPECT_EQ(x.mesh.degree(f), 5u);
}

TEST(Extract, RejectsJumpsThatAreNotIntegralOrInconsistent) {
  const Mesh mesh = Plane(60, 80, -0.6, 0.9, -1.0, 1.0, 0.0);
  VertexIndex origin;
  for (VertexIndex v : mesh.vertices())
    if (Pos(mesh, v).norm() < 1e-9) origin = v;
  const CutGraph cut = ComputeCutGraph(mesh, {origin});
  LevelSetFunctions fn;
  fn.cut = &cut;
  fn.g.assign(cut.num_wedges, 0.1);
  fn.h.assign(cut.num_wedges, 0.2);
  fn.alpha_g = {0.3};  // 1.2 spacings
  fn.alpha_h = {0.0};
  fn.sign_g = {-1};
  fn.sign_h = {-1};
  fn.spacing_g = fn.spacing_h = 0.25;
  Extraction x = ExtractQuadMesh(mesh, fn);
  EXPECT_FALSE(x.ok);
  EXPECT_NE(x.error.find("integer multiple"), std::string::npos) << x.error;
  // Integral, but the values violate g_left = −g_right by 0.8 spacings.
  fn.alpha_g = {0.0};
  x = ExtractQuadMesh(mesh, fn);
  EXPECT_FALSE(x.ok);
  EXPECT_NE(x.error.find("violate the jump"), std::string::npos) << x.error;
}

}  // namespace
}  // namespace archgeo
