// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for the TCD field and level-set energies (energies/tcd_*.h,
// energies/level_set_*.h):
//  (a) autodiff Jacobians against numeric differences (GradientChecker) on
//      random samples from a fixed seed;
//  (b) invariances: frame rotations (spin-2 for z), rigid motions and scaling
//      of the triangle for the level sets;
//  (c) values on analytic cases, and the zero sets the paper defines
//      (a prescribed direction belongs to the conjugate pair iff r = 0, …);
//  (d) degenerate inputs give finite residuals and Jacobians.
// And the principal-field pre-processing (energies/principal_*.h): the same
// checks for its angle field (a line field: θ and θ + π alike).
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <ceres/cost_function.h>
#include <gtest/gtest.h>

#include "tests/energy_checks.h"
#include "energies/autodiff.h"

#include "energies/level_set_alignment.h"
#include "energies/level_set_branch_point.h"
#include "energies/level_set_conjugacy.h"
#include "energies/level_set_jump.h"
#include "energies/level_set_normalised.h"
#include "energies/principal_fit.h"
#include "energies/principal_smoothing.h"
#include "energies/tcd_dirichlet.h"
#include "energies/tcd_prescribed_direction.h"
#include "energies/tcd_singularity_avoidance.h"
#include "energies/tcd_singularity_placement.h"
#include "energies/tcd_transversality.h"
#include "fields/conjugate.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using energy_checks::Blocks;
using energy_checks::Evaluate;
using energy_checks::ExpectFiniteEverywhere;
using energy_checks::ExpectGradientsMatch;

constexpr unsigned kSeed = 20100507;
constexpr int kNumSamples = 20;
// Agreement of quantities equal in exact arithmetic.
constexpr double kTolerance = 1e-11;

using Vec2 = Eigen::Vector2d;

double Norm(const std::vector<double>& r) {
  double s = 0.0;
  for (double v : r) s += v * v;
  return std::sqrt(s);
}

Eigen::Matrix2d Rot(double a) {
  Eigen::Matrix2d R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return R;
}

// z in a frame turned by φ: the point turns about e1 by −2φ (fields/conjugate.h).
Vec2 TurnZ(const Vec2& z, double phi) {
  const Vec2 e1(1.0, 0.0);
  return e1 + Rot(-2.0 * phi) * (z - e1);
}

std::vector<double> B2(const Vec2& z) { return {z.x(), z.y()}; }

Vec2 RandomZ(std::mt19937& rng) {  // inside the auxiliary circle
  std::uniform_real_distribution<double> u(-0.9, 0.9);
  Vec2 d;
  do d = Vec2(u(rng), u(rng));
  while (d.norm() > 0.9);
  return Vec2(1.0, 0.0) + d;
}

// ---------------------------------------------------------------- tcd_dirichlet

TEST(TcdDirichlet, GradientsMatchNumericDifferences) {
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), weight(0.1, 3.0);
  for (int s = 0; s < kNumSamples; ++s) {
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(TcdDirichlet(angle(rng), weight(rng))));
    ExpectGradientsMatch(*cost, {B2(RandomZ(rng)), B2(RandomZ(rng))});
  }
}

TEST(TcdDirichlet, VanishesForTheTransportedFieldAndHasTheAnalyticValue) {
  const double tau = 0.7, w = 2.5;
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(TcdDirichlet(tau, w)));
  // ζ_f = R(2τ) ζ_g: the same conjugate pair seen from both frames.
  const Vec2 zeta_g(0.3, -0.2);
  const Vec2 z_g = Vec2(1, 0) + zeta_g, z_f = Vec2(1, 0) + Rot(2 * tau) * zeta_g;
  EXPECT_LT(Norm(Evaluate(*cost, {B2(z_f), B2(z_g)})), kTolerance);
  // Principal fields (z = e1) in both faces: zero for every transport.
  EXPECT_LT(Norm(Evaluate(*cost, {B2(Vec2(1, 0)), B2(Vec2(1, 0))})), kTolerance);
  // ζ_g = 0, ζ_f = (0.3, 0.4): ‖r‖ = sqrt(w)·0.5.
  EXPECT_NEAR(Norm(Evaluate(*cost, {B2(Vec2(1.3, 0.4)), B2(Vec2(1, 0))})), std::sqrt(w) * 0.5,
              kTolerance);
}

