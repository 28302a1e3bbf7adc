// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for fields/cuts.h: the cut graph makes every surface a disk (Euler
// characteristic 1 per component after cutting) — plane with a singularity,
// cylinder, closed ellipsoid with four singularities, torus, the real meshes
// with holes — wedges and relations are as documented, and the field's
// matching across a cut is −1 exactly for cuts from ±1/2 singularities.
#include <cmath>
#include <complex>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "fields/cut_jumps.h"
#include "fields/cuts.h"
#include "fields/extract.h"
#include "fields/face_frames.h"
#include "fields/triangle_surfaces.h"
#include "io/io.h"
#include "tests/make_mesh.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using V3 = Eigen::Vector3d;

int CutEdges(const CutGraph& c) {
  int n = 0;
  for (bool b : c.is_cut_edge) n += b;
  return n;
}

// Grid (nu x nv cells) on [x0, x1] x [y0, y1] in the plane z = 0.
Mesh PlanePatch(int nu, int nv, double x0, double x1, double y0, double y1, double jitter = 0.0) {
  TriangleGridOptions opt;
  opt.jitter = jitter;
  return TriangulatedGrid(nu, nv, [=](double u, double v) -> Vec3 {
    return {x0 + (x1 - x0) * u, y0 + (y1 - y0) * v, 0.0};
  }, opt);
}

TEST(CutGraph, SingularityOnADiskIsJoinedToTheNearestBoundary) {
  // [−0.6, 1] x [−1, 1]: the origin (a vertex) is nearest to the left side.
  const Mesh mesh = PlanePatch(16, 20, -0.6, 1.0, -1.0, 1.0);
  const VertexIndex s = Nearest(mesh, V3(0, 0, 0));
  ASSERT_LT(Pos(mesh, s).norm(), 1e-12);
  const CutGraph cut = ComputeCutGraph(mesh, {s});
  // A straight path of 6 edges along y = 0 to x = −0.6.
  EXPECT_EQ(CutEdges(cut), 6);
  ASSERT_EQ(cut.chains.size(), 1u);
  const CutChain& ch = cut.chains[0];
  EXPECT_TRUE(ch.from_singularity);
  EXPECT_TRUE((ch.start == s) != (ch.end == s));
  for (HalfedgeIndex h : ch.halfedges) EXPECT_NEAR(Pos(mesh, mesh.target(h)).y(), 0.0, 1e-12);
  const CutSurfaceTopology t = CutSurface(mesh, cut);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.euler_characteristic, 1);
  // Wedges: one per vertex, plus one per interior cut vertex (5) and one more
  // at the boundary end; the singular vertex keeps one wedge.
  EXPECT_EQ(cut.num_wedges, static_cast<int>(mesh.number_of_vertices()) + 6);
  int branch = 0;
  for (const JumpRelation& r : cut.relations) {
    EXPECT_EQ(cut.wedge_vertex[r.left_wedge], r.vertex);
    EXPECT_EQ(cut.wedge_vertex[r.right_wedge], r.vertex);
    if (r.left_wedge == r.right_wedge) {
      ++branch;
      EXPECT_EQ(r.vertex, s);
    }
  }
  EXPECT_EQ(branch, 1);
  EXPECT_EQ(cut.relations.size(), 7u);  // 7 vertices on the cut, one pair each
  // Every corner has a wedge of its own vertex.
  for (HalfedgeIndex h : mesh.halfedges()) {
    if (mesh.is_border(h)) continue;
    ASSERT_GE(cut.corner_wedge[h.idx()], 0);
    EXPECT_EQ(cut.wedge_vertex[cut.corner_wedge[h.idx()]], mesh.target(h));
  }
}

