// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for the orientation of a conjugate pair across the cuts
// (fields/cut_jumps.h OrientPair) and the parity of the rounded jumps at
// singular vertices (RoundJumps):
//  - a +1/2 bisector field whose pair opens and closes (δ alternating 12° /
//    168°) around the singular vertex: w turns by more than 90° between
//    neighbouring faces there, so w oriented on its own disagrees with the
//    bisector's index (the failure seen on Concerthall); oriented from the
//    bisector, v and w both flip across the singularity's cut (s = −1) and
//    no edge mismatches;
//  - two ±1/2 singularities on one straight cut: the chain from the boundary
//    to the first singular vertex does not flip the field (s = +1); rounded
//    to an even multiple, both singular vertices land on a level (even
//    rounding) or on a half level (odd rounding), which an odd constant on
//    that chain would swap at one of them.
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "fields/conjugate.h"
#include "fields/cut_jumps.h"
#include "fields/cuts.h"
#include "fields/face_frames.h"
#include "fields/singularities.h"
#include "fields/triangle_surfaces.h"
#include "tests/make_mesh.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using V3 = Eigen::Vector3d;

// Grid (nu x nv cells) on [x0, x1] x [y0, y1] in the plane z = 0.
Mesh PlanePatch(int nu, int nv, double x0, double x1, double y0, double y1) {
  return TriangulatedGrid(nu, nv, [=](double u, double v) -> Vec3 {
    return {x0 + (x1 - x0) * u, y0 + (y1 - y0) * v, 0.0};
  });
}

TEST(OrientPair, VAndWFollowTheBisectorsIndexWhereTheyTurnFast) {
  const Mesh mesh = PlanePatch(16, 20, -0.6, 1.0, -1.0, 1.0);
  const VertexIndex s = Nearest(mesh, V3(0, 0, 0));
  ASSERT_LT(Pos(mesh, s).norm(), 1e-12);
  const FaceFrames fr = ComputeSmoothFrames(mesh);
  std::vector<int> e2t;
  const std::vector<EdgeTransport> tr = ComputeTransports(mesh, fr, &e2t);
  // Bisector at arg(c)/2 (index +1/2 at s); the pair at ∓δ/2 from it, δ
  // alternating 12° and 168° on the faces around s (ordered by angle), 90°
  // elsewhere.
  std::vector<FaceIndex> ring;
  for (FaceIndex f : mesh.faces_around_target(mesh.halfedge(s))) ring.push_back(f);
  std::vector<Eigen::Vector2d> v(mesh.number_of_faces()), w(mesh.number_of_faces());
  std::vector<double> bisector(mesh.number_of_faces());
  for (FaceIndex f : mesh.faces()) {
    const V3 c = fr.centroid[f.idx()];
    const double b = 0.5 * std::atan2(c.y(), c.x());
    double delta = 0.5 * M_PI;
    for (size_t k = 0; k < ring.size(); ++k)
      if (ring[k] == f) delta = (k % 2 == 0 ? 12.0 : 168.0) * M_PI / 180.0;
    v[f.idx()] = ToFrame(fr, f, V3(std::cos(b - 0.5 * delta), std::sin(b - 0.5 * delta), 0));
    w[f.idx()] = ToFrame(fr, f, V3(std::cos(b + 0.5 * delta), std::sin(b + 0.5 * delta), 0));
    bisector[f.idx()] = BisectorAngle(v[f.idx()], w[f.idx()]);
  }
  const std::vector<double> index = VertexIndices(mesh, tr, e2t, bisector);
  for (VertexIndex x : mesh.vertices()) EXPECT_EQ(index[x.idx()], x == s ? 0.5 : 0.0);
  const CutGraph cut = ComputeCutGraph(mesh, {s});
  ASSERT_EQ(cut.chains.size(), 1u);

  // On its own, w's matching around s is not the bisector's.
  const FieldOrientation alone = OrientField(mesh, cut, tr, e2t, w);
  EXPECT_TRUE(alone.chain_sign[0] == 1 || alone.mismatched_cut_edges > 0 ||
              alone.mismatched_edges > 0);

  const PairOrientation pair = OrientPair(mesh, cut, tr, e2t, v, w);
  for (const FieldOrientation* o : {&pair.v, &pair.w}) {
    EXPECT_EQ(o->chain_sign[0], -1);
    EXPECT_EQ(o->mismatched_cut_edges, 0);
    EXPECT_EQ(o->mismatched_edges, 0);
  }
  // The oriented v and w make the angle δ (< 180°) counter-clockwise.
  for (FaceIndex f : mesh.faces()) {
    const Eigen::Vector2d a = double(pair.v.face_sign[f.idx()]) * v[f.idx()];
    const Eigen::Vector2d b = double(pair.w.face_sign[f.idx()]) * w[f.idx()];
    EXPECT_GT(a.x() * b.y() - a.y() * b.x(), 0.0) << "face " << f.idx();
  }
}

