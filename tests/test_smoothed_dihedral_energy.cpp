// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for energies/smoothed_dihedral_energy.h, the directly minimised
// E_ε = Σ ℓ_e sqrt(ℓ*²_e + ε²) [Pellis 2019, §3, §5.1]:
//  (a) autodiff Jacobians against numeric differences, bent and flat hinges;
//  (b) singular configurations give finite residuals and Jacobians;
//  (c) the known value ½‖r‖² = (ℓ/L) sqrt((2 sin(α/2))² + ε²) of a hinge
//      with dihedral angle α, and Gauss–Newton's JᵀJ equal to the Hessian of
//      ½‖r‖² at a flat hinge (ℓ/(Lε) along a bending motion);
//  (d) invariance under rigid motions, uniform scaling and the edge's
//      traversal.
#include <algorithm>
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

#include "energies/smoothed_dihedral_energy.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

constexpr unsigned kSeed = 20190731;
constexpr int kNumSamples = 20;
// Agreement of quantities equal in exact arithmetic.
constexpr double kTolerance = 1e-10;
// Relative effect of the normal and length regularisations plus rounding.
constexpr double kRegularisedTolerance = 1e-9;
// Relative error of the second difference below (step 1e-5 at a flat hinge):
// about x²/4 with x = step · dℓ*/dt / ε ≈ 0.0125, i.e. 4e-5.
constexpr double kSecondDifferenceTolerance = 1e-3;

// Ridders' initial step, relative: below the smoothing scale ε.
constexpr double kRiddersInitialStep = 1e-6;

using namespace energy_checks;

std::vector<double> TriTri(const Hinge& h, double inv_length, double epsilon) {
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(SmoothedDihedralTriTri(inv_length, epsilon)));
  return Evaluate(*cost, TriTriBlocks(h));
}

// Autodiff against Ridders' differences (ceres::GradientChecker's), entry by
// entry within kRelativePrecision × the largest entry of the block, from a
// small initial step. Not GradientChecker's own pass/fail: at flat or nearly
// flat hinges (ℓ* ≲ ε) some entries are 0 analytically and ~1e-14
// numerically (relative error 1 in its measure), E_ε bends on the scale ε,
// and from its default initial step (1e-4 relative to coordinates ~5 apart
// from the origin) Ridders' extrapolation was off by up to 0.7% on a bent
// hinge with short edges, while a 1e-6 step agrees to 1e-6.
void ExpectJacobiansClose(const ceres::CostFunction& cost, const Blocks& blocks,
                          const Manifolds* manifolds = nullptr) {
  ceres::NumericDiffOptions options;
  options.ridders_relative_initial_step_size = kRiddersInitialStep;
  ceres::GradientChecker checker(&cost, manifolds, options);
  ceres::GradientChecker::ProbeResults results;
  const auto params = Pointers(blocks);
  checker.Probe(params.data(), kRelativePrecision, &results);
  ASSERT_EQ(results.local_jacobians.size(), blocks.size());
  for (size_t i = 0; i < blocks.size(); ++i) {
    const auto& user = results.local_jacobians[i];
    const auto& numeric = results.local_numeric_jacobians[i];
    const double scale = std::max(user.cwiseAbs().maxCoeff(), 1.0);
    EXPECT_LE((user - numeric).cwiseAbs().maxCoeff(), kRelativePrecision * scale) << "block " << i;
  }
}

