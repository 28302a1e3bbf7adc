// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for the goal-library energies [Gebreiter 2012, §10.1, §11]
// (energies/spring, shear, bending, conical, load, laplacian,
// mean_curvature_flow, on_curve):
//  (a) autodiff Jacobians against numeric differences (ceres::GradientChecker)
//      on random well-shaped samples from a fixed seed;
//  (b) degenerate inputs give finite residuals and Jacobians;
//  (c) invariance under rigid motions and uniform scaling, relabelling;
//  (d) analytic values;
//  (e) the curve manifold's Plus/Minus/Jacobian identities.
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <ceres/cost_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <gtest/gtest.h>

#include "energies/bending.h"
#include "energies/autodiff.h"
#include "energies/conical.h"
#include "energies/laplacian.h"
#include "energies/load.h"
#include "energies/mean_curvature_flow.h"
#include "energies/on_curve.h"
#include "energies/shear.h"
#include "energies/spring.h"
#include "tests/energy_checks.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

// The spring term's residual (energies/spring.cpp): the zero-length spring
// at rest length 0.
ceres::CostFunction* MakeSpring(double rest_length, double inv_length) {
  if (rest_length == 0.0) return MakeAutoDiff(ZeroLengthSpring(inv_length));
  return MakeAutoDiff(Spring(rest_length, inv_length));
}

using namespace energy_checks;

constexpr unsigned kSeed = 20120601;
constexpr int kNumSamples = 20;
// Agreement of values equal in exact arithmetic (coordinates of order 10).
constexpr double kTolerance = 1e-10;

Blocks ToBlocks(const std::vector<Vec3>& points) {
  Blocks blocks;
  for (const Vec3& p : points) blocks.push_back(ToBlock(p));
  return blocks;
}

std::vector<double> Residual(ceres::CostFunction* raw, const std::vector<Vec3>& points) {
  std::unique_ptr<ceres::CostFunction> cost(raw);
  return Evaluate(*cost, ToBlocks(points));
}

double Norm(const std::vector<double>& r) {
  double s = 0.0;
  for (double v : r) s += v * v;
  return std::sqrt(s);
}

// x → R x + t for every point.
std::vector<Vec3> Moved(const std::vector<Vec3>& points, const Eigen::Matrix3d& rot,
                        const Vec3& shift) {
  std::vector<Vec3> moved;
  for (const Vec3& p : points) moved.push_back(rot * p + shift);
  return moved;
}

std::vector<Vec3> Scaled(const std::vector<Vec3>& points, double s) {
  std::vector<Vec3> scaled;
  for (const Vec3& p : points) scaled.push_back(s * p);
  return scaled;
}

// A valence-n star around v: neighbours at angles 2πk/n (jittered) at
// distance ≈ radius, with heights, randomly placed.
std::vector<Vec3> RandomStar(std::mt19937& rng, int n, double radius = 1.0, double height = 0.3) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> star = {Vec3(0, 0, 0)};
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * (k + 0.2 * u(rng)) / n;
    const double r = radius * (1.0 + 0.2 * u(rng));
    star.push_back(Vec3(r * std::cos(a), r * std::sin(a), height * u(rng)));
  }
  return Moved(star, RandomRotation(rng), RandomVec(rng, 5.0));
}

// ---------------------------------------------------------------------------
// spring

TEST(Spring, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed);
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 a = RandomVec(rng, 5.0), b = a + RandomVec(rng, 1.0);
    for (double rest : {0.0, 0.7}) {
      std::unique_ptr<ceres::CostFunction> cost(MakeSpring(rest, 1.3));
      ExpectGradientsMatch(*cost, ToBlocks({a, b}));
    }
  }
}

TEST(Spring, KnownValues) {
  // |a − b| = 2, L0 = 1.5, L = 0.5: r = (2 − 1.5)/0.5 = 1.
  const Vec3 a(1, 2, 3), b = a + Vec3(0, 2, 0);
  const auto r = Residual(MakeSpring(1.5, 2.0), {a, b});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NEAR(r[0], 1.0, 1e-12);
  // Compressed: |a − b| = 2 < L0 = 3, L = 1: r = −1.
  EXPECT_NEAR(Residual(MakeSpring(3.0, 1.0), {a, b})[0], -1.0, 1e-12);
  // Zero-length: r = (a − b)/L, 3 residuals.
  const auto z = Residual(MakeSpring(0.0, 0.5), {a, b});
  ASSERT_EQ(z.size(), 3u);
  EXPECT_NEAR(AsVec(z)[1], -1.0, 1e-15);
  EXPECT_NEAR(Norm(z), 1.0, 1e-15);
  // The energy is continuous in L0 at 0: ½(|d| − L0)² → ½|d|².
  EXPECT_NEAR(Residual(MakeSpring(1e-12, 0.5), {a, b})[0], Norm(z), 1e-11);
}

TEST(Spring, DegenerateInputsAreFinite) {
  const Vec3 a(1, 1, 1);
  for (double rest : {0.0, 1.0}) {
    std::unique_ptr<ceres::CostFunction> cost(MakeSpring(rest, 1.0));
    ExpectFiniteEverywhere(*cost, ToBlocks({a, a}));
  }
  // Coincident ends of a length spring: r ≈ −L0/L (the regularisation εL).
  EXPECT_NEAR(Residual(MakeSpring(2.0, 1.0), {a, a})[0], -2.0, 1e-5);
}

