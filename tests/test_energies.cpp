// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for the planar-quad energies (energies/pq_diagonal, pq_worst, face_planarity,
// fairness, proximity, boundary_proximity, anchor):
//  (a) autodiff Jacobians against numeric differences (ceres::GradientChecker)
//      on random well-shaped samples from a fixed seed;
//  (b) degenerate inputs give finite residuals and Jacobians;
//  (c) invariance under rigid motions and uniform scaling;
//  (d) known values and relabelling signs.
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <ceres/cost_function.h>
#include <ceres/gradient_checker.h>
#include <ceres/manifold.h>
#include <ceres/sphere_manifold.h>
#include <gtest/gtest.h>

#include "tests/energy_checks.h"
#include "energies/autodiff.h"

#include "energies/anchor.h"
#include "energies/boundary_proximity.h"
#include "energies/face_planarity.h"
#include "energies/fairness.h"
#include "energies/pq_diagonal.h"
#include "energies/pq_worst.h"
#include "energies/proximity.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

constexpr unsigned kSeed = 20100501;
constexpr int kNumSamples = 25;
// Agreement of residuals that are equal in exact arithmetic.
constexpr double kTolerance = 1e-10;
// The same for nearly parallel diagonals (angle θ ≈ 3e-6): c = d1 × d2 loses
// ~log10(|x|²/(θ L²)) digits to cancellation, |x| ≈ 15 the coordinates.
constexpr double kIllConditionedTolerance = 1e-7;

using namespace energy_checks;

double Norm(const std::vector<double>& r) {
  double s = 0.0;
  for (double v : r) s += v * v;
  return std::sqrt(s);
}

// A well-shaped, moderately non-planar quad (cyclic order), randomly placed.
std::vector<Vec3> RandomQuad(std::mt19937& rng) {
  const Eigen::Matrix3d rot = RandomRotation(rng);
  const Vec3 shift = RandomVec(rng, 5.0);
  std::uniform_real_distribution<double> scale(0.5, 2.0);
  const double s = scale(rng);
  const Vec3 corners[4] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0),
                           Vec3(0, 1, 0)};
  std::vector<Vec3> quad;
  for (const Vec3& c : corners) {
    quad.push_back(rot * (s * (c + RandomVec(rng, 0.25))) + shift);
  }
  return quad;
}

double MeanDiagonal(const std::vector<Vec3>& q) {
  return 0.5 * ((q[2] - q[0]).norm() + (q[3] - q[1]).norm());
}

Blocks QuadBlocks(const std::vector<Vec3>& q) {
  return {ToBlock(q[0]), ToBlock(q[1]), ToBlock(q[2]), ToBlock(q[3])};
}

double PqResidual(const std::vector<Vec3>& q, double inv_length) {
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(PqDiagonal(inv_length)));
  return Evaluate(*cost, QuadBlocks(q))[0];
}

// Exact signed distance between the diagonal lines (no regularisation).
double ExactDiagonalDistance(const std::vector<Vec3>& q) {
  const Vec3 c = (q[2] - q[0]).cross(q[3] - q[1]);
  return c.normalized().dot(q[1] - q[0]);
}

// ---------------------------------------------------------------- pq_diagonal

TEST(PqDiagonal, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed);
  for (int i = 0; i < kNumSamples; ++i) {
    const auto q = RandomQuad(rng);
    std::unique_ptr<ceres::CostFunction> cost(
        MakeAutoDiff(PqDiagonal(1.0 / MeanDiagonal(q))));
    SCOPED_TRACE(i);
    ExpectGradientsMatch(*cost, QuadBlocks(q));
  }
}

