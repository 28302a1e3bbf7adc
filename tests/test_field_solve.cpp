// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Small test-only Ceres problems that check the minimisers of the field and
// level-set functors (not the phase-2 orchestration):
//  - Dirichlet with frame transport: boundary values of a parallel line field
//    on a cylinder (flat metric) are continued as that parallel field, also
//    with unsmooth per-face frames (the spin-2 transport is what makes the
//    energy frame-independent);
//  - Dirichlet + transversality from a random start on a surface of
//    revolution reaches the principal directions (meridians, parallels)
//    within 2°;
//  - a prescribed conjugate direction is met by the solved field;
//  - eq. 5 with a jump across a seam on a cylinder: α converges to the
//    circumference, and the extracted layout is the 12 x 5 grid.
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <ceres/loss_function.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <gtest/gtest.h>

#include "energies/level_set_alignment.h"
#include "energies/autodiff.h"
#include "energies/level_set_jump.h"
#include "energies/tcd_dirichlet.h"
#include "energies/tcd_prescribed_direction.h"
#include "energies/tcd_transversality.h"
#include "fields/conjugate.h"
#include "fields/cut_jumps.h"
#include "fields/cuts.h"
#include "fields/extract.h"
#include "fields/face_curvature.h"
#include "fields/face_frames.h"
#include "fields/singularities.h"
#include "fields/triangle_surfaces.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using V3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;

double LineDeg(const V3& a, const V3& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * 180 / M_PI;
}

ceres::Solver::Summary Solve(ceres::Problem* problem) {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = 200;
  options.function_tolerance = 1e-14;
  options.gradient_tolerance = 1e-14;
  options.parameter_tolerance = 1e-14;
  options.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(options, problem, &summary);
  EXPECT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
  return summary;
}

// z of a line field given by a 3-D direction d in face f's frame, ζ = e^{2iθ}·ρ.
Vec2 ZOfLine(const FaceFrames& fr, FaceIndex f, const V3& d, double rho) {
  const Vec2 x = ToFrame(fr, f, d);
  const double t = std::atan2(x.y(), x.x());
  return Vec2(1 + rho * std::cos(2 * t), rho * std::sin(2 * t));
}

TEST(FieldSolve, DirichletContinuesAParallelFieldWithAnyFrames) {
  // Without jitter every grid quad of the cylinder is a planar rectangle:
  // the polyhedral surface is developable (no angle defect), so a parallel
  // field exists and is the exact minimiser.
  TriangleGridOptions opt;
  opt.closed_u = true;
  const Mesh mesh = TriangulatedGrid(32, 12, [](double u, double v) -> Vec3 {
    return {std::cos(2 * M_PI * u), std::sin(2 * M_PI * u), 2 * v};
  }, opt);
  // A parallel line field: at 30° to the axis in every face (the face's
  // horizontal direction is axis × n_f).
  auto helix = [](const FaceFrames& fr, FaceIndex f) {
    const V3 axis(0, 0, 1), around = axis.cross(fr.normal[f.idx()]).normalized();
    return V3(std::cos(M_PI / 6) * axis + std::sin(M_PI / 6) * around);
  };
  for (const FaceFrames& fr : {ComputeSmoothFrames(mesh), ComputeEdgeFrames(mesh)}) {
    std::vector<int> e2t;
    const std::vector<EdgeTransport> tr = ComputeTransports(mesh, fr, &e2t);
    std::vector<std::array<double, 2>> z(mesh.number_of_faces(), {1.0, 0.0});
    ceres::Problem problem;
    for (const EdgeTransport& t : tr)
      problem.AddResidualBlock(MakeAutoDiff(TcdDirichlet(t.angle, t.weight)), nullptr, z[t.f.idx()].data(),
                               z[t.g.idx()].data());
    // Boundary faces hold the field (ρ = 0.4), the rest starts at e1.
    int fixed = 0;
    for (FaceIndex f : mesh.faces()) {
      bool boundary = false;
      for (HalfedgeIndex h : mesh.halfedges_around_face(mesh.halfedge(f)))
        boundary = boundary || mesh.is_border(mesh.opposite(h));
      if (!boundary) continue;
      const Vec2 zf = ZOfLine(fr, f, helix(fr, f), 0.4);
      z[f.idx()] = {zf.x(), zf.y()};
      problem.SetParameterBlockConstant(z[f.idx()].data());
      ++fixed;
    }
    ASSERT_EQ(fixed, 64);
    Solve(&problem);
    double worst = 0.0;
    for (FaceIndex f : mesh.faces()) {
      const Vec2 expected = ZOfLine(fr, f, helix(fr, f), 0.4);
      worst = std::max(worst, (Vec2(z[f.idx()][0], z[f.idx()][1]) - expected).norm());
    }
    // Exact on a developable surface, up to the solver's tolerance.
    EXPECT_LT(worst, 1e-8);
  }
}

