// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Small test-only Ceres problems proving that the goal-library formulations
// reach what the thesis' workflows need [Gebreiter 2012, §11.2.2, §11.7.1,
// §10.1] (the real problem declarations belong to the engine):
//  - hanging net: a square net of springs with fixed boundary under a
//    uniform load reaches force balance ≤ 1e-6 of the load, sags most at its
//    centre and keeps the square's symmetry to 1e-9 (energies/load.h);
//  - vertices bound to a closed curve by the curve manifold and joined by
//    springs spread evenly and stay on the curve to rounding
//    (energies/on_curve.h, spring.h);
//  - a noisy torus principal net becomes conical with planar faces and
//    constant face offsets (energies/conical.h, pq_diagonal.h, anchor.h).
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <ceres/loss_function.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <Eigen/Core>
#include <gtest/gtest.h>

#include "energies/anchor.h"
#include "energies/autodiff.h"
#include "energies/conical.h"
#include "energies/load.h"
#include "energies/on_curve.h"
#include "energies/pq_diagonal.h"
#include "energies/spring.h"
#include "geometry/curves.h"
#include "generators/generators.h"
#include "analysis/goal_metrics.h"
#include "analysis/metrics.h"
#include "generators/smoothness_surfaces.h"
#include "mesh/topology.h"
#include "tests/make_mesh.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

ceres::Solver::Options TightOptions() {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = 200;
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-16;
  options.num_threads = 1;
  return options;
}

void Solve(ceres::Problem* problem) {
  ceres::Solver::Summary summary;
  ceres::Solve(TightOptions(), problem, &summary);
  ASSERT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
}

std::vector<VertexIndex> Neighbours(const Mesh& mesh, VertexIndex v) {
  std::vector<VertexIndex> ring;
  for (VertexIndex w : mesh.vertices_around_target(mesh.halfedge(v))) ring.push_back(w);
  return ring;
}

double MeanEdgeLength(const Mesh& mesh) { return EdgeLengthSpread(mesh).mean; }

// ---------------------------------------------------------------------------
// Hanging net

struct HangingNet {
  Mesh mesh;
  int n;                    // quads per side; vertex (i, j) = j (n + 1) + i
  std::vector<Vec3> loads;  // per vertex
  std::vector<bool> fixed;  // boundary
};

// A flat unit square of n × n quads, boundary fixed, loaded by q per area
// (tributary areas) along +z: the inverted hanging net of §11.2.2.
HangingNet MakeNet(int n, double q) {
  HangingNet net;
  net.n = n;
  net.mesh = QuadGrid(n, n, [](double u, double v) { return Vec3{u, v, 0.0}; });
  net.fixed = BoundaryVertices(net.mesh);
  const std::vector<double> areas = TributaryAreas(net.mesh);
  for (double a : areas) net.loads.push_back({0.0, 0.0, q * a});
  return net;
}

// Adds one LoadEquilibrium per free vertex (springs of stiffness k and rest
// length l0 on every edge) and solves.
void SolveNet(HangingNet* net, double k, double l0) {
  Mesh& mesh = net->mesh;
  double load_sum = 0.0;
  int free = 0;
  for (VertexIndex v : mesh.vertices()) {
    if (net->fixed[v.idx()]) continue;
    load_sum += Eigen::Vector3d(net->loads[v.idx()].data()).norm();
    ++free;
  }
  const double inv_force = free / load_sum;
  ceres::Problem problem;
  for (VertexIndex v : mesh.vertices()) {
    if (net->fixed[v.idx()]) continue;
    const std::vector<VertexIndex> ring = Neighbours(mesh, v);
    std::vector<double*> blocks = {PositionBlock(mesh, v)};
    for (VertexIndex w : ring) blocks.push_back(PositionBlock(mesh, w));
    problem.AddResidualBlock(
        MakeStarAutoDiff(LoadEquilibrium(net->loads[v.idx()].data(), std::vector<double>(ring.size(), k), std::vector<double>(ring.size(), l0), inv_force)),
        nullptr, blocks);
  }
  for (VertexIndex v : mesh.vertices()) {
    if (net->fixed[v.idx()] && problem.HasParameterBlock(PositionBlock(mesh, v))) {
      problem.SetParameterBlockConstant(PositionBlock(mesh, v));
    }
  }
  Solve(&problem);
}

