// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for the A-net / H-net energies [Shi, Wang, Pottmann 2014, §3.2]:
// energies/anet_planarity (vertex-normal and quad variants),
// energies/frame_coplanarity and the third-difference fairness of
// energies/fairness:
//  (a) autodiff Jacobians against numeric differences (ceres::GradientChecker,
//      typed null manifolds, and a SphereManifold on the vertex normal);
//  (b) degenerate inputs (coincident points, collinear stars) are finite;
//  (c) invariance under rigid motions and uniform scaling;
//  (d) zero on exactly planar stars / exactly smooth joins, non-zero otherwise,
//      known values.
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <ceres/cost_function.h>
#include <ceres/gradient_checker.h>
#include <ceres/manifold.h>
#include <ceres/sphere_manifold.h>
#include <gtest/gtest.h>

#include "tests/energy_checks.h"
#include "energies/autodiff.h"

#include "energies/anet_planarity.h"
#include "energies/fairness.h"
#include "energies/frame_coplanarity.h"
#include "energies/pq_diagonal.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

constexpr unsigned kSeed = 20140301;
constexpr int kNumSamples = 25;
// Agreement of residuals that are equal in exact arithmetic.
constexpr double kTolerance = 1e-10;
// A residual that must be clearly non-zero (perturbations are >= 0.05 L).
constexpr double kClearlyNonZero = 1e-3;
// Tangent-plane agreement of two rational bilinear patches measured with
// central differences of step kDifferenceStep (error ~ step² ≈ 1e-10).
constexpr double kDifferenceStep = 1e-5;
constexpr double kNormalTolerance = 1e-7;

using namespace energy_checks;

Blocks ToBlocks(const std::vector<Vec3>& points) {
  Blocks b;
  for (const Vec3& p : points) b.push_back(ToBlock(p));
  return b;
}

// A random vertex star: centre v, n neighbours in cyclic order around v at
// distance ~1 (angles evenly spread and jittered), lying in a random plane
// through v, then lifted off the plane by up to `lift` each; a random rigid
// placement. Returns {v, w_0, …, w_{n−1}} and the plane normal in *normal.
std::vector<Vec3> RandomStar(std::mt19937& rng, int n, double lift,
                             Vec3* normal = nullptr) {
  const Eigen::Matrix3d rot = RandomRotation(rng);
  const Vec3 shift = RandomVec(rng, 5.0);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  std::uniform_real_distribution<double> radius(0.7, 1.3);
  std::uniform_real_distribution<double> up(-lift, lift);
  std::vector<Vec3> star = {shift};
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * (i + jitter(rng)) / n;
    const double r = radius(rng);
    star.push_back(rot * Vec3(r * std::cos(a), r * std::sin(a), up(rng)) +
                   shift);
  }
  if (normal != nullptr) *normal = rot.col(2);
  return star;
}

double MeanSpoke(const std::vector<Vec3>& star) {
  double sum = 0.0;
  for (size_t i = 1; i < star.size(); ++i) sum += (star[i] - star[0]).norm();
  return sum / (star.size() - 1);
}

// ------------------------------------------------- anet_planarity: variant (i)

double NormalResidual(const Vec3& n, const Vec3& v, const Vec3& w,
                      double inv_length) {
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(AnetVertexNormal(inv_length)));
  return Evaluate(*cost, {ToBlock(n), ToBlock(v), ToBlock(w)})[0];
}

TEST(AnetVertexNormal, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed);
  ceres::SphereManifold<3> sphere;
  const std::vector<const ceres::Manifold*> with_sphere = {&sphere, nullptr,
                                                           nullptr};
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 n = RandomVec(rng, 1.0).normalized();
    const Vec3 v = RandomVec(rng, 5.0);
    std::unique_ptr<ceres::CostFunction> cost(
        MakeAutoDiff(AnetVertexNormal(1.0 / (0.5 + 0.1 * i))));
    const Blocks blocks = {ToBlock(n), ToBlock(v),
                           ToBlock(v + RandomVec(rng, 1.0))};
    SCOPED_TRACE(i);
    ExpectGradientsMatch(*cost, blocks);
    ExpectGradientsMatch(*cost, blocks, &with_sphere);
  }
}

