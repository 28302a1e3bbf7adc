// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for the visual-smoothness energies of Pellis 2019
// (energies/dihedral_energy, total_absolute_curvature, principal_symmetric):
//  (a) autodiff Jacobians against numeric differences (ceres::GradientChecker,
//      SphereManifold<3> on unit-vector blocks) away from the singular sets;
//  (b) singular configurations give finite residuals and Jacobians;
//  (c) known values: hinge of two triangles with angle α, W′ on a sphere and
//      a cylinder, exact principal-symmetric configurations;
//  (d) invariance under rigid motions and uniform scaling (with L scaled).
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <ceres/cost_function.h>
#include <ceres/gradient_checker.h>
#include <ceres/manifold.h>
#include <ceres/sphere_manifold.h>
#include <gtest/gtest.h>

#include "tests/energy_checks.h"
#include "energies/autodiff.h"

#include "energies/dihedral_energy.h"
#include "energies/co_spherical.h"
#include "energies/principal_strip.h"
#include "energies/saddle_sign.h"
#include "energies/total_absolute_curvature.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

constexpr unsigned kSeed = 20190731;
constexpr int kNumSamples = 20;
// Agreement of quantities that are equal in exact arithmetic.
constexpr double kTolerance = 1e-10;
// Relative effect of the normal regularisation, ½(ε_n L²/‖c‖)² ≈ 1e-12 for
// well-shaped unit triangles, plus rounding.
constexpr double kRegularisedTolerance = 1e-9;
// λ with vs without the half-gap regularisation ε_g L: differ by ≤ ε_g L.
constexpr double kGapTolerance = 2e-6;

using namespace energy_checks;

Vec3 RandomUnit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Vec3(g(rng), g(rng), g(rng)).normalized();
}

// ============================================================ dihedral_energy

Vec3 TriTriResidual(const Hinge& h, double inv_length, double omega) {
  std::unique_ptr<ceres::CostFunction> cost(
      MakeAutoDiff(DihedralTriTri(inv_length, omega)));
  return AsVec(Evaluate(*cost, TriTriBlocks(h)));
}

double MeanEdge(const Hinge& h) {
  return ((h.w - h.v).norm() + (h.a - h.v).norm() + (h.a - h.w).norm() +
          (h.b - h.v).norm() + (h.b - h.w).norm()) /
         5.0;
}

TEST(DihedralEnergy, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> omega_dist(0.05, 1.0);
  ceres::SphereManifold<3> sphere;
  const Manifolds tri_poly = {nullptr, nullptr, nullptr, &sphere};
  const Manifolds poly_poly = {nullptr, nullptr, &sphere, &sphere};
  for (int i = 0; i < kNumSamples; ++i) {
    SCOPED_TRACE(i);
    const Hinge h = RandomHinge(rng);
    const double inv_length = 1.0 / MeanEdge(h);
    const double omega = omega_dist(rng);
    std::unique_ptr<ceres::CostFunction> tt(
        MakeAutoDiff(DihedralTriTri(inv_length, omega)));
    std::unique_ptr<ceres::CostFunction> tp(
        MakeAutoDiff(DihedralTriPoly(inv_length, omega)));
    std::unique_ptr<ceres::CostFunction> pp(
        MakeAutoDiff(DihedralPolyPoly(inv_length, omega)));
    ExpectGradientsMatch(*tt, TriTriBlocks(h));
    // Polygon normals off the exact face normals (as during a solve).
    Blocks tp_blocks = TriPolyBlocks(h);
    tp_blocks[3] = ToBlock((AsVec(tp_blocks[3]) + RandomVec(rng, 0.2)).normalized());
    Blocks pp_blocks = PolyPolyBlocks(h);
    pp_blocks[2] = ToBlock((AsVec(pp_blocks[2]) + RandomVec(rng, 0.2)).normalized());
    ExpectGradientsMatch(*tp, tp_blocks);
    ExpectGradientsMatch(*tp, tp_blocks, &tri_poly);
    ExpectGradientsMatch(*pp, pp_blocks);
    ExpectGradientsMatch(*pp, pp_blocks, &poly_poly);
  }
}

TEST(DihedralEnergy, SingularConfigurationsAreFinite) {
  const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const std::vector<Hinge> cases = {
      {o, x, 0.5 * x + y, 0.5 * x - y},  // coplanar: ℓ* = 0
      {o, o, y, -y},                     // zero-length edge
      {o, o, o, o},                      // everything coincident
      {o, x, 2 * x, 0.5 * x - y},        // degenerate f (a on the line vw)
      {o, x, o, 0.5 * x - y},            // degenerate f (a = v)
      {o, x, 0.5 * x + y, x},            // degenerate f′ (b = w)
      {o, x, 0.5 * x + y, 0.5 * x + y},  // folded flat: n_f′ = −n_f
      {o, x, 0.5 * x + y, 0.5 * x + y + 1e-13 * z},  // nearly folded
  };
  for (double inv_length : {1.0, 1e-3, 1e3}) {
    std::unique_ptr<ceres::CostFunction> tt(MakeAutoDiff(DihedralTriTri(inv_length, 1e-3)));
    std::unique_ptr<ceres::CostFunction> tp(MakeAutoDiff(DihedralTriPoly(inv_length, 1e-3)));
    std::unique_ptr<ceres::CostFunction> pp(
        MakeAutoDiff(DihedralPolyPoly(inv_length, 1e-3)));
    for (size_t i = 0; i < cases.size(); ++i) {
      SCOPED_TRACE(i);
      const Hinge& h = cases[i];
      ExpectFiniteEverywhere(*tt, TriTriBlocks(h));
      ExpectFiniteEverywhere(
          *tp, {ToBlock(h.v), ToBlock(h.w), ToBlock(h.a), ToBlock(z)});
      ExpectFiniteEverywhere(*tp, {ToBlock(h.v), ToBlock(h.w), ToBlock(h.a),
                                   ToBlock(Vec3::Zero())});
      ExpectFiniteEverywhere(
          *pp, {ToBlock(h.v), ToBlock(h.w), ToBlock(z), ToBlock(z)});
    }
    // Coplanar faces: the residual vanishes (ℓ* = 0), also for polygons.
    EXPECT_NEAR(SquaredNorm(Evaluate(*tt, TriTriBlocks(cases[0]))), 0.0,
                kTolerance);
    EXPECT_NEAR(SquaredNorm(Evaluate(*pp, PolyPolyBlocks(cases[0]))), 0.0,
                kTolerance);
  }
}

