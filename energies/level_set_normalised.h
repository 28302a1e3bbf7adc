// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Alignment of a level-set function with a direction field, ignoring spacing,
// one triangle f, 2 residuals:
//
//   r = sqrt(A_f / A_Φ) · (∇g / sqrt(‖∇g‖² + ε²) − R v̂),   v̂ = v / ‖v‖
//
//   [Zadravec 2010, §5 eq. 6: Σ_f (area(f)/area(Φ)) ⟨v_f, ∇g_f/‖∇g_f‖⟩² → min,
//    initialised from a solution of eq. 5]
//
// Re-derived: eq. 5 asks ∇g = R v (R the rotation by +90° in the face), i.e.
// level sets of g parallel to v with spacing 1/‖v‖; eq. 6 keeps only the
// direction. With θ the angle between ∇g and R v̂, the paper's summand is
// ⟨v̂, ∇ĝ⟩² = sin²θ, ours ‖∇ĝ − R v̂‖² = 4 sin²(θ/2): equal to second order in
// θ (both θ² + O(θ⁴)), but the paper's also vanishes for θ = π — a function
// folded along a line (∇g = −R v beyond it) costs nothing, and in a solve
// with cut jumps such folds appeared next to singularities (level sets
// turning back, fans of thin faces in the layout). Ours is zero only for ∇g
// along +R v, whatever ‖∇g‖, and independent of ‖v‖.
//
// Units / normalisation: dimensionless. Ceres minimises ½Σ‖r‖².
//
// Singular configurations: ∇g = 0 makes the direction undefined; the norm is
// regularised with ε = kLevelSetGradientEpsilon · gradient_scale, where
// gradient_scale is the expected size of ‖∇g‖ (1 when g has the units of
// length and comes from eq. 5 with unit v). A constant g has ‖r‖² = A_f/A_Φ
// (the largest value but one, θ = π gives 4 A_f/A_Φ): unlike the paper's,
// this functional is not minimised by a constant. Never returns false.
//
// Invariances: rigid motions of the face frame (corners and v; r turns with
// the frame, ‖r‖ kept); uniform scaling x → s x (with g → s g,
// gradient_scale kept); g → a g + b with a > 0 up to the regularisation;
// v → c v for c > 0.
#ifndef ARCHGEO_ENERGIES_LEVEL_SET_NORMALISED_H_
#define ARCHGEO_ENERGIES_LEVEL_SET_NORMALISED_H_

#include <cmath>

#include <Eigen/Core>

#include "energies/level_set_gradient.h"

#include "energies/autodiff.h"

namespace archgeo {

inline constexpr double kLevelSetGradientEpsilon = 1e-6;

struct LevelSetNormalised {
  using Shape = CostShape<2, 1, 1, 1>;

  // corners: 6 doubles (face frame, counter-clockwise); v: 2 doubles, nonzero;
  // inv_total_area: 1 / A_Φ; gradient_scale: expected ‖∇g‖ > 0.
  LevelSetNormalised(const double corners[6], const double v[2], double inv_total_area,
                     double gradient_scale)
      : gradient(corners),
        direction(Eigen::Vector2d(v[0], v[1]).normalized()),
        scale(std::sqrt(gradient.area * inv_total_area)),
        epsilon(kLevelSetGradientEpsilon * gradient_scale) {}

  // g0, g1, g2: 1 double each, the corner values; residual: 2.
  template <typename T>
  bool operator()(const T* g0, const T* g1, const T* g2, T* residual) const {
    using std::sqrt;
    const Eigen::Matrix<T, 2, 1> grad = gradient(g0[0], g1[0], g2[0]);
    const T norm = sqrt(grad.squaredNorm() + T(epsilon * epsilon));
    residual[0] = T(scale) * (grad.x() / norm + T(direction.y()));
    residual[1] = T(scale) * (grad.y() / norm - T(direction.x()));
    return true;
  }

  TriangleGradient gradient;
  Eigen::Vector2d direction;  // v̂
  double scale;               // sqrt(A_f / A_Φ)
  double epsilon;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_LEVEL_SET_NORMALISED_H_