TEST(TcdDirichlet, IndependentOfTheFaceFrames) {
  std::mt19937 rng(kSeed + 1);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), weight(0.1, 3.0);
  for (int s = 0; s < kNumSamples; ++s) {
    const double tau = angle(rng), w = weight(rng), phi_f = angle(rng), phi_g = angle(rng);
    const Vec2 z_f = RandomZ(rng), z_g = RandomZ(rng);
    std::unique_ptr<ceres::CostFunction> a(MakeAutoDiff(TcdDirichlet(tau, w)));
    std::unique_ptr<ceres::CostFunction> b(MakeAutoDiff(TcdDirichlet(tau + phi_g - phi_f, w)));
    const double before = Norm(Evaluate(*a, {B2(z_f), B2(z_g)}));
    const double after = Norm(Evaluate(*b, {B2(TurnZ(z_f, phi_f)), B2(TurnZ(z_g, phi_g))}));
    EXPECT_NEAR(before, after, kTolerance);
    // Swapping the faces (τ → −τ) keeps the norm.
    std::unique_ptr<ceres::CostFunction> c(MakeAutoDiff(TcdDirichlet(-tau, w)));
    EXPECT_NEAR(before, Norm(Evaluate(*c, {B2(z_g), B2(z_f)})), kTolerance);
  }
}

// ------------------------------------------------------------ tcd_transversality

TEST(TcdTransversality, FourthPowerOfTheDistanceToE1) {
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(TcdTransversality()));
  // ‖z − e1‖ = 0.5: r = 0.25, ½r² = ½ φ(0.5) = ½·0.0625.
  const double r = Evaluate(*cost, {B2(Vec2(1.3, 0.4))})[0];
  EXPECT_NEAR(r, 0.25, kTolerance);
  EXPECT_NEAR(r * r, std::pow(0.5, 4), kTolerance);
  EXPECT_NEAR(Evaluate(*cost, {B2(Vec2(1, 0))})[0], 0.0, kTolerance);
  // Eq. 1: cos∠(v, w) ≤ ‖z_N − e1‖ = sqrt(r) for any M.
  std::mt19937 rng(kSeed + 2);
  std::normal_distribution<double> g;
  for (int s = 0; s < kNumSamples; ++s) {
    Eigen::Matrix2d M;
    M << g(rng), g(rng), 0, g(rng);
    M(1, 0) = M(0, 1);
    const Vec2 z = RandomZ(rng);
    const ConjugatePair pair = ConjugatePairOf(M, z);
    ASSERT_TRUE(pair.valid);
    const double rz = Evaluate(*cost, {B2(z)})[0];
    EXPECT_LE(std::abs(pair.v.dot(pair.w)), std::sqrt(rz) + 1e-12);
  }
}

TEST(TcdTransversality, GradientsAndFrameInvariance) {
  std::mt19937 rng(kSeed + 3);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(TcdTransversality()));
  for (int s = 0; s < kNumSamples; ++s) {
    const Vec2 z = RandomZ(rng);
    ExpectGradientsMatch(*cost, {B2(z)});
    EXPECT_NEAR(Evaluate(*cost, {B2(z)})[0], Evaluate(*cost, {B2(TurnZ(z, angle(rng)))})[0],
                kTolerance);
  }
  ExpectFiniteEverywhere(*cost, {B2(Vec2(1, 0))});
}

// ------------------------------------------------------ tcd_singularity_avoidance

TEST(TcdSingularityAvoidance, PsiOfThePaper) {
  const double z_m[2] = {0.5, 0.2};
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(TcdSingularityAvoidance(z_m, 1.0)));
  // t = 0.5: Ψ = (0.5 − 1)⁴ = 0.0625 = r².
  const double r = Evaluate(*cost, {B2(Vec2(0.8, 0.6))})[0];
  EXPECT_NEAR(r * r, 0.0625, 1e-10);
  // t ≥ 1: 0.
  EXPECT_EQ(Evaluate(*cost, {B2(Vec2(1.1, 1.0))})[0], 0.0);
  // Monotone: closer to z_M costs more; at z_M, Ψ = 1.
  double previous = -1.0;
  for (double t = 0.95; t > 0.0; t -= 0.05) {
    const double v = Evaluate(*cost, {B2(Vec2(0.5 + t, 0.2))})[0];
    EXPECT_GT(v, previous);
    previous = v;
  }
  EXPECT_NEAR(Evaluate(*cost, {B2(Vec2(0.5, 0.2))})[0], 1.0, 1e-5);
  // A smaller radius confines the term.
  std::unique_ptr<ceres::CostFunction> narrow(MakeAutoDiff(TcdSingularityAvoidance(z_m, 0.25)));
  EXPECT_EQ(Evaluate(*narrow, {B2(Vec2(0.8, 0.6))})[0], 0.0);
}