// Max |p(i, j) − S p(σ(i, j))| over the symmetries of the square (mirror in
// x = ½, mirror in y = ½, swap of x and y).
double SymmetryError(const HangingNet& net) {
  const int n = net.n;
  using V = Eigen::Vector3d;
  auto at = [&](int i, int j) { return Pos(net.mesh, VertexIndex(j * (n + 1) + i)); };
  double worst = 0.0;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const V p = at(i, j);
      const V mx = at(n - i, j), my = at(i, n - j), swap = at(j, i);
      worst = std::max(worst, (p - V(1.0 - mx[0], mx[1], mx[2])).norm());
      worst = std::max(worst, (p - V(my[0], 1.0 - my[1], my[2])).norm());
      worst = std::max(worst, (p - V(swap[1], swap[0], swap[2])).norm());
    }
  }
  return worst;
}

TEST(HangingNet, ZeroLengthSpringsReachForceBalanceAndKeepTheSquaresSymmetry) {
  const int n = 8;
  const double k = 1.0, q = 8.0;
  HangingNet net = MakeNet(n, q);
  SolveNet(&net, k, 0.0);
  const std::vector<double> stiffness(net.mesh.num_edges(), k), rest(net.mesh.num_edges(), 0.0);
  const ForceBalanceMeasure balance =
      MeasureForceBalance(net.mesh, net.loads, stiffness, rest, net.fixed);
  EXPECT_EQ(balance.free_vertices, (n - 1) * (n - 1));
  EXPECT_LE(balance.max_relative, 1e-6);
  EXPECT_LE(SymmetryError(net), 1e-9);
  // A vault (load along +z): every free vertex above the supports, the
  // centre highest.
  const VertexIndex centre((n / 2) * (n + 1) + n / 2);
  const double top = net.mesh.point(centre).z();
  EXPECT_GT(top, 0.0);
  for (VertexIndex v : net.mesh.vertices()) {
    if (!net.fixed[v.idx()]) {
      EXPECT_GT(net.mesh.point(v).z(), 0.0);
    }
    if (v != centre) {
      EXPECT_LT(net.mesh.point(v).z(), top);
    }
  }
}

TEST(HangingNet, LengthSpringsReachForceBalance) {
  const int n = 6;
  const double k = 2.0, q = 4.0;
  HangingNet net = MakeNet(n, q);
  const double l0 = 0.5 / n;  // half the grid spacing: springs in tension
  SolveNet(&net, k, l0);
  const std::vector<double> stiffness(net.mesh.num_edges(), k), rest(net.mesh.num_edges(), l0);
  EXPECT_LE(MeasureForceBalance(net.mesh, net.loads, stiffness, rest, net.fixed).max_relative,
            1e-6);
  EXPECT_LE(SymmetryError(net), 1e-9);
}

// ---------------------------------------------------------------------------
// Vertices sliding on a curve