TEST(PqDiagonal, DegenerateInputsAreFinite) {
  const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const std::vector<std::vector<Vec3>> cases = {
      {o, x, o, y},                    // zero-length diagonal b0b2
      {o, x, x + y, x},                // zero-length diagonal b1b3
      {o, o, o, o},                    // all four coincident
      {o, x, 2 * x, 3 * x},            // all collinear
      {o, y, 2 * x, y + x},            // parallel diagonals, coplanar
      {o, y + z, 2 * x, y + z + 3 * x},  // parallel diagonals, skew offset
      {o, y + z, 2 * x, y + z + 3 * x + 1e-12 * y},  // nearly parallel
  };
  for (double inv_length : {1.0, 1e-3, 1e3}) {
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(PqDiagonal(inv_length)));
    for (size_t i = 0; i < cases.size(); ++i) {
      SCOPED_TRACE(i);
      ExpectFiniteEverywhere(*cost, QuadBlocks(cases[i]));
    }
    // Exactly parallel or zero-length diagonals: the residual vanishes.
    for (size_t i = 0; i < 6; ++i) {
      EXPECT_EQ(PqResidual(cases[i], inv_length), 0.0) << i;
    }
  }
}

TEST(PqDiagonal, RegularisationOnlyShrinksAndFadesWithAngle) {
  // Diagonals at angle ~delta, offset by 1 along z: exact distance 1.
  const double inv_length = 0.5;  // L = 2 = the diagonal length
  double previous = 0.0;
  for (double delta : {0.0, 1e-12, 1e-9, 1e-6, 1e-4, 1e-2}) {
    const std::vector<Vec3> q = {Vec3(-1, 0, 0), Vec3(-1, -delta, 1),
                                 Vec3(1, 0, 0), Vec3(1, delta, 1)};
    const double r = std::abs(PqResidual(q, inv_length));
    EXPECT_TRUE(std::isfinite(r));
    EXPECT_LE(r, 1.0 * inv_length + kTolerance);
    EXPECT_GE(r, previous);  // monotone as the diagonals open up
    previous = r;
  }
  // Well away from the singular set the residual is the exact distance.
  EXPECT_NEAR(previous, 1.0 * inv_length, 1e-8);
}

TEST(PqDiagonal, InvariantUnderRigidMotionAndScaling) {
  std::mt19937 rng(kSeed + 1);
  for (int i = 0; i < kNumSamples; ++i) {
    auto q = RandomQuad(rng);
    const bool near_singular = i % 5 == 0;
    const double tolerance =
        near_singular ? kIllConditionedTolerance : kTolerance;
    if (near_singular) {
      // Nearly parallel diagonals (angle 3e-6 ≈ 3ε): the regularisation is
      // active, and must be invariant too.
      const Vec3 d = q[2] - q[0];
      const Vec3 perp = d.cross(RandomVec(rng, 1.0)).normalized();
      q[3] = q[1] + d + 3e-6 * d.norm() * perp;
    }
    const double inv_length = 1.0 / MeanDiagonal(q);
    const double r = PqResidual(q, inv_length);
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 shift = RandomVec(rng, 10.0);
    std::vector<Vec3> moved;
    for (const Vec3& b : q) moved.push_back(rot * b + shift);
    EXPECT_NEAR(PqResidual(moved, inv_length), r, tolerance) << i;
    for (double s : {1e-3, 0.37, 1e3}) {
      std::vector<Vec3> scaled;
      for (const Vec3& b : q) scaled.push_back(s * b);
      EXPECT_NEAR(PqResidual(scaled, inv_length / s), r, tolerance)
          << i << " s=" << s;
    }
  }
}

// ---------------------------------------------------------------- pq_worst

TEST(PqWorst, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 7);
  for (int i = 0; i < kNumSamples; ++i) {
    const auto q = RandomQuad(rng);
    const double inv_length = 1.0 / MeanDiagonal(q);
    const double worst = 1.5 * std::abs(PqResidual(q, inv_length)) + 1e-3;
    for (double power : {2.0, 16.0}) {
      std::unique_ptr<ceres::CostFunction> cost(
          MakeAutoDiff(PqWorst(inv_length, 1.0 / worst, power)));
      SCOPED_TRACE(i);
      ExpectGradientsMatch(*cost, QuadBlocks(q));
    }
  }
}

