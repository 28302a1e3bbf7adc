// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for the grid energies (energies/grid_orthogonality, grid_equilaterality,
// grid_quad_equilaterality, grid_boundary, grid_fairness), whose variables are the (u, v) of grid
// vertices on a parametric surface:
//  (a) autodiff Jacobians (through the surface map) against numeric
//      differences (ceres::GradientChecker) on four surfaces, random
//      well-shaped grid stencils from a fixed seed;
//  (b) degenerate stencils give finite residuals and Jacobians;
//  (c) invariance under a rigid motion of the surface (a torus and its
//      rotated and translated copy) and under uniform scaling (a torus scaled
//      by s, with the reference length scaled by s);
//  (d) analytic values: a square plane grid gives zero residuals, a sheared
//      one the known cosine and signed distance, a stretched edge its
//      relative deviation, a 2 × 1 rectangle its sides' deviations from
//      their mean (±1/3), a circle on a cylinder its second difference.
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <ceres/cost_function.h>
#include <gtest/gtest.h>

#include "tests/energy_checks.h"
#include "energies/autodiff.h"

#include "energies/grid_boundary.h"
#include "energies/grid_equilaterality.h"
#include "energies/grid_fairness.h"
#include "energies/grid_orthogonality.h"
#include "energies/grid_quad_equilaterality.h"
#include "energies/grid_side_manifold.h"
#include "surfaces/surface_factory.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

constexpr unsigned kSeed = 20260512;
constexpr int kNumSamples = 20;
// Agreement of residuals equal in exact arithmetic.
constexpr double kTolerance = 1e-11;

using namespace energy_checks;
using Uv = Eigen::Vector2d;

std::vector<double> Block(const Uv& uv) { return {uv[0], uv[1]}; }

// A grid stencil around a random parameter of `surface`: the vertex p and its
// neighbours at parameter steps ≈ (hu, hv) (a 20th of the domain), jittered.
struct Stencil {
  Uv p, l0, l1, t0, t1;
};

Stencil RandomStencil(const Surface& surface, std::mt19937& rng) {
  const ParameterDomain d = surface.Domain();
  std::uniform_real_distribution<double> unit(0.2, 0.8), jitter(-0.3, 0.3);
  const double hu = d.PeriodU() / 20, hv = d.PeriodV() / 20;
  const Uv p(d.u0 + unit(rng) * d.PeriodU(), d.v0 + unit(rng) * d.PeriodV());
  const auto near = [&](double du, double dv) {
    return Uv(p[0] + hu * (du + jitter(rng)), p[1] + hv * (dv + jitter(rng)));
  };
  return {p, near(-1, 0), near(1, 0), near(0, -1), near(0, 1)};
}

std::vector<std::string> CheckedSurfaces() {
  return {"torus", "klein_bottle", "tower", "dupin_bridge"};
}

double Length(const Surface& s, const Uv& a, const Uv& b) { return (s.Point(b) - s.Point(a)).norm(); }

// The parameters are angles (radians) of surfaces of radius up to 100 (the
// bridge's ring) while the stencil spans a few units: Ridders' first step of
// energy_checks.h (1e-4 relative, ≈ 15 mm of the bridge) is too coarse for
// 1e-6 there, so the grid energies start at 1e-6 relative.
constexpr double kRiddersStep = 1e-6;

void ExpectGridGradientsMatch(const ceres::CostFunction& cost, const Blocks& blocks) {
  ceres::NumericDiffOptions options;
  options.ridders_relative_initial_step_size = kRiddersStep;
  const std::vector<const ceres::Manifold*>* no_manifolds = nullptr;
  ceres::GradientChecker checker(&cost, no_manifolds, options);
  ceres::GradientChecker::ProbeResults results;
  const auto params = Pointers(blocks);
  EXPECT_TRUE(checker.Probe(params.data(), kRelativePrecision, &results)) << results.error_log;
}

TEST(GridEnergies, GradientsMatchNumericDifferences) {
  std::mt19937 rng(kSeed);
  for (const std::string& name : CheckedSurfaces()) {
    const Surface s = MakeSurface(name);
    for (int sample = 0; sample < kNumSamples; ++sample) {
      const Stencil st = RandomStencil(s, rng);
      const double L = Length(s, st.l0, st.l1) / 2;
      SCOPED_TRACE(name + " sample " + std::to_string(sample));
      std::unique_ptr<ceres::CostFunction> orthogonality(MakeAutoDiff(GridOrthogonality(s, 1.0 / L)));
      ExpectGridGradientsMatch(*orthogonality, {Block(st.l0), Block(st.l1), Block(st.t0), Block(st.t1)});
      std::unique_ptr<ceres::CostFunction> equilaterality(MakeAutoDiff(GridEquilaterality(s, L)));
      ExpectGridGradientsMatch(*equilaterality, {Block(st.p), Block(st.l1)});
      std::unique_ptr<ceres::CostFunction> quad(MakeAutoDiff(GridQuadEquilaterality(s, 1.0 / L)));
      ExpectGridGradientsMatch(*quad, {Block(st.p), Block(st.l1), Block(st.l1 + st.t1 - st.p),
                                       Block(st.t1)});
      std::unique_ptr<ceres::CostFunction> boundary(MakeAutoDiff(GridBoundary(s, 1.0 / L)));
      ExpectGridGradientsMatch(*boundary, {Block(st.p), Block(st.l0), Block(st.l1), Block(st.t1)});
      std::unique_ptr<ceres::CostFunction> fairness(MakeAutoDiff(GridFairness(s, 1.0 / L)));
      ExpectGridGradientsMatch(*fairness, {Block(st.l0), Block(st.p), Block(st.l1)});
    }
  }
}

