// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Proximity to a reference surface through its tangent plane, one residual per
// vertex:
//
//   r = n·(v − p) / L
//
//   [Zadravec 2010, §6 eq. 8, f_prox = Σ_v ‖v − τ_π(v)‖²; Shi 2014, §3.2, F_prox]
//
// p is the closest point π(v) of the reference surface to v and n the
// reference's unit normal there; both are constants, re-computed by the
// builder every outer iteration (re-linearisation), so r is the signed
// distance of v from the tangent plane τ_π(v). Shi's F_prox adds the squared
// distance to p itself: that part is the anchor energy (energies/anchor.h)
// with target p, weighted separately by the builder.
//
// Units / normalisation: L = 1/inv_length is a fixed length chosen by the
// builder (e.g. the reference's bounding-box diagonal or mean edge length),
// so r is unit-free. Ceres minimises ½Σr².
//
// Singular configurations: none in v (r is affine in v). The constructor
// normalises the given normal, so a non-unit normal is accepted; a zero normal
// (e.g. from a degenerate reference triangle) yields r ≡ 0 with a zero
// Jacobian — no pull, no NaN — and the builder's anchor term then carries the
// proximity. Never returns false.
//
// Invariances: rigid motions x → R x + t applied to v and p, with n → R n
// (r unchanged); uniform scaling x → s x with inv_length → inv_length / s
// (r unchanged); flipping n flips the sign of r.
#ifndef ARCHGEO_ENERGIES_PROXIMITY_H_
#define ARCHGEO_ENERGIES_PROXIMITY_H_

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

struct Proximity {
  using Shape = CostShape<1, 3>;

  // point: 3 doubles, the closest reference point p; normal: 3 doubles, the
  // reference normal at p (normalised here; zero stays zero); inv_length: 1/L.
  Proximity(const double point[3], const double normal[3], double inv_length)
      : point(point[0], point[1], point[2]), inv_length(inv_length) {
    const Eigen::Vector3d n(normal[0], normal[1], normal[2]);
    const double length = n.norm();
    this->normal = length > 0.0 ? Eigen::Vector3d(n / length)
                                : Eigen::Vector3d::Zero();
  }

  // v: 3 doubles, the vertex; residual: 1 double.
  template <typename T>
  bool operator()(const T* v_ptr, T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> v(v_ptr);
    residual[0] = normal.cast<T>().dot(v - point.cast<T>()) * T(inv_length);
    return true;
  }

  Eigen::Vector3d point;
  Eigen::Vector3d normal;  // unit, or zero
  double inv_length;
};

// The functor after checking its input (CHECKs: point and normal finite,
// inv_length finite and > 0); proximity and tangent_plane add it.
Proximity CheckedProximity(const double point[3], const double normal[3], double inv_length);

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_PROXIMITY_H_