// Its square is (|r_PQ| / δ_worst)^p with r_PQ's sign kept: a quad at 0.8 of
// the worst counts 0.8^16 of it for p = 16, 0.8^2 for p = 2 (pq_diagonal's
// sum, relative to the worst quad).
TEST(PqWorst, IsThePNormOfPlanarityRelativeToTheWorstQuad) {
  std::mt19937 rng(kSeed + 8);
  for (int i = 0; i < kNumSamples; ++i) {
    const auto q = RandomQuad(rng);
    const double inv_length = 1.0 / MeanDiagonal(q);
    const double r = PqResidual(q, inv_length);
    const double worst = std::abs(r) / 0.8;
    for (double power : {2.0, 16.0}) {
      std::unique_ptr<ceres::CostFunction> cost(
          MakeAutoDiff(PqWorst(inv_length, 1.0 / worst, power)));
      const double w = Evaluate(*cost, QuadBlocks(q))[0];
      EXPECT_NEAR(w * w, std::pow(0.8, power), 1e-12) << i;
      EXPECT_EQ(std::signbit(w), std::signbit(r)) << i;
    }
  }
  // A planar quad: residual and Jacobian 0 (p > 2), finite.
  const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0);
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(PqWorst(1.0, 10.0, 16)));
  ExpectFiniteEverywhere(*cost, QuadBlocks({o, x, x + y, y}));
  EXPECT_EQ(Evaluate(*cost, QuadBlocks({o, x, x + y, y}))[0], 0.0);
}

TEST(PqDiagonal, KnownValues) {
  std::mt19937 rng(kSeed + 2);
  // A planar quad, placed at random: r = 0.
  for (int i = 0; i < 5; ++i) {
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 shift = RandomVec(rng, 3.0);
    std::vector<Vec3> q = {Vec3(0, 0, 0), Vec3(2, 0.3, 0), Vec3(2.5, 1.7, 0),
                           Vec3(-0.2, 1, 0)};
    for (Vec3& b : q) b = rot * b + shift;
    EXPECT_NEAR(PqResidual(q, 1.0), 0.0, kTolerance);
  }
  // (0,0,0),(1,0,0),(1,1,h),(0,1,0): diagonals (1,1,h) and (−1,1,0),
  // c = (−h, −h, 2), r = −h / sqrt(2h² + 4) / L.
  for (double h : {1.0, 0.3, -2.0}) {
    for (double inv_length : {1.0, 0.5}) {
      const std::vector<Vec3> q = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, h),
                                   Vec3(0, 1, 0)};
      EXPECT_NEAR(PqResidual(q, inv_length),
                  -h / std::sqrt(2 * h * h + 4) * inv_length, 1e-12);
    }
  }
  // h = 1: distance 1/sqrt(6).
  EXPECT_NEAR(std::abs(PqResidual({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 1),
                                   Vec3(0, 1, 0)},
                                  1.0)),
              1.0 / std::sqrt(6.0), 1e-12);
}

TEST(PqDiagonal, RelabellingSigns) {
  std::mt19937 rng(kSeed + 3);
  for (int i = 0; i < kNumSamples; ++i) {
    const auto q = RandomQuad(rng);
    const double inv_length = 1.0 / MeanDiagonal(q);
    const double r = PqResidual(q, inv_length);
    EXPECT_NEAR(r, ExactDiagonalDistance(q) * inv_length, 1e-9);
    // Cyclic shift by one flips the sign, by two keeps it.
    EXPECT_NEAR(PqResidual({q[1], q[2], q[3], q[0]}, inv_length), -r,
                kTolerance);
    EXPECT_NEAR(PqResidual({q[2], q[3], q[0], q[1]}, inv_length), r,
                kTolerance);
    EXPECT_NEAR(PqResidual({q[3], q[0], q[1], q[2]}, inv_length), -r,
                kTolerance);
    // Reversed orientation flips it.
    EXPECT_NEAR(PqResidual({q[0], q[3], q[2], q[1]}, inv_length), -r,
                kTolerance);
  }
}

// ------------------------------------------------------------- face_planarity

struct PlaneSample {
  Vec3 center, n, v;
  double d, inv_length;
};