TEST(DihedralEnergy, KnownDihedralAngle) {
  // ½‖r‖² = ½ (ℓ/L)² (2 sin(α/2))² / ω for a hinge with angle α.
  for (double alpha : {0.0, 0.05, 0.7, M_PI / 2, 2.5, 3.1, -0.4}) {
    for (double length : {1.0, 0.3, 4.0}) {
      for (double inv_length : {1.0, 2.5}) {
        const double omega = 0.37;
        const Hinge h = KnownHinge(alpha, length);
        const double ratio = length * inv_length;
        const double expected =
            0.5 * ratio * ratio * std::pow(2.0 * std::sin(alpha / 2), 2) / omega;
        const double tolerance =
            kRegularisedTolerance * std::max(1.0, expected);
        std::unique_ptr<ceres::CostFunction> tt(
            MakeAutoDiff(DihedralTriTri(inv_length, omega)));
        std::unique_ptr<ceres::CostFunction> tp(
            MakeAutoDiff(DihedralTriPoly(inv_length, omega)));
        std::unique_ptr<ceres::CostFunction> pp(
            MakeAutoDiff(DihedralPolyPoly(inv_length, omega)));
        SCOPED_TRACE(alpha);
        EXPECT_NEAR(0.5 * SquaredNorm(Evaluate(*tt, TriTriBlocks(h))), expected,
                    tolerance);
        EXPECT_NEAR(0.5 * SquaredNorm(Evaluate(*tp, TriPolyBlocks(h))),
                    expected, tolerance);
        EXPECT_NEAR(0.5 * SquaredNorm(Evaluate(*pp, PolyPolyBlocks(h))),
                    expected, tolerance);
        // The residual is the vector (ℓ/L)(n_f − n_f′)/sqrt(ω).
        const Vec3 n_right(0.0, -std::sin(alpha), std::cos(alpha));
        const Vec3 expected_r =
            ratio * (Vec3::UnitZ() - n_right) / std::sqrt(omega);
        EXPECT_NEAR((TriTriResidual(h, inv_length, omega) - expected_r).norm(),
                    0.0, kRegularisedTolerance * std::max(1.0, ratio));
      }
    }
  }
}

TEST(DihedralEnergy, IrlsFixedPointGivesHalfTheEnergyTerm) {
  // With ω from the current values, ½‖r‖² = ½ x²/(x + ε), x = ℓℓ*/L.
  for (double alpha : {0.01, 0.1, 0.5, 1.5}) {
    const double length = 1.3, inv_length = 1.0 / 1.1;
    const Hinge h = KnownHinge(alpha, length);
    const double dual = 2.0 * std::sin(alpha / 2.0);
    const double omega = DihedralIrlsWeight(length, dual, inv_length);
    const double x = length * dual * inv_length;
    const double half_r2 =
        0.5 * TriTriResidual(h, inv_length, omega).squaredNorm();
    EXPECT_NEAR(half_r2, 0.5 * x * x / (x + kDihedralIrlsEpsilon),
                kRegularisedTolerance);
    // ... within the documented relative error of ½ x.
    EXPECT_LE(std::abs(half_r2 - 0.5 * x),
              0.5 * x * kDihedralIrlsEpsilon / (x + kDihedralIrlsEpsilon) +
                  kRegularisedTolerance);
  }
  EXPECT_DOUBLE_EQ(DihedralIrlsWeight(2.0, 0.5, 0.25), 0.25 + 1e-3);
  EXPECT_DOUBLE_EQ(DihedralIrlsWeight(0.0, 0.0, 1.0, 0.1), 0.1);
}

// The IRLS weight ω divides the residual by √ω.
TEST(DihedralEnergy, OmegaScalesTheResidual) {
  const Hinge h = KnownHinge(0.8, 1.0);
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(DihedralTriTri(1.0, 0.5)));
  const Vec3 before = AsVec(Evaluate(*cost, TriTriBlocks(h)));
  cost.reset(MakeAutoDiff(DihedralTriTri(1.0, 2.0)));  // 4× ω: r halves
  const Vec3 after = AsVec(Evaluate(*cost, TriTriBlocks(h)));
  EXPECT_GT(before.norm(), 0.1);
  EXPECT_NEAR((after - 0.5 * before).norm(), 0.0, kTolerance);
}

