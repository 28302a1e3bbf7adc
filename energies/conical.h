// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Conical-mesh angle condition at an interior vertex v of valence 4 — the
// YAML term `conical`, one residual per vertex star (v; w1, w2, w3, w4):
//
//   r = (ω1 + ω3) − (ω2 + ω4)            [radians]
//   ω_k = atan2(‖e_k × e_{k+1}‖_ε, e_k·e_{k+1}),   e_k = w_k − v,  e_5 = e_1,
//   ‖c‖_ε = sqrt(‖c‖² + (ε L²)²),  ε = kConicalEpsilon
//
//   [Liu, Pottmann, Wallner, Yang, Wang 2006, "Geometric modeling with
//    conical meshes and developable surfaces", §3 (angle criterion: a vertex
//    of valence four with planar faces is conical iff ω1 + ω3 = ω2 + ω4),
//    via Gebreiter 2012, §10.1 "Conical meshes"]
//
// Star order: w1 … w4 are v's neighbours in cyclic order around v (counter-
// clockwise about the face orientation, i.e. following the faces), so that
// v, w_k, w_{k+1} are three corners of the k-th face at v; ω_k is that face's
// corner angle at v. For a mesh with planar faces, r = 0 iff the four face
// planes at v are tangent to a common right circular cone with apex v — the
// condition for offset faces at constant distance (the offset planes of the
// four faces meet in one point, analysis/goal_metrics.h FaceOffsetCheck). The
// angle criterion alone does not make faces planar: combine with
// pq_diagonal. Only valence 4: at other valences the criterion is different.
// At a flat vertex (four coplanar faces) every offset works, yet r = 0 still
// asks for ω1 + ω3 = π there: the angle condition is the limit of the
// conical condition for nearly flat stars and stricter than needed on exactly
// flat ones (e.g. a planar parallelogram grid of angle α has r = 4α − 2π).
//
// Angles via atan2 of the cross and dot products: accurate for every angle
// in [0, π] (acos of the normalised dot loses half the digits near 0 and π,
// and its derivative is infinite there).
//
// Units / normalisation: radians, unit-free. L = 1/inv_length (the builder's
// mean edge length of the star) only scales the regularisation.
//
// Singular configurations: a zero-length edge (w_k = v), or collinear
// consecutive edges (ω_k = 0 or π), make e_k × e_{k+1} = 0 where ‖·‖ is not
// differentiable; it is regularised with εL², so ω_k stays finite (at
// w_k = v: atan2(εL², 0) = π/2) and the Jacobian is bounded by about 1/(εL)
// per unit of length. For ‖e_k × e_{k+1}‖ ≫ εL² the angle error is below
// ½(εL²)²/(‖e_k‖‖e_{k+1}‖ ‖e_k × e_{k+1}‖). Never returns false.
//
// Invariances: rigid motions and uniform scaling x → s x with
// inv_length → inv_length / s (r unchanged: it is made of angles).
// Relabelling: a cyclic shift by one (w2, w3, w4, w1) flips the sign of r, a
// shift by two keeps it; reversing the order flips it when w1 stays first
// (w1, w4, w3, w2) and keeps it for (w4, w3, w2, w1). Only r² enters the
// energy, so any cyclic order around v will do.
#ifndef ARCHGEO_ENERGIES_CONICAL_H_
#define ARCHGEO_ENERGIES_CONICAL_H_

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()

#include "energies/autodiff.h"

namespace archgeo {

// Regularisation of ‖e_k × e_{k+1}‖, relative to L² (see above).
inline constexpr double kConicalEpsilon = 1e-8;

// The angle between a and b in [0, π]: atan2(‖a × b‖_δ, a·b) with
// ‖c‖_δ = sqrt(‖c‖² + δ²).
template <typename T>
T RegularisedAngle(const Eigen::Matrix<T, 3, 1>& a,
                   const Eigen::Matrix<T, 3, 1>& b, double delta) {
  using std::atan2;
  using std::sqrt;
  return atan2(sqrt(a.cross(b).squaredNorm() + T(delta * delta)), a.dot(b));
}

struct Conical {
  using Shape = CostShape<1, 3, 3, 3, 3, 3>;

  // inv_length: 1/L, L > 0 the builder's mean edge length of the star.
  explicit Conical(double inv_length) : inv_length(inv_length) {}

  // v: 3 doubles, the vertex; w1..w4: 3 doubles each, its neighbours in
  // cyclic order; residual: 1 double (radians).
  template <typename T>
  bool operator()(const T* v_ptr, const T* w1_ptr, const T* w2_ptr,
                  const T* w3_ptr, const T* w4_ptr, T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> v(v_ptr);
    const Vec3 e[4] = {
        Eigen::Map<const Vec3>(w1_ptr) - v, Eigen::Map<const Vec3>(w2_ptr) - v,
        Eigen::Map<const Vec3>(w3_ptr) - v, Eigen::Map<const Vec3>(w4_ptr) - v};
    const double delta = kConicalEpsilon / (inv_length * inv_length);
    T omega[4];
    for (int k = 0; k < 4; ++k) {
      omega[k] = RegularisedAngle<T>(e[k], e[(k + 1) % 4], delta);
    }
    residual[0] = (omega[0] + omega[2]) - (omega[1] + omega[3]);
    return true;
  }

  double inv_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_CONICAL_H_