TEST(CutGraph, WedgeValuesOfABranchedFunctionSatisfyTheRelations) {
  // g + i h = sqrt(z) (principal branch) is single-valued on the cut surface
  // with the cut along the negative real axis; across it g_left = −g_right,
  // h_left = −h_right (s = −1, α = 0) and g = h = 0 at the branch point.
  const Mesh mesh = PlanePatch(16, 20, -0.6, 1.0, -1.0, 1.0);
  const VertexIndex s = Nearest(mesh, V3(0, 0, 0));
  const CutGraph cut = ComputeCutGraph(mesh, {s});
  const FaceFrames fr = ComputeEdgeFrames(mesh);
  std::vector<std::complex<double>> value(cut.num_wedges);
  for (HalfedgeIndex h : mesh.halfedges()) {
    if (mesh.is_border(h)) continue;
    const V3 c = fr.centroid[mesh.face(h).idx()], p = Pos(mesh, mesh.target(h));
    // arg(p) continued from the face centroid's side.
    double a = std::atan2(p.y(), p.x());
    const double ac = std::atan2(c.y(), c.x());
    if (a - ac > M_PI) a -= 2 * M_PI;
    if (ac - a > M_PI) a += 2 * M_PI;
    value[cut.corner_wedge[h.idx()]] = std::polar(std::sqrt(p.head<2>().norm()), 0.5 * a);
  }
  // (The grid's origin is x = 1e-16, whose square root is 1e-8.)
  for (const JumpRelation& r : cut.relations) {
    EXPECT_NEAR(std::abs(value[r.left_wedge] + value[r.right_wedge]), 0.0, 1e-7);
  }
}

TEST(CutGraph, CylinderGetsOneSeamAndTorusTwoLoops) {
  TriangleGridOptions opt;
  opt.closed_u = true;
  const Mesh cylinder = TriangulatedGrid(24, 8, [](double u, double v) -> Vec3 {
    return {std::cos(2 * M_PI * u), std::sin(2 * M_PI * u), 2 * v};
  }, opt);
  CutGraph cut = ComputeCutGraph(cylinder, {});
  ASSERT_EQ(cut.chains.size(), 1u);
  CutSurfaceTopology t = CutSurface(cylinder, cut);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.euler_characteristic, 1);
  // The seam joins the two boundary circles.
  const CutChain& seam = cut.chains[0];
  EXPECT_NE(Pos(cylinder, seam.start).z(), Pos(cylinder, seam.end).z());

  // Torus: a closed grid in both directions (glue v by hand: closed_u only).
  const int nu = 24, nv = 12;
  Mesh torus;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double a = 2 * M_PI * i / nu, b = 2 * M_PI * j / nv;
      torus.add_vertex(Point((2 + std::cos(b)) * std::cos(a), (2 + std::cos(b)) * std::sin(a),
                             std::sin(b)));
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      auto id = [&](int x, int y) { return VertexIndex(((y + nv) % nv) * nu + (x + nu) % nu); };
      ASSERT_NE(torus.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1)), Mesh::null_face());
      ASSERT_NE(torus.add_face(id(i, j), id(i + 1, j + 1), id(i, j + 1)), Mesh::null_face());
    }
  cut = ComputeCutGraph(torus, {});
  t = CutSurface(torus, cut);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.euler_characteristic, 1);
}

TEST(CutGraph, ClosedEllipsoidWithFourSingularitiesIsCutIntoADisk) {
  const Mesh mesh = TriangulatedEllipsoid(1.5, 1.0, 0.6, 3);
  std::vector<VertexIndex> s;
  for (const V3& p : {V3(1.2, 0, 0.3), V3(-1.2, 0, 0.3), V3(1.2, 0, -0.3), V3(-1.2, 0, -0.3)})
    s.push_back(Nearest(mesh, p));
  const CutGraph cut = ComputeCutGraph(mesh, s);
  const CutSurfaceTopology t = CutSurface(mesh, cut);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.euler_characteristic, 1);
  // A tree whose leaves include the four singular vertices: every singular
  // vertex ends a chain, and the cut has one edge fewer than vertices.
  std::map<int, int> degree;
  int edges = 0;
  for (EdgeIndex e : mesh.edges()) {
    if (!cut.is_cut_edge[e.idx()]) continue;
    ++edges;
    ++degree[mesh.vertex(e, 0).idx()];
    ++degree[mesh.vertex(e, 1).idx()];
  }
  EXPECT_EQ(edges, static_cast<int>(degree.size()) - 1);
  for (VertexIndex v : s) {
    bool ends = false;
    for (const CutChain& c : cut.chains) ends = ends || c.start == v || c.end == v;
    EXPECT_TRUE(ends);
  }
}