TEST(AnetVertexNormal, DegenerateInputsAreFinite) {
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(AnetVertexNormal(1.0)));
  ExpectFiniteEverywhere(*cost, {{0, 0, 0}, {1, 2, 3}, {4, 5, 6}});  // n = 0
  ExpectFiniteEverywhere(*cost, {{0, 0, 1}, {1, 2, 3}, {1, 2, 3}});  // w = v
  ExpectFiniteEverywhere(*cost, {{0, 3, 4}, {1, 2, 3}, {7, 2, 3}});  // |n| ≠ 1
  EXPECT_EQ(Evaluate(*cost, {{0, 0, 0}, {1, 2, 3}, {4, 5, 6}})[0], 0.0);
  EXPECT_EQ(Evaluate(*cost, {{0, 0, 1}, {1, 2, 3}, {1, 2, 3}})[0], 0.0);
}

TEST(AnetVertexNormal, InvariantUnderRigidMotionAndScaling) {
  std::mt19937 rng(kSeed + 1);
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 n = RandomVec(rng, 1.0).normalized();
    const Vec3 v = RandomVec(rng, 5.0), w = v + RandomVec(rng, 1.0);
    const double inv_length = 1.0 / (0.5 + 0.1 * i);
    const double r = NormalResidual(n, v, w, inv_length);
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 shift = RandomVec(rng, 10.0);
    EXPECT_NEAR(
        NormalResidual(rot * n, rot * v + shift, rot * w + shift, inv_length),
        r, kTolerance);
    for (double s : {1e-3, 0.37, 1e3}) {
      EXPECT_NEAR(NormalResidual(n, s * v, s * w, inv_length / s), r,
                  kTolerance);
    }
    EXPECT_NEAR(NormalResidual(-n, v, w, inv_length), -r, kTolerance);
  }
}

TEST(AnetVertexNormal, ZeroOnPlanarStarsPositiveOtherwise) {
  std::mt19937 rng(kSeed + 2);
  for (int valence : {3, 4, 5, 6}) {
    for (int i = 0; i < 5; ++i) {
      Vec3 normal;
      const auto star = RandomStar(rng, valence, 0.0, &normal);
      const double inv_length = 1.0 / MeanSpoke(star);
      for (int k = 1; k <= valence; ++k) {
        EXPECT_NEAR(NormalResidual(normal, star[0], star[k], inv_length), 0.0,
                    kTolerance);
      }
    }
  }
  // Non-planar stars (valence >= 4): for every unit n the sum of squared
  // residuals is at least λ_min(Σ (w − v)(w − v)ᵀ) / L² > 0, with equality at
  // the eigenvector (the least-squares plane through v).
  for (int valence : {4, 6}) {
    for (int i = 0; i < 5; ++i) {
      const auto star = RandomStar(rng, valence, 0.2);
      const double inv_length = 1.0 / MeanSpoke(star);
      Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
      for (int k = 1; k <= valence; ++k) {
        const Vec3 e = star[k] - star[0];
        scatter += e * e.transpose();
      }
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);
      const double lambda_min = eig.eigenvalues()[0];
      ASSERT_GT(lambda_min, 1e-4);
      const auto energy = [&](const Vec3& n) {
        double sum = 0.0;
        for (int k = 1; k <= valence; ++k) {
          const double r = NormalResidual(n, star[0], star[k], inv_length);
          sum += r * r;
        }
        return sum;
      };
      EXPECT_NEAR(energy(eig.eigenvectors().col(0)),
                  lambda_min * inv_length * inv_length, kTolerance);
      for (int trial = 0; trial < 10; ++trial) {
        EXPECT_GE(energy(RandomVec(rng, 1.0).normalized()),
                  lambda_min * inv_length * inv_length - kTolerance);
      }
    }
  }
}

// ------------------------------------------------ anet_planarity: variant (ii)