TEST(TcdSingularityAvoidance, GradientsInvarianceAndTheSingularPoint) {
  std::mt19937 rng(kSeed + 4);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), rad(0.05, 0.95);
  for (int s = 0; s < kNumSamples; ++s) {
    const Vec2 zm = RandomZ(rng);
    const double a = angle(rng);
    // Inside the support, away from t = 1 where the second derivative jumps.
    const Vec2 z = zm + rad(rng) * Vec2(std::cos(a), std::sin(a));
    const double zm_b[2] = {zm.x(), zm.y()};
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(TcdSingularityAvoidance(zm_b, 1.0)));
    ExpectGradientsMatch(*cost, {B2(z)});
    const double phi = angle(rng);
    const Vec2 zm2 = TurnZ(zm, phi);
    const double zm2_b[2] = {zm2.x(), zm2.y()};
    std::unique_ptr<ceres::CostFunction> turned(MakeAutoDiff(TcdSingularityAvoidance(zm2_b, 1.0)));
    EXPECT_NEAR(Evaluate(*cost, {B2(z)})[0], Evaluate(*turned, {B2(TurnZ(z, phi))})[0],
                kTolerance);
  }
  // Exactly singular: finite, zero Jacobian (a stationary point).
  const double zm_b[2] = {0.7, 0.1};
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(TcdSingularityAvoidance(zm_b, 1.0)));
  Blocks jac;
  Evaluate(*cost, {B2(Vec2(0.7, 0.1))}, &jac);
  EXPECT_EQ(jac[0][0], 0.0);
  EXPECT_EQ(jac[0][1], 0.0);
}

// ------------------------------------------------------ tcd_singularity_placement

TEST(TcdSingularityPlacement, ValueGradientAndInvariance) {
  const double zm[2] = {0.6, -0.3};
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(TcdSingularityPlacement(zm)));
  const std::vector<double> r = Evaluate(*cost, {B2(Vec2(1.0, 0.0))});
  EXPECT_NEAR(r[0], 0.4, kTolerance);
  EXPECT_NEAR(r[1], 0.3, kTolerance);
  ExpectGradientsMatch(*cost, {B2(Vec2(0.9, 0.2))});
  const Vec2 zm2 = TurnZ(Vec2(0.6, -0.3), 0.4);
  const double zm2_b[2] = {zm2.x(), zm2.y()};
  std::unique_ptr<ceres::CostFunction> turned(MakeAutoDiff(TcdSingularityPlacement(zm2_b)));
  EXPECT_NEAR(Norm(r), Norm(Evaluate(*turned, {B2(TurnZ(Vec2(1.0, 0.0), 0.4))})), kTolerance);
  // z_N = z_M makes the face singular: the pair is undetermined.
  Eigen::Matrix2d M;
  M << 1.0, 0.2, 0.2, 3.0;
  Vec2 z;
  ASSERT_TRUE(ZOfMatrix(M, &z));
  EXPECT_FALSE(ConjugatePairOf(M, z).valid);
  EXPECT_TRUE(ConjugatePairOf(M, z + Vec2(0.05, 0.0)).valid);
}

// ------------------------------------------------------- tcd_prescribed_direction

TEST(TcdPrescribedDirection, DistanceFromTheLineOfProp1) {
  // M = diag(1, 2), d = e1: the conjugate of d is e2, the line through
  // p(e1) = (2, 0) and p(e2) = (0, 0) is the x-axis; z_M = (4/3, 0) is on it.
  const double m[3] = {1.0, 0.0, 2.0}, d[2] = {1.0, 0.0};
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(CheckedTcdPrescribedDirection(m, d)));
  EXPECT_NEAR(std::abs(Evaluate(*cost, {B2(Vec2(1.0, 0.3))})[0]), 0.3, kTolerance);
  EXPECT_NEAR(Evaluate(*cost, {B2(Vec2(1.0, 0.0))})[0], 0.0, kTolerance);
  ExpectGradientsMatch(*cost, {B2(Vec2(0.8, 0.1))});
}

TEST(TcdPrescribedDirection, ZeroExactlyWhenThePairContainsTheDirection) {
  std::mt19937 rng(kSeed + 5);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> angle(0, M_PI), t(-2.0, 2.0);
  int checked = 0;
  for (int s = 0; s < 4 * kNumSamples; ++s) {
    Eigen::Matrix2d M;
    M << g(rng), g(rng), 0, g(rng);
    M(1, 0) = M(0, 1);
    const double a = angle(rng);
    const double d[2] = {std::cos(a), std::sin(a)};
    const double m[3] = {M(0, 0), M(0, 1), M(1, 1)};
    Vec2 point, dir;
    if (!TcdPrescribedLine(m, d, &point, &dir)) continue;
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(CheckedTcdPrescribedDirection(m, d)));
    // A point of the line inside the circle: its pair contains d.
    const Vec2 z = point + t(rng) * dir;
    if ((z - Vec2(1, 0)).norm() > 0.95) continue;
    const ConjugatePair pair = ConjugatePairOf(M, z);
    if (!pair.valid) continue;
    EXPECT_NEAR(Evaluate(*cost, {B2(z)})[0], 0.0, 1e-12);
    const Vec2 dv(d[0], d[1]);
    const double cross_v = std::abs(dv.x() * pair.v.y() - dv.y() * pair.v.x());
    const double cross_w = std::abs(dv.x() * pair.w.y() - dv.y() * pair.w.x());
    EXPECT_LT(std::min(cross_v, cross_w), 1e-8);
    // Off the line by 0.05: the residual is ±0.05 and d is in neither line.
    const Vec2 off = z + 0.05 * Vec2(-dir.y(), dir.x());
    if ((off - Vec2(1, 0)).norm() > 0.95) continue;
    EXPECT_NEAR(std::abs(Evaluate(*cost, {B2(off)})[0]), 0.05, 1e-12);
    const ConjugatePair moved = ConjugatePairOf(M, off);
    if (!moved.valid) continue;
    EXPECT_GT(std::min(std::abs(dv.x() * moved.v.y() - dv.y() * moved.v.x()),
                       std::abs(dv.x() * moved.w.y() - dv.y() * moved.w.x())),
              1e-6);
    ++checked;
  }
  EXPECT_GE(checked, kNumSamples);
}

