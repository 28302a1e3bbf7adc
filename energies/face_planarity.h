// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Face planarity through an auxiliary plane, one residual per (face, vertex):
//
//   r = (n·(v − c) − d) / L
//
//   [DESIGN.md "face_planarity"; Pellis 2019, Fig. 18 (planarity of faces with
//    more than four vertices via a per-face normal and offset)]
//
// Variables: n, the face's unit normal (3; the builder puts
// ceres::SphereManifold<3> on it so ‖n‖ = 1 is kept exactly), d, the plane's
// offset from the fixed centre c (1), and v, one vertex of the face (3). c is a
// constant (the face centroid at build time), so the plane is
// {x : n·(x − c) = d} and d stays small and well-conditioned instead of being
// the distance from the world origin. With ‖n‖ = 1, n·(v − c) − d is the
// signed distance of v from that plane; the face is planar iff all its
// residuals vanish. Used for polygons with more than four vertices (quads use
// pq_diagonal, which needs no auxiliary variables).
//
// Units / normalisation: L = 1/inv_length is a fixed length chosen by the
// builder (e.g. the face's mean edge or diagonal length), r is unit-free;
// d has units of length. Ceres minimises ½Σr².
//
// Singular configurations: none; the residual is linear in v and d and
// bilinear in (n, v). The functor does not normalise n (the manifold does), so
// a non-unit n still gives a finite residual and Jacobian; n = 0 gives
// r = −d/L (no NaN). Never returns false.
//
// Invariances: under a rigid motion x → R x + t applied to v and c, with
// n → R n and d unchanged, r is unchanged; under uniform scaling x → s x with
// d → s d and inv_length → inv_length / s, r is unchanged. Flipping (n, d) →
// (−n, −d) flips the sign of r.
#ifndef ARCHGEO_ENERGIES_FACE_PLANARITY_H_
#define ARCHGEO_ENERGIES_FACE_PLANARITY_H_

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

struct FacePlanarity {
  using Shape = CostShape<1, 3, 1, 3>;

  // center: 3 doubles, the fixed reference point c of the face's plane;
  // inv_length: 1/L.
  FacePlanarity(const double center[3], double inv_length)
      : center(center[0], center[1], center[2]), inv_length(inv_length) {}

  // n: 3 doubles (unit normal), d: 1 double (offset), v: 3 doubles (vertex);
  // residual: 1 double.
  template <typename T>
  bool operator()(const T* n_ptr, const T* d_ptr, const T* v_ptr,
                  T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> n(n_ptr);
    const Eigen::Map<const Vec3> v(v_ptr);
    residual[0] = (n.dot(v - center.cast<T>()) - d_ptr[0]) * T(inv_length);
    return true;
  }

  Eigen::Vector3d center;
  double inv_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_FACE_PLANARITY_H_
