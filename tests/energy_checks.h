// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Shared helpers for the energy tests (test_energies, test_anet_energies,
// test_smoothness_energies, test_smoothed_dihedral_energy): evaluate a Ceres
// cost function on plain blocks, compare autodiff with numeric differences
// (GradientChecker), check that degenerate inputs stay finite, random rigid
// motions, and the hinges (two triangles at an edge) of the dihedral
// energies.
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
using Manifolds = std::vector<const ceres::Manifold*>;  // one per block, null: Euclidean

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
                                 const Manifolds* manifolds = nullptr,
                                 double relative_precision = kRelativePrecision) {
  ceres::NumericDiffOptions options;
  options.ridders_relative_initial_step_size = kRiddersRelativeInitialStep;
  ceres::GradientChecker checker(&cost, manifolds, options);
  ceres::GradientChecker::ProbeResults results;
  const auto params = Pointers(blocks);
  EXPECT_TRUE(checker.Probe(params.data(), relative_precision, &results)) << results.error_log;
}

inline double SquaredNorm(const std::vector<double>& r) {
  double s = 0.0;
  for (double v : r) s += v * v;
  return s;
}

inline Vec3 UnitNormal(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  return (p1 - p0).cross(p2 - p0).normalized();
}

// Two triangles f = (v, w, a) (left of v→w) and f′ = (w, v, b)
// (energies/dihedral_hinge.h).
struct Hinge {
  Vec3 v, w, a, b;
};

inline Hinge Moved(const Hinge& h, const Eigen::Matrix3d& rot, const Vec3& shift, double scale) {
  return {scale * (rot * h.v) + shift, scale * (rot * h.w) + shift, scale * (rot * h.a) + shift,
          scale * (rot * h.b) + shift};
}

// A well-shaped hinge, randomly bent (bend = 0: flat; 1: moderately bent)
// and placed.
inline Hinge RandomHinge(std::mt19937& rng, double bend = 1.0) {
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  const Hinge flat = {Vec3(0, 0, 0), Vec3(1, 0, 0),
                      Vec3(0.5 + u(rng), 0.9 + 0.3 * u(rng), bend * u(rng)),
                      Vec3(0.5 + u(rng), -0.9 + 0.3 * u(rng), bend * u(rng))};
  std::uniform_real_distribution<double> scale(0.5, 2.0);
  return Moved(flat, RandomRotation(rng), RandomVec(rng, 5.0), scale(rng));
}

// Hinge with dihedral angle alpha at an edge of length `length` along x: f in
// the xy-plane (normal +z), f′ rotated about the x-axis by alpha.
inline Hinge KnownHinge(double alpha, double length) {
  const Vec3 b_flat(0.4 * length, -0.8 * length, 0.0);
  return {Vec3(0, 0, 0), Vec3(length, 0, 0), Vec3(0.3 * length, 0.7 * length, 0),
          Eigen::AngleAxisd(alpha, Vec3::UnitX()) * b_flat};
}

// The blocks of the hinge functors (v, w, a, b), (v, w, a, n_right),
// (v, w, n_left, n_right), the polygons' normals the exact normals of the
// hinge's faces.
inline Blocks TriTriBlocks(const Hinge& h) {
  return {ToBlock(h.v), ToBlock(h.w), ToBlock(h.a), ToBlock(h.b)};
}
inline Blocks TriPolyBlocks(const Hinge& h) {
  return {ToBlock(h.v), ToBlock(h.w), ToBlock(h.a), ToBlock(UnitNormal(h.w, h.v, h.b))};
}
inline Blocks PolyPolyBlocks(const Hinge& h) {
  return {ToBlock(h.v), ToBlock(h.w), ToBlock(UnitNormal(h.v, h.w, h.a)),
          ToBlock(UnitNormal(h.w, h.v, h.b))};
}

}  // namespace archgeo::energy_checks