TEST(SmoothedDihedralEnergy, GradientMatchesNumeric) {
  std::mt19937 rng(kSeed);
  ceres::SphereManifold<3> sphere;
  const Manifolds tri_poly = {nullptr, nullptr, nullptr, &sphere};
  const Manifolds poly_poly = {nullptr, nullptr, &sphere, &sphere};
  for (int i = 0; i < kNumSamples; ++i) {
    SCOPED_TRACE(i);
    // Bent, slightly bent (ℓ* ~ ε) and exactly flat hinges: E_ε is smooth at all.
    for (double bend : {1.0, 2e-3, 0.0}) {
      SCOPED_TRACE(bend);
      const Hinge h = RandomHinge(rng, bend);
      const double inv_length = 1.0 / (h.w - h.v).norm();
      std::unique_ptr<ceres::CostFunction> tt(MakeAutoDiff(SmoothedDihedralTriTri(inv_length, kSmoothedDihedralEpsilon)));
      std::unique_ptr<ceres::CostFunction> tp(MakeAutoDiff(SmoothedDihedralTriPoly(inv_length, kSmoothedDihedralEpsilon)));
      std::unique_ptr<ceres::CostFunction> pp(MakeAutoDiff(SmoothedDihedralPolyPoly(inv_length, kSmoothedDihedralEpsilon)));
      Blocks tp_blocks = TriPolyBlocks(h);
      Blocks pp_blocks = PolyPolyBlocks(h);
      if (bend > 0.5) {  // polygon normals off the exact face normals
        tp_blocks[3] = ToBlock((AsVec(tp_blocks[3]) + RandomVec(rng, 0.2)).normalized());
        pp_blocks[2] = ToBlock((AsVec(pp_blocks[2]) + RandomVec(rng, 0.2)).normalized());
      }
      ExpectJacobiansClose(*tt, TriTriBlocks(h));
      ExpectJacobiansClose(*tp, tp_blocks, &tri_poly);
      ExpectJacobiansClose(*pp, pp_blocks, &poly_poly);
    }
  }
}

TEST(SmoothedDihedralEnergy, SingularConfigurationsAreFinite) {
  const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const std::vector<Hinge> cases = {
      {o, x, 0.5 * x + y, 0.5 * x - y},  // coplanar: ℓ* = 0
      {o, o, y, -y},                     // zero-length edge
      {o, o, o, o},                      // everything coincident
      {o, x, 2 * x, 0.5 * x - y},        // degenerate f
      {o, x, 0.5 * x + y, x},            // degenerate f′ (b = w)
      {o, x, 0.5 * x + y, 0.5 * x + y},  // folded flat: n_f′ = −n_f
  };
  for (double inv_length : {1.0, 1e-3, 1e3}) {
    std::unique_ptr<ceres::CostFunction> tt(MakeAutoDiff(SmoothedDihedralTriTri(inv_length, kSmoothedDihedralEpsilon)));
    std::unique_ptr<ceres::CostFunction> tp(MakeAutoDiff(SmoothedDihedralTriPoly(inv_length, kSmoothedDihedralEpsilon)));
    std::unique_ptr<ceres::CostFunction> pp(MakeAutoDiff(SmoothedDihedralPolyPoly(inv_length, kSmoothedDihedralEpsilon)));
    for (size_t i = 0; i < cases.size(); ++i) {
      SCOPED_TRACE(i);
      const Hinge& h = cases[i];
      ExpectFiniteEverywhere(*tt, TriTriBlocks(h));
      ExpectFiniteEverywhere(*tp, {ToBlock(h.v), ToBlock(h.w), ToBlock(h.a), ToBlock(z)});
      ExpectFiniteEverywhere(*pp, {ToBlock(h.v), ToBlock(h.w), ToBlock(z), ToBlock(z)});
    }
  }
  // Coplanar faces: ½‖r‖² = (ℓ/L) ε, the floor of the smoothing.
  const double eps = kSmoothedDihedralEpsilon;
  EXPECT_NEAR(0.5 * SquaredNorm(TriTri(cases[0], 1.0, eps)), eps, kRegularisedTolerance);
}