TEST(Spring, InvariantUnderRigidMotionAndScaling) {
  std::mt19937 rng(kSeed + 1);
  for (int i = 0; i < kNumSamples; ++i) {
    const std::vector<Vec3> e = {RandomVec(rng, 5.0), RandomVec(rng, 5.0)};
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 shift = RandomVec(rng, 10.0);
    const double length = Residual(MakeSpring(2.0, 0.4), e)[0];
    EXPECT_NEAR(Residual(MakeSpring(2.0, 0.4), Moved(e, rot, shift))[0], length, kTolerance);
    const double zero = Norm(Residual(MakeSpring(0.0, 0.4), e));
    EXPECT_NEAR(Norm(Residual(MakeSpring(0.0, 0.4), Moved(e, rot, shift))), zero, kTolerance);
    for (double s : {1e-3, 0.37, 1e3}) {
      EXPECT_NEAR(Residual(MakeSpring(2.0 * s, 0.4 / s), Scaled(e, s))[0], length, kTolerance);
      EXPECT_NEAR(Norm(Residual(MakeSpring(0.0, 0.4 / s), Scaled(e, s))), zero, kTolerance);
    }
    // Swapping the ends.
    EXPECT_NEAR(Residual(MakeSpring(2.0, 0.4), {e[1], e[0]})[0], length, kTolerance);
  }
}

// ---------------------------------------------------------------------------
// shear

TEST(Shear, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 10);
  for (int i = 0; i < kNumSamples; ++i) {
    std::vector<Vec3> q = RandomStar(rng, 4);
    q.erase(q.begin());
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(Shear(0.7)));
    ExpectGradientsMatch(*cost, ToBlocks(q));
  }
}

TEST(Shear, KnownValues) {
  // A rectangle (any size, anywhere): equal diagonals, r = 0.
  std::mt19937 rng(kSeed + 11);
  const std::vector<Vec3> rectangle = {Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(3, 1, 0), Vec3(0, 1, 0)};
  EXPECT_NEAR(
      Residual(MakeAutoDiff(Shear(1.0)), Moved(rectangle, RandomRotation(rng), RandomVec(rng, 5.0)))[0], 0.0,
      kTolerance);
  // A rhombus with diagonals 2 (b0b2) and 1 (b1b3), L = 1.5 (their mean):
  // r = (4 − 1)/(2·2.25) = 2/3 = (2 − 1)/1.5, the relative difference.
  const std::vector<Vec3> rhombus = {Vec3(-1, 0, 0), Vec3(0, -0.5, 0), Vec3(1, 0, 0),
                                     Vec3(0, 0.5, 0)};
  EXPECT_NEAR(Residual(MakeAutoDiff(Shear(1.0 / 1.5)), rhombus)[0], 2.0 / 3.0, 1e-15);
  // Relabelling: shift by one flips the sign, by two keeps it, reversal keeps it.
  const auto& q = rhombus;
  EXPECT_NEAR(Residual(MakeAutoDiff(Shear(1.0 / 1.5)), {q[1], q[2], q[3], q[0]})[0], -2.0 / 3.0, 1e-15);
  EXPECT_NEAR(Residual(MakeAutoDiff(Shear(1.0 / 1.5)), {q[2], q[3], q[0], q[1]})[0], 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(Residual(MakeAutoDiff(Shear(1.0 / 1.5)), {q[0], q[3], q[2], q[1]})[0], 2.0 / 3.0, 1e-15);
}

TEST(Shear, DegenerateInputsAreFinite) {
  const Vec3 o(1, 2, 3), x(1, 0, 0);
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(Shear(1.0)));
  ExpectFiniteEverywhere(*cost, ToBlocks({o, o, o, o}));
  ExpectFiniteEverywhere(*cost, ToBlocks({o, o + x, o + 2 * x, o + 3 * x}));
  EXPECT_EQ(Residual(MakeAutoDiff(Shear(1.0)), {o, o, o, o})[0], 0.0);
}

TEST(Shear, InvariantUnderRigidMotionAndScaling) {
  std::mt19937 rng(kSeed + 12);
  for (int i = 0; i < kNumSamples; ++i) {
    std::vector<Vec3> q = RandomStar(rng, 4);
    q.erase(q.begin());
    const double r = Residual(MakeAutoDiff(Shear(0.8)), q)[0];
    EXPECT_NEAR(Residual(MakeAutoDiff(Shear(0.8)), Moved(q, RandomRotation(rng), RandomVec(rng, 10.0)))[0], r,
                kTolerance);
    for (double s : {1e-3, 0.37, 1e3}) {
      EXPECT_NEAR(Residual(MakeAutoDiff(Shear(0.8 / s)), Scaled(q, s))[0], r, kTolerance);
    }
  }
}

// ---------------------------------------------------------------------------
// bending

TEST(Bending, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 20);
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 v = RandomVec(rng, 5.0);
    const Vec3 u = v - Vec3(1, 0, 0) + RandomVec(rng, 0.6);
    const Vec3 w = v + Vec3(1, 0, 0) + RandomVec(rng, 0.6);
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(Bending(1.0)));
    ExpectGradientsMatch(*cost, ToBlocks({u, v, w}));
  }
}