TEST(DihedralEnergy, InvariantUnderRigidMotionScalingAndSides) {
  std::mt19937 rng(kSeed + 1);
  for (int i = 0; i < kNumSamples; ++i) {
    const Hinge h = RandomHinge(rng);
    const double inv_length = 1.0 / MeanEdge(h), omega = 0.2;
    const Vec3 r = TriTriResidual(h, inv_length, omega);
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 moved =
        TriTriResidual(Moved(h, rot, RandomVec(rng, 10.0), 1.0), inv_length, omega);
    EXPECT_NEAR((moved - rot * r).norm(), 0.0, kRegularisedTolerance) << i;
    for (double s : {1e-3, 0.37, 1e3}) {
      const Vec3 scaled = TriTriResidual(
          Moved(h, Eigen::Matrix3d::Identity(), Vec3::Zero(), s),
          inv_length / s, omega);
      EXPECT_NEAR((scaled - r).norm(), 0.0, kRegularisedTolerance) << s;
    }
    // Traversing the edge the other way swaps f and f′: r flips.
    EXPECT_NEAR((TriTriResidual({h.w, h.v, h.b, h.a}, inv_length, omega) + r)
                    .norm(),
                0.0, kTolerance);
  }
}

// =================================================== total_absolute_curvature

// A vertex with its one-ring (counter-clockwise seen from the normals' side).
struct Star {
  Vec3 v;
  std::vector<Vec3> ring;
  bool closed = true;
};

Blocks StarBlocks(const Star& s) {
  Blocks b = {ToBlock(s.v)};
  for (const Vec3& w : s.ring) b.push_back(ToBlock(w));
  return b;
}

Star MovedStar(const Star& s, const Eigen::Matrix3d& rot, const Vec3& shift,
               double scale) {
  Star m = s;
  m.v = scale * (rot * s.v) + shift;
  for (Vec3& w : m.ring) w = scale * (rot * w) + shift;
  return m;
}

// Residuals of the functor with the given weights.
std::vector<double> TacResidual(const Star& s, double inv_length,
                                double omega1 = 1.0, double omega2 = 1.0) {
  std::unique_ptr<ceres::CostFunction> cost(MakeStarAutoDiff(TotalAbsoluteCurvature(static_cast<int>(s.ring.size()), s.closed, inv_length, omega1, omega2)));
  return Evaluate(*cost, StarBlocks(s));
}

VertexShapeOperator Plain(const Star& s) {
  std::vector<const double*> ring;
  for (const Vec3& w : s.ring) ring.push_back(w.data());
  return EvaluateVertexShapeOperator(s.v.data(), ring, s.closed);
}

// The north pole of a sphere of radius R and a regular k-ring at polar
// angle theta: a vertex of a fine triangulated sphere (outward normals).
Star SphereStar(double radius, double theta, int k) {
  Star s;
  s.v = Vec3(0, 0, radius);
  for (int i = 0; i < k; ++i) {
    const double phi = 2.0 * M_PI * i / k;
    s.ring.push_back(radius * Vec3(std::sin(theta) * std::cos(phi),
                                   std::sin(theta) * std::sin(phi),
                                   std::cos(theta)));
  }
  return s;
}

// The vertex's area of influence: its Voronoi area in the star, Σ over the
// faces (v, a, b) of the kites v, (v + a)/2, circumcentre, (v + b)/2 (the
// stars used here have no obtuse angles). For a regular valence-k star at
// polar angle θ, λ1 = λ2 = (k/4) tan(π/k) R θ² + O(θ⁴) = A_Voronoi / R to
// leading order; one third of the star's area would be off by the factor
// 3/(4 cos²(π/k)) except for k = 6.
double AreaOfInfluence(const Star& s) {
  const int k = static_cast<int>(s.ring.size());
  const int faces = s.closed ? k : k - 1;
  double area = 0.0;
  for (int i = 0; i < faces; ++i) {
    const Vec3 a = s.ring[i] - s.v, b = s.ring[(i + 1) % k] - s.v;
    const Vec3 n = a.cross(b);
    const Vec3 centre =
        (a.squaredNorm() * b.cross(n) + b.squaredNorm() * n.cross(a)) /
        (2.0 * n.squaredNorm());  // circumcentre relative to v
    area += 0.5 * (0.5 * a).cross(centre).norm() +
            0.5 * centre.cross(0.5 * b).norm();
  }
  return area;
}

// Vertex (0, 0) of the cylinder grid P(i, j) = (R cos iΔ, R sin iΔ, j h),
// quads split along (i, j)–(i+1, j+1); outward normals.
Vec3 CylinderPoint(double radius, double delta, double h, int i, int j) {
  return Vec3(radius * std::cos(i * delta), radius * std::sin(i * delta),
              j * h);
}
Star CylinderStar(double radius, double delta, double h) {
  Star s;
  s.v = CylinderPoint(radius, delta, h, 0, 0);
  const int ij[6][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 0}, {-1, -1}, {0, -1}};
  for (const auto& p : ij) {
    s.ring.push_back(CylinderPoint(radius, delta, h, p[0], p[1]));
  }
  return s;
}

// A star on the saddle-like quadric z = 0.4x² − 0.25y² + 0.1xy with jittered
// angles and radii, randomly placed: λ1 and λ2 clearly apart.
Star RandomStar(std::mt19937& rng, int k, bool closed) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Star s;
  s.closed = closed;
  s.v = Vec3::Zero();
  const double span = closed ? 2.0 * M_PI : 1.2 * M_PI;
  for (int i = 0; i < k; ++i) {
    const double phi = span * (i + 0.2 * u(rng)) / (closed ? k : k - 1);
    const double r = 1.0 + 0.2 * u(rng);
    const double x = r * std::cos(phi), y = r * std::sin(phi);
    s.ring.push_back(Vec3(x, y, 0.4 * x * x - 0.25 * y * y + 0.1 * x * y));
  }
  std::uniform_real_distribution<double> scale(0.5, 2.0);
  return MovedStar(s, RandomRotation(rng), RandomVec(rng, 5.0), scale(rng));
}