TEST(SmoothedDihedralEnergy, KnownDihedralAngle) {
  for (double alpha : {0.0, 1e-4, 0.05, 0.7, M_PI / 2, 2.5, 3.1, -0.4}) {
    for (double length : {1.0, 0.3, 4.0}) {
      for (double inv_length : {1.0, 2.5}) {
        for (double eps : {kSmoothedDihedralEpsilon, 0.1}) {
          SCOPED_TRACE(alpha);
          const Hinge h = KnownHinge(alpha, length);
          const double dual = 2.0 * std::sin(alpha / 2);
          const double expected = length * inv_length * std::sqrt(dual * dual + eps * eps);
          const double tolerance = kRegularisedTolerance * std::max(1.0, expected);
          std::unique_ptr<ceres::CostFunction> tp(MakeAutoDiff(SmoothedDihedralTriPoly(inv_length, eps)));
          std::unique_ptr<ceres::CostFunction> pp(MakeAutoDiff(SmoothedDihedralPolyPoly(inv_length, eps)));
          EXPECT_NEAR(0.5 * SquaredNorm(TriTri(h, inv_length, eps)), expected, tolerance);
          EXPECT_NEAR(0.5 * SquaredNorm(Evaluate(*tp, TriPolyBlocks(h))), expected, tolerance);
          EXPECT_NEAR(0.5 * SquaredNorm(Evaluate(*pp, PolyPolyBlocks(h))), expected, tolerance);
          // Bounds of the smoothing: ℓℓ* ≤ ½‖r‖² ≤ ℓ(ℓ* + ε) (units of L).
          EXPECT_GE(expected, length * inv_length * std::abs(dual));
          EXPECT_LE(expected, length * inv_length * (std::abs(dual) + eps));
        }
      }
    }
  }
}

// The reason for the four-entry residual: at a flat hinge, Gauss–Newton's
// JᵀJ along a bending motion of b equals the second derivative of ½‖r‖²,
// ℓ/(Lε)·(dℓ*/dt)² (a scalar sqrt(2ℓ sqrt(ℓ*² + ε²)) would give 0 there).
TEST(SmoothedDihedralEnergy, GaussNewtonModelIsExactAtAFlatHinge) {
  const double eps = kSmoothedDihedralEpsilon;
  for (double length : {1.0, 2.0}) {
    const Hinge h = KnownHinge(0.0, length);
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(SmoothedDihedralTriTri(1.0, eps)));
    Blocks jacobians;
    Evaluate(*cost, TriTriBlocks(h), &jacobians);
    // Motion of b along z; J_b is 4×3 row-major.
    double jtj = 0;
    for (int row = 0; row < 4; ++row) jtj += std::pow(jacobians[3][row * 3 + 2], 2);
    const double step = 1e-5;
    auto energy = [&](double t) {
      Hinge moved = h;
      moved.b += t * Vec3::UnitZ();
      return 0.5 * SquaredNorm(Evaluate(*cost, TriTriBlocks(moved)));
    };
    const double second = (energy(step) - 2 * energy(0) + energy(-step)) / (step * step);
    EXPECT_GT(jtj, 1.0);  // ℓ/ε · (dℓ*/dt)²: of order 10³
    EXPECT_NEAR(jtj / second, 1.0, kSecondDifferenceTolerance) << jtj << " vs " << second;
  }
}

TEST(SmoothedDihedralEnergy, InvariantUnderRigidMotionScalingAndSides) {
  std::mt19937 rng(kSeed + 1);
  const double eps = kSmoothedDihedralEpsilon;
  for (int i = 0; i < kNumSamples; ++i) {
    SCOPED_TRACE(i);
    const Hinge h = RandomHinge(rng, 1.0);
    const double inv_length = 1.0 / (h.w - h.v).norm();
    const std::vector<double> r = TriTri(h, inv_length, eps);
    const Eigen::Matrix3d rot = RandomRotation(rng);
    const std::vector<double> moved = TriTri(Moved(h, rot, RandomVec(rng, 10.0), 1.0), inv_length, eps);
    EXPECT_NEAR((AsVec(moved) - rot * AsVec(r)).norm(), 0.0, kRegularisedTolerance);
    EXPECT_NEAR(moved[3], r[3], kRegularisedTolerance);
    for (double s : {1e-3, 0.37, 1e3}) {
      const std::vector<double> scaled =
          TriTri(Moved(h, Eigen::Matrix3d::Identity(), Vec3::Zero(), s), inv_length / s, eps);
      for (int k = 0; k < 4; ++k) EXPECT_NEAR(scaled[k], r[k], kRegularisedTolerance) << s;
    }
    // Traversing the edge the other way swaps f and f′: d flips, the rest stays.
    const std::vector<double> swapped = TriTri({h.w, h.v, h.b, h.a}, inv_length, eps);
    EXPECT_NEAR((AsVec(swapped) + AsVec(r)).norm(), 0.0, kTolerance);
    EXPECT_NEAR(swapped[3], r[3], kTolerance);
  }
}

}  // namespace
}  // namespace archgeo
