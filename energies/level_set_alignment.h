// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Alignment of a level-set function with a direction field, one triangle f,
// 2 residuals:
//
//   r = sqrt(A_f / A_Φ) · (R v − ∇g)
//
//   [Zadravec 2010, §5 eq. 5: Σ_f area(f) ‖R_f v_f − (∇g)_f‖² → min]
//
// g is piecewise linear with corner values g0, g1, g2 (energies/
// level_set_gradient.h), v the field direction of the face (v of the
// conjugate pair for g, w for h) and R the rotation by +90° about the face
// normal, all in the face's 2-D frame. ∇g = R v makes the level sets of g
// parallel to v with spacing Δw/‖v‖ between g = iΔw and g = (i+1)Δw: unit v
// gives even spacing (the paper's choice). The paper leaves the rotation's
// sense open; +90° (counter-clockwise about n_f) fixes g's sign.
// With v = 0 the residual is −sqrt(A_f/A_Φ) ∇g: the Dirichlet term
// λ_even Σ_f (A_f/A_Φ)‖∇h_f‖² that augments eq. 7 (the text's "area(Φ)" there
// is read as the normalisation of eq. 6/7; see level_set_conjugacy.h).
//
// Units / normalisation: the paper's weight area(f) is normalised by the total
// area A_Φ so that r is unit-free when g has the units of length (∇g and v
// dimensionless). Ceres minimises ½Σ‖r‖².
//
// Singular configurations: none in g (r is affine in g). The corners must
// span a positive area (CHECKed by the factory). Never returns false.
//
// Invariances: rigid motions of the face frame applied to the corners and to
// v (r turns with the frame, ‖r‖ kept; translations do not change ∇g);
// uniform scaling x → s x with g → s g and inv_total_area → inv_total_area/s²
// (r unchanged); adding a constant to g (r unchanged).
#ifndef ARCHGEO_ENERGIES_LEVEL_SET_ALIGNMENT_H_
#define ARCHGEO_ENERGIES_LEVEL_SET_ALIGNMENT_H_

#include <cmath>

#include <Eigen/Core>

#include "energies/level_set_gradient.h"

#include "energies/autodiff.h"

namespace archgeo {

struct LevelSetAlignment {
  using Shape = CostShape<2, 1, 1, 1>;

  // corners: 6 doubles (face frame, counter-clockwise); v: 2 doubles (face
  // frame); inv_total_area: 1 / A_Φ.
  LevelSetAlignment(const double corners[6], const double v[2], double inv_total_area)
      : gradient(corners),
        target(-v[1], v[0]),
        scale(std::sqrt(gradient.area * inv_total_area)) {}

  // g0, g1, g2: 1 double each, the corner values; residual: 2.
  template <typename T>
  bool operator()(const T* g0, const T* g1, const T* g2, T* residual) const {
    const Eigen::Matrix<T, 2, 1> grad = gradient(g0[0], g1[0], g2[0]);
    residual[0] = T(scale) * (T(target.x()) - grad.x());
    residual[1] = T(scale) * (T(target.y()) - grad.y());
    return true;
  }

  TriangleGradient gradient;
  Eigen::Vector2d target;  // R v
  double scale;            // sqrt(A_f / A_Φ)
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_LEVEL_SET_ALIGNMENT_H_