double QuadResidual(const Vec3& b0, const Vec3& b1, const Vec3& b2,
                    const Vec3& b3, double inv_length) {
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(AnetStarQuad(inv_length)));
  return Evaluate(*cost, ToBlocks({b0, b1, b2, b3}))[0];
}

// Residuals of all n − 2 auxiliary quads of a star {v, w_0, …}.
std::vector<double> StarResiduals(const std::vector<Vec3>& star,
                                  double inv_length) {
  std::vector<double> r;
  for (const auto& q : AnetStarQuadNeighbours(static_cast<int>(star.size()) - 1)) {
    r.push_back(QuadResidual(star[0], star[1 + q[0]], star[1 + q[1]],
                             star[1 + q[2]], inv_length));
  }
  return r;
}

TEST(AnetStarQuad, QuadsOfAStar) {
  EXPECT_EQ(AnetStarQuadNeighbours(3),
            (std::vector<std::array<int, 3>>{{0, 1, 2}}));
  EXPECT_EQ(AnetStarQuadNeighbours(4),
            (std::vector<std::array<int, 3>>{{0, 1, 2}, {1, 2, 3}}));
  EXPECT_EQ(AnetStarQuadNeighbours(6).size(), 4u);
  EXPECT_EQ(AnetStarQuadNeighbours(6).back(), (std::array<int, 3>{3, 4, 5}));
}

TEST(AnetStarQuad, IsMinusPqDiagonalAndMatchesTheDefinition) {
  std::mt19937 rng(kSeed + 10);
  for (int i = 0; i < kNumSamples; ++i) {
    const auto star = RandomStar(rng, 4, 0.3);
    const double inv_length = 1.0 / MeanSpoke(star);
    const Vec3 &b0 = star[0], &b1 = star[1], &b2 = star[2], &b3 = star[3];
    const double r = QuadResidual(b0, b1, b2, b3, inv_length);
    std::unique_ptr<ceres::CostFunction> pq(MakeAutoDiff(PqDiagonal(inv_length)));
    EXPECT_NEAR(r, -Evaluate(*pq, ToBlocks({b0, b1, b2, b3}))[0], kTolerance);
    // Shi §3.2: n = unit(b02 × b13), d = (b0 + b2 − b1 − b3)/2, r = n·d / L.
    const Vec3 n = (b0 - b2).cross(b1 - b3).normalized();
    const Vec3 d = 0.5 * (b0 + b2 - b1 - b3);
    EXPECT_NEAR(r, n.dot(d) * inv_length, 1e-9);
  }
}

TEST(AnetStarQuad, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 11);
  for (int i = 0; i < kNumSamples; ++i) {
    const auto star = RandomStar(rng, 4, 0.3);
    std::unique_ptr<ceres::CostFunction> cost(
        MakeAutoDiff(AnetStarQuad(1.0 / MeanSpoke(star))));
    SCOPED_TRACE(i);
    ExpectGradientsMatch(*cost, ToBlocks({star[0], star[1], star[2], star[3]}));
    ExpectGradientsMatch(*cost, ToBlocks({star[0], star[2], star[3], star[4]}));
  }
}

TEST(AnetStarQuad, DegenerateInputsAreFinite) {
  const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const std::vector<std::vector<Vec3>> cases = {
      {o, x, 2 * x, -x},           // collinear star
      {o, x, -x, 3 * x},           // collinear star, other order
      {o, o, o, o},                // coincident
      {o, x, o, y},                // w_{i+1} = v: zero diagonal
      {o, x, y, x},                // w_i = w_{i+2}: zero diagonal
      {o, y, x + y, x + 2 * y + 1e-13 * z},  // nearly parallel diagonals
  };
  for (double inv_length : {1.0, 1e-3, 1e3}) {
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(AnetStarQuad(inv_length)));
    for (size_t i = 0; i < cases.size(); ++i) {
      SCOPED_TRACE(i);
      ExpectFiniteEverywhere(*cost, ToBlocks(cases[i]));
    }
    for (size_t i = 0; i < 5; ++i) {
      EXPECT_EQ(QuadResidual(cases[i][0], cases[i][1], cases[i][2],
                             cases[i][3], inv_length),
                0.0)
          << i;
    }
  }
}