double MeanRingDistance(const Star& s) {
  double sum = 0.0;
  for (const Vec3& w : s.ring) sum += (w - s.v).norm();
  return sum / s.ring.size();
}

TEST(TotalAbsoluteCurvature, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 10);
  std::uniform_real_distribution<double> omega_dist(0.05, 1.0);
  const std::vector<std::pair<int, bool>> shapes = {
      {5, true}, {6, true}, {7, true}, {3, true}, {4, false}, {5, false}};
  // (An open fan of 3 has one interior edge: W′ = c êêᵀ has rank one and
  // λ2 ≡ 0 identically, a rounding-level residual unfit for the checker.)
  for (int i = 0; i < kNumSamples; ++i) {
    for (const auto& [k, closed] : shapes) {
      SCOPED_TRACE(testing::Message() << i << " k=" << k << " closed=" << closed);
      const Star s = RandomStar(rng, k, closed);
      std::unique_ptr<ceres::CostFunction> cost(MakeStarAutoDiff(TotalAbsoluteCurvature(k, closed, 1.0 / MeanRingDistance(s), omega_dist(rng), omega_dist(rng))));
      ExpectGradientsMatch(*cost, StarBlocks(s));
    }
  }
}

TEST(TotalAbsoluteCurvature, SingularConfigurationsAreFinite) {
  std::vector<Star> cases;
  cases.push_back(SphereStar(2.0, 0.3, 6));  // umbilic: λ1 = λ2
  Star flat = SphereStar(1.0, M_PI / 2, 6);  // flat star: λ1 = λ2 = 0
  flat.v = Vec3::Zero();
  cases.push_back(flat);
  Star zero_edge = SphereStar(1.0, 0.4, 6);  // w_1 = v
  zero_edge.ring[0] = zero_edge.v;
  cases.push_back(zero_edge);
  Star degenerate = SphereStar(1.0, 0.4, 6);  // w_2 = w_1: zero-area face
  degenerate.ring[1] = degenerate.ring[0];
  cases.push_back(degenerate);
  Star collinear = SphereStar(1.0, 0.4, 6);  // w_1, v, w_4 collinear + w_2 on it
  collinear.ring[1] = 0.5 * (collinear.v + collinear.ring[0]);
  cases.push_back(collinear);
  Star point = SphereStar(1.0, 0.4, 5);  // everything coincident
  for (Vec3& w : point.ring) w = point.v;
  cases.push_back(point);
  Star folded;  // faces cancel: Σ n_f = 0
  folded.v = Vec3::Zero();
  folded.ring = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  cases.push_back(folded);
  Star open = flat;  // a flat boundary fan
  open.closed = false;
  open.ring.resize(3);
  cases.push_back(open);
  for (size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(i);
    const Star& s = cases[i];
    for (double inv_length : {1.0, 1e-3, 1e3}) {
      std::unique_ptr<ceres::CostFunction> cost(MakeStarAutoDiff(TotalAbsoluteCurvature(static_cast<int>(s.ring.size()), s.closed, inv_length, 1e-3, 1e-3)));
      ExpectFiniteEverywhere(*cost, StarBlocks(s));
    }
    const VertexShapeOperator plain = Plain(s);
    EXPECT_TRUE(std::isfinite(plain.lambda1) && std::isfinite(plain.lambda2));
    EXPECT_TRUE(plain.shape.allFinite() && plain.normal.allFinite());
  }
  // The umbilic's regularised gap is 2 ε_g (in units of L), the exact one 0.
  const std::vector<double> r = TacResidual(cases[0], 1.0);
  EXPECT_NEAR(r[0] - r[1], 2.0 * kTotalAbsoluteCurvatureGapEpsilon, kTolerance);
  EXPECT_NEAR(Plain(cases[0]).lambda1, Plain(cases[0]).lambda2, kTolerance);
  // The flat star has no curvature.
  EXPECT_NEAR(std::abs(Plain(flat).lambda1) + std::abs(Plain(flat).lambda2),
              0.0, kTolerance);
}

TEST(TotalAbsoluteCurvature, SphereGivesAreaOverRadius) {
  // λ1 ≈ λ2 ≈ A_v / R (> 0 for outward normals), with an O(θ²) error that
  // shrinks as the triangulation is refined.
  const double radius = 2.5;
  for (int k : {5, 6, 7}) {
    double previous_error = 1.0;
    for (double theta : {0.2, 0.1, 0.05}) {
      const Star s = SphereStar(radius, theta, k);
      const VertexShapeOperator w = Plain(s);
      const double expected = AreaOfInfluence(s) / radius;
      const double error = std::max(std::abs(w.lambda1 / expected - 1.0),
                                    std::abs(w.lambda2 / expected - 1.0));
      SCOPED_TRACE(testing::Message() << "k=" << k << " theta=" << theta);
      EXPECT_GT(w.lambda2, 0.0);
      EXPECT_LT(error, 0.25 * theta * theta);  // measured 0.15–0.19 θ²
      EXPECT_LT(error, 0.3 * previous_error);  // ≈ quartered per halving
      previous_error = error;
      // The vertex normal is the sphere's normal (+z).
      EXPECT_NEAR((w.normal - Vec3::UnitZ()).norm(), 0.0, kRegularisedTolerance);
      // The functor with unit weights returns λ/L.
      const double inv_length = 1.0 / (radius * theta);
      const std::vector<double> r = TacResidual(s, inv_length);
      EXPECT_NEAR(r[0], w.lambda1 * inv_length, kGapTolerance);
      EXPECT_NEAR(r[1], w.lambda2 * inv_length, kGapTolerance);
    }
  }
  // Reversed orientation (inward normals): both signs flip.
  Star inward = SphereStar(radius, 0.1, 6);
  std::reverse(inward.ring.begin(), inward.ring.end());
  const VertexShapeOperator out = Plain(SphereStar(radius, 0.1, 6));
  const VertexShapeOperator in = Plain(inward);
  EXPECT_LT(in.lambda1, 0.0);
  EXPECT_NEAR(in.lambda1, -out.lambda2, kTolerance);
  EXPECT_NEAR(in.lambda2, -out.lambda1, kTolerance);
}

