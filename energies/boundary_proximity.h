// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Proximity to the reference boundary through its tangent line, one 3-vector
// residual per boundary vertex:
//
//   r = (I − t tᵀ)(v − p) / L
//
//   [Zadravec 2010, §6 eq. 8, f∂_prox = Σ_(v ∈ V∂) ‖v − T_π̃(v)‖²]
//
// p is the closest point π̃(v) of the reference boundary curve ∂Φ to v and t
// the curve's unit tangent there; both are constants, re-computed by the
// builder every outer iteration (re-linearisation). r is the vector from the
// tangent line T_π̃(v) to v, so ‖r‖·L is the distance of v from that line; v
// may slide freely along the line.
//
// Units / normalisation: L = 1/inv_length is a fixed length chosen by the
// builder, so r is unit-free. Ceres minimises ½Σ‖r‖².
//
// Singular configurations: none in v (r is affine in v). The constructor
// normalises the given tangent; a zero tangent (a degenerate boundary edge)
// gives t = 0 and r = (v − p)/L, the distance to the closest point itself —
// the natural limit, finite, no NaN. Never returns false.
//
// Invariances: rigid motions x → R x + t applied to v and p, with t → R t
// (r → R r, ‖r‖ unchanged); uniform scaling x → s x with
// inv_length → inv_length / s (r unchanged); the sign of t is irrelevant.
#ifndef ARCHGEO_ENERGIES_BOUNDARY_PROXIMITY_H_
#define ARCHGEO_ENERGIES_BOUNDARY_PROXIMITY_H_

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

struct BoundaryProximity {
  using Shape = CostShape<3, 3>;

  // point: 3 doubles, the closest boundary point p; tangent: 3 doubles, the
  // boundary tangent at p (normalised here; zero stays zero); inv_length: 1/L.
  BoundaryProximity(const double point[3], const double tangent[3],
                    double inv_length)
      : point(point[0], point[1], point[2]), inv_length(inv_length) {
    const Eigen::Vector3d t(tangent[0], tangent[1], tangent[2]);
    const double length = t.norm();
    this->tangent = length > 0.0 ? Eigen::Vector3d(t / length)
                                 : Eigen::Vector3d::Zero();
  }

  // v: 3 doubles, the boundary vertex; residual: 3 doubles.
  template <typename T>
  bool operator()(const T* v_ptr, T* residual_ptr) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> v(v_ptr);
    Eigen::Map<Vec3> residual(residual_ptr);
    const Vec3 t = tangent.cast<T>();
    const Vec3 e = v - point.cast<T>();
    residual = (e - t * t.dot(e)) * T(inv_length);
    return true;
  }

  Eigen::Vector3d point;
  Eigen::Vector3d tangent;  // unit, or zero
  double inv_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_BOUNDARY_PROXIMITY_H_