TEST(AnetStarQuad, InvariantUnderRigidMotionAndScaling) {
  std::mt19937 rng(kSeed + 12);
  for (int i = 0; i < kNumSamples; ++i) {
    const auto star = RandomStar(rng, 6, 0.3);
    const double inv_length = 1.0 / MeanSpoke(star);
    const std::vector<double> r = StarResiduals(star, inv_length);
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 shift = RandomVec(rng, 10.0);
    std::vector<Vec3> moved, reversed = {star[0]};
    for (const Vec3& p : star) moved.push_back(rot * p + shift);
    for (int k = 6; k >= 1; --k) reversed.push_back(star[k]);
    const std::vector<double> r_moved = StarResiduals(moved, inv_length);
    const std::vector<double> r_reversed = StarResiduals(reversed, inv_length);
    for (size_t q = 0; q < r.size(); ++q) {
      EXPECT_NEAR(r_moved[q], r[q], kTolerance);
      // Reversed cyclic order: quad q becomes quad n − 3 − q, reversed.
      EXPECT_NEAR(r_reversed[r.size() - 1 - q], -r[q], kTolerance);
    }
    for (double s : {1e-3, 0.37, 1e3}) {
      std::vector<Vec3> scaled;
      for (const Vec3& p : star) scaled.push_back(s * p);
      const std::vector<double> r_scaled = StarResiduals(scaled, inv_length / s);
      for (size_t q = 0; q < r.size(); ++q) {
        EXPECT_NEAR(r_scaled[q], r[q], kTolerance) << s;
      }
    }
  }
}

TEST(AnetStarQuad, ZeroOnPlanarStarsNonZeroOtherwise) {
  std::mt19937 rng(kSeed + 13);
  for (int valence : {4, 6}) {
    for (int i = 0; i < 10; ++i) {
      Vec3 normal;
      const auto star = RandomStar(rng, valence, 0.0, &normal);
      const double inv_length = 1.0 / MeanSpoke(star);
      for (double r : StarResiduals(star, inv_length)) {
        EXPECT_NEAR(r, 0.0, kTolerance);
      }
      // Lifting any one vertex of the star off the plane makes some
      // auxiliary quad non-planar: the n − 2 quads detect every deviation.
      for (int k = 0; k <= valence; ++k) {
        std::vector<Vec3> lifted = star;
        lifted[k] += 0.1 * normal / inv_length;
        double largest = 0.0;
        for (double r : StarResiduals(lifted, inv_length)) {
          largest = std::max(largest, std::abs(r));
        }
        EXPECT_GT(largest, kClearlyNonZero) << valence << " " << k;
      }
    }
  }
}

TEST(AnetStarQuad, KnownValues) {
  // The star of z = x y at (x0, y0) with spacing h (an exact A-net): zero.
  for (double h : {0.1, 0.5}) {
    const double x0 = 0.3, y0 = -0.7;
    const auto p = [](double x, double y) { return Vec3(x, y, x * y); };
    const std::vector<Vec3> star = {p(x0, y0), p(x0 + h, y0), p(x0, y0 + h),
                                    p(x0 - h, y0), p(x0, y0 - h)};
    for (double r : StarResiduals(star, 1.0 / h)) {
      EXPECT_NEAR(r, 0.0, kTolerance);
    }
  }
  // v = 0, w = (1,0,0), (0,1,h), (−1,0,0), (0,−1,0): the first quad is
  // planar (v, w_0, w_2 collinear), the second has diagonals along the x axis
  // and through (0,±1,·): r = −h / sqrt(h² + 4) / L.
  for (double h : {1.0, 0.3, -2.0}) {
    const std::vector<Vec3> star = {Vec3(0, 0, 0), Vec3(1, 0, 0),
                                    Vec3(0, 1, h), Vec3(-1, 0, 0),
                                    Vec3(0, -1, 0)};
    const std::vector<double> r = StarResiduals(star, 0.5);
    EXPECT_NEAR(r[0], 0.0, kTolerance);
    EXPECT_NEAR(r[1], -h / std::sqrt(h * h + 4.0) * 0.5, 1e-12);
  }
}