TEST(GridEnergies, DegenerateStencilsStayFinite) {
  const Surface s = MakeSurface("torus");
  const Uv p(1.0, 2.0), q(1.2, 2.1);
  std::unique_ptr<ceres::CostFunction> orthogonality(MakeAutoDiff(GridOrthogonality(s, 1.0)));
  ExpectFiniteEverywhere(*orthogonality, {Block(p), Block(p), Block(q), Block(q)});  // a = b = 0
  ExpectFiniteEverywhere(*orthogonality, {Block(p), Block(p), Block(p), Block(q)});  // a = 0
  std::unique_ptr<ceres::CostFunction> equilaterality(MakeAutoDiff(GridEquilaterality(s, 1.0)));
  ExpectFiniteEverywhere(*equilaterality, {Block(p), Block(p)});
  std::unique_ptr<ceres::CostFunction> quad(MakeAutoDiff(GridQuadEquilaterality(s, 1.0)));
  ExpectFiniteEverywhere(*quad, {Block(p), Block(p), Block(p), Block(p)});  // a point
  for (double r : Evaluate(*quad, {Block(p), Block(p), Block(p), Block(p)})) EXPECT_EQ(r, 0.0);
  ExpectFiniteEverywhere(*quad, {Block(p), Block(p), Block(q), Block(q)});  // two sides 0
  std::unique_ptr<ceres::CostFunction> boundary(MakeAutoDiff(GridBoundary(s, 1.0)));
  ExpectFiniteEverywhere(*boundary, {Block(p), Block(q), Block(q), Block(p)});  // p1 = p2
  // At a = 0 the orthogonality residual is 0; at p1 = p2 the boundary one too.
  EXPECT_EQ(Evaluate(*orthogonality, {Block(p), Block(p), Block(p), Block(q)})[0], 0.0);
  EXPECT_EQ(Evaluate(*boundary, {Block(p), Block(q), Block(q), Block(q)})[0], 0.0);
}

// Residuals of all four energies on one stencil.
std::vector<double> AllResiduals(const Surface& s, const Stencil& st, double L) {
  std::vector<double> r;
  const auto add = [&](ceres::CostFunction* cost, const Blocks& blocks) {
    std::unique_ptr<ceres::CostFunction> owned(cost);
    for (double x : Evaluate(*owned, blocks)) r.push_back(x);
  };
  add(MakeAutoDiff(GridOrthogonality(s, 1.0 / L)), {Block(st.l0), Block(st.l1), Block(st.t0), Block(st.t1)});
  add(MakeAutoDiff(GridEquilaterality(s, L)), {Block(st.p), Block(st.t1)});
  add(MakeAutoDiff(GridBoundary(s, 1.0 / L)), {Block(st.p), Block(st.l0), Block(st.l1), Block(st.t1)});
  add(MakeAutoDiff(GridQuadEquilaterality(s, 1.0 / L)), {Block(st.p), Block(st.l1), Block(st.t1 + st.l1 - st.p),
                                               Block(st.t1)});
  // Fairness: only its norm is invariant under rotation.
  std::unique_ptr<ceres::CostFunction> fairness(MakeAutoDiff(GridFairness(s, 1.0 / L)));
  r.push_back(AsVec(Evaluate(*fairness, {Block(st.t0), Block(st.p), Block(st.t1)})).norm());
  return r;
}

TEST(GridEnergies, InvariantUnderRigidMotionsOfTheSurface) {
  std::mt19937 rng(kSeed + 1);
  const Surface torus = MakeSurface("torus");
  std::vector<double> largest(8, 0.0);  // not a vacuous invariance: residuals ≠ 0
  for (int sample = 0; sample < kNumSamples; ++sample) {
    const Surface moved = torus.Placed(RandomRotation(rng), RandomVec(rng, 10.0));
    const Stencil st = RandomStencil(torus, rng);
    const std::vector<double> a = AllResiduals(torus, st, 0.7), b = AllResiduals(moved, st, 0.7);
    ASSERT_EQ(a.size(), b.size());
    for (size_t k = 0; k < a.size(); ++k) {
      EXPECT_NEAR(a[k], b[k], kTolerance) << k;
      largest[k] = std::max(largest[k], std::abs(a[k]));
    }
  }
  for (double r : largest) EXPECT_GT(r, 1e-2);
}

