// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Polyline fairness, one 3-vector residual per triple (u, v, w) of consecutive
// vertices on a mesh polyline:
//
//   r = ((u − 2v + w) − Δ⁰) / L
//
//   [Zadravec 2010, §6 eq. 8, f_fair = Σ_(uvw) ‖Δ²_uvw − Δ²,orig_uvw‖²]
//
// Δ⁰ = target is a constant: the original second difference Δ²,orig_uvw
// computed at build time (relative fairness, Zadravec's f_fair: keeps the
// initial spacing and bending of the polylines), or zero (absolute fairness:
// straight, evenly spaced polylines are optimal).
//
// Units / normalisation: L = 1/inv_length is a fixed length chosen by the
// builder (e.g. the mean edge length), so r is unit-free. Ceres minimises ½Σ‖r‖².
//
// Singular configurations: none; r is affine in (u, v, w), so coincident or
// collinear points give finite residuals and constant Jacobians
// (±I/L, −2I/L). Never returns false.
//
// Invariances: translation (with Δ⁰ unchanged); rotation x → R x with
// Δ⁰ → R Δ⁰ (r → R r, so ‖r‖ is unchanged); uniform scaling x → s x with
// Δ⁰ → s Δ⁰ and inv_length → inv_length / s (r unchanged). Reversing the
// triple (w, v, u) leaves r unchanged.
//
// Third differences (FairnessThird below), one 3-vector residual per
// quadruple (a, b, c, d) = (v_{i−1}, v_i, v_{i+1}, v_{i+2}) of consecutive
// polyline vertices:
//
//   r = ((d − 3c + 3b − a) − Δ⁰) / L
//
//   [Shi, Wang, Pottmann 2014, §3.2 step 1: "sum of squares of second or third
//    order differences at vertices of all those mesh polylines which should be
//    fair; we follow Deng et al. [2011]"]
//
// Third differences vanish on polylines sampled from a quadratic (parabolic)
// curve at even spacing, so unlike second differences they do not pull curved
// polylines straight: a bent asymptotic polyline keeps its bending and only
// the change of bending is penalised. Δ⁰ (target) is the original third
// difference (relative fairness) or zero. Units, singular set (none: r is
// affine, Jacobian blocks −I/L, 3I/L, −3I/L, I/L) and invariances (translation;
// rotation with Δ⁰ → R Δ⁰; scaling with Δ⁰ → s Δ⁰, inv_length → inv_length / s)
// as for Fairness. Reversing the quadruple to (d, c, b, a) together with
// Δ⁰ → −Δ⁰ maps r to −r (so ‖r‖ is unchanged).
#ifndef ARCHGEO_ENERGIES_FAIRNESS_H_
#define ARCHGEO_ENERGIES_FAIRNESS_H_

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

struct Fairness {
  using Shape = CostShape<3, 3, 3, 3>;

  // target: 3 doubles, the second difference Δ⁰ to keep (or zero);
  // inv_length: 1/L.
  Fairness(const double target[3], double inv_length)
      : target(target[0], target[1], target[2]), inv_length(inv_length) {}

  // u, v, w: 3 doubles each, consecutive polyline vertices; residual: 3 doubles.
  template <typename T>
  bool operator()(const T* u_ptr, const T* v_ptr, const T* w_ptr,
                  T* residual_ptr) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> u(u_ptr);
    const Eigen::Map<const Vec3> v(v_ptr);
    const Eigen::Map<const Vec3> w(w_ptr);
    Eigen::Map<Vec3> residual(residual_ptr);
    residual = ((u - T(2.0) * v + w) - target.cast<T>()) * T(inv_length);
    return true;
  }

  Eigen::Vector3d target;
  double inv_length;
};

struct FairnessThird {
  using Shape = CostShape<3, 3, 3, 3, 3>;

  // target: 3 doubles, the third difference Δ⁰ to keep (or zero);
  // inv_length: 1/L.
  FairnessThird(const double target[3], double inv_length)
      : target(target[0], target[1], target[2]), inv_length(inv_length) {}

  // a, b, c, d: 3 doubles each, consecutive polyline vertices v_{i−1}, v_i,
  // v_{i+1}, v_{i+2}; residual: 3 doubles.
  template <typename T>
  bool operator()(const T* a_ptr, const T* b_ptr, const T* c_ptr,
                  const T* d_ptr, T* residual_ptr) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> a(a_ptr);
    const Eigen::Map<const Vec3> b(b_ptr);
    const Eigen::Map<const Vec3> c(c_ptr);
    const Eigen::Map<const Vec3> d(d_ptr);
    Eigen::Map<Vec3> residual(residual_ptr);
    residual = ((d - T(3.0) * c + T(3.0) * b - a) - target.cast<T>()) *
               T(inv_length);
    return true;
  }

  Eigen::Vector3d target;
  double inv_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_FAIRNESS_H_