TEST(TcdPrescribedDirection, FrameInvarianceAndVoidCondition) {
  std::mt19937 rng(kSeed + 6);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  for (int s = 0; s < kNumSamples; ++s) {
    Eigen::Matrix2d M;
    M << g(rng), g(rng), 0, g(rng);
    M(1, 0) = M(0, 1);
    const double a = angle(rng), phi = angle(rng);
    const Vec2 dv(std::cos(a), std::sin(a)), z = RandomZ(rng);
    const double m[3] = {M(0, 0), M(0, 1), M(1, 1)}, d[2] = {dv.x(), dv.y()};
    // The same geometry in a frame turned by φ: d → R(−φ)d, M → RᵀMR.
    const Eigen::Matrix2d Mt = Rot(phi).transpose() * M * Rot(phi);
    const Vec2 dt = Rot(-phi) * dv;
    const double mt[3] = {Mt(0, 0), Mt(0, 1), Mt(1, 1)}, dtb[2] = {dt.x(), dt.y()};
    std::unique_ptr<ceres::CostFunction> a1(MakeAutoDiff(CheckedTcdPrescribedDirection(m, d)));
    std::unique_ptr<ceres::CostFunction> a2(MakeAutoDiff(CheckedTcdPrescribedDirection(mt, dtb)));
    EXPECT_NEAR(std::abs(Evaluate(*a1, {B2(z)})[0]),
                std::abs(Evaluate(*a2, {B2(TurnZ(z, phi))})[0]), 1e-10);
    ExpectGradientsMatch(*a1, {B2(z)});
  }
  // d with M d = 0 (a zero principal curvature) or M = 0: every direction is
  // conjugate to d, the condition is void.
  const double m0[3] = {0.0, 0.0, 1.0}, d0[2] = {1.0, 0.0}, zero[3] = {0, 0, 0};
  Vec2 p, q;
  EXPECT_FALSE(TcdPrescribedLine(m0, d0, &p, &q));
  EXPECT_FALSE(TcdPrescribedLine(zero, d0, &p, &q));
  // z_M at infinity (m11 + m22 = 0) is still a line.
  const double minimal[3] = {1.0, 0.3, -1.0};
  EXPECT_TRUE(TcdPrescribedLine(minimal, d0, &p, &q));
}

// ----------------------------------------------------------------- level sets

// A well-shaped counter-clockwise triangle in a random frame position.
std::vector<Vec2> RandomTriangle(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-0.2, 0.2), s(0.5, 2.0), a(-M_PI, M_PI);
  const double scale = s(rng);
  const Eigen::Matrix2d R = Rot(a(rng));
  const Vec2 shift(u(rng) * 10, u(rng) * 10);
  std::vector<Vec2> p = {Vec2(0, 0), Vec2(1, 0), Vec2(0.4, 0.9)};
  for (Vec2& x : p) x = R * (scale * (x + Vec2(u(rng), u(rng)))) + shift;
  return p;
}

std::vector<double> Corners6(const std::vector<Vec2>& p) {
  return {p[0].x(), p[0].y(), p[1].x(), p[1].y(), p[2].x(), p[2].y()};
}