TEST(GridEnergies, InvariantUnderScalingWithTheReferenceLength) {
  std::mt19937 rng(kSeed + 2);
  constexpr double kScale = 3.5;
  const Surface torus = MakeSurface("torus", {{"R", 3.0}, {"r", 1.0}});
  const Surface scaled = MakeSurface("torus", {{"R", 3.0 * kScale}, {"r", kScale}});
  for (int sample = 0; sample < kNumSamples; ++sample) {
    const Stencil st = RandomStencil(torus, rng);
    const std::vector<double> a = AllResiduals(torus, st, 0.7),
                              b = AllResiduals(scaled, st, 0.7 * kScale);
    for (size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], kTolerance) << k;
    EXPECT_GT(std::abs(a[1]), 1e-3);  // the edge is not exactly of length L
  }
}

TEST(GridEnergies, SquarePlaneGridHasZeroResiduals) {
  // Plane grid with spacing h: p at (3h, 4h).
  const Surface plane = MakeSurface("plane");
  constexpr double h = 0.5;
  const Stencil st{Uv(1.5, 2.0), Uv(1.0, 2.0), Uv(2.0, 2.0), Uv(1.5, 1.5), Uv(1.5, 2.5)};
  for (double r : AllResiduals(plane, st, h)) EXPECT_NEAR(r, 0.0, kTolerance);
}

TEST(GridEnergies, ShearedPlaneGridHasTheKnownAngle) {
  // u-line along (1, 0), v-line along (cos φ, sin φ), spacing h: the crossing
  // angle is φ, the orthogonality residual cos φ, the boundary residual
  // (p3 − p0)·e_u / L = h cos φ / L.
  const Surface plane = MakeSurface("plane");
  constexpr double h = 0.5, L = 0.4;
  for (double degrees : {30.0, 60.0, 75.0, 90.0, 120.0}) {
    const double phi = degrees * M_PI / 180.0;
    const Uv p(2.0, 2.0), e(h * std::cos(phi), h * std::sin(phi));
    std::unique_ptr<ceres::CostFunction> orthogonality(MakeAutoDiff(GridOrthogonality(plane, 1.0 / L)));
    const double r = Evaluate(*orthogonality, {Block(p - Uv(h, 0)), Block(p + Uv(h, 0)),
                                               Block(p - e), Block(p + e)})[0];
    EXPECT_NEAR(r, std::cos(phi), 1e-10) << degrees;
    std::unique_ptr<ceres::CostFunction> boundary(MakeAutoDiff(GridBoundary(plane, 1.0 / L)));
    const double b = Evaluate(*boundary, {Block(p), Block(p - Uv(h, 0)), Block(p + Uv(h, 0)),
                                          Block(p + e)})[0];
    EXPECT_NEAR(b, h * std::cos(phi) / L, 1e-10) << degrees;
    // Reversing the transversal line flips the orthogonality sign.
    const double flipped = Evaluate(*orthogonality, {Block(p - Uv(h, 0)), Block(p + Uv(h, 0)),
                                                     Block(p + e), Block(p - e)})[0];
    EXPECT_NEAR(flipped, -r, kTolerance);
  }
}

TEST(GridEnergies, EdgeLengthDeviationIsRelative) {
  const Surface plane = MakeSurface("plane");
  std::unique_ptr<ceres::CostFunction> equilaterality(MakeAutoDiff(GridEquilaterality(plane, 2.0)));
  EXPECT_NEAR(Evaluate(*equilaterality, {Block(Uv(1, 1)), Block(Uv(1, 3.2))})[0], 0.1, 1e-10);
  EXPECT_NEAR(Evaluate(*equilaterality, {Block(Uv(1, 1)), Block(Uv(2.2, 2.6))})[0], 0.0, 1e-10);
  EXPECT_NEAR(Evaluate(*equilaterality, {Block(Uv(1, 1)), Block(Uv(2, 1))})[0], -0.5, 1e-10);
}