TEST(Bending, KnownValues) {
  const Vec3 v(1, 1, 1), x(1, 0, 0), y(0, 1, 0);
  // Straight, unequal edges: r = 0 (the term does not equalise lengths) up
  // to the regularisation, ½(εL/0.5)² = 2e-12 for the short edge.
  EXPECT_NEAR(Norm(Residual(MakeAutoDiff(Bending(1.0)), {v - 0.5 * x, v, v + 3 * x})), 0.0, 3e-12);
  // Turning angle θ: |r| = 2 sin(θ/2).
  for (double theta : {0.1, M_PI / 2, 2.0, 3.0}) {
    const Vec3 w = v + 2.0 * (std::cos(theta) * x + std::sin(theta) * y);
    EXPECT_NEAR(Norm(Residual(MakeAutoDiff(Bending(1.0)), {v - x, v, w})), 2 * std::sin(theta / 2), 1e-10)
        << theta;
  }
  // Folded back (θ = π): |r| = 2, the maximum — no false zero as with the
  // cross product of the edges.
  EXPECT_NEAR(Norm(Residual(MakeAutoDiff(Bending(1.0)), {v - x, v, v - 2 * x})), 2.0, 1e-10);
}

TEST(Bending, DegenerateInputsAreFinite) {
  const Vec3 v(1, 1, 1), x(1, 0, 0);
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(Bending(1.0)));
  ExpectFiniteEverywhere(*cost, ToBlocks({v, v, v + x}));
  ExpectFiniteEverywhere(*cost, ToBlocks({v - x, v, v}));
  ExpectFiniteEverywhere(*cost, ToBlocks({v, v, v}));
  // A collapsed edge has no direction: r = the other unit direction.
  EXPECT_NEAR(Norm(Residual(MakeAutoDiff(Bending(1.0)), {v, v, v + x})), 1.0, 1e-10);
}

TEST(Bending, InvariantUnderRigidMotionScalingAndReversal) {
  std::mt19937 rng(kSeed + 21);
  for (int i = 0; i < kNumSamples; ++i) {
    const std::vector<Vec3> t = {RandomVec(rng, 2.0), RandomVec(rng, 2.0), RandomVec(rng, 2.0)};
    const double r = Norm(Residual(MakeAutoDiff(Bending(0.5)), t));
    EXPECT_NEAR(Norm(Residual(MakeAutoDiff(Bending(0.5)), Moved(t, RandomRotation(rng), RandomVec(rng, 10)))),
                r, kTolerance);
    for (double s : {1e-3, 0.37, 1e3}) {
      EXPECT_NEAR(Norm(Residual(MakeAutoDiff(Bending(0.5 / s)), Scaled(t, s))), r, kTolerance);
    }
    const auto forward = AsVec(Residual(MakeAutoDiff(Bending(0.5)), t));
    const auto reversed = AsVec(Residual(MakeAutoDiff(Bending(0.5)), {t[2], t[1], t[0]}));
    EXPECT_NEAR((forward - reversed).norm(), 0.0, kTolerance);
  }
}

// ---------------------------------------------------------------------------
// conical

// (ω1 + ω3) − (ω2 + ω4) with angles by acos (independent of the functor).
double ConicalByAcos(const std::vector<Vec3>& s) {
  double omega[4];
  for (int k = 0; k < 4; ++k) {
    const Vec3 a = (s[1 + k] - s[0]).normalized(), b = (s[1 + (k + 1) % 4] - s[0]).normalized();
    omega[k] = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
  }
  return (omega[0] + omega[2]) - (omega[1] + omega[3]);
}

TEST(Conical, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 30);
  for (int i = 0; i < kNumSamples; ++i) {
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(Conical(1.0)));
    ExpectGradientsMatch(*cost, ToBlocks(RandomStar(rng, 4)));
  }
}

TEST(Conical, KnownValues) {
  const double inv_length = 1.0;
  // Planar star: ω1 = ω2 = π/2, w4 at angle φ ∈ (π, 2π): ω3 = φ − π,
  // ω4 = 2π − φ, so r = 2φ − 3π.
  for (double phi : {1.2 * M_PI, 1.5 * M_PI, 1.9 * M_PI}) {
    const std::vector<Vec3> s = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 2, 0), Vec3(-0.5, 0, 0),
                                 Vec3(std::cos(phi), std::sin(phi), 0)};
    EXPECT_NEAR(Residual(MakeAutoDiff(Conical(inv_length)), s)[0], 2 * phi - 3 * M_PI, 1e-12) << phi;
  }
  // A star symmetric about the plane x = 0 through v, w2 and w4 (the star of
  // a surface of revolution's meridian/parallel net): ω1 = ω2, ω3 = ω4, r = 0.
  const std::vector<Vec3> symmetric = {Vec3(0, 0, 0), Vec3(1, 0.2, 0.3), Vec3(0, 1, -0.4),
                                       Vec3(-1, 0.2, 0.3), Vec3(0, -1.3, -0.2)};
  EXPECT_NEAR(Residual(MakeAutoDiff(Conical(inv_length)), symmetric)[0], 0.0, 1e-14);
  // Random stars: equal to the acos formula.
  std::mt19937 rng(kSeed + 31);
  for (int i = 0; i < kNumSamples; ++i) {
    const auto s = RandomStar(rng, 4);
    EXPECT_NEAR(Residual(MakeAutoDiff(Conical(inv_length)), s)[0], ConicalByAcos(s), 1e-9);
  }
}