double Area(const std::vector<Vec2>& p) {
  const Vec2 a = p[1] - p[0], b = p[2] - p[0];
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

// Corner values of the linear function x ↦ a·x + c.
Blocks Linear(const std::vector<Vec2>& p, const Vec2& a, double c) {
  return {{a.dot(p[0]) + c}, {a.dot(p[1]) + c}, {a.dot(p[2]) + c}};
}

TEST(LevelSetAlignment, AnalyticValueAndGradients) {
  std::mt19937 rng(kSeed + 7);
  std::normal_distribution<double> g;
  for (int s = 0; s < kNumSamples; ++s) {
    const std::vector<Vec2> p = RandomTriangle(rng);
    const std::vector<double> c6 = Corners6(p);
    const Vec2 v = Vec2(g(rng), g(rng)).normalized();
    const double v2[2] = {v.x(), v.y()}, inv_total = 1.0 / 7.0;
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(LevelSetAlignment(c6.data(), v2, inv_total)));
    // g with ∇g = R v (R: +90°): zero.
    const Vec2 rv(-v.y(), v.x());
    EXPECT_LT(Norm(Evaluate(*cost, Linear(p, rv, g(rng)))), kTolerance);
    // ∇g = a: r = sqrt(A/A_Φ)(R v − a).
    const Vec2 a(g(rng), g(rng));
    const std::vector<double> r = Evaluate(*cost, Linear(p, a, g(rng)));
    EXPECT_NEAR(Norm(r), std::sqrt(Area(p) * inv_total) * (rv - a).norm(), 1e-10);
    ExpectGradientsMatch(*cost, {{g(rng)}, {g(rng)}, {g(rng)}});
    // v = 0: the Dirichlet term ‖r‖² = (A/A_Φ)‖∇g‖² of λ_even.
    const double zero[2] = {0.0, 0.0};
    std::unique_ptr<ceres::CostFunction> even(MakeAutoDiff(LevelSetAlignment(c6.data(), zero, inv_total)));
    EXPECT_NEAR(std::pow(Norm(Evaluate(*even, Linear(p, a, 0.3))), 2),
                Area(p) * inv_total * a.squaredNorm(), 1e-10);
  }
}

TEST(LevelSetAlignment, RigidMotionAndScalingInvariance) {
  std::mt19937 rng(kSeed + 8);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), scale(0.2, 5.0);
  for (int s = 0; s < kNumSamples; ++s) {
    const std::vector<Vec2> p = RandomTriangle(rng);
    const Vec2 v = Vec2(g(rng), g(rng)).normalized(), shift(g(rng), g(rng));
    const Blocks values = {{g(rng)}, {g(rng)}, {g(rng)}};
    const double inv_total = 0.3, phi = angle(rng), k = scale(rng);
    const std::vector<double> c6 = Corners6(p);
    const double v2[2] = {v.x(), v.y()};
    std::unique_ptr<ceres::CostFunction> a(MakeAutoDiff(LevelSetAlignment(c6.data(), v2, inv_total)));
    const double before = Norm(Evaluate(*a, values));
    // Rotate + translate the frame: corners and v turn.
    std::vector<Vec2> q = p;
    for (Vec2& x : q) x = Rot(phi) * x + shift;
    const Vec2 vq = Rot(phi) * v;
    const std::vector<double> q6 = Corners6(q);
    const double vq2[2] = {vq.x(), vq.y()};
    std::unique_ptr<ceres::CostFunction> b(MakeAutoDiff(LevelSetAlignment(q6.data(), vq2, inv_total)));
    EXPECT_NEAR(before, Norm(Evaluate(*b, values)), 1e-10);
    // Scale by k: g scales by k, 1/A_Φ by 1/k².
    std::vector<Vec2> r = p;
    for (Vec2& x : r) x *= k;
    const std::vector<double> r6 = Corners6(r);
    std::unique_ptr<ceres::CostFunction> c(MakeAutoDiff(LevelSetAlignment(r6.data(), v2, inv_total / (k * k))));
    EXPECT_NEAR(before,
                Norm(Evaluate(*c, {{k * values[0][0]}, {k * values[1][0]}, {k * values[2][0]}})),
                1e-10);
  }
}