TEST(CutGraph, RealMeshesWithHolesBecomeDisks) {
  for (const char* name : {"directional_train-station.off", "directional_Concerthall.off",
                           "libigl_inspired_mesh.obj"}) {
    const Mesh mesh = ReadMesh(std::string(ARCHGEO_DATA_DIR) + "/" + name);
    const CutGraph cut = ComputeCutGraph(mesh, {});
    const CutSurfaceTopology t = CutSurface(mesh, cut);
    EXPECT_EQ(t.euler_characteristic, t.components) << name;
    std::printf("%s: %d components, %d cut edges in %zu chains\n", name, t.components,
                CutEdges(cut), cut.chains.size());
  }
}

TEST(OrientField, MatchingIsMinusOneAcrossAHalfSingularityCutAndPlusOneOnACylinder) {
  const Mesh mesh = PlanePatch(16, 20, -0.6, 1.0, -1.0, 1.0, 0.0);
  const VertexIndex s = Nearest(mesh, V3(0, 0, 0));
  const CutGraph cut = ComputeCutGraph(mesh, {s});
  const FaceFrames fr = ComputeSmoothFrames(mesh);
  std::vector<int> e2t;
  const std::vector<EdgeTransport> tr = ComputeTransports(mesh, fr, &e2t);
  // Level-set tangent of Re sqrt(z): the gradient conj(z^(−1/2)/2) has angle
  // arg(z)/2; a +1/2 line field.
  std::vector<Eigen::Vector2d> dir(mesh.number_of_faces());
  for (FaceIndex f : mesh.faces()) {
    const V3 c = fr.centroid[f.idx()];
    const double a = 0.5 * std::atan2(c.y(), c.x());
    dir[f.idx()] = ToFrame(fr, f, V3(std::cos(a), std::sin(a), 0));
  }
  FieldOrientation o = OrientField(mesh, cut, tr, e2t, dir);
  ASSERT_EQ(o.chain_sign.size(), 1u);
  EXPECT_EQ(o.chain_sign[0], -1);
  EXPECT_EQ(o.mismatched_cut_edges, 0);
  EXPECT_EQ(o.mismatched_edges, 0);
  // A constant field: +1, and without the singularity no cut at all.
  for (FaceIndex f : mesh.faces()) dir[f.idx()] = ToFrame(fr, f, V3(1, 0.3, 0));
  o = OrientField(mesh, cut, tr, e2t, dir);
  EXPECT_EQ(o.chain_sign[0], 1);
  EXPECT_EQ(CutEdges(ComputeCutGraph(mesh, {})), 0);

  TriangleGridOptions opt;
  opt.closed_u = true;
  const Mesh cylinder = TriangulatedGrid(24, 8, [](double u, double v) -> Vec3 {
    return {std::cos(2 * M_PI * u), std::sin(2 * M_PI * u), 2 * v};
  }, opt);
  const CutGraph seam = ComputeCutGraph(cylinder, {});
  const FaceFrames cf = ComputeSmoothFrames(cylinder);
  const std::vector<EdgeTransport> ct = ComputeTransports(cylinder, cf, &e2t);
  std::vector<Eigen::Vector2d> around(cylinder.number_of_faces());
  for (FaceIndex f : cylinder.faces()) {
    const V3 c = cf.centroid[f.idx()];
    around[f.idx()] = ToFrame(cf, f, V3(-c.y(), c.x(), 0));  // along the parallels
  }
  o = OrientField(cylinder, seam, ct, e2t, around);
  EXPECT_EQ(o.chain_sign[0], 1);
  EXPECT_EQ(o.mismatched_cut_edges, 0);
  EXPECT_EQ(o.mismatched_edges, 0);
}

