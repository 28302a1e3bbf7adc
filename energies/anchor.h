// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Soft anchor, one 3-vector residual per vertex:
//
//   r = (v − a) / L
//
//   [Shi 2014, §3.2, F_prox (point-distance part: ‖b_i − b_i^c‖²);
//    DESIGN.md "fixed" vertices held softly]
//
// a = target is a constant: the vertex's original position (soft-anchored
// vertices) or the closest reference point (the point-distance part of
// proximity, re-computed by the builder every outer iteration; the
// tangent-plane part is energies/proximity.h).
//
// Units / normalisation: L = 1/inv_length is a fixed length chosen by the
// builder, so r is unit-free. Ceres minimises ½Σ‖r‖².
//
// Singular configurations: none; r is affine in v (Jacobian I/L), v = a gives
// r = 0. Never returns false.
//
// Invariances: rigid motions applied to v and a (r → R r, ‖r‖ unchanged);
// uniform scaling x → s x with inv_length → inv_length / s (r unchanged).
#ifndef ARCHGEO_ENERGIES_ANCHOR_H_
#define ARCHGEO_ENERGIES_ANCHOR_H_

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

struct Anchor {
  using Shape = CostShape<3, 3>;

  // target: 3 doubles, the anchor point a; inv_length: 1/L.
  Anchor(const double target[3], double inv_length)
      : target(target[0], target[1], target[2]), inv_length(inv_length) {}

  // v: 3 doubles, the vertex; residual: 3 doubles.
  template <typename T>
  bool operator()(const T* v_ptr, T* residual_ptr) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> v(v_ptr);
    Eigen::Map<Vec3> residual(residual_ptr);
    residual = (v - target.cast<T>()) * T(inv_length);
    return true;
  }

  Eigen::Vector3d target;
  double inv_length;
};

// The functor after checking its input (CHECKs: target finite, inv_length
// finite and > 0); the terms anchor, handles, step, displacement_guard and
// proximity's point part add it.
Anchor CheckedAnchor(const double target[3], double inv_length);

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_ANCHOR_H_