TEST(RoundJumps, SingularVerticesLandOnALevelOrAHalfLevel) {
  // Cut along y = 0 from the boundary x = −0.6 to s2 = (0, 0), on to
  // s1 = (0.3, 0): chain A (boundary – s2, s = +1) and chain B (s2 – s1,
  // s = −1).
  const Mesh mesh = PlanePatch(16, 20, -0.6, 1.0, -1.0, 1.0);
  std::vector<bool> edges(mesh.number_of_edges(), false);
  for (int i = 0; i < 9; ++i) {
    const VertexIndex a = Nearest(mesh, V3(-0.6 + 0.1 * i, 0, 0));
    const VertexIndex b = Nearest(mesh, V3(-0.5 + 0.1 * i, 0, 0));
    const HalfedgeIndex h = mesh.halfedge(a, b);
    ASSERT_TRUE(h.is_valid());
    edges[mesh.edge(h).idx()] = true;
  }
  const VertexIndex s1 = Nearest(mesh, V3(0.3, 0, 0)), s2 = Nearest(mesh, V3(0, 0, 0));
  const CutGraph cut = CutGraphFromEdges(mesh, edges, {s1, s2});
  ASSERT_EQ(cut.chains.size(), 2u);
  std::vector<int> sign(2);
  int a_chain = -1;
  for (int c = 0; c < 2; ++c) {
    const bool to_boundary = mesh.is_border(cut.chains[c].start, true) ||
                             mesh.is_border(cut.chains[c].end, true);
    sign[c] = to_boundary ? 1 : -1;
    if (to_boundary) a_chain = c;
  }
  ASSERT_GE(a_chain, 0);
  const double spacing = 0.25;
  for (int parity : {0, 1}) {
    std::vector<double> alpha(2), rounded;
    alpha[a_chain] = 2.9 * spacing;      // nearest integer 3 (odd)
    alpha[1 - a_chain] = 1.2 * spacing;  // nearest even 2, nearest odd 1
    std::string message;
    EXPECT_TRUE(RoundJumps(cut, sign, alpha, spacing, parity, &rounded, &message)) << message;
    EXPECT_EQ(std::lround(rounded[a_chain] / spacing) % 2, 0);
    std::vector<double> k = {rounded[0] / spacing, rounded[1] / spacing};
    std::vector<double> values(cut.num_wedges, 0.3);
    double change = 0;
    std::string error;
    ASSERT_TRUE(ProjectOntoJumps(cut, k, sign, &values, &change, &error)) << error;
    for (int x = 0; x < cut.num_wedges; ++x) {
      if (cut.wedge_vertex[x] != s1 && cut.wedge_vertex[x] != s2) continue;
      const double twice = 2.0 * values[x];
      EXPECT_NEAR(twice, std::round(twice), 1e-12);
      EXPECT_EQ(std::abs(std::lround(twice)) % 2, parity)
          << "parity " << parity << ", vertex " << cut.wedge_vertex[x].idx() << ", value "
          << values[x];
    }
  }
}

}  // namespace
}  // namespace archgeo