TEST(GridEnergies, QuadSidesDeviateFromTheirMean) {
  // A 2 × 1 rectangle (sides 2, 1, 2, 1, mean 1.5): r = ±1/3 up to the
  // regularisation ε L (relative effect ≤ (ε L)² / 2 = 5e-13 with L = 1).
  const Surface plane = MakeSurface("plane");
  std::unique_ptr<ceres::CostFunction> quad(MakeAutoDiff(GridQuadEquilaterality(plane, 1.0)));
  const std::vector<double> r =
      Evaluate(*quad, {Block(Uv(1, 1)), Block(Uv(3, 1)), Block(Uv(3, 2)), Block(Uv(1, 2))});
  const double expected[] = {1.0 / 3, -1.0 / 3, 1.0 / 3, -1.0 / 3};
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(r[k], expected[k], 1e-10) << k;
  // A rhombus (equal sides, not a square): 0 — the term measures sides only.
  const std::vector<double> rhombus =
      Evaluate(*quad, {Block(Uv(0, 0)), Block(Uv(2, 0)), Block(Uv(3, std::sqrt(3.0))),
                       Block(Uv(1, std::sqrt(3.0)))});
  for (double x : rhombus) EXPECT_NEAR(x, 0.0, 1e-10);
}

TEST(GridEnergies, FairnessOfACircleOnACylinder) {
  // Three points of a horizontal circle, angle step δ: the second difference
  // points to the axis with length 2R(1 − cos δ); a vertical line gives 0.
  const Surface cylinder = MakeSurface("cylinder", {{"R", 2.0}, {"H", 5.0}});
  constexpr double delta = 0.3, L = 0.5;
  std::unique_ptr<ceres::CostFunction> fairness(MakeAutoDiff(GridFairness(cylinder, 1.0 / L)));
  const Vec3 r = AsVec(Evaluate(*fairness, {Block(Uv(1.0 - delta, 1.0)), Block(Uv(1.0, 1.0)),
                                            Block(Uv(1.0 + delta, 1.0))}));
  EXPECT_NEAR(r.norm(), 2.0 * 2.0 * (1.0 - std::cos(delta)) / L, 1e-12);
  EXPECT_NEAR(r.normalized().dot(Vec3(-std::cos(1.0), -std::sin(1.0), 0.0)), 1.0, 1e-12);
  const Vec3 straight = AsVec(Evaluate(*fairness, {Block(Uv(1.0, 0.5)), Block(Uv(1.0, 1.0)),
                                                   Block(Uv(1.0, 1.5))}));
  EXPECT_NEAR(straight.norm(), 0.0, 1e-15);
}

// The side manifold (energies/grid_side_manifold.h): the held coordinate
// never changes, the free one stays within the side however long the step,
// Minus inverts Plus, and the Jacobians are the derivatives of Plus and Minus
// (central differences) with MinusJacobian · PlusJacobian = 1.
TEST(GridSideManifold, SlidesAlongItsSideAndNeverPastItsEnds) {
  constexpr double kStep = 1e-6, kDerivative = 1e-8;
  const GridSideManifold side(0, 2.0, 5.0);  // u held, v ∈ [2, 5]
  const double x[2] = {1.25, 3.0};
  for (double delta : {-100.0, -1.0, -1e-3, 0.0, 0.4, 7.0, 1e6}) {
    double y[2], back;
    ASSERT_TRUE(side.Plus(x, &delta, y));
    EXPECT_EQ(y[0], x[0]) << delta;
    EXPECT_GE(y[1], 2.0) << delta;
    EXPECT_LE(y[1], 5.0) << delta;
    if (std::abs(delta) < 1.0) {  // within a half turn of the sine: invertible
      ASSERT_TRUE(side.Minus(y, x, &back));
      EXPECT_NEAR(back, delta, 1e-12) << delta;
    }
  }
  double plus_j[2], minus_j[2];
  ASSERT_TRUE(side.PlusJacobian(x, plus_j));
  ASSERT_TRUE(side.MinusJacobian(x, minus_j));
  double ya[2], yb[2];
  const double a = kStep, b = -kStep;
  side.Plus(x, &a, ya);
  side.Plus(x, &b, yb);
  EXPECT_EQ(plus_j[0], 0.0);
  EXPECT_NEAR(plus_j[1], (ya[1] - yb[1]) / (2 * kStep), kDerivative);
  const double xa[2] = {x[0], x[1] + kStep}, xb[2] = {x[0], x[1] - kStep};
  double ma, mb;
  side.Minus(xa, x, &ma);
  side.Minus(xb, x, &mb);
  EXPECT_EQ(minus_j[0], 0.0);
  EXPECT_NEAR(minus_j[1], (ma - mb) / (2 * kStep), kDerivative);
  EXPECT_NEAR(minus_j[1] * plus_j[1], 1.0, 1e-14);
  // Holding v, sliding u: the same with the roles swapped.
  const GridSideManifold bottom(1, -1.0, 1.0);
  const double p[2] = {0.5, 7.0}, delta = 50.0;
  double q[2];
  bottom.Plus(p, &delta, q);
  EXPECT_EQ(q[1], 7.0);
  EXPECT_LE(std::abs(q[0]), 1.0);
}

}  // namespace
}  // namespace archgeo