TEST(TotalAbsoluteCurvature, CylinderHasOneZeroEigenvalue) {
  // Only the two axial edges bend (angle Δ), so W′ = h sin(Δ) ẑẑᵀ exactly:
  // λ1 = h sin Δ ≈ A_v / R, λ2 = 0.
  const double radius = 1.7, h = 0.35;
  for (double delta : {0.3, 0.1}) {
    const Star s = CylinderStar(radius, delta, h);
    const VertexShapeOperator w = Plain(s);
    SCOPED_TRACE(delta);
    EXPECT_NEAR(w.lambda1, h * std::sin(delta), kRegularisedTolerance);
    EXPECT_NEAR(w.lambda2, 0.0, kRegularisedTolerance);
    EXPECT_NEAR(w.lambda1, AreaOfInfluence(s) / radius,
                0.2 * delta * delta * w.lambda1);
    EXPECT_NEAR((w.shape - h * std::sin(delta) * Vec3::UnitZ() *
                               Vec3::UnitZ().transpose())
                    .norm(),
                0.0, kRegularisedTolerance);
    const double inv_length = 1.0 / h;
    const std::vector<double> r = TacResidual(s, inv_length);
    EXPECT_NEAR(r[0], h * std::sin(delta) * inv_length, kGapTolerance);
    EXPECT_NEAR(r[1], 0.0, kGapTolerance);
    // Boundary vertex: the open fan (1,0), (1,1), (0,1), (−1,0) keeps one
    // axial edge (0,1) and the diagonal (1,1), whose faces are coplanar; the
    // boundary edges (1,0) and (−1,0) do not count: λ1 = ½ h sin Δ.
    Star open = s;
    open.closed = false;
    open.ring.resize(4);
    const VertexShapeOperator half = Plain(open);
    EXPECT_NEAR(half.lambda1, 0.5 * h * std::sin(delta), kRegularisedTolerance);
    EXPECT_NEAR(half.lambda2, 0.0, kRegularisedTolerance);
  }
}

TEST(TotalAbsoluteCurvature, IrlsWeightsAndFunctorUpdate) {
  EXPECT_DOUBLE_EQ(TotalAbsoluteCurvatureIrlsWeight(-0.3, 2.0), 0.6 + 1e-3);
  EXPECT_DOUBLE_EQ(TotalAbsoluteCurvatureIrlsWeight(0.0, 1.0, 0.01), 0.01);
  // ½‖r‖² = ½ Σ (λ_j/L)² / ω_j ≈ ½ Σ |λ_j| / L at the fixed point.
  std::mt19937 rng(kSeed + 11);
  const Star s = RandomStar(rng, 6, true);
  const double inv_length = 1.0 / MeanRingDistance(s);
  const VertexShapeOperator w = Plain(s);
  const double omega1 = TotalAbsoluteCurvatureIrlsWeight(w.lambda1, inv_length);
  const double omega2 = TotalAbsoluteCurvatureIrlsWeight(w.lambda2, inv_length);
  std::unique_ptr<ceres::CostFunction> cost(
      MakeStarAutoDiff(TotalAbsoluteCurvature(6, true, inv_length, omega1, omega2)));
  const std::vector<double> r = Evaluate(*cost, StarBlocks(s));
  const double y1 = std::abs(w.lambda1) * inv_length;
  const double y2 = std::abs(w.lambda2) * inv_length;
  EXPECT_GT(std::min(y1, y2), 0.05);  // a genuine saddle-ish star
  EXPECT_LT(w.lambda2, 0.0);
  EXPECT_GT(w.lambda1, 0.0);
  const double eps = kTotalAbsoluteCurvatureIrlsEpsilon;
  EXPECT_NEAR(0.5 * SquaredNorm(r),
              0.5 * (y1 * y1 / (y1 + eps) + y2 * y2 / (y2 + eps)),
              kGapTolerance);
  EXPECT_NEAR(0.5 * SquaredNorm(r), 0.5 * (y1 + y2), 0.5 * (y1 + y2) * 0.03);
  cost.reset(MakeStarAutoDiff(TotalAbsoluteCurvature(6, true, inv_length, 4.0 * omega1, omega2)));
  const std::vector<double> r2 = Evaluate(*cost, StarBlocks(s));
  EXPECT_NEAR(r2[0], 0.5 * r[0], kTolerance);
  EXPECT_NEAR(r2[1], r[1], kTolerance);
}