TEST(CurveSliding, SpringsSpreadVerticesEvenlyAndTheyStayOnTheCurve) {
  // Ellipse 2 × 1 as a closed 400-point polyline; 16 vertices placed
  // unevenly on it, joined in a closed chain of length springs whose rest
  // length is the mean chord of the previous round.
  std::vector<Vec3> samples;
  for (int k = 0; k < 400; ++k) {
    const double a = 2 * M_PI * k / 400;
    samples.push_back({2 * std::cos(a), std::sin(a), 0.1 * std::sin(3 * a)});
  }
  const Polyline ellipse = MakePolyline(samples, true);
  const auto curve = std::make_shared<const CurvePolyline>(Coordinates(ellipse), true);
  const int m = 16;
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < m; ++k) {
    const double s = (k + 0.4 * std::sin(1.7 * k)) / m;
    x.push_back(curve->Evaluate(s * curve->length()));
  }
  auto chords = [&] {
    std::vector<double> c;
    for (int k = 0; k < m; ++k) c.push_back((x[(k + 1) % m] - x[k]).norm());
    return c;
  };
  for (int round = 0; round < 8; ++round) {
    const double mean = SpreadOf(chords()).mean;
    ceres::Problem problem;
    for (int k = 0; k < m; ++k) {
      problem.AddResidualBlock(MakeAutoDiff(Spring(mean, 1.0 / mean)), nullptr, x[k].data(),
                               x[(k + 1) % m].data());
    }
    for (int k = 0; k < m; ++k) problem.SetManifold(x[k].data(), MakeCurveManifold(curve));
    Solve(&problem);
  }
  EXPECT_LE(SpreadOf(chords()).max_relative_deviation, 1e-6);
  const PolylineLocator locator(ellipse);
  for (const auto& p : x) EXPECT_LE(locator.Closest({p[0], p[1], p[2]}).distance, 1e-12);
}

// ---------------------------------------------------------------------------
// Conical torus

TEST(ConicalTorus, NoisyPrincipalNetBecomesConicalPlanarWithConstantOffsets) {
  Mesh mesh = TorusPrincipalQuads(3.0, 1.0, 16, 8);
  const double edge = MeanEdgeLength(mesh);
  std::mt19937 rng(18);
  std::uniform_real_distribution<double> noise(-0.02 * edge, 0.02 * edge);
  for (VertexIndex v : mesh.vertices()) {
    double* p = PositionBlock(mesh, v);
    for (int c = 0; c < 3; ++c) p[c] += noise(rng);
  }
  const Mesh noisy = mesh;
  const double before = MeasureConical(noisy).max;
  EXPECT_GT(before, 1e-2);  // the noise breaks the conical property
  // Conical + planar faces, each round anchored weakly to the previous result.
  for (int round = 0; round < 6; ++round) {
    ceres::Problem problem;
    for (VertexIndex v : mesh.vertices()) {
      std::vector<double*> blocks = {PositionBlock(mesh, v)};
      for (VertexIndex w : Neighbours(mesh, v)) blocks.push_back(PositionBlock(mesh, w));
      problem.AddResidualBlock(MakeAutoDiff(Conical(1.0 / edge)), nullptr, blocks);
      const Vec3 target = ToVec3(mesh.point(v));
      problem.AddResidualBlock(MakeAutoDiff(Anchor(target.data(), 1e-3 / edge)), nullptr,
                               PositionBlock(mesh, v));
    }
    for (FaceIndex f : mesh.faces()) {
      std::vector<double*> quad;
      for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) {
        quad.push_back(PositionBlock(mesh, v));
      }
      problem.AddResidualBlock(MakeAutoDiff(PqDiagonal(1.0 / (1.4 * edge))), nullptr, quad);
    }
    Solve(&problem);
  }
  EXPECT_LE(MeasureConical(mesh).max, 1e-6);
  const PlanarityMeasure planarity = MeasureFacePlanarity(mesh);
  EXPECT_LE(*std::max_element(planarity.normalized.begin(), planarity.normalized.end()), 1e-6);
  EXPECT_LE(MeasureFaceOffsets(mesh, edge).max_relative, 1e-5);
  // Nearby: the vertices move by about the noise, not more.
  double moved = 0.0;
  for (VertexIndex v : mesh.vertices()) {
    moved = std::max(moved, (Pos(mesh, v) - Pos(noisy, v)).norm());
  }
  EXPECT_LE(moved, 0.1 * edge);
}

}  // namespace
}  // namespace archgeo