TEST(FieldSolve, DirichletAndTransversalityReachThePrincipalDirections) {
  TriangleGridOptions opt;
  opt.closed_u = true;
  opt.jitter = 0.2;
  auto r = [](double t) { return 1.0 + 0.4 * std::sin(2.0 * t); };
  const Mesh mesh = TriangulatedGrid(60, 40, [&](double u, double v) -> Vec3 {
    const double th = 2 * M_PI * u, t = 3.0 * v;
    return {r(t) * std::cos(th), r(t) * std::sin(th), t};
  }, opt);
  const FaceFrames fr = ComputeSmoothFrames(mesh);
  const std::vector<FaceCurvature> curv = ComputeFaceCurvature(mesh, fr);
  const std::vector<EdgeTransport> tr = ComputeTransports(mesh, fr);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::vector<std::array<double, 2>> z(mesh.number_of_faces());
  for (auto& x : z) x = {1 + u(rng), u(rng)};
  ceres::Problem problem;
  for (const EdgeTransport& t : tr)
    problem.AddResidualBlock(MakeAutoDiff(TcdDirichlet(t.angle, t.weight)), nullptr, z[t.f.idx()].data(),
                             z[t.g.idx()].data());
  for (auto& x : z)
    problem.AddResidualBlock(MakeAutoDiff(TcdTransversality()), new ceres::ScaledLoss(nullptr, 0.01, ceres::TAKE_OWNERSHIP),
                             x.data());
  const ceres::Solver::Summary summary = Solve(&problem);
  std::vector<Vec2> zn;
  for (const auto& x : z) zn.emplace_back(x[0], x[1]);
  const std::vector<ConjugatePair> pairs = TcdPairs(curv, zn);
  const TcdFieldStats stats = FieldStats(curv, pairs);
  EXPECT_LE(stats.max_conjugacy_error, 1e-8);
  double sum = 0.0;
  int n = 0;
  for (FaceIndex f : mesh.faces()) {
    const V3 c = fr.centroid[f.idx()];
    if (c.z() < 0.3 || c.z() > 2.7) continue;
    const FaceCurvature& cf = curv[f.idx()];
    if (std::abs(cf.k1 - cf.k2) < 0.2 * std::max(std::abs(cf.k1), std::abs(cf.k2))) continue;
    ASSERT_TRUE(pairs[f.idx()].valid);
    const V3 normal = fr.normal[f.idx()];
    V3 parallel(-c.y(), c.x(), 0);
    parallel -= parallel.dot(normal) * normal;
    sum += std::min(LineDeg(FromFrame(fr, f, pairs[f.idx()].v), parallel),
                    LineDeg(FromFrame(fr, f, pairs[f.idx()].w), parallel));
    ++n;
  }
  ASSERT_GT(n, 1000);
  std::printf("principal field solve: %d iterations, mean deviation %.3f deg on %d faces\n",
              static_cast<int>(summary.iterations.size()), sum / n, n);
  EXPECT_LT(sum / n, 2.0);
}