TEST(TotalAbsoluteCurvature, InvariantUnderRigidMotionScalingAndRelabelling) {
  std::mt19937 rng(kSeed + 12);
  for (int i = 0; i < kNumSamples; ++i) {
    const bool closed = i % 3 != 0;
    const Star s = RandomStar(rng, closed ? 6 : 4, closed);
    const double inv_length = 1.0 / MeanRingDistance(s);
    const std::vector<double> r = TacResidual(s, inv_length, 0.3, 0.7);
    const VertexShapeOperator w = Plain(s);
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Star moved = MovedStar(s, rot, RandomVec(rng, 10.0), 1.0);
    const std::vector<double> rm = TacResidual(moved, inv_length, 0.3, 0.7);
    EXPECT_NEAR(rm[0], r[0], kRegularisedTolerance) << i;
    EXPECT_NEAR(rm[1], r[1], kRegularisedTolerance) << i;
    EXPECT_NEAR((Plain(moved).shape - rot * w.shape * rot.transpose()).norm(),
                0.0, kRegularisedTolerance);
    for (double scale : {1e-3, 0.37, 1e3}) {
      const Star scaled =
          MovedStar(s, Eigen::Matrix3d::Identity(), Vec3::Zero(), scale);
      const std::vector<double> rs =
          TacResidual(scaled, inv_length / scale, 0.3, 0.7);
      EXPECT_NEAR(rs[0], r[0], kRegularisedTolerance) << scale;
      EXPECT_NEAR(rs[1], r[1], kRegularisedTolerance) << scale;
      const VertexShapeOperator ws = Plain(scaled);
      EXPECT_NEAR(ws.lambda1, scale * w.lambda1,
                  kRegularisedTolerance * scale);
      EXPECT_NEAR(ws.lambda2, scale * w.lambda2,
                  kRegularisedTolerance * scale);
    }
    if (closed) {
      Star shifted = s;
      std::rotate(shifted.ring.begin(), shifted.ring.begin() + 2,
                  shifted.ring.end());
      const std::vector<double> rr = TacResidual(shifted, inv_length, 0.3, 0.7);
      EXPECT_NEAR(rr[0], r[0], kTolerance);
      EXPECT_NEAR(rr[1], r[1], kTolerance);
    }
  }
}

// ======================================================== principal_symmetric

// A vertex sphere: v on it, unit normal n, curvature κ (κ = 0: the plane).
struct Sphere {
  Vec3 v, n;
  double kappa;
};

// A point on the sphere at geodesic-ish parameter (direction u, tangential).
Vec3 PointOnSphere(const Sphere& s, const Vec3& u_raw, double t) {
  const Vec3 u = (u_raw - u_raw.dot(s.n) * s.n).normalized();
  if (s.kappa == 0.0) return s.v + t * u;
  // Circle through v in the plane (n, u) of radius 1/|κ| about c = v + n/κ.
  const double a = t * s.kappa;  // angle subtended at the centre
  return s.v + (std::sin(a) * u + (1.0 - std::cos(a)) * s.n) / s.kappa;
}

double CoSphericalResidual(const Sphere& s, const Vec3& w, double inv_length) {
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(CoSpherical(inv_length)));
  return Evaluate(*cost,
                  {ToBlock(s.v), ToBlock(s.n), {s.kappa}, ToBlock(w)})[0];
}

Vec3 StripResidual(const Vec3& n_e, const Vec3& v, const Vec3& w,
                   const Vec3& n_v, const Vec3& n_w, double inv_length) {
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(PrincipalStrip(inv_length)));
  return AsVec(Evaluate(*cost, {ToBlock(n_e), ToBlock(v), ToBlock(w),
                                ToBlock(n_v), ToBlock(n_w)}));
}

double SaddleResidual(const Sphere& s, const Vec3& w, double delta) {
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(SaddleSign()));
  return Evaluate(*cost, {ToBlock(s.v), ToBlock(s.n), {s.kappa}, ToBlock(w),
                          {delta}})[0];
}

Sphere RandomSphere(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return {RandomVec(rng, 5.0), RandomUnit(rng), 0.8 * u(rng)};
}

TEST(PrincipalSymmetric, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed + 20);
  ceres::SphereManifold<3> sphere;
  const Manifolds co_spherical = {nullptr, &sphere, nullptr, nullptr};
  const Manifolds strip = {&sphere, nullptr, nullptr, &sphere, &sphere};
  const Manifolds saddle = {nullptr, &sphere, nullptr, nullptr, nullptr};
  for (int i = 0; i < kNumSamples; ++i) {
    SCOPED_TRACE(i);
    const Sphere s = RandomSphere(rng);
    const Vec3 w = s.v + RandomVec(rng, 1.0);
    const double inv_length = 1.0 / (0.5 + 0.1 * i);
    std::unique_ptr<ceres::CostFunction> cs(MakeAutoDiff(CoSpherical(inv_length)));
    const Blocks cs_blocks = {ToBlock(s.v), ToBlock(s.n), {s.kappa}, ToBlock(w)};
    ExpectGradientsMatch(*cs, cs_blocks);
    ExpectGradientsMatch(*cs, cs_blocks, &co_spherical);
    std::unique_ptr<ceres::CostFunction> ps(MakeAutoDiff(PrincipalStrip(inv_length)));
    const Blocks ps_blocks = {ToBlock(RandomUnit(rng)), ToBlock(s.v),
                              ToBlock(w), ToBlock(s.n),
                              ToBlock(RandomUnit(rng))};
    ExpectGradientsMatch(*ps, ps_blocks);
    ExpectGradientsMatch(*ps, ps_blocks, &strip);
    std::unique_ptr<ceres::CostFunction> ss(MakeAutoDiff(SaddleSign()));
    const Blocks ss_blocks = {ToBlock(s.v), ToBlock(s.n), {s.kappa}, ToBlock(w),
                              {0.3 + 0.05 * i}};
    ExpectGradientsMatch(*ss, ss_blocks);
    ExpectGradientsMatch(*ss, ss_blocks, &saddle);
  }
}