TEST(LevelSetNormalised, UnitGradientMinusRvAndInvariances) {
  std::mt19937 rng(kSeed + 9);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), scale(0.2, 5.0);
  for (int s = 0; s < kNumSamples; ++s) {
    const std::vector<Vec2> p = RandomTriangle(rng);
    const std::vector<double> c6 = Corners6(p);
    const Vec2 v = Vec2(g(rng), g(rng)) * 3.0;  // any length: normalised
    const double v2[2] = {v.x(), v.y()}, inv_total = 0.5;
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(LevelSetNormalised(c6.data(), v2, inv_total, 1.0)));
    const double th = angle(rng);
    const Vec2 a = scale(rng) * Vec2(std::cos(th), std::sin(th));
    const Vec2 rv = Vec2(-v.y(), v.x()).normalized();
    const Vec2 expected = std::sqrt(Area(p) * inv_total) * (a.normalized() - rv);
    const std::vector<double> r = Evaluate(*cost, Linear(p, a, g(rng)));
    EXPECT_NEAR(r[0], expected.x(), 1e-10);
    EXPECT_NEAR(r[1], expected.y(), 1e-10);
    // ‖r‖² = (A/A_Φ)·4 sin²(θ/2), θ the angle between ∇g and R v: the paper's
    // sin²θ to second order.
    const double theta = std::acos(std::clamp(a.normalized().dot(rv), -1.0, 1.0));
    EXPECT_NEAR(Norm(r), std::sqrt(Area(p) * inv_total) * 2 * std::sin(theta / 2), 1e-9);
    // Zero for ∇g along +R v, whatever ‖∇g‖ (eq. 5's minimiser with any
    // spacing); the folded gradient −R v costs the most (the paper's sin²θ
    // would be 0 there). (ε² / ‖∇g‖² ≈ 1e-12 is the regularisation's share.)
    EXPECT_NEAR(Norm(Evaluate(*cost, Linear(p, 0.37 * Vec2(-v.y(), v.x()), 1.0))), 0.0, 1e-10);
    EXPECT_NEAR(Norm(Evaluate(*cost, Linear(p, -0.37 * Vec2(-v.y(), v.x()), 1.0))),
                2 * std::sqrt(Area(p) * inv_total), 1e-9);
    // g → k g + b (k > 0): unchanged up to ε.
    const Blocks values = {{g(rng)}, {g(rng)}, {g(rng)}};
    const double k = scale(rng);
    const std::vector<double> r1 = Evaluate(*cost, values);
    const std::vector<double> r2 = Evaluate(
        *cost, {{k * values[0][0] + 1}, {k * values[1][0] + 1}, {k * values[2][0] + 1}});
    EXPECT_NEAR(r1[0], r2[0], 1e-8);
    EXPECT_NEAR(r1[1], r2[1], 1e-8);
    ExpectGradientsMatch(*cost, values);
  }
  // Rigid motion of the frame (corners and v turn and shift): ‖r‖ unchanged.
  for (int s = 0; s < kNumSamples; ++s) {
    const std::vector<Vec2> p = RandomTriangle(rng);
    const Vec2 v(g(rng), g(rng)), shift(g(rng), g(rng));
    const Blocks values = {{g(rng)}, {g(rng)}, {g(rng)}};
    const double phi = angle(rng);
    std::vector<Vec2> q = p;
    for (Vec2& x : q) x = Rot(phi) * x + shift;
    const Vec2 vq = Rot(phi) * v;
    const std::vector<double> p6 = Corners6(p), q6 = Corners6(q);
    const double vp[2] = {v.x(), v.y()}, vqb[2] = {vq.x(), vq.y()};
    std::unique_ptr<ceres::CostFunction> a(MakeAutoDiff(LevelSetNormalised(p6.data(), vp, 0.5, 1.0)));
    std::unique_ptr<ceres::CostFunction> b(MakeAutoDiff(LevelSetNormalised(q6.data(), vqb, 0.5, 1.0)));
    EXPECT_NEAR(Norm(Evaluate(*a, values)), Norm(Evaluate(*b, values)), 1e-10);
    EXPECT_GT(Norm(Evaluate(*a, values)), 1e-6);
  }
  // Constant g: finite (regularised), ‖r‖ = sqrt(A/A_Φ).
  const std::vector<double> c6 = {0, 0, 1, 0, 0, 1};
  const double v2[2] = {1, 0};
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(LevelSetNormalised(c6.data(), v2, 1.0, 1.0)));
  ExpectFiniteEverywhere(*cost, {{2.0}, {2.0}, {2.0}});
  EXPECT_NEAR(Norm(Evaluate(*cost, {{2.0}, {2.0}, {2.0}})), std::sqrt(0.5), 1e-12);
}

TEST(LevelSetConjugacy, PrincipalLevelSetsAreConjugateAndTheAnalyticValue) {
  // Unit right triangle, g = x, h = y: level-set tangents t_g = R e1 = e2,
  // t_h = R e2 = −e1; r = sqrt(A)·e2ᵀ M (−e1) = −sqrt(A) m12.
  const std::vector<Vec2> p = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)};
  const std::vector<double> c6 = Corners6(p);
  const Blocks g = Linear(p, Vec2(1, 0), 0.0), h = Linear(p, Vec2(0, 1), 0.0);
  const double diag[3] = {1.5, 0.0, -0.7}, off[3] = {1.5, 0.4, -0.7};
  std::unique_ptr<ceres::CostFunction> c1(MakeAutoDiff(LevelSetConjugacy(c6.data(), diag, 1.0)));
  std::unique_ptr<ceres::CostFunction> c2(MakeAutoDiff(LevelSetConjugacy(c6.data(), off, 1.0)));
  const Blocks all = {g[0], g[1], g[2], h[0], h[1], h[2]};
  EXPECT_NEAR(Evaluate(*c1, all)[0], 0.0, kTolerance);
  EXPECT_NEAR(Evaluate(*c2, all)[0], -std::sqrt(0.5) * 0.4, 1e-10);
}