TEST(Conical, DegenerateInputsAreFinite) {
  const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0);
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(Conical(1.0)));
  ExpectFiniteEverywhere(*cost, ToBlocks({o, o, y, -x, -y}));      // w1 = v
  ExpectFiniteEverywhere(*cost, ToBlocks({o, x, 2 * x, -x, -y}));  // ω1 = 0
  ExpectFiniteEverywhere(*cost, ToBlocks({o, x, -x, x, -x}));      // all collinear
  ExpectFiniteEverywhere(*cost, ToBlocks({o, o, o, o, o}));
}

TEST(Conical, InvariantUnderRigidMotionScalingAndRelabelling) {
  std::mt19937 rng(kSeed + 32);
  for (int i = 0; i < kNumSamples; ++i) {
    const auto s = RandomStar(rng, 4);
    const double r = Residual(MakeAutoDiff(Conical(1.0)), s)[0];
    EXPECT_NEAR(Residual(MakeAutoDiff(Conical(1.0)), Moved(s, RandomRotation(rng), RandomVec(rng, 10)))[0], r,
                1e-9);
    for (double scale : {1e-3, 0.37, 1e3}) {
      EXPECT_NEAR(Residual(MakeAutoDiff(Conical(1.0 / scale)), Scaled(s, scale))[0], r, 1e-9);
    }
    EXPECT_NEAR(Residual(MakeAutoDiff(Conical(1.0)), {s[0], s[2], s[3], s[4], s[1]})[0], -r, 1e-12);
    EXPECT_NEAR(Residual(MakeAutoDiff(Conical(1.0)), {s[0], s[3], s[4], s[1], s[2]})[0], r, 1e-12);
    EXPECT_NEAR(Residual(MakeAutoDiff(Conical(1.0)), {s[0], s[1], s[4], s[3], s[2]})[0], -r, 1e-12);
    EXPECT_NEAR(Residual(MakeAutoDiff(Conical(1.0)), {s[0], s[4], s[3], s[2], s[1]})[0], r, 1e-12);
  }
}

// ---------------------------------------------------------------------------
// load (force balance)

TEST(LoadEquilibrium, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 40);
  for (int i = 0; i < kNumSamples; ++i) {
    const int n = 3 + i % 4;
    const auto star = RandomStar(rng, n);
    std::vector<double> k, l0;
    for (int j = 0; j < n; ++j) {
      k.push_back(0.5 + j);
      l0.push_back(j % 2 == 0 ? 0.0 : 0.8);  // zero-length and length springs
    }
    const double f[3] = {0.1, -0.2, 1.0};
    std::unique_ptr<ceres::CostFunction> cost(MakeStarAutoDiff(LoadEquilibrium(f, k, l0, 0.9)));
    ExpectGradientsMatch(*cost, ToBlocks(star));
  }
}

TEST(LoadEquilibrium, KnownValues) {
  // Centre of a 3 × 3 grid, spacing h, sagging by z under a downward load P,
  // four zero-length springs k: resultant = (0, 0, −4kz − P); zero at
  // z = −P/(4k).
  const double h = 2.0, k = 3.0, P = 6.0;
  const double f[3] = {0, 0, -P};
  const std::vector<double> stiff(4, k), zero(4, 0.0);
  auto grid = [&](double z) {
    return std::vector<Vec3>{Vec3(0, 0, z), Vec3(h, 0, 0), Vec3(0, h, 0), Vec3(-h, 0, 0),
                             Vec3(0, -h, 0)};
  };
  const double z0 = -P / (4 * k);
  EXPECT_NEAR(Norm(Residual(MakeStarAutoDiff(LoadEquilibrium(f, stiff, zero, 1.0 / P)), grid(z0))), 0.0, 1e-15);
  const auto r = AsVec(Residual(MakeStarAutoDiff(LoadEquilibrium(f, stiff, zero, 1.0 / P)), grid(0.0)));
  EXPECT_NEAR((r - Vec3(0, 0, -1)).norm(), 0.0, 1e-15);  // the whole load, over F = P
  // Length springs L0: vertical balance 4k(√(h² + z²) − L0) z/√(h² + z²) = P,
  // solved for z by bisection (the horizontal parts cancel by symmetry).
  const double l0 = 1.5;
  const std::vector<double> rest(4, l0);
  auto vertical = [&](double z) {
    const double s = std::sqrt(h * h + z * z);
    return 4 * k * (s - l0) * (-z) / s - P;  // force on v along +z for z < 0
  };
  double lo = -10.0, hi = -1e-9;  // vertical(lo) > 0 > vertical(hi)
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (vertical(mid) > 0 ? lo : hi) = mid;
  }
  EXPECT_NEAR(Norm(Residual(MakeStarAutoDiff(LoadEquilibrium(f, stiff, rest, 1.0 / P)), grid(lo))), 0.0, 1e-12);
}

TEST(LoadEquilibrium, DegenerateInputsAreFinite) {
  const Vec3 o(1, 1, 1), x(1, 0, 0);
  const double f[3] = {0, 0, 1};
  std::unique_ptr<ceres::CostFunction> cost(
      MakeStarAutoDiff(LoadEquilibrium(f, {1.0, 1.0, 2.0}, {1.0, 0.0, 0.5}, 1.0)));
  ExpectFiniteEverywhere(*cost, ToBlocks({o, o, o, o}));
  ExpectFiniteEverywhere(*cost, ToBlocks({o, o, o + x, o - x}));
}