// ---------------------------------------------------------- frame_coplanarity

struct Join {
  std::vector<Vec3> b;  // b0 … b5 (Shi Fig. 2)
  double w1, w2, w4, w5;
};

double FrameResidual(const Join& j, double inv_length) {
  std::unique_ptr<ceres::CostFunction> cost(
      MakeAutoDiff(FrameCoplanarity(j.w1, j.w2, j.w4, j.w5, inv_length)));
  return Evaluate(*cost, ToBlocks(j.b))[0];
}

double Det(const Vec3& a, const Vec3& b, const Vec3& c) {
  return a.dot(b.cross(c));
}

// An exactly smooth join (Shi Prop. 1): planar stars at b0 (b0, b1, b3, b5)
// and at b3 (b0, b2, b3, b4), w1 = w5 = 1, w2 random and w4 from eq. (5);
// randomly placed. The two planes through the edge b0b3 differ.
Join SmoothJoin(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.6, 1.4);
  const Vec3 b0(0, 0, 0), b3(0, 1, 0);
  // T0 = the xy plane; T3 = the plane through the y axis tilted about it.
  const double tilt = 0.5 + 0.3 * u(rng);
  const Vec3 e3(std::cos(tilt), 0, std::sin(tilt));
  const Vec3 b1 = Vec3(u(rng), 0.2 * u(rng) - 0.1, 0);       // T0, x > 0
  const Vec3 b5 = Vec3(-u(rng), 0.2 * u(rng) - 0.1, 0);      // T0, x < 0
  const Vec3 b2 = b3 + u(rng) * e3 + Vec3(0, 0.2 * u(rng) - 0.1, 0);   // T3
  const Vec3 b4 = b3 - u(rng) * e3 + Vec3(0, 0.2 * u(rng) - 0.1, 0);   // T3
  Join j;
  j.w1 = 1.0;
  j.w5 = 1.0;
  j.w2 = u(rng);
  j.w4 = j.w2 * Det(b3 - b0, b5 - b0, b2 - b0) / Det(b3 - b0, b1 - b0, b4 - b0);
  EXPECT_GT(j.w4, 0.0);  // equitwist (Remark 2)
  const Eigen::Matrix3d rot = RandomRotation(rng);
  const Vec3 shift = RandomVec(rng, 5.0);
  for (const Vec3& p : {b0, b1, b2, b3, b4, b5}) j.b.push_back(rot * p + shift);
  return j;
}

// Rational bilinear patch (Shi eq. 1), corners c0 … c3 with weights ω0 … ω3.
Vec3 Patch(const Vec3 c[4], const double w[4], double u, double v) {
  const double k[4] = {(1 - u) * (1 - v) * w[0], u * (1 - v) * w[1],
                       u * v * w[2], (1 - u) * v * w[3]};
  Vec3 num = Vec3::Zero();
  double den = 0.0;
  for (int i = 0; i < 4; ++i) {
    num += k[i] * c[i];
    den += k[i];
  }
  return num / den;
}

Vec3 PatchNormal(const Vec3 c[4], const double w[4], double u, double v) {
  const double e = kDifferenceStep;
  const Vec3 xu = (Patch(c, w, u + e, v) - Patch(c, w, u - e, v)) / (2 * e);
  const Vec3 xv = (Patch(c, w, u, v + e) - Patch(c, w, u, v - e)) / (2 * e);
  return xu.cross(xv).normalized();
}