TEST(FieldSolve, PrescribedDirectionIsMetAndTheFieldStaysSmooth) {
  // A doubly curved roof; prescribe at one face a conjugate direction 25°
  // off its first principal direction (inside the positively curved part).
  TriangleGridOptions opt;
  opt.jitter = 0.2;
  const Mesh mesh = TriangulatedGrid(30, 30, [](double u, double v) -> Vec3 {
    const double x = 2 * u - 1, y = 2 * v - 1;
    return {x, y, -0.3 * x * x - 0.5 * y * y};
  }, opt);
  const FaceFrames fr = ComputeSmoothFrames(mesh);
  const std::vector<FaceCurvature> curv = ComputeFaceCurvature(mesh, fr);
  const std::vector<EdgeTransport> tr = ComputeTransports(mesh, fr);
  FaceIndex target;
  double best = INFINITY;
  for (FaceIndex f : mesh.faces()) {
    const double d = fr.centroid[f.idx()].head<2>().norm();
    if (d < best) best = d, target = f;
  }
  const FaceCurvature& ct = curv[target.idx()];
  ASSERT_EQ(ct.gaussian_sign, 1);
  const double a = 25 * M_PI / 180;
  const Vec2 d = std::cos(a) * ct.d1 + std::sin(a) * ct.d2;
  const double m[3] = {ct.M(0, 0), ct.M(0, 1), ct.M(1, 1)}, dir[2] = {d.x(), d.y()};
  std::vector<std::array<double, 2>> z(mesh.number_of_faces(), {1.0, 0.0});
  ceres::Problem problem;
  for (const EdgeTransport& t : tr)
    problem.AddResidualBlock(MakeAutoDiff(TcdDirichlet(t.angle, t.weight)), nullptr, z[t.f.idx()].data(),
                             z[t.g.idx()].data());
  for (auto& x : z)
    problem.AddResidualBlock(MakeAutoDiff(TcdTransversality()), new ceres::ScaledLoss(nullptr, 1e-3, ceres::TAKE_OWNERSHIP),
                             x.data());
  problem.AddResidualBlock(MakeAutoDiff(CheckedTcdPrescribedDirection(m, dir)), new ceres::ScaledLoss(nullptr, 1e4, ceres::TAKE_OWNERSHIP),
                           z[target.idx()].data());
  Solve(&problem);
  const ConjugatePair pair = ConjugatePairOf(ct.M, Vec2(z[target.idx()][0], z[target.idx()][1]));
  ASSERT_TRUE(pair.valid);
  const double off = std::min(LineDeg(FromFrame(fr, target, pair.v), FromFrame(fr, target, d)),
                              LineDeg(FromFrame(fr, target, pair.w), FromFrame(fr, target, d)));
  EXPECT_LT(off, 0.5);
  // The prescription does not create singularities: the solved field has
  // those of the principal field (the two +1/2 near the paraboloid's
  // umbilics), which in K > 0 may move (§3, Prop. 4 fixes them only in K < 0).
  std::vector<int> e2t;
  const std::vector<EdgeTransport> tr2 = ComputeTransports(mesh, fr, &e2t);
  auto singular = [&](const std::vector<Vec2>& zs) {
    return Singularities(mesh, VertexIndices(mesh, tr2, e2t, BisectorAngles(TcdPairs(curv, zs))));
  };
  std::vector<Vec2> zn;
  for (const auto& x : z) zn.emplace_back(x[0], x[1]);
  const std::vector<Singularity> solved = singular(zn);
  const std::vector<Singularity> principal =
      singular(std::vector<Vec2>(mesh.number_of_faces(), Vec2(1, 0)));
  ASSERT_EQ(solved.size(), principal.size());
  for (size_t i = 0; i < solved.size(); ++i) EXPECT_EQ(solved[i].index, principal[i].index);
}

