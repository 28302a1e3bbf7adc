// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Prescribed conjugate direction in one face, 1 residual:
//
//   r = (z_N − p_d) × D̂,   p_d = e1 + (cos 2θ, sin 2θ),
//   D = 2 (m22, −m12) − (m11 + m22) p_d = (m11 + m22)(z_M − p_d),   D̂ = D/‖D‖
//
//   [Zadravec 2010, §4: "we must penalize deviation of z_N,f from the straight
//    line ([v_f] ∩ c_f) ∨ ([w_f] ∩ c_f) … we add the square of this distance"]
//
// d (angle θ in the face frame) is the prescribed direction, p_d = [d] ∩ c
// its point on the auxiliary circle. By Prop. 1 the point of the direction w
// conjugate to d lies on the line through p_d and z_M, so the pair chosen by
// z_N (Prop. 2: the chord of c through z_M and z_N) contains d iff z_N lies on
// that line; r is the signed distance of z_N from it (a × b = a1 b2 − a2 b1).
// D is written homogeneously so that z_M at infinity (m11 + m22 = 0) is
// handled: the line then runs through p_d parallel to (m22, −m12).
//
// Units / normalisation: dimensionless (c has radius 1). Ceres minimises ½Σr².
//
// Singular configurations: D = 0 when z_M = p_d, i.e. d is a principal
// direction of zero curvature (M d = 0): every direction is then conjugate to
// d and the condition is void (also for M = 0). The factory CHECKs that D is
// not 0 relative to ‖M‖; TcdPrescribedLine tells callers beforehand. An
// asymptotic d (dᵀ M d = 0) gives the tangent of c at p_d: the pair (d, d) is
// not transverse, and transversality terms will fight the constraint. The
// residual itself is linear in z_N; never returns false.
//
// Invariances: rotating the face frame by φ (d → R(−φ) d, M → RᵀMR, z_N → e1 +
// R(−2φ)(z_N − e1)) keeps r; scaling M by s ≠ 0 keeps r (D̂ is normalised).
#ifndef ARCHGEO_ENERGIES_TCD_PRESCRIBED_DIRECTION_H_
#define ARCHGEO_ENERGIES_TCD_PRESCRIBED_DIRECTION_H_

#include <cmath>

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

// Relative size of D (to ‖M‖_F) below which the condition is void.
inline constexpr double kTcdPrescribedMinDirection = 1e-9;

// The line of the condition: the point p_d and the unit direction D̂. m: m11,
// m12, m22; d: 2 doubles, nonzero. Returns false (outputs untouched) when the
// condition is void (see above) or d = 0.
inline bool TcdPrescribedLine(const double m[3], const double d[2], Eigen::Vector2d* point,
                              Eigen::Vector2d* direction) {
  const double theta = std::atan2(d[1], d[0]);
  if (d[0] == 0.0 && d[1] == 0.0) return false;
  const Eigen::Vector2d p(1.0 + std::cos(2.0 * theta), std::sin(2.0 * theta));
  const Eigen::Vector2d D = 2.0 * Eigen::Vector2d(m[2], -m[1]) - (m[0] + m[2]) * p;
  const double size = std::sqrt(m[0] * m[0] + 2.0 * m[1] * m[1] + m[2] * m[2]);
  if (!(D.norm() > kTcdPrescribedMinDirection * size)) return false;
  *point = p;
  *direction = D.normalized();
  return true;
}

struct TcdPrescribedDirection {
  using Shape = CostShape<1, 2>;

  // point, direction: the line from TcdPrescribedLine (direction unit).
  TcdPrescribedDirection(const Eigen::Vector2d& point, const Eigen::Vector2d& direction)
      : point(point), direction(direction) {}

  // z: 2 doubles (z_N of the face, own frame); residual: 1.
  template <typename T>
  bool operator()(const T* z, T* residual) const {
    const T a = z[0] - T(point.x()), b = z[1] - T(point.y());
    residual[0] = a * T(direction.y()) - b * T(direction.x());
    return true;
  }

  Eigen::Vector2d point, direction;
};

// The functor of the prescribed direction `direction` (2 doubles, the face
// frame) at a face of conjugacy matrix M (`m`, 3 doubles), after checking
// them (CHECKs: finite, and TcdPrescribedLine finds the line).
TcdPrescribedDirection CheckedTcdPrescribedDirection(const double m[3], const double direction[2]);

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_TCD_PRESCRIBED_DIRECTION_H_