TEST(PrincipalSymmetric, SingularConfigurationsAreFinite) {
  const Vec3 p(1, 2, 3), z(0, 0, 1), zero(0, 0, 0);
  std::unique_ptr<ceres::CostFunction> cs(MakeAutoDiff(CoSpherical(1.0)));
  std::unique_ptr<ceres::CostFunction> ps(MakeAutoDiff(PrincipalStrip(1.0)));
  std::unique_ptr<ceres::CostFunction> ss(MakeAutoDiff(SaddleSign()));
  for (double kappa : {0.0, 1e-300, -2.0}) {
    for (const Vec3& n : {z, zero}) {
      for (const Vec3& w : {p, Vec3(p + Vec3(1, 0, 0))}) {  // w = v and w ≠ v
        ExpectFiniteEverywhere(*cs, {ToBlock(p), ToBlock(n), {kappa}, ToBlock(w)});
        ExpectFiniteEverywhere(
            *ss, {ToBlock(p), ToBlock(n), {kappa}, ToBlock(w), {0.0}});
        ExpectFiniteEverywhere(
            *ps, {ToBlock(n), ToBlock(p), ToBlock(w), ToBlock(n), ToBlock(n)});
      }
    }
  }
  // κ = 0: a flat sphere is the tangent plane; r = −n·(w − v)/L.
  EXPECT_NEAR(CoSphericalResidual({p, z, 0.0}, p + Vec3(4, -1, 0.5), 0.5),
              -0.25, kTolerance);
}

TEST(PrincipalSymmetric, CoSphericalIsZeroOnTheSphereAndADistanceOffIt) {
  std::mt19937 rng(kSeed + 21);
  for (int i = 0; i < kNumSamples; ++i) {
    Sphere s = RandomSphere(rng);
    if (i % 5 == 0) s.kappa = 0.0;  // flat spheres are legal
    const double inv_length = 1.0 / (0.5 + 0.05 * i);
    // Four non-principal neighbours of a valence-6 vertex, on Σ(v).
    for (int j = 0; j < 4; ++j) {
      const Vec3 w = PointOnSphere(s, RandomVec(rng, 1.0), 0.5 + 0.2 * j);
      EXPECT_NEAR(CoSphericalResidual(s, w, inv_length), 0.0, kTolerance)
          << i << " " << j;
    }
    if (std::abs(s.kappa) < 0.05) continue;  // radius ≤ 20
    // Off the sphere by d along the radius: r = sign(κ)(d/L)(1 + |κ|d/2).
    const Vec3 c = s.v + s.n / s.kappa;
    const double rho = 1.0 / std::abs(s.kappa);
    const Vec3 u = RandomUnit(rng);
    for (double d : {-0.1, 0.02, 0.3}) {
      const double expected = (s.kappa > 0 ? 1.0 : -1.0) * d * inv_length *
                              (1.0 + std::abs(s.kappa) * d / 2.0);
      EXPECT_NEAR(CoSphericalResidual(s, c + (rho + d) * u, inv_length),
                  expected, kRegularisedTolerance * (1.0 + rho * rho));
    }
    // (n, κ) → (−n, −κ) is the same sphere: the sign flips.
    const Vec3 w = s.v + RandomVec(rng, 1.0);
    EXPECT_NEAR(CoSphericalResidual({s.v, -s.n, -s.kappa}, w, inv_length),
                -CoSphericalResidual(s, w, inv_length), kTolerance);
  }
}

TEST(PrincipalSymmetric, StripIsZeroIffEdgeAndNormalsAreCoplanar) {
  // A meridian edge of a torus (R = 3, r = 1): the surface normals at both
  // ends lie in the meridian plane, whose normal is n(e); and the centres
  // c = x + n/κ of any curvatures κ lie in it too.
  const double big = 3.0, small = 1.0, phi = 0.7;
  const auto torus = [&](double theta) {
    return Vec3((big + small * std::cos(theta)) * std::cos(phi),
                (big + small * std::cos(theta)) * std::sin(phi),
                small * std::sin(theta));
  };
  const auto normal = [&](double theta) {
    return Vec3(std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi),
                std::sin(theta));
  };
  const Vec3 n_e(-std::sin(phi), std::cos(phi), 0.0);
  const Vec3 v = torus(0.4), w = torus(0.65);
  const Vec3 n_v = normal(0.4), n_w = normal(0.65);
  EXPECT_NEAR(StripResidual(n_e, v, w, n_v, n_w, 4.0).norm(), 0.0, kTolerance);
  EXPECT_NEAR(StripResidual(-n_e, v, w, n_v, n_w, 4.0).norm(), 0.0, kTolerance);
  const Vec3 c_v = v + n_v / 0.8, c_w = w + n_w / -0.3;
  EXPECT_NEAR((w - v).dot((c_v - v).cross(c_w - v)), 0.0, kTolerance);
  // A parallel edge (v → w along the parallel circle) is principal too, but
  // the meridian plane's normal is not its strip normal.
  EXPECT_GT(StripResidual(n_e, v, torus(0.4) + 0.3 * n_e, n_v, n_v, 1.0).norm(),
            0.29);
  // In general: min over unit n(e) of ‖r‖ is the smallest singular value of
  // the rows ((v − w)/L, n_v, n_w), zero iff det(w − v, n_v, n_w) = 0.
  std::mt19937 rng(kSeed + 22);
  for (int i = 0; i < kNumSamples; ++i) {
    const Vec3 a = RandomVec(rng, 3.0);
    const Vec3 b = a + RandomVec(rng, 1.0);
    const Vec3 na = RandomUnit(rng);
    Vec3 nb = RandomUnit(rng);
    if (i % 2 == 0) {  // make them coplanar with the edge
      const Vec3 plane = (b - a).cross(na).normalized();
      nb = (nb - nb.dot(plane) * plane).normalized();
    }
    const double inv_length = 1.0 / (b - a).norm();
    Eigen::Matrix3d rows;
    rows.row(0) = (a - b).transpose() * inv_length;
    rows.row(1) = na.transpose();
    rows.row(2) = nb.transpose();
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(rows, Eigen::ComputeFullV);
    const Vec3 best = svd.matrixV().col(2);
    const double sigma_min = svd.singularValues()(2);
    EXPECT_NEAR(StripResidual(best, a, b, na, nb, inv_length).norm(), sigma_min,
                kTolerance);
    const double det = (b - a).dot(na.cross(nb)) * inv_length;
    if (i % 2 == 0) {
      EXPECT_NEAR(sigma_min, 0.0, kTolerance) << i;
    } else {
      // |det| = σ1σ2σ_min and σ1σ2 ≤ ½‖rows‖²_F = 3/2 (unit rows).
      EXPECT_GT(std::abs(det), 1e-3) << i;
      EXPECT_GE(sigma_min, std::abs(det) / 1.5) << i;
    }
  }
}