// Largest |sin| of the angle between the two patches' normals at points of
// the common edge b0b3 (the patches extend smoothly past u, v = 0, so central
// differences there are fine).
double JoinKink(const Join& j) {
  // Left patch (b0, b1, b2, b3), weights (1, w1, w2, 1): edge b0b3 is u = 0.
  const Vec3 left[4] = {j.b[0], j.b[1], j.b[2], j.b[3]};
  const double wl[4] = {1.0, j.w1, j.w2, 1.0};
  // Right patch (b0, b3, b4, b5), weights (1, 1, w4, w5): edge b0b3 is v = 0.
  const Vec3 right[4] = {j.b[0], j.b[3], j.b[4], j.b[5]};
  const double wr[4] = {1.0, 1.0, j.w4, j.w5};
  double kink = 0.0;
  for (double a : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    const Vec3 nl = PatchNormal(left, wl, 0.0, a);
    const Vec3 nr = PatchNormal(right, wr, a, 0.0);
    kink = std::max(kink, nl.cross(nr).norm());
  }
  return kink;
}

TEST(FrameCoplanarity, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 20);
  std::uniform_real_distribution<double> weight(0.3, 3.0);
  for (int i = 0; i < kNumSamples; ++i) {
    Join j = SmoothJoin(rng);
    for (Vec3& p : j.b) p += RandomVec(rng, 0.2);
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(FrameCoplanarity(weight(rng), weight(rng), weight(rng), weight(rng), 1.0)));
    SCOPED_TRACE(i);
    ExpectGradientsMatch(*cost, ToBlocks(j.b));
  }
}

TEST(FrameCoplanarity, DegenerateInputsAreFinite) {
  const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0);
  const std::vector<std::vector<Vec3>> cases = {
      {o, x, 2 * x, 3 * x, 4 * x, 5 * x},  // all collinear
      {o, o, o, o, o, o},                  // all coincident
      {o, x, x + y, o, -x, -x - y},        // b0 = b3
      {o, x, y, y, x, y},                  // f1 = f4 (equal weights)
      {o, x, x + y, y, -x + y, -x},        // all six coplanar
  };
  for (double inv_length : {1.0, 1e-3, 1e3}) {
    std::unique_ptr<ceres::CostFunction> cost(
        MakeAutoDiff(FrameCoplanarity(1.0, 1.0, 1.0, 1.0, inv_length)));
    for (size_t i = 0; i < cases.size(); ++i) {
      SCOPED_TRACE(i);
      ExpectFiniteEverywhere(*cost, ToBlocks(cases[i]));
      EXPECT_EQ(Evaluate(*cost, ToBlocks(cases[i]))[0], 0.0);
    }
  }
}

TEST(FrameCoplanarity, InvariantUnderRigidMotionScalingAndRelabelling) {
  std::mt19937 rng(kSeed + 21);
  std::uniform_real_distribution<double> weight(0.3, 3.0);
  for (int i = 0; i < kNumSamples; ++i) {
    Join j = SmoothJoin(rng);
    for (Vec3& p : j.b) p += RandomVec(rng, 0.2);
    j.w1 = weight(rng);
    j.w2 = weight(rng);
    j.w4 = weight(rng);
    j.w5 = weight(rng);
    const double inv_length = 1.0 / (j.b[3] - j.b[0]).norm();
    const double r = FrameResidual(j, inv_length);
    EXPECT_GT(std::abs(r), 1e-6);
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 shift = RandomVec(rng, 10.0);
    Join moved = j;
    for (Vec3& p : moved.b) p = rot * p + shift;
    EXPECT_NEAR(FrameResidual(moved, inv_length), r, kTolerance);
    for (double s : {1e-3, 0.37, 1e3}) {
      Join scaled = j;
      for (Vec3& p : scaled.b) p *= s;
      EXPECT_NEAR(FrameResidual(scaled, inv_length / s), r, kTolerance) << s;
    }
    // Only the weight ratios per edge enter.
    Join reweighted = j;
    reweighted.w1 *= 2.5;
    reweighted.w2 *= 2.5;
    reweighted.w4 *= 0.1;
    reweighted.w5 *= 0.1;
    EXPECT_NEAR(FrameResidual(reweighted, inv_length), r, kTolerance);
    // Exchanging the patches flips the sign.
    Join exchanged;
    exchanged.b = {j.b[0], j.b[5], j.b[4], j.b[3], j.b[2], j.b[1]};
    exchanged.w1 = j.w5;
    exchanged.w2 = j.w4;
    exchanged.w4 = j.w2;
    exchanged.w5 = j.w1;
    EXPECT_NEAR(FrameResidual(exchanged, inv_length), -r, kTolerance);
  }
}