TEST(LoadEquilibrium, InvariantUnderRigidMotionScalingAndOrder) {
  std::mt19937 rng(kSeed + 41);
  for (int i = 0; i < kNumSamples; ++i) {
    const auto star = RandomStar(rng, 5);
    const std::vector<double> k = {1.0, 2.0, 0.5, 1.5, 3.0}, l0 = {0.0, 0.9, 0.0, 1.1, 0.7};
    const Vec3 force(0.2, 0.1, -1.0);
    const double r = Norm(Residual(MakeStarAutoDiff(LoadEquilibrium(force.data(), k, l0, 0.8)), star));
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 rotated = rot * force;
    EXPECT_NEAR(Norm(Residual(MakeStarAutoDiff(LoadEquilibrium(rotated.data(), k, l0, 0.8)),
                              Moved(star, rot, RandomVec(rng, 10.0)))),
                r, kTolerance);
    for (double s : {1e-3, 0.37, 1e3}) {
      std::vector<double> ks, ls;
      for (int j = 0; j < 5; ++j) {
        ks.push_back(k[j] / s);
        ls.push_back(l0[j] * s);
      }
      EXPECT_NEAR(Norm(Residual(MakeStarAutoDiff(LoadEquilibrium(force.data(), ks, ls, 0.8)), Scaled(star, s))),
                  r, kTolerance);
    }
    // Neighbours (with their springs) in another order.
    const std::vector<Vec3> shuffled = {star[0], star[3], star[1], star[5], star[2], star[4]};
    EXPECT_NEAR(Norm(Residual(MakeStarAutoDiff(LoadEquilibrium(force.data(), {0.5, 1.0, 3.0, 2.0, 1.5}, {0.0, 0.0, 0.7, 0.9, 1.1}, 0.8)),
                              shuffled)),
                r, kTolerance);
  }
}

// ---------------------------------------------------------------------------
// laplacian

TEST(Laplacian, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 50);
  for (int i = 0; i < kNumSamples; ++i) {
    const int n = 3 + i % 5;
    std::unique_ptr<ceres::CostFunction> cost(MakeStarAutoDiff(Laplacian(std::vector<double>(n, 1.0), 0.6)));
    ExpectGradientsMatch(*cost, ToBlocks(RandomStar(rng, n)));
  }
}

TEST(Laplacian, KnownValues) {
  // v = 0, neighbours (2,0,0), (0,2,0), (0,0,2): barycentre (2/3)(1,1,1).
  const std::vector<Vec3> s = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(0, 0, 2)};
  const auto r = AsVec(Residual(MakeStarAutoDiff(Laplacian(std::vector<double>(3, 1.0), 0.5)), s));
  EXPECT_NEAR((r - Vec3(1, 1, 1) / 3).norm(), 0.0, 1e-15);
  // Weights 1, 1, 2: weighted barycentre (2, 2, 4)/4; their scale drops out.
  const auto weighted = AsVec(Residual(MakeStarAutoDiff(Laplacian({3, 3, 6}, 1.0)), s));
  EXPECT_NEAR((weighted - Vec3(0.5, 0.5, 1.0)).norm(), 0.0, 1e-15);
  // v at the barycentre: r = 0.
  EXPECT_NEAR(Norm(Residual(MakeStarAutoDiff(Laplacian(std::vector<double>(3, 1.0), 1.0)), {Vec3(2, 2, 2) / 3, s[1], s[2], s[3]})), 0.0,
              1e-15);
}

TEST(Laplacian, DegenerateInputsAreFinite) {
  const Vec3 o(1, 1, 1);
  std::unique_ptr<ceres::CostFunction> cost(MakeStarAutoDiff(Laplacian({2.0, -0.5, 1.0}, 1.0)));
  ExpectFiniteEverywhere(*cost, ToBlocks({o, o, o, o}));
}

TEST(Laplacian, InvariantUnderRigidMotionAndScaling) {
  std::mt19937 rng(kSeed + 51);
  for (int i = 0; i < kNumSamples; ++i) {
    const auto s = RandomStar(rng, 6);
    const double r = Norm(Residual(MakeStarAutoDiff(Laplacian(std::vector<double>(6, 1.0), 0.7)), s));
    EXPECT_NEAR(
        Norm(Residual(MakeStarAutoDiff(Laplacian(std::vector<double>(6, 1.0), 0.7)), Moved(s, RandomRotation(rng), RandomVec(rng, 10.0)))),
        r, kTolerance);
    for (double scale : {1e-3, 0.37, 1e3}) {
      EXPECT_NEAR(Norm(Residual(MakeStarAutoDiff(Laplacian(std::vector<double>(6, 1.0), 0.7 / scale)), Scaled(s, scale))), r, kTolerance);
    }
  }
}

// ---------------------------------------------------------------------------
// mean_curvature_flow

std::vector<const double*> RingPointers(const std::vector<Vec3>& star) {
  std::vector<const double*> ring;
  for (size_t j = 1; j < star.size(); ++j) ring.push_back(star[j].data());
  return ring;
}