TEST(PrincipalSymmetric, SaddleSignAdmitsOnlyTheOtherSide) {
  std::mt19937 rng(kSeed + 23);
  for (int i = 0; i < kNumSamples; ++i) {
    Sphere s = RandomSphere(rng);
    if (std::abs(s.kappa) < 0.1) s.kappa = 0.5;
    // The sphere lies on the side of κ n; w below the tangent plane w.r.t. it.
    const Vec3 side = s.kappa > 0 ? s.n : Vec3(-s.n);
    const Vec3 u = RandomUnit(rng);
    const Vec3 t = u - u.dot(s.n) * s.n;  // tangential
    const Vec3 other = s.v + t - 0.2 * side;
    const Vec3 same = s.v + t + 0.2 * side;
    const double delta = std::sqrt(-s.kappa * s.n.dot(other - s.v));
    EXPECT_NEAR(SaddleResidual(s, other, delta), 0.0, kTolerance) << i;
    // Agrees with the paper's (v − c)ᵀ(v − w) = −δ_p², δ = |κ| δ_p.
    const Vec3 c = s.v + s.n / s.kappa;
    EXPECT_NEAR((s.v - c).dot(s.v - other), -std::pow(delta / s.kappa, 2),
                kTolerance);
    // On the sphere's side no δ makes it vanish: r ≥ κ n·(w − v) > 0.
    const double floor = s.kappa * s.n.dot(same - s.v);
    EXPECT_GT(floor, 0.0);
    for (double d : {0.0, 0.1, 1.0, 10.0}) {
      EXPECT_GE(SaddleResidual(s, same, d), floor - kTolerance);
    }
  }
  // A flat sphere makes the condition vacuous (δ = 0 works for any w).
  EXPECT_EQ(SaddleResidual({Vec3(1, 2, 3), Vec3(0, 0, 1), 0.0}, Vec3(5, 1, -2),
                           0.0),
            0.0);
}

TEST(PrincipalSymmetric, InvariantUnderRigidMotionAndScaling) {
  std::mt19937 rng(kSeed + 24);
  for (int i = 0; i < kNumSamples; ++i) {
    const Sphere s = RandomSphere(rng);
    const Vec3 w = s.v + RandomVec(rng, 1.0);
    const Vec3 n_e = RandomUnit(rng), n_w = RandomUnit(rng);
    const double inv_length = 1.0 / (0.5 + 0.05 * i), delta = 0.4;
    const double r_cs = CoSphericalResidual(s, w, inv_length);
    const Vec3 r_ps = StripResidual(n_e, s.v, w, s.n, n_w, inv_length);
    const double r_ss = SaddleResidual(s, w, delta);
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const Vec3 shift = RandomVec(rng, 10.0);
    const Sphere ms = {rot * s.v + shift, rot * s.n, s.kappa};
    const Vec3 mw = rot * w + shift;
    EXPECT_NEAR(CoSphericalResidual(ms, mw, inv_length), r_cs, kTolerance);
    EXPECT_NEAR((StripResidual(rot * n_e, ms.v, mw, ms.n, rot * n_w, inv_length) -
                 r_ps).norm(),
                0.0, kTolerance);
    EXPECT_NEAR(SaddleResidual(ms, mw, delta), r_ss, kTolerance);
    for (double k : {1e-3, 0.37, 1e3}) {
      const Sphere ss = {k * s.v, s.n, s.kappa / k};
      EXPECT_NEAR(CoSphericalResidual(ss, k * w, inv_length / k), r_cs,
                  kTolerance) << k;
      EXPECT_NEAR((StripResidual(n_e, ss.v, k * w, s.n, n_w, inv_length / k) -
                   r_ps).norm(),
                  0.0, kTolerance) << k;
      EXPECT_NEAR(SaddleResidual(ss, k * w, delta), r_ss, kTolerance) << k;
    }
  }
}

}  // namespace
}  // namespace archgeo