TEST(FrameCoplanarity, ZeroExactlyOnSmoothJoins) {
  std::mt19937 rng(kSeed + 22);
  for (int i = 0; i < 10; ++i) {
    const Join j = SmoothJoin(rng);
    const double inv_length = 1.0 / (j.b[3] - j.b[0]).norm();
    // Eq. (5) with planar stars: frame points coplanar with b0b3 ...
    EXPECT_NEAR(FrameResidual(j, inv_length), 0.0, kTolerance) << i;
    // ... and the rational bilinear patches really share tangent planes
    // along the whole edge (independent check of Shi Prop. 1).
    EXPECT_LT(JoinKink(j), kNormalTolerance) << i;
    // A wrong weight: the frame points leave the plane and the join kinks.
    Join wrong = j;
    wrong.w4 *= 1.5;
    EXPECT_GT(std::abs(FrameResidual(wrong, inv_length)), kClearlyNonZero);
    EXPECT_GT(JoinKink(wrong), kClearlyNonZero);
    // Moving b1 out of the star plane T0 (weights kept): non-zero as well.
    Join moved = j;
    const Vec3 t0 = (j.b[3] - j.b[0]).cross(j.b[1] - j.b[0]).normalized();
    moved.b[1] += 0.2 * t0 / inv_length;
    EXPECT_GT(std::abs(FrameResidual(moved, inv_length)), kClearlyNonZero);
  }
}

TEST(FrameCoplanarity, KnownValue) {
  // b0 = 0, b3 = (0,1,0); f1 = (1, ½, 0) (w1 = w2 on b1 = (1,0,0),
  // b2 = (1,1,0)); f4 = (−1, ½, h) (w4 = w5 on b4 = (−1,1,h), b5 = (−1,0,h)).
  // Quad (b0, f1, b3, f4): c = b03 × (f1 − f4) = (h, 0, 2),
  // d = (b0 + b3 − f1 − f4)/2 = (0, 0, −h/2), so r = n·d / L with
  // n·d = −h / sqrt(h² + 4), the distance of the diagonal lines.
  for (double h : {0.5, -1.0, 2.0}) {
    const Join j = {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0),
                     Vec3(0, 1, 0), Vec3(-1, 1, h), Vec3(-1, 0, h)},
                    1.0, 1.0, 1.0, 1.0};
    const Vec3 c = (Vec3(0, 0, 0) - Vec3(0, 1, 0))
                       .cross(Vec3(1, 0.5, 0) - Vec3(-1, 0.5, h));
    const double expected = c.normalized().dot(Vec3(0, 0, -0.5 * h));
    EXPECT_NEAR(std::abs(expected), std::abs(h) / std::sqrt(h * h + 4.0),
                1e-12);
    EXPECT_NEAR(FrameResidual(j, 2.0), 2.0 * expected, 1e-12);
  }
}

// ---------------------------------------------------- fairness: third order

std::vector<double> ThirdResidual(const Vec3& target, double inv_length,
                                  const std::vector<Vec3>& p) {
  std::unique_ptr<ceres::CostFunction> cost(
      MakeAutoDiff(FairnessThird(target.data(), inv_length)));
  return Evaluate(*cost, ToBlocks(p));
}

TEST(FairnessThird, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 30);
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 target = RandomVec(rng, 0.3);
    std::unique_ptr<ceres::CostFunction> cost(
        MakeAutoDiff(FairnessThird(target.data(), 1.0 / (0.5 + 0.1 * i))));
    const Vec3 v = RandomVec(rng, 5.0);
    SCOPED_TRACE(i);
    ExpectGradientsMatch(*cost, ToBlocks({v, v + RandomVec(rng, 1.0),
                                          v + RandomVec(rng, 2.0),
                                          v + RandomVec(rng, 3.0)}));
  }
}