TEST(LevelSetConjugacy, GradientsAndInvariances) {
  std::mt19937 rng(kSeed + 10);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), scale(0.2, 5.0);
  for (int s = 0; s < kNumSamples; ++s) {
    const std::vector<Vec2> p = RandomTriangle(rng);
    Eigen::Matrix2d M;
    M << g(rng), g(rng), 0, g(rng);
    M(1, 0) = M(0, 1);
    const double m[3] = {M(0, 0), M(0, 1), M(1, 1)};
    const std::vector<double> c6 = Corners6(p);
    const Blocks vals = {{g(rng)}, {g(rng)}, {g(rng)}, {g(rng)}, {g(rng)}, {g(rng)}};
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(LevelSetConjugacy(c6.data(), m, 1.0)));
    ExpectGradientsMatch(*cost, vals);
    const double before = Evaluate(*cost, vals)[0];
    // Rotated frame: corners turn by φ, M → R M Rᵀ in the new coordinates.
    const double phi = angle(rng), k = scale(rng);
    std::vector<Vec2> q = p;
    for (Vec2& x : q) x = Rot(phi) * x;
    const Eigen::Matrix2d Mq = Rot(phi) * M * Rot(phi).transpose();
    const double mq[3] = {Mq(0, 0), Mq(0, 1), Mq(1, 1)};
    const std::vector<double> q6 = Corners6(q);
    std::unique_ptr<ceres::CostFunction> turned(MakeAutoDiff(LevelSetConjugacy(q6.data(), mq, 1.0)));
    EXPECT_NEAR(before, Evaluate(*turned, vals)[0], 1e-10);
    // Scaled by k: M/k, g and h times k.
    std::vector<Vec2> r = p;
    for (Vec2& x : r) x *= k;
    const double mr[3] = {m[0] / k, m[1] / k, m[2] / k};
    const std::vector<double> r6 = Corners6(r);
    std::unique_ptr<ceres::CostFunction> scaled(MakeAutoDiff(LevelSetConjugacy(r6.data(), mr, 1.0)));
    Blocks kv = vals;
    for (auto& b : kv) b[0] *= k;
    EXPECT_NEAR(before, Evaluate(*scaled, kv)[0], 1e-8);
    // Swapping g and h.
    EXPECT_NEAR(before, Evaluate(*cost, {vals[3], vals[4], vals[5], vals[0], vals[1], vals[2]})[0],
                1e-10);
  }
  // Constant g: finite.
  const std::vector<double> c6 = {0, 0, 1, 0, 0, 1};
  const double m[3] = {1, 0.2, 0.5};
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(LevelSetConjugacy(c6.data(), m, 1.0)));
  ExpectFiniteEverywhere(*cost, {{1.0}, {1.0}, {1.0}, {0.0}, {1.0}, {2.0}});
}

TEST(LevelSetJump, BothSignsValuesAndGradients) {
  std::unique_ptr<ceres::CostFunction> minus(MakeAutoDiff(LevelSetJump(-1, 0.5)));
  std::unique_ptr<ceres::CostFunction> plus(MakeAutoDiff(LevelSetJump(+1, 0.5)));
  // g_left = α − g_right: 3 = 5 − 2.
  EXPECT_NEAR(Evaluate(*minus, {{3.0}, {2.0}, {5.0}})[0], 0.0, kTolerance);
  EXPECT_NEAR(Evaluate(*minus, {{3.0}, {2.0}, {4.0}})[0], 0.5, kTolerance);
  // g_left = α + g_right: 7 = 5 + 2.
  EXPECT_NEAR(Evaluate(*plus, {{7.0}, {2.0}, {5.0}})[0], 0.0, kTolerance);
  EXPECT_NEAR(Evaluate(*plus, {{7.0}, {3.0}, {5.0}})[0], -0.5, kTolerance);
  ExpectGradientsMatch(*minus, {{0.3}, {1.7}, {-0.4}});
  ExpectGradientsMatch(*plus, {{0.3}, {1.7}, {-0.4}});
  // Shift g by c on both sides, α by (1 − s)c: unchanged.
  EXPECT_NEAR(Evaluate(*minus, {{3.0 + 1.1}, {2.0 + 1.1}, {5.0 + 2.2}})[0], 0.0, kTolerance);
}

TEST(LevelSetBranchPoint, SourceVertexOfAHalfSingularityCut) {
  std::unique_ptr<ceres::CostFunction> half(MakeAutoDiff(LevelSetBranchPoint(-1, 2.0)));
  std::unique_ptr<ceres::CostFunction> whole(MakeAutoDiff(LevelSetBranchPoint(+1, 2.0)));
  // g(v0) = α/2.
  EXPECT_NEAR(Evaluate(*half, {{1.5}, {3.0}})[0], 0.0, kTolerance);
  EXPECT_NEAR(Evaluate(*half, {{1.0}, {3.0}})[0], -2.0, kTolerance);
  // s = +1: α = 0 whatever g.
  EXPECT_NEAR(Evaluate(*whole, {{1.0}, {0.0}})[0], 0.0, kTolerance);
  EXPECT_NEAR(Evaluate(*whole, {{1.0}, {0.25}})[0], -0.5, kTolerance);
  ExpectGradientsMatch(*half, {{0.3}, {1.7}});
  ExpectGradientsMatch(*whole, {{0.3}, {1.7}});
}