TEST(MeanCurvatureFlow, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 60);
  for (int i = 0; i < kNumSamples; ++i) {
    const int n = 4 + i % 4;
    const bool closed = i % 2 == 0;
    std::unique_ptr<ceres::CostFunction> cost(MakeStarAutoDiff(MeanCurvatureFlow(n, closed, 0.9)));
    ExpectGradientsMatch(*cost, ToBlocks(RandomStar(rng, n)));
  }
}

TEST(MeanCurvatureFlow, KnownValues) {
  // Apex v = (0, 0, h) of a pyramid over a regular n-gon of circumradius ρ:
  // A = n · ½ b s, b = 2ρ sin(π/n), s = √(h² + (ρ cos(π/n))²), so
  // −∇_v A = −(0, 0, n b h / (2 s)).
  const double h = 0.7, rho = 1.3, inv_length = 0.5;
  for (int n : {3, 4, 6}) {
    std::vector<Vec3> star = {Vec3(0, 0, h)};
    for (int k = 0; k < n; ++k) {
      star.push_back(rho * Vec3(std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n), 0));
    }
    const double b = 2 * rho * std::sin(M_PI / n);
    const double s = std::hypot(h, rho * std::cos(M_PI / n));
    const auto r = AsVec(Residual(MakeStarAutoDiff(MeanCurvatureFlow(n, true, inv_length)), star));
    EXPECT_NEAR((r - Vec3(0, 0, -n * b * h / (2 * s)) * inv_length).norm(), 0.0, 1e-12) << n;
  }
  // The cotangent form ½ Σ (cot α + cot β)(w_j − v) / L is the same vector
  // (closed and boundary fans, random stars).
  std::mt19937 rng(kSeed + 61);
  for (int i = 0; i < kNumSamples; ++i) {
    const int n = 4 + i % 3;
    const bool closed = i % 2 == 0;
    const auto star = RandomStar(rng, n);
    const std::vector<double> c = CotangentWeights(star[0].data(), RingPointers(star), closed);
    Vec3 expected = Vec3::Zero();
    for (int j = 0; j < n; ++j) expected += c[j] * (star[j + 1] - star[0]) * inv_length;
    const auto r = AsVec(Residual(MakeStarAutoDiff(MeanCurvatureFlow(n, closed, inv_length)), star));
    EXPECT_NEAR((r - expected).norm(), 0.0, 1e-10) << i;
  }
  // A planar regular star with v at its centre: r = 0 (a critical point of
  // the area), and the cotangent weights of equilateral triangles are 1/√3.
  std::vector<Vec3> hexagon = {Vec3(0, 0, 0)};
  for (int k = 0; k < 6; ++k)
    hexagon.push_back(Vec3(std::cos(M_PI * k / 3), std::sin(M_PI * k / 3), 0));
  EXPECT_NEAR(Norm(Residual(MakeStarAutoDiff(MeanCurvatureFlow(6, true, 1.0)), hexagon)), 0.0, 1e-15);
  for (double c : CotangentWeights(hexagon[0].data(), RingPointers(hexagon), true)) {
    EXPECT_NEAR(c, 1.0 / std::sqrt(3.0), 1e-15);
  }
}

TEST(MeanCurvatureFlow, DegenerateInputsAreFinite) {
  const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0);
  std::unique_ptr<ceres::CostFunction> cost(MakeStarAutoDiff(MeanCurvatureFlow(4, true, 1.0)));
  ExpectFiniteEverywhere(*cost, ToBlocks({o, o, o, o, o}));
  ExpectFiniteEverywhere(*cost, ToBlocks({o, x, 2 * x, -x, y}));  // a needle triangle
  const std::vector<Vec3> collapsed = {o, o, o, o, o};
  for (double c : CotangentWeights(o.data(), RingPointers(collapsed), true)) {
    EXPECT_TRUE(std::isfinite(c));
  }
}

TEST(MeanCurvatureFlow, InvariantUnderRigidMotionScalingAndReversal) {
  std::mt19937 rng(kSeed + 62);
  for (int i = 0; i < kNumSamples; ++i) {
    const auto s = RandomStar(rng, 5);
    const double r = Norm(Residual(MakeStarAutoDiff(MeanCurvatureFlow(5, true, 0.7)), s));
    EXPECT_NEAR(Norm(Residual(MakeStarAutoDiff(MeanCurvatureFlow(5, true, 0.7)),
                              Moved(s, RandomRotation(rng), RandomVec(rng, 10.0)))),
                r, kTolerance);
    for (double scale : {1e-3, 0.37, 1e3}) {
      EXPECT_NEAR(Norm(Residual(MakeStarAutoDiff(MeanCurvatureFlow(5, true, 0.7 / scale)), Scaled(s, scale))), r,
                  kTolerance);
    }
    const auto forward = AsVec(Residual(MakeStarAutoDiff(MeanCurvatureFlow(5, true, 0.7)), s));
    const auto reversed =
        AsVec(Residual(MakeStarAutoDiff(MeanCurvatureFlow(5, true, 0.7)), {s[0], s[5], s[4], s[3], s[2], s[1]}));
    EXPECT_NEAR((forward - reversed).norm(), 0.0, kTolerance);
  }
}

// ---------------------------------------------------------------------------
// on_curve