TEST(FairnessThird, DegenerateInputsAreFinite) {
  const double zero[3] = {0, 0, 0};
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(FairnessThird(zero, 1.0)));
  const Vec3 a(1, 2, 3);
  ExpectFiniteEverywhere(*cost, ToBlocks({a, a, a, a}));  // coincident
  EXPECT_EQ(AsVec(Evaluate(*cost, ToBlocks({a, a, a, a}))).norm(), 0.0);
  ExpectFiniteEverywhere(*cost, ToBlocks({a, 2 * a, 3 * a, 7 * a}));
  // Constant Jacobians −I/L, 3I/L, −3I/L, I/L.
  Blocks jac;
  Evaluate(*cost, ToBlocks({a, 2 * a, 3 * a, 7 * a}), &jac);
  const double diagonal[4] = {-1.0, 3.0, -3.0, 1.0};
  for (int b = 0; b < 4; ++b) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(jac[b][3 * r + c], r == c ? diagonal[b] : 0.0);
      }
    }
  }
}

TEST(FairnessThird, InvariantUnderRigidMotionAndScaling) {
  std::mt19937 rng(kSeed + 31);
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 target = RandomVec(rng, 0.3);
    const double inv_length = 1.0 / (0.5 + 0.1 * i);
    std::vector<Vec3> p;
    for (int k = 0; k < 4; ++k) p.push_back(RandomVec(rng, 3.0));
    const Vec3 r = AsVec(ThirdResidual(target, inv_length, p));
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 shift = RandomVec(rng, 10.0);
    std::vector<Vec3> moved, reversed(p.rbegin(), p.rend());
    for (const Vec3& x : p) moved.push_back(rot * x + shift);
    EXPECT_NEAR((AsVec(ThirdResidual(rot * target, inv_length, moved)) - rot * r)
                    .norm(),
                0.0, kTolerance);
    for (double s : {1e-3, 0.37, 1e3}) {
      std::vector<Vec3> scaled;
      for (const Vec3& x : p) scaled.push_back(s * x);
      EXPECT_NEAR(
          (AsVec(ThirdResidual(s * target, inv_length / s, scaled)) - r).norm(),
          0.0, kTolerance)
          << s;
    }
    EXPECT_NEAR(
        (AsVec(ThirdResidual(-target, inv_length, reversed)) + r).norm(), 0.0,
        kTolerance);
  }
}

TEST(FairnessThird, KnownValues) {
  const Vec3 zero(0, 0, 0);
  // An evenly sampled parabola: zero (second differences are not).
  const Vec3 a(1, -2, 0.5), b(0.3, 0.7, -0.2), c(-0.4, 0.1, 0.9);
  std::vector<Vec3> parabola;
  for (int k = 0; k < 4; ++k) parabola.push_back(a + k * b + k * k * c);
  EXPECT_NEAR(AsVec(ThirdResidual(zero, 2.0, parabola)).norm(), 0.0,
              kTolerance);
  // p_k = k³ e: Δ³ = 6 e.
  const Vec3 e(0.5, -1.0, 2.0);
  std::vector<Vec3> cubic;
  for (int k = -1; k < 3; ++k) cubic.push_back(double(k * k * k) * e);
  EXPECT_NEAR((AsVec(ThirdResidual(zero, 0.25, cubic)) - 1.5 * e).norm(), 0.0,
              kTolerance);
  // Target = own third difference: zero (relative fairness).
  EXPECT_NEAR(AsVec(ThirdResidual(6.0 * e, 0.25, cubic)).norm(), 0.0,
              kTolerance);
  // The functor matches the factory.
  const double pts[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1}};
  double r[3];
  const double target[3] = {0, 0, 0};
  ASSERT_TRUE(FairnessThird(target, 1.0)(pts[0], pts[1], pts[2], pts[3], r));
  // d − 3c + 3b − a = (0,1,1) − (3,3,0) + (3,0,0) − 0 = (0, −2, 1).
  EXPECT_NEAR((Vec3(r[0], r[1], r[2]) - Vec3(0, -2, 1)).norm(), 0.0,
              kTolerance);
}

}  // namespace
}  // namespace archgeo