// ---------------------------------------------------------------- principal_fit, principal_smoothing

TEST(PrincipalFit, GradientsMatchNumericDifferences) {
  std::mt19937 rng(kSeed + 40);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), weight(0.1, 3.0);
  for (int s = 0; s < kNumSamples; ++s) {
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(PrincipalFit(angle(rng), weight(rng))));
    ExpectGradientsMatch(*cost, {{angle(rng)}});
  }
}

TEST(PrincipalFit, VanishesOnTheMeasuredLineAndHasTheAnalyticValue) {
  const double theta0 = 0.4, w = 2.0;
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(PrincipalFit(theta0, w)));
  EXPECT_LT(Norm(Evaluate(*cost, {{theta0}})), kTolerance);
  EXPECT_LT(Norm(Evaluate(*cost, {{theta0 + M_PI}})), kTolerance);  // a line: θ ≡ θ + π
  // A line turned by 90°: the doubled angles are opposite, ‖r‖ = 2 sqrt(w).
  EXPECT_NEAR(Norm(Evaluate(*cost, {{theta0 + M_PI / 2}})), 2 * std::sqrt(w), kTolerance);
  // Turned by δ: ‖r‖ = 2 sqrt(w) |sin δ|.
  EXPECT_NEAR(Norm(Evaluate(*cost, {{theta0 + 0.3}})), 2 * std::sqrt(w) * std::sin(0.3), kTolerance);
}

TEST(PrincipalFit, IndependentOfTheFaceFrame) {
  std::mt19937 rng(kSeed + 41);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  for (int s = 0; s < kNumSamples; ++s) {
    const double theta0 = angle(rng), theta = angle(rng), phi = angle(rng);
    std::unique_ptr<ceres::CostFunction> a(MakeAutoDiff(PrincipalFit(theta0, 1.5)));
    std::unique_ptr<ceres::CostFunction> b(MakeAutoDiff(PrincipalFit(theta0 - phi, 1.5)));
    EXPECT_NEAR(Norm(Evaluate(*a, {{theta}})), Norm(Evaluate(*b, {{theta - phi}})), kTolerance);
  }
}

TEST(PrincipalSmoothing, GradientsMatchNumericDifferences) {
  std::mt19937 rng(kSeed + 42);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), weight(0.1, 3.0);
  for (int s = 0; s < kNumSamples; ++s) {
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(PrincipalSmoothing(angle(rng), weight(rng))));
    ExpectGradientsMatch(*cost, {{angle(rng)}, {angle(rng)}});
  }
}

TEST(PrincipalSmoothing, VanishesForTheTransportedLineAndHasTheAnalyticValue) {
  const double tau = 0.7, w = 2.5;
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(PrincipalSmoothing(tau, w)));
  // The line at θ_g in g's frame is at θ_g + τ in f's.
  EXPECT_LT(Norm(Evaluate(*cost, {{0.2 + tau}, {0.2}})), kTolerance);
  EXPECT_LT(Norm(Evaluate(*cost, {{0.2 + tau - M_PI}, {0.2}})), kTolerance);
  // Off by 90°: ‖r‖ = 2 sqrt(w).
  EXPECT_NEAR(Norm(Evaluate(*cost, {{0.2 + tau + M_PI / 2}, {0.2}})), 2 * std::sqrt(w), kTolerance);
}

TEST(PrincipalSmoothing, IndependentOfTheFaceFrames) {
  std::mt19937 rng(kSeed + 43);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  for (int s = 0; s < kNumSamples; ++s) {
    const double tau = angle(rng), tf = angle(rng), tg = angle(rng), phi_f = angle(rng),
                 phi_g = angle(rng);
    std::unique_ptr<ceres::CostFunction> a(MakeAutoDiff(PrincipalSmoothing(tau, 1.2)));
    std::unique_ptr<ceres::CostFunction> b(MakeAutoDiff(PrincipalSmoothing(tau + phi_g - phi_f, 1.2)));
    const double before = Norm(Evaluate(*a, {{tf}, {tg}}));
    EXPECT_NEAR(before, Norm(Evaluate(*b, {{tf - phi_f}, {tg - phi_g}})), kTolerance);
    std::unique_ptr<ceres::CostFunction> c(MakeAutoDiff(PrincipalSmoothing(-tau, 1.2)));
    EXPECT_NEAR(before, Norm(Evaluate(*c, {{tg}, {tf}})), kTolerance);
  }
}

}  // namespace
}  // namespace archgeo