TEST(FieldSolve, LevelSetsAcrossASeamGiveTheCircumferenceAndTheGrid) {
  const double radius = 1.3;
  TriangleGridOptions opt;
  opt.closed_u = true;
  opt.jitter = 0.2;
  const Mesh mesh = TriangulatedGrid(48, 16, [&](double u, double v) -> Vec3 {
    return {radius * std::cos(2 * M_PI * u), radius * std::sin(2 * M_PI * u), 2 * v};
  }, opt);
  const FaceFrames fr = ComputeSmoothFrames(mesh);
  std::vector<int> e2t;
  const std::vector<EdgeTransport> tr = ComputeTransports(mesh, fr, &e2t);
  const CutGraph cut = ComputeCutGraph(mesh, {});
  ASSERT_EQ(cut.chains.size(), 1u);
  // The field: v along the axis (levels of g run along it, ∇g = R v points
  // around), w around (∇h = R w along the axis). Orient on the cut surface.
  std::vector<Vec2> v(mesh.number_of_faces()), w(mesh.number_of_faces());
  for (FaceIndex f : mesh.faces()) {
    const V3 c = fr.centroid[f.idx()];
    v[f.idx()] = ToFrame(fr, f, V3(0, 0, 1)).normalized();
    w[f.idx()] = ToFrame(fr, f, V3(-c.y(), c.x(), 0)).normalized();
  }
  const FieldOrientation ov = OrientField(mesh, cut, tr, e2t, v);
  const FieldOrientation ow = OrientField(mesh, cut, tr, e2t, w);
  EXPECT_EQ(ov.chain_sign[0], 1);
  EXPECT_EQ(ow.chain_sign[0], 1);
  double area = 0.0;
  for (double a : fr.area) area += a;
  std::vector<double> g(cut.num_wedges, 0.0), h(cut.num_wedges, 0.0);
  double alpha_g = 0.0, alpha_h = 0.0;
  ceres::Problem problem;
  for (FaceIndex f : mesh.faces()) {
    const auto c = FaceCorners2D(mesh, fr, f);
    const double corners[6] = {c[0].x(), c[0].y(), c[1].x(), c[1].y(), c[2].x(), c[2].y()};
    const Vec2 vf = ov.face_sign[f.idx()] * v[f.idx()], wf = ow.face_sign[f.idx()] * w[f.idx()];
    const double vb[2] = {vf.x(), vf.y()}, wb[2] = {wf.x(), wf.y()};
    const HalfedgeIndex h0 = mesh.halfedge(f), h1 = mesh.next(h0), h2 = mesh.next(h1);
    const int k0 = cut.corner_wedge[h0.idx()], k1 = cut.corner_wedge[h1.idx()],
              k2 = cut.corner_wedge[h2.idx()];
    problem.AddResidualBlock(MakeAutoDiff(LevelSetAlignment(corners, vb, 1.0 / area)), nullptr, &g[k0],
                             &g[k1], &g[k2]);
    problem.AddResidualBlock(MakeAutoDiff(LevelSetAlignment(corners, wb, 1.0 / area)), nullptr, &h[k0],
                             &h[k1], &h[k2]);
  }
  for (const JumpRelation& r : cut.relations) {
    ASSERT_NE(r.left_wedge, r.right_wedge);
    auto* loss = new ceres::ScaledLoss(nullptr, 1e4, ceres::TAKE_OWNERSHIP);
    problem.AddResidualBlock(MakeAutoDiff(LevelSetJump(ov.chain_sign[r.chain], 1.0)), loss, &g[r.left_wedge],
                             &g[r.right_wedge], &alpha_g);
    auto* loss_h = new ceres::ScaledLoss(nullptr, 1e4, ceres::TAKE_OWNERSHIP);
    problem.AddResidualBlock(MakeAutoDiff(LevelSetJump(ow.chain_sign[r.chain], 1.0)), loss_h,
                             &h[r.left_wedge], &h[r.right_wedge], &alpha_h);
  }
  problem.SetParameterBlockConstant(&g[0]);  // g and h up to constants
  problem.SetParameterBlockConstant(&h[0]);
  Solve(&problem);
  // ∇g = R v integrates around the cylinder: |α_g| = 2π r; h has no jump.
  // ∇g = R v integrates around the cylinder: |α_g| is the circumference of
  // the polyhedral cylinder (48-gon, 2 n r sin(π/n)); h has no jump.
  const double perimeter = 2 * 48 * radius * std::sin(M_PI / 48);
  std::printf("alpha_g %.6f (48-gon perimeter %.6f), alpha_h %.2e\n", alpha_g, perimeter, alpha_h);
  EXPECT_NEAR(std::abs(alpha_g), perimeter, 1e-3 * perimeter);
  EXPECT_NEAR(alpha_h, 0.0, 1e-4);
  // Spacing from a target of 12 columns: Δw = |α|/12, so α is an exact
  // multiple; h levels at z = 0.25 + k/2 (h = ±z + c, shifted).
  LevelSetFunctions fn;
  fn.cut = &cut;
  fn.g = g;
  fn.h = h;
  fn.spacing_g = std::abs(alpha_g) / 12;
  fn.spacing_h = 0.5;
  fn.alpha_g = {alpha_g};
  fn.alpha_h = {0.0};
  fn.sign_g = {ov.chain_sign[0]};
  fn.sign_h = {ow.chain_sign[0]};
  const double shift = 0.25 - h[0];  // wedge 0 is vertex 0, at z = 0
  for (double& x : fn.h) x += shift;
  const Extraction x = ExtractQuadMesh(mesh, fn);
  ASSERT_TRUE(x.ok) << x.error;
  EXPECT_LT(x.max_jump_correction, 1e-3);
  // 12 columns x 5 rows (the first and last clipped by the boundary).
  EXPECT_EQ(x.quads, 60);
  EXPECT_EQ(x.mesh.number_of_faces(), 60u);
  EXPECT_EQ(x.interior_valence.at(4), 48);
  EXPECT_EQ(x.valence.at(3), 24);
}

}  // namespace
}  // namespace archgeo
