// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The planar_quads builder in process: polygons, fixed vertices, mixed
// meshes, fixed-weight convergence and agreement between linear solvers.
#include <gtest/gtest.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <cmath>
#include <memory>

#include "core/tolerance_band.h"
#include "energies/autodiff.h"
#include "energies/pq_diagonal.h"
#include "generators/generators.h"
#include "analysis/metrics.h"
#include "geometry/reference.h"
#include "mesh/similarity.h"
#include "problems/runtime/solve.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

constexpr double kTolerance = 1e-3;

// A noisy grid in its canonical frame, with its own reference.
struct Case {
  Mesh mesh;
  Mesh original;
};

Case NoisyGrid(int nu, int nv, double noise) {
  Case c{QuadGrid(nu, nv, RoofSurface, noise, 3), {}};
  ToCanonical(CanonicalFrame(c.mesh), c.mesh);
  c.original = c.mesh;
  return c;
}

double MaxPlanarity(const Mesh& mesh) {
  return ComputeMetrics(mesh, nullptr, nullptr).pq_normalized_max;
}

// Solves planar_quads with the spec's defaults plus `yaml` on c.mesh, against
// its original; c.mesh becomes the output.
std::unique_ptr<Solution> PlanarQuads(Case& c, const std::string& yaml = "") {
  const ProblemSpec spec = ParseSpec("problem: planar_quads\n" + yaml);
  std::unique_ptr<Solution> s = Solve(spec, c.mesh, &c.original, {});
  c.mesh = s->output;
  return s;
}

bool Met(const Solution& s) { return s.loop.tolerances.at("tolerance.pq_normalized_max"); }

TEST(PlanarQuads, MeetsTheToleranceOnANoisyGrid) {
  Case c = NoisyGrid(12, 9, 0.05);
  ASSERT_GT(MaxPlanarity(c.mesh), 10 * kTolerance);
  const ReferenceSurface reference(c.original);
  const auto s = PlanarQuads(c);
  EXPECT_TRUE(s->loop.usable);
  EXPECT_TRUE(Met(*s));
  EXPECT_LE(MaxPlanarity(c.mesh), kTolerance);
  // Positions, and the plane of every quad: unit normal and offset
  // (face_planarity; the dihedral energy reads the normal).
  EXPECT_EQ(s->loop.variables,
            3 * int(c.mesh.number_of_vertices()) + 4 * int(c.mesh.number_of_faces()));
  EXPECT_GT(s->loop.objective.at("total"), 0);
  const Metrics m = ComputeMetrics(c.mesh, &reference, &c.original);
  EXPECT_LT(m.surface_distance_max, 0.1);  // mean edge lengths: the canonical unit
}

// The same grid 1e8 mean edge lengths from the origin gives the same result
// (issue 48, item 3): its normals and its reference surface are computed
// relative to each face's first corner (core/newell.h), not from absolute
// positions, which made every face degenerate.
TEST(PlanarQuads, FarFromTheOriginAsAtIt) {
  Case near = NoisyGrid(8, 6, 0.05);
  Case far = near;
  for (Mesh* m : {&far.mesh, &far.original}) {
    for (VertexIndex v : m->vertices()) m->point(v) = m->point(v) + Vector(1e8, -1e8, 1e8);
  }
  const auto a = PlanarQuads(near);
  const auto b = PlanarQuads(far);
  EXPECT_TRUE(Met(*a));
  EXPECT_TRUE(Met(*b));
  EXPECT_NEAR(MaxPlanarity(far.mesh), MaxPlanarity(near.mesh), 1e-6);
  EXPECT_NEAR(b->loop.objective.at("total"), a->loop.objective.at("total"),
              1e-4 * a->loop.objective.at("total"));
}

TEST(PlanarQuads, HexagonsBecomePlanar) {
  Case c = NoisyGrid(8, 6, 0.05);
  // Merge pairs of quads into hexagons by removing a shared interior edge.
  int merged = 0;
  for (int j = 1; j < 6; j += 2) {
    for (int i = 1; i + 1 < 8; i += 3) {
      const VertexIndex a(j * 9 + i + 1), b((j + 1) * 9 + i + 1);
      const HalfedgeIndex h = c.mesh.halfedge(a, b);
      ASSERT_NE(h, Mesh::null_halfedge());
      CGAL::Euler::join_face(h, c.mesh);
      ++merged;
    }
  }
  c.mesh.collect_garbage();
  c.original = c.mesh;
  const Metrics before = ComputeMetrics(c.mesh, nullptr, nullptr);
  ASSERT_EQ(before.polygons, merged);
  ASSERT_GT(before.pq_normalized_max, 10 * kTolerance);
  const auto s = PlanarQuads(c);
  EXPECT_TRUE(Met(*s));
  const PlanarityMeasure p = MeasureFacePlanarity(c.mesh);
  for (FaceIndex f : c.mesh.faces()) {
    EXPECT_LE(p.normalized[f.idx()], kTolerance) << "face " << f.idx() << " of degree "
                                                 << c.mesh.degree(f);
  }
  EXPECT_GT(s->loop.objective.count("face_planarity"), 0u);
}