// A "Y" of cut edges on a plane: from s1 = (−0.5, 0.5) and s2 = (−0.5, −0.5)
// down/up to the junction X = (−0.5, 0), and from X to the boundary (−1, 0).
CutGraph YCut(const Mesh& mesh, VertexIndex* s1, VertexIndex* s2) {
  auto at = [&](int i, int j) { return VertexIndex(j * 21 + i); };  // x = −1 + i/10
  std::vector<bool> cut(mesh.number_of_edges(), false);
  auto mark = [&](VertexIndex a, VertexIndex b) {
    const HalfedgeIndex h = mesh.halfedge(a, b);
    EXPECT_TRUE(h.is_valid());
    cut[mesh.edge(h).idx()] = true;
  };
  for (int j = 10; j < 15; ++j) mark(at(5, j), at(5, j + 1));  // X … s1
  for (int j = 5; j < 10; ++j) mark(at(5, j), at(5, j + 1));   // s2 … X
  for (int i = 0; i < 5; ++i) mark(at(i, 10), at(i + 1, 10));  // boundary … X
  *s1 = at(5, 15);
  *s2 = at(5, 5);
  return CutGraphFromEdges(mesh, cut, {*s1, *s2});
}

TEST(JumpConstraints, AJunctionOfTwoHalfSingularityCutsFixesTheTrunk) {
  const Mesh mesh = PlanePatch(20, 20, -1.0, 1.0, -1.0, 1.0);
  VertexIndex s1, s2;
  const CutGraph cut = YCut(mesh, &s1, &s2);
  ASSERT_EQ(cut.chains.size(), 3u);
  EXPECT_EQ(CutSurface(mesh, cut).euler_characteristic, 1);
  // Signs: −1 across the branches from the two ±1/2 singularities, +1 across
  // the trunk (the field turns by 2π around both).
  std::vector<int> sign(3);
  int trunk = -1;
  for (int c = 0; c < 3; ++c) {
    sign[c] = cut.chains[c].from_singularity ? -1 : 1;
    if (!cut.chains[c].from_singularity) trunk = c;
  }
  ASSERT_GE(trunk, 0);
  const std::vector<JumpConstraint> constraints = JumpConstraints(cut, sign);
  ASSERT_EQ(constraints.size(), 1u);
  EXPECT_EQ(Pos(mesh, constraints[0].vertex).head<2>(), Eigen::Vector2d(-0.5, 0.0));
  ASSERT_EQ(constraints[0].terms.size(), 3u);
  for (const auto& [chain, coefficient] : constraints[0].terms) EXPECT_EQ(std::abs(coefficient), 1);
  // Rounding: the branches to even (odd) multiples, the trunk computed.
  const double spacing = 0.25;
  for (int parity : {0, 1}) {
    std::vector<double> alpha = {2.3 * spacing, -0.8 * spacing, 1.1 * spacing}, rounded;
    std::string message;
    EXPECT_TRUE(RoundJumps(cut, sign, alpha, spacing, parity, &rounded, &message)) << message;
    long sum = 0;
    for (const auto& [chain, coefficient] : constraints[0].terms) {
      const double k = rounded[chain] / spacing;
      EXPECT_EQ(k, std::round(k));
      sum += coefficient * std::lround(k);
      if (chain != trunk) {
        EXPECT_EQ(std::abs(std::lround(k)) % 2, parity) << "chain " << chain;
      }
    }
    EXPECT_EQ(sum, 0);
    // The extraction accepts the rounded constants and rejects a trunk one
    // spacing off (the jumps around X no longer compose to the identity).
    LevelSetFunctions fn;
    fn.cut = &cut;
    fn.g.assign(cut.num_wedges, 0.1);
    fn.h.assign(cut.num_wedges, 0.1);
    fn.alpha_g = rounded;
    fn.alpha_h = std::vector<double>(3, 0.0);
    fn.sign_g = fn.sign_h = sign;
    fn.spacing_g = fn.spacing_h = spacing;
    ExtractOptions loose;
    loose.jump_tolerance = 1e9;
    EXPECT_TRUE(ExtractQuadMesh(mesh, fn, loose).ok);
    fn.alpha_g[trunk] += spacing;
    const Extraction bad = ExtractQuadMesh(mesh, fn, loose);
    EXPECT_FALSE(bad.ok);
    EXPECT_NE(bad.error.find("do not compose"), std::string::npos) << bad.error;
  }
}

}  // namespace
}  // namespace archgeo