PlaneSample RandomPlaneSample(std::mt19937& rng) {
  PlaneSample s;
  s.center = RandomVec(rng, 5.0);
  s.n = RandomVec(rng, 1.0).normalized();
  s.v = s.center + RandomVec(rng, 1.0);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  s.d = u(rng);
  s.inv_length = 1.0 / (0.5 + std::abs(u(rng)));
  return s;
}

double PlanarityResidual(const PlaneSample& s) {
  std::unique_ptr<ceres::CostFunction> cost(
      MakeAutoDiff(FacePlanarity(s.center.data(), s.inv_length)));
  return Evaluate(*cost, {ToBlock(s.n), {s.d}, ToBlock(s.v)})[0];
}

TEST(FacePlanarity, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 10);
  ceres::SphereManifold<3> sphere;
  const std::vector<const ceres::Manifold*> with_sphere = {&sphere, nullptr,
                                                           nullptr};
  for (int i = 0; i < kNumSamples; ++i) {
    const PlaneSample s = RandomPlaneSample(rng);
    std::unique_ptr<ceres::CostFunction> cost(
        MakeAutoDiff(FacePlanarity(s.center.data(), s.inv_length)));
    const Blocks blocks = {ToBlock(s.n), {s.d}, ToBlock(s.v)};
    SCOPED_TRACE(i);
    ExpectGradientsMatch(*cost, blocks);
    ExpectGradientsMatch(*cost, blocks, &with_sphere);
  }
}

TEST(FacePlanarity, DegenerateInputsAreFinite) {
  const double center[3] = {1, 2, 3};
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(FacePlanarity(center, 1.0)));
  ExpectFiniteEverywhere(*cost, {{0, 0, 0}, {0.5}, {1, 2, 3}});  // n = 0
  ExpectFiniteEverywhere(*cost, {{0, 0, 1}, {0}, {1, 2, 3}});    // v = c
  ExpectFiniteEverywhere(*cost, {{0, 3, 4}, {0}, {7, 2, 3}});    // non-unit n
  EXPECT_EQ(Evaluate(*cost, {{0, 0, 0}, {0.5}, {4, 5, 6}})[0], -0.5);
}

TEST(FacePlanarity, InvariantUnderRigidMotionAndScaling) {
  std::mt19937 rng(kSeed + 11);
  for (int i = 0; i < kNumSamples; ++i) {
    const PlaneSample s = RandomPlaneSample(rng);
    const double r = PlanarityResidual(s);
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 shift = RandomVec(rng, 10.0);
    PlaneSample moved = s;
    moved.center = rot * s.center + shift;
    moved.v = rot * s.v + shift;
    moved.n = rot * s.n;
    EXPECT_NEAR(PlanarityResidual(moved), r, kTolerance) << i;
    for (double k : {1e-3, 0.37, 1e3}) {
      PlaneSample scaled = s;
      scaled.center = k * s.center;
      scaled.v = k * s.v;
      scaled.d = k * s.d;
      scaled.inv_length = s.inv_length / k;
      EXPECT_NEAR(PlanarityResidual(scaled), r, kTolerance) << i << " " << k;
    }
    // (n, d) → (−n, −d) flips the sign.
    PlaneSample flipped = s;
    flipped.n = -s.n;
    flipped.d = -s.d;
    EXPECT_NEAR(PlanarityResidual(flipped), -r, kTolerance);
  }
}

TEST(FacePlanarity, KnownValues) {
  PlaneSample s;
  s.center = Vec3(1, 2, 3);
  s.n = Vec3(0, 0, 1);
  s.d = 0.5;
  s.inv_length = 0.25;
  s.v = Vec3(5, -7, 3.5);  // on the plane z = 3.5
  EXPECT_NEAR(PlanarityResidual(s), 0.0, kTolerance);
  s.v = Vec3(0, 0, 4);  // 0.5 above it
  EXPECT_NEAR(PlanarityResidual(s), 0.5 * 0.25, kTolerance);
  s.v = Vec3(9, 1, 1);  // 2.5 below it
  EXPECT_NEAR(PlanarityResidual(s), -2.5 * 0.25, kTolerance);
  // Every vertex of a planar polygon gives 0 with the fitted plane.
  std::mt19937 rng(kSeed + 12);
  const Eigen::Matrix3d rot = RandomRotation(rng);
  const Vec3 origin = RandomVec(rng, 3.0);
  PlaneSample p;
  p.center = origin;
  p.n = rot.col(2);
  p.d = 0.0;
  p.inv_length = 1.0;
  for (int k = 0; k < 6; ++k) {
    const double a = 2.0 * M_PI * k / 6.0;
    p.v = origin + rot * Vec3(std::cos(a), 1.3 * std::sin(a), 0.0);
    EXPECT_NEAR(PlanarityResidual(p), 0.0, kTolerance) << k;
  }
}