// An L-shaped open polyline (0,0,0) → (2,0,0) → (2,3,0): Λ = 5.
std::shared_ptr<const CurvePolyline> LCurve(bool closed = false) {
  return std::make_shared<CurvePolyline>(std::vector<double>{0, 0, 0, 2, 0, 0, 2, 3, 0}, closed);
}

std::vector<double> OnCurveResidual(const std::shared_ptr<const CurvePolyline>& curve,
                                    double inv_length, const Vec3& v, double t) {
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(OnCurve(curve, inv_length)));
  return Evaluate(*cost, {ToBlock(v), {t}});
}

TEST(OnCurve, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 70);
  std::uniform_real_distribution<double> along(0.1, 1.9);
  for (bool closed : {false, true}) {
    const auto curve = LCurve(closed);
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(OnCurve(curve, 0.8)));
    for (int i = 0; i < kNumSamples; ++i) {
      // t inside a segment (away from the kinks at 2, 5 and, closed, 0 = Λ).
      const double t = along(rng) + (i % 2 == 0 ? 0.0 : 3.0);
      ExpectGradientsMatch(*cost, {ToBlock(RandomVec(rng, 3.0)), {t}});
    }
  }
}

TEST(OnCurve, KnownValues) {
  const auto curve = LCurve();
  EXPECT_DOUBLE_EQ(curve->length(), 5.0);
  // C(1) = (1, 0, 0), C(3.5) = (2, 1.5, 0).
  EXPECT_NEAR((curve->Evaluate(1.0) - Vec3(1, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((curve->Evaluate(3.5) - Vec3(2, 1.5, 0)).norm(), 0.0, 1e-15);
  // Open curves extend linearly: C(−1) = (−1, 0, 0), C(6) = (2, 4, 0).
  EXPECT_NEAR((curve->Evaluate(-1.0) - Vec3(-1, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((curve->Evaluate(6.0) - Vec3(2, 4, 0)).norm(), 0.0, 1e-15);
  // r = (v − C(t))/L.
  const auto r = AsVec(OnCurveResidual(curve, 0.5, Vec3(2, 1.5, 1), 3.5));
  EXPECT_NEAR((r - Vec3(0, 0, 0.5)).norm(), 0.0, 1e-15);
  // Closed: the closing segment (2,3,0) → (0,0,0) of length √13, periodic t.
  const auto loop = LCurve(true);
  const double total = 5.0 + std::sqrt(13.0);
  EXPECT_NEAR(loop->length(), total, 1e-15);
  EXPECT_NEAR((loop->Evaluate(5.0 + 0.5 * std::sqrt(13.0)) - Vec3(1, 1.5, 0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((loop->Evaluate(1.0 + 3 * total) - Vec3(1, 0, 0)).norm(), 0.0, 1e-13);
  EXPECT_NEAR((loop->Evaluate(1.0 - total) - Vec3(1, 0, 0)).norm(), 0.0, 1e-13);
  // Parameter of points on and off the curve.
  const Vec3 p(2, 1.5, 0), q(3, 1, 7);
  EXPECT_NEAR(curve->Parameter(p.data()), 3.5, 1e-15);
  EXPECT_NEAR(curve->Parameter(q.data()), 3.0, 1e-15);  // closest (2, 1, 0)
  EXPECT_NEAR((curve->Tangent(3.0) - Vec3(0, 1, 0)).norm(), 0.0, 1e-15);
}

TEST(OnCurve, InvariantUnderRigidMotionAndScaling) {
  std::mt19937 rng(kSeed + 71);
  const std::vector<Vec3> points = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 3, 0), Vec3(4, 3, 1)};
  auto make = [](const std::vector<Vec3>& p) {
    std::vector<double> xyz;
    for (const Vec3& x : p) xyz.insert(xyz.end(), {x[0], x[1], x[2]});
    return std::make_shared<CurvePolyline>(xyz, false);
  };
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 v = RandomVec(rng, 3.0);
    const double t = 0.37 * (i + 1) * 0.3;
    const double r = Norm(OnCurveResidual(make(points), 0.6, v, t));
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 shift = RandomVec(rng, 10.0);
    EXPECT_NEAR(Norm(OnCurveResidual(make(Moved(points, rot, shift)), 0.6, rot * v + shift, t)), r,
                kTolerance);
    for (double s : {1e-3, 0.37, 1e3}) {
      EXPECT_NEAR(Norm(OnCurveResidual(make(Scaled(points, s)), 0.6 / s, s * v, s * t)), r,
                  kTolerance);
    }
  }
}

TEST(OnCurve, DegenerateInputsAreFinite) {
  // Exactly at a kink and at the ends, and far outside an open curve.
  const auto curve = LCurve();
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(OnCurve(curve, 1.0)));
  for (double t : {0.0, 2.0, 5.0, -100.0, 100.0}) {
    ExpectFiniteEverywhere(*cost, {ToBlock(Vec3(1, 1, 1)), {t}});
  }
}

// ---------------------------------------------------------------------------
// CurveManifold

Vec3 Plus(const ceres::Manifold& m, const Vec3& x, double delta) {
  Vec3 y;
  EXPECT_TRUE(m.Plus(x.data(), &delta, y.data()));
  return y;
}

double Minus(const ceres::Manifold& m, const Vec3& y, const Vec3& x) {
  double d = 0.0;
  EXPECT_TRUE(m.Minus(y.data(), x.data(), &d));
  return d;
}

TEST(CurveManifold, PlusMovesAlongThePolylineExactly) {
  const auto curve = LCurve();
  std::unique_ptr<ceres::Manifold> m(MakeCurveManifold(curve));
  EXPECT_EQ(m->AmbientSize(), 3);
  EXPECT_EQ(m->TangentSize(), 1);
  const Vec3 x(1.5, 0, 0);  // t = 1.5
  EXPECT_NEAR((Plus(*m, x, 0.0) - x).norm(), 0.0, 1e-15);
  EXPECT_NEAR((Plus(*m, x, 0.25) - Vec3(1.75, 0, 0)).norm(), 0.0, 1e-15);
  // Across the corner at t = 2: to t = 3.5, i.e. (2, 1.5, 0), on the curve.
  EXPECT_NEAR((Plus(*m, x, 2.0) - Vec3(2, 1.5, 0)).norm(), 0.0, 1e-15);
  // Open ends clamp.
  EXPECT_NEAR((Plus(*m, x, 10.0) - Vec3(2, 3, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((Plus(*m, x, -10.0) - Vec3(0, 0, 0)).norm(), 0.0, 1e-15);
  // Minus is the inverse of Plus (within the curve).
  for (double d : {-1.5, -0.3, 0.0, 0.4, 2.0, 3.4}) {
    EXPECT_NEAR(Minus(*m, Plus(*m, x, d), x), d, 1e-14) << d;
  }
  // Closed: wraps through p_0, Minus takes the short way round.
  const auto loop = LCurve(true);
  std::unique_ptr<ceres::Manifold> ml(MakeCurveManifold(loop));
  const Vec3 start(0.5, 0, 0);               // t = 0.5
  const Vec3 back = Plus(*ml, start, -1.0);  // t = Λ − 0.5, on the closing segment
  EXPECT_NEAR((back - Vec3(0.5 * 2 / std::sqrt(13.0), 0.5 * 3 / std::sqrt(13.0), 0)).norm(), 0.0,
              1e-14);
  EXPECT_NEAR(Minus(*ml, back, start), -1.0, 1e-14);
}

TEST(CurveManifold, JacobiansAreTheUnitTangent) {
  const auto curve = LCurve();
  std::unique_ptr<ceres::Manifold> m(MakeCurveManifold(curve));
  for (const Vec3& x : {Vec3(0.7, 0, 0), Vec3(2, 2.2, 0)}) {
    Vec3 plus_jacobian, minus_jacobian;
    ASSERT_TRUE(m->PlusJacobian(x.data(), plus_jacobian.data()));
    ASSERT_TRUE(m->MinusJacobian(x.data(), minus_jacobian.data()));
    // Central difference of Plus inside the segment.
    const double h = 1e-6;
    const Vec3 numeric = (Plus(*m, x, h) - Plus(*m, x, -h)) / (2 * h);
    EXPECT_NEAR((plus_jacobian - numeric).norm(), 0.0, 1e-9);
    EXPECT_NEAR(minus_jacobian.dot(plus_jacobian), 1.0, 1e-15);  // MinusJ · PlusJ = I
    EXPECT_NEAR(plus_jacobian.norm(), 1.0, 1e-15);
  }
}

// At a polyline vertex the Jacobian is the unit bisector of the two segments
// (their central difference): a vertex sitting on a right-angled corner sees
// the pull of the segment behind it and slides back onto it.
TEST(CurveManifold, AtACornerTheJacobianIsTheBisectorAndTheVertexCanMoveBack) {
  const auto curve = LCurve();  // (0,0,0) → (2,0,0) → (2,3,0)
  std::unique_ptr<ceres::Manifold> m(MakeCurveManifold(curve));
  Vec3 x(2, 0, 0), plus_jacobian, minus_jacobian;
  ASSERT_TRUE(m->PlusJacobian(x.data(), plus_jacobian.data()));
  ASSERT_TRUE(m->MinusJacobian(x.data(), minus_jacobian.data()));
  EXPECT_NEAR((plus_jacobian - Vec3(1, 1, 0).normalized()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(minus_jacobian.dot(plus_jacobian), 1.0, 1e-15);
  // The open curve's ends keep their one segment.
  Vec3 end(0, 0, 0), end_jacobian;
  ASSERT_TRUE(m->PlusJacobian(end.data(), end_jacobian.data()));
  EXPECT_NEAR((end_jacobian - Vec3(1, 0, 0)).norm(), 0.0, 1e-15);
  // A zero-length spring to (0.5, 0, 0) pulls the corner vertex back along
  // the first segment (with the forward tangent (0, 1, 0) alone the pull has
  // no component along the curve and the vertex would stay).
  Vec3 anchor(0.5, 0, 0);
  ceres::Problem problem;
  problem.AddResidualBlock(MakeSpring(0.0, 1.0), nullptr, x.data(), anchor.data());
  problem.SetParameterBlockConstant(anchor.data());
  problem.SetManifold(x.data(), MakeCurveManifold(curve));
  ceres::Solver::Options options;
  options.function_tolerance = 1e-16;
  options.parameter_tolerance = 1e-16;
  options.gradient_tolerance = 1e-16;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  EXPECT_NEAR((x - Vec3(0.5, 0, 0)).norm(), 0.0, 1e-9) << summary.BriefReport();
}

}  // namespace
}  // namespace archgeo
