// Shared helpers for the energy tests (test_energies, test_anet_energies,
// test_smoothness_energies): evaluate a Ceres cost function on plain blocks,
// compare autodiff with numeric differences (GradientChecker), check that
// degenerate inputs stay finite, random rigid motions.
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <ceres/cost_function.h>
#include <ceres/gradient_checker.h>
#include <ceres/manifold.h>
#include <gtest/gtest.h>

namespace archgeo::energy_checks {

using Vec3 = Eigen::Vector3d;
using Blocks = std::vector<std::vector<double>>;

// GradientChecker: relative precision of autodiff vs numeric Jacobians.
inline constexpr double kRelativePrecision = 1e-6;
// Ridders' default first step (32 × 1e-2 × |x|) exceeds the size of a unit
// element placed a few units from the origin; start well inside it.
inline constexpr double kRiddersRelativeInitialStep = 1e-4;

inline Vec3 RandomVec(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return Vec3(u(rng), u(rng), u(rng));
}

inline Eigen::Matrix3d RandomRotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  q.normalize();
  return q.toRotationMatrix();
}

inline std::vector<double> ToBlock(const Vec3& x) { return {x[0], x[1], x[2]}; }

inline Vec3 AsVec(const std::vector<double>& r) { return Vec3(r[0], r[1], r[2]); }

inline std::vector<const double*> Pointers(const Blocks& blocks) {
  std::vector<const double*> p;
  for (const auto& b : blocks) p.push_back(b.data());
  return p;
}

// Evaluates `cost` with Jacobians; returns residuals, fills `jacobians`
// (row-major, one per block). Expects Evaluate to succeed.
inline std::vector<double> Evaluate(const ceres::CostFunction& cost, const Blocks& blocks,
                                    Blocks* jacobians = nullptr) {
  const auto& sizes = cost.parameter_block_sizes();
  EXPECT_EQ(sizes.size(), blocks.size());
  std::vector<double> residuals(cost.num_residuals());
  Blocks jac(blocks.size());
  std::vector<double*> jac_ptrs;
  for (size_t i = 0; i < blocks.size(); ++i) {
    EXPECT_EQ(static_cast<size_t>(sizes[i]), blocks[i].size());
    jac[i].assign(cost.num_residuals() * sizes[i], 0.0);
    jac_ptrs.push_back(jac[i].data());
  }
  const auto params = Pointers(blocks);
  EXPECT_TRUE(cost.Evaluate(params.data(), residuals.data(), jac_ptrs.data()));
  if (jacobians != nullptr) *jacobians = jac;
  return residuals;
}

inline bool AllFinite(const std::vector<double>& x) {
  for (double v : x) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

// Residuals and every Jacobian entry finite.
inline void ExpectFiniteEverywhere(const ceres::CostFunction& cost, const Blocks& blocks) {
  Blocks jacobians;
  const std::vector<double> r = Evaluate(cost, blocks, &jacobians);
  EXPECT_TRUE(AllFinite(r));
  for (const auto& j : jacobians) EXPECT_TRUE(AllFinite(j));
}

// Autodiff against numeric differences (typed null manifolds when none).
inline void ExpectGradientsMatch(const ceres::CostFunction& cost, const Blocks& blocks,
                                 const std::vector<const ceres::Manifold*>* manifolds = nullptr,
                                 double relative_precision = kRelativePrecision) {
  ceres::NumericDiffOptions options;
  options.ridders_relative_initial_step_size = kRiddersRelativeInitialStep;
  ceres::GradientChecker checker(&cost, manifolds, options);
  ceres::GradientChecker::ProbeResults results;
  const auto params = Pointers(blocks);
  EXPECT_TRUE(checker.Probe(params.data(), relative_precision, &results)) << results.error_log;
}

}  // namespace archgeo::energy_checks