// ------------------------------------------------------------------ fairness

std::vector<double> FairnessResidual(const Vec3& target, double inv_length,
                                     const Vec3& u, const Vec3& v,
                                     const Vec3& w) {
  std::unique_ptr<ceres::CostFunction> cost(
      MakeAutoDiff(Fairness(target.data(), inv_length)));
  return Evaluate(*cost, {ToBlock(u), ToBlock(v), ToBlock(w)});
}

TEST(Fairness, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 20);
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 target = RandomVec(rng, 0.3);
    std::unique_ptr<ceres::CostFunction> cost(
        MakeAutoDiff(Fairness(target.data(), 1.0 / (0.5 + i * 0.1))));
    const Vec3 v = RandomVec(rng, 5.0);
    SCOPED_TRACE(i);
    ExpectGradientsMatch(*cost, {ToBlock(v + RandomVec(rng, 1.0)), ToBlock(v),
                                 ToBlock(v + RandomVec(rng, 1.0))});
  }
}

TEST(Fairness, DegenerateInputsAreFinite) {
  const double zero[3] = {0, 0, 0};
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(Fairness(zero, 1.0)));
  ExpectFiniteEverywhere(*cost, {{1, 2, 3}, {1, 2, 3}, {1, 2, 3}});  // coincident
  ExpectFiniteEverywhere(*cost, {{0, 0, 0}, {1, 1, 1}, {5, 5, 5}});  // collinear
  ExpectFiniteEverywhere(*cost, {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}});
}

TEST(Fairness, InvariantUnderRigidMotionAndScaling) {
  std::mt19937 rng(kSeed + 21);
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 target = RandomVec(rng, 0.3);
    const double inv_length = 1.0 / (0.5 + 0.1 * i);
    const Vec3 u = RandomVec(rng, 3.0), v = RandomVec(rng, 3.0),
               w = RandomVec(rng, 3.0);
    const Vec3 r = AsVec(FairnessResidual(target, inv_length, u, v, w));
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 shift = RandomVec(rng, 10.0);
    // Points move rigidly, the target (a difference vector) only rotates.
    const Vec3 moved = AsVec(FairnessResidual(
        rot * target, inv_length, rot * u + shift, rot * v + shift,
        rot * w + shift));
    EXPECT_NEAR(moved.norm(), r.norm(), kTolerance);
    EXPECT_NEAR((moved - rot * r).norm(), 0.0, kTolerance);
    for (double s : {1e-3, 0.37, 1e3}) {
      const Vec3 scaled = AsVec(FairnessResidual(s * target, inv_length / s,
                                                 s * u, s * v, s * w));
      EXPECT_NEAR((scaled - r).norm(), 0.0, kTolerance) << s;
    }
    // Reversing the triple leaves r unchanged.
    EXPECT_NEAR(
        (AsVec(FairnessResidual(target, inv_length, w, v, u)) - r).norm(), 0.0,
        kTolerance);
  }
}