TEST(PlanarQuads, FixedVerticesDoNotMove) {
  Case c = NoisyGrid(10, 8, 0.05);
  PlanarQuads(c, "fixed: [0, 10, 98, 5, 40]\n");
  for (int i : {0, 10, 98, 5, 40}) {
    EXPECT_EQ(c.mesh.point(VertexIndex(i)), c.original.point(VertexIndex(i)));
  }
  EXPECT_LE(MaxPlanarity(c.mesh), kTolerance);
}

TEST(PlanarQuads, TrianglesInAQuadDominantMeshAreAllowed) {
  Case c = NoisyGrid(6, 5, 0.05);
  // Split one quad into two triangles.
  const FaceIndex f(7);
  const HalfedgeIndex h = c.mesh.halfedge(f);
  CGAL::Euler::split_face(h, c.mesh.next(c.mesh.next(h)), c.mesh);
  c.original = c.mesh;
  ASSERT_EQ(ComputeMetrics(c.mesh, nullptr, nullptr).triangles, 2);
  const auto s = PlanarQuads(c);
  EXPECT_TRUE(Met(*s));
  EXPECT_LE(MaxPlanarity(c.mesh), kTolerance);
}

TEST(PlanarQuads, FixedWeightsRunToRest) {
  Case c = NoisyGrid(8, 6, 0.05);
  // (The re-projection onto the reference after each round and the fairness
  // relative to the input settle geometrically, by about 0.8 per round here.)
  const auto s = PlanarQuads(c, "tolerance: {pq_normalized_max: 0}\nschedule: {outer_iterations: 60}\n");
  EXPECT_LT(s->loop.rounds, 60);
  EXPECT_LT(s->loop.log.back().max_move, 1e-6);
  EXPECT_DOUBLE_EQ(s->loop.log.back().weight_scale, 1.0);  // no continuation
}

// Fixed weights, one round: every linear solver reaches the same minimum.
TEST(PlanarQuads, LinearSolversReachTheSameFinalCost) {
  const Case c = NoisyGrid(6, 5, 0.05);
  std::vector<double> costs;
  for (const auto& [solver, library] : std::vector<std::pair<std::string, std::string>>{
           {"sparse_normal_cholesky", "suite_sparse"},
           {"sparse_normal_cholesky", "eigen_sparse"},
           {"dense_qr", "suite_sparse"},
           {"cgnr", "suite_sparse"}}) {
    Case run = c;
    const auto s = PlanarQuads(run, "tolerance: {pq_normalized_max: 0}\nschedule: {outer_iterations: 1}\n"
                                    "solver: {max_num_iterations: 500, linear_solver_type: " + solver +
                                    ", sparse_linear_algebra_library_type: " + library + "}\n");
    ASSERT_TRUE(s->loop.usable) << solver;
    costs.push_back(s->loop.objective.at("total"));
  }
  for (double cost : costs) EXPECT_NEAR(cost, costs[0], 1e-6 * costs[0]);
}

// The band removes ±b from the residual and zeroes the Jacobian inside it.
TEST(ToleranceBand, ShiftsTheResidualAndZeroesTheJacobianInside) {
  const double kBand = 0.05;
  ToleranceBand banded(MakeAutoDiff(PqDiagonal(1.0)), kBand);
  std::unique_ptr<ceres::CostFunction> plain(MakeAutoDiff(PqDiagonal(1.0)));
  for (double h : {0.0, 0.03, 0.3, -0.3}) {
    double b0[3] = {0, 0, 0}, b1[3] = {1, 0, 0}, b2[3] = {1, 1, h}, b3[3] = {0, 1, 0};
    const double* params[4] = {b0, b1, b2, b3};
    double r_plain, r_band, j_plain[4][3], j_band[4][3];
    double* jp[4] = {j_plain[0], j_plain[1], j_plain[2], j_plain[3]};
    double* jb[4] = {j_band[0], j_band[1], j_band[2], j_band[3]};
    ASSERT_TRUE(plain->Evaluate(params, &r_plain, jp));
    ASSERT_TRUE(banded.Evaluate(params, &r_band, jb));
    const bool inside = std::abs(r_plain) <= kBand;
    EXPECT_DOUBLE_EQ(r_band, inside ? 0.0 : r_plain - std::copysign(kBand, r_plain)) << h;
    for (int k = 0; k < 4; ++k) {
      for (int d = 0; d < 3; ++d) EXPECT_DOUBLE_EQ(j_band[k][d], inside ? 0.0 : j_plain[k][d]);
    }
  }
}

}  // namespace
}  // namespace archgeo