TEST(Fairness, KnownValues) {
  const Vec3 zero(0, 0, 0);
  // Straight, evenly spaced polyline: zero (absolute fairness).
  const Vec3 a(1, -2, 0.5), step(0.3, 0.7, -0.2);
  EXPECT_NEAR(Norm(FairnessResidual(zero, 2.0, a, a + step, a + 2 * step)), 0.0,
              kTolerance);
  // Target = own second difference: zero (relative fairness).
  std::mt19937 rng(kSeed + 22);
  for (int i = 0; i < 5; ++i) {
    const Vec3 u = RandomVec(rng, 2.0), v = RandomVec(rng, 2.0),
               w = RandomVec(rng, 2.0);
    EXPECT_NEAR(Norm(FairnessResidual(u - 2 * v + w, 1.5, u, v, w)), 0.0,
                kTolerance);
  }
  // A kink: u = (0,0,0), v = (1,1,0), w = (2,0,0): Δ² = (0,−2,0).
  const Vec3 r =
      AsVec(FairnessResidual(zero, 0.5, zero, Vec3(1, 1, 0), Vec3(2, 0, 0)));
  EXPECT_NEAR((r - Vec3(0, -1, 0)).norm(), 0.0, kTolerance);
  // Uneven spacing on a straight line: Δ² = (1,0,0).
  const Vec3 r2 =
      AsVec(FairnessResidual(zero, 1.0, zero, Vec3(1, 0, 0), Vec3(3, 0, 0)));
  EXPECT_NEAR((r2 - Vec3(1, 0, 0)).norm(), 0.0, kTolerance);
}

// ----------------------------------------------------------------- proximity

double ProximityResidual(const Vec3& p, const Vec3& n, double inv_length,
                         const Vec3& v) {
  std::unique_ptr<ceres::CostFunction> cost(
      MakeAutoDiff(Proximity(p.data(), n.data(), inv_length)));
  return Evaluate(*cost, {ToBlock(v)})[0];
}

TEST(Proximity, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 30);
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 p = RandomVec(rng, 5.0), n = RandomVec(rng, 1.0).normalized();
    std::unique_ptr<ceres::CostFunction> cost(
        MakeAutoDiff(Proximity(p.data(), n.data(), 1.0 / (0.5 + 0.1 * i))));
    SCOPED_TRACE(i);
    ExpectGradientsMatch(*cost, {ToBlock(p + RandomVec(rng, 1.0))});
  }
}

TEST(Proximity, DegenerateInputsAreFinite) {
  const Vec3 p(1, 2, 3), zero(0, 0, 0);
  std::unique_ptr<ceres::CostFunction> zero_normal(
      MakeAutoDiff(Proximity(p.data(), zero.data(), 1.0)));
  ExpectFiniteEverywhere(*zero_normal, {ToBlock(Vec3(4, 5, 6))});
  ExpectFiniteEverywhere(*zero_normal, {ToBlock(p)});
  EXPECT_EQ(Evaluate(*zero_normal, {ToBlock(Vec3(4, 5, 6))})[0], 0.0);
  const Vec3 tiny(0, 0, 1e-300);
  std::unique_ptr<ceres::CostFunction> tiny_normal(
      MakeAutoDiff(Proximity(p.data(), tiny.data(), 1.0)));
  ExpectFiniteEverywhere(*tiny_normal, {ToBlock(Vec3(4, 5, 6))});
  std::unique_ptr<ceres::CostFunction> unit(
      MakeAutoDiff(Proximity(p.data(), Vec3(0, 0, 1).data(), 1.0)));
  ExpectFiniteEverywhere(*unit, {ToBlock(p)});  // v = p
}

TEST(Proximity, InvariantUnderRigidMotionAndScaling) {
  std::mt19937 rng(kSeed + 31);
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 p = RandomVec(rng, 5.0), n = RandomVec(rng, 1.0).normalized();
    const Vec3 v = p + RandomVec(rng, 1.0);
    const double inv_length = 1.0 / (0.5 + 0.1 * i);
    const double r = ProximityResidual(p, n, inv_length, v);
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 shift = RandomVec(rng, 10.0);
    EXPECT_NEAR(
        ProximityResidual(rot * p + shift, rot * n, inv_length, rot * v + shift),
        r, kTolerance);
    for (double s : {1e-3, 0.37, 1e3}) {
      EXPECT_NEAR(ProximityResidual(s * p, n, inv_length / s, s * v), r,
                  kTolerance);
    }
    EXPECT_NEAR(ProximityResidual(p, -n, inv_length, v), -r, kTolerance);
  }
}

TEST(Proximity, KnownValues) {
  const Vec3 p(0, 0, 0);
  EXPECT_NEAR(ProximityResidual(p, Vec3(0, 0, 1), 1.0, Vec3(3, 4, 2)), 2.0,
              kTolerance);
  EXPECT_NEAR(ProximityResidual(p, Vec3(0, 0, 1), 0.5, Vec3(3, 4, -2)), -1.0,
              kTolerance);
  // A non-unit normal is normalised.
  EXPECT_NEAR(ProximityResidual(p, Vec3(0, 0, 7), 1.0, Vec3(3, 4, 2)), 2.0,
              kTolerance);
  // On the tangent plane: zero.
  EXPECT_NEAR(ProximityResidual(Vec3(1, 1, 1), Vec3(1, 1, 1), 1.0,
                                Vec3(1, 1, 1) + Vec3(1, -1, 0)),
              0.0, kTolerance);
}

// -------------------------------------------------------- boundary_proximity

Vec3 BoundaryResidual(const Vec3& p, const Vec3& t, double inv_length,
                      const Vec3& v) {
  std::unique_ptr<ceres::CostFunction> cost(
      MakeAutoDiff(BoundaryProximity(p.data(), t.data(), inv_length)));
  return AsVec(Evaluate(*cost, {ToBlock(v)}));
}

TEST(BoundaryProximity, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 40);
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 p = RandomVec(rng, 5.0), t = RandomVec(rng, 1.0).normalized();
    std::unique_ptr<ceres::CostFunction> cost(
        MakeAutoDiff(BoundaryProximity(p.data(), t.data(), 1.0 / (0.5 + 0.1 * i))));
    SCOPED_TRACE(i);
    ExpectGradientsMatch(*cost, {ToBlock(p + RandomVec(rng, 1.0))});
  }
}

TEST(BoundaryProximity, DegenerateInputsAreFinite) {
  const Vec3 p(1, 2, 3), zero(0, 0, 0);
  std::unique_ptr<ceres::CostFunction> zero_tangent(
      MakeAutoDiff(BoundaryProximity(p.data(), zero.data(), 2.0)));
  ExpectFiniteEverywhere(*zero_tangent, {ToBlock(Vec3(4, 5, 6))});
  ExpectFiniteEverywhere(*zero_tangent, {ToBlock(p)});
  // Zero tangent: distance to the closest point itself.
  EXPECT_NEAR((BoundaryResidual(p, zero, 2.0, Vec3(4, 5, 6)) - Vec3(6, 6, 6))
                  .norm(),
              0.0, kTolerance);
  std::unique_ptr<ceres::CostFunction> unit(
      MakeAutoDiff(BoundaryProximity(p.data(), Vec3(1, 0, 0).data(), 1.0)));
  ExpectFiniteEverywhere(*unit, {ToBlock(p)});  // v = p
}

TEST(BoundaryProximity, InvariantUnderRigidMotionAndScaling) {
  std::mt19937 rng(kSeed + 41);
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 p = RandomVec(rng, 5.0), t = RandomVec(rng, 1.0).normalized();
    const Vec3 v = p + RandomVec(rng, 1.0);
    const double inv_length = 1.0 / (0.5 + 0.1 * i);
    const Vec3 r = BoundaryResidual(p, t, inv_length, v);
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 shift = RandomVec(rng, 10.0);
    const Vec3 moved =
        BoundaryResidual(rot * p + shift, rot * t, inv_length, rot * v + shift);
    EXPECT_NEAR(moved.norm(), r.norm(), kTolerance);
    EXPECT_NEAR((moved - rot * r).norm(), 0.0, kTolerance);
    for (double s : {1e-3, 0.37, 1e3}) {
      EXPECT_NEAR((BoundaryResidual(s * p, t, inv_length / s, s * v) - r).norm(),
                  0.0, kTolerance);
    }
    EXPECT_NEAR((BoundaryResidual(p, -t, inv_length, v) - r).norm(), 0.0,
                kTolerance);
  }
}

TEST(BoundaryProximity, KnownValues) {
  const Vec3 p(0, 0, 0);
  // Tangent x: the x-component is free, (y, z) is the offset.
  EXPECT_NEAR((BoundaryResidual(p, Vec3(1, 0, 0), 1.0, Vec3(3, 4, 0)) -
               Vec3(0, 4, 0)).norm(),
              0.0, kTolerance);
  EXPECT_NEAR((BoundaryResidual(p, Vec3(5, 0, 0), 0.5, Vec3(-7, 3, 4)) -
               Vec3(0, 1.5, 2)).norm(),
              0.0, kTolerance);
  // Anywhere on the tangent line: zero.
  const Vec3 q(1, 2, 3), t(1, 1, 0);
  EXPECT_NEAR(BoundaryResidual(q, t, 1.0, q + 4.2 * t).norm(), 0.0, kTolerance);
  // Distance to the line: |r| L.
  EXPECT_NEAR(BoundaryResidual(q, t, 0.25, q + 2.0 * t + Vec3(0, 0, 3)).norm(),
              0.75, kTolerance);
}

// -------------------------------------------------------------------- anchor

Vec3 AnchorResidual(const Vec3& a, double inv_length, const Vec3& v) {
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(Anchor(a.data(), inv_length)));
  return AsVec(Evaluate(*cost, {ToBlock(v)}));
}

TEST(Anchor, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 50);
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 a = RandomVec(rng, 5.0);
    std::unique_ptr<ceres::CostFunction> cost(
        MakeAutoDiff(Anchor(a.data(), 1.0 / (0.5 + 0.1 * i))));
    SCOPED_TRACE(i);
    ExpectGradientsMatch(*cost, {ToBlock(a + RandomVec(rng, 1.0))});
  }
}

TEST(Anchor, DegenerateInputsAreFinite) {
  const Vec3 a(1, 2, 3);
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(Anchor(a.data(), 1.0)));
  ExpectFiniteEverywhere(*cost, {ToBlock(a)});  // v = a
  EXPECT_EQ(Norm(Evaluate(*cost, {ToBlock(a)})), 0.0);
}

TEST(Anchor, InvariantUnderRigidMotionAndScaling) {
  std::mt19937 rng(kSeed + 51);
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 a = RandomVec(rng, 5.0), v = a + RandomVec(rng, 1.0);
    const double inv_length = 1.0 / (0.5 + 0.1 * i);
    const Vec3 r = AnchorResidual(a, inv_length, v);
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 shift = RandomVec(rng, 10.0);
    const Vec3 moved = AnchorResidual(rot * a + shift, inv_length, rot * v + shift);
    EXPECT_NEAR(moved.norm(), r.norm(), kTolerance);
    EXPECT_NEAR((moved - rot * r).norm(), 0.0, kTolerance);
    for (double s : {1e-3, 0.37, 1e3}) {
      EXPECT_NEAR((AnchorResidual(s * a, inv_length / s, s * v) - r).norm(), 0.0,
                  kTolerance);
    }
  }
}

TEST(Anchor, KnownValues) {
  EXPECT_NEAR((AnchorResidual(Vec3(1, 2, 3), 0.5, Vec3(3, 2, -1)) -
               Vec3(1, 0, -2)).norm(),
              0.0, kTolerance);
}

// Functors are usable directly (the builder and other tests may do so).
TEST(Functors, DirectEvaluationMatchesFactory) {
  const double b[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}};
  double r = 0.0;
  ASSERT_TRUE(PqDiagonal(1.0)(b[0], b[1], b[2], b[3], &r));
  EXPECT_NEAR(r, -1.0 / std::sqrt(6.0), 1e-12);
  const double center[3] = {0, 0, 0}, n[3] = {0, 0, 1}, d = 0.25;
  ASSERT_TRUE(FacePlanarity(center, 2.0)(n, &d, b[2], &r));
  EXPECT_NEAR(r, 1.5, kTolerance);
}

}  // namespace
}  // namespace archgeo
