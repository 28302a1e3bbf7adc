// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Principal-symmetric triangle meshes: the three conditions of Pellis 2019,
// §2.3, in the implementation of §5.2, with a sphere parametrisation that
// admits planes.
//
// Sphere of a vertex. Each valence-6 vertex v carries a unit normal n(v)
// (3 doubles, ceres::SphereManifold<3>) and a signed curvature κ(v)
// (1 double, units 1/length), and the sphere through v
//
//   Σ(v) = {x : κ ‖x − v‖² − 2 n·(x − v) = 0},   centre c(v) = v + n/κ,
//   radius 1/|κ|, tangent plane at v ⟂ n.
//
// κ = 0 is the tangent plane itself (a flat sphere), so nearly flat regions
// and the passage of κ through 0 are regular points of the parametrisation.
// The paper's variables (centres c(v), §5.2) go to infinity there, and the
// radius ‖v − c‖ is ill-conditioned for large radii; this is why we use
// (n, κ) instead. Every residual below is polynomial in its variables, so
// none has a singular configuration: κ = 0, n = 0, coincident points all give
// finite residuals and Jacobians, and the functors never return false.
//
// 1. Co-sphericity [§2.3 first condition, Schling 2018; §5.2
//    ‖v − c(v)‖² = ‖w − c(v)‖²], one residual per non-principal neighbour w
//    (four per valence-6 vertex):
//
//      r = (κ ‖w − v‖² − 2 n·(w − v)) / (2L)
//
//    r = 0 iff w ∈ Σ(v). For κ ≠ 0 this is κ(‖w − c‖² − 1/κ²)/(2L) = the
//    paper's constraint multiplied by κ/(2L); with d = ‖w − c‖ − 1/|κ| the
//    signed distance of w from the sphere (> 0 outside),
//      r = sign(κ) (d/L)(1 + |κ| d / 2),
//    and for κ = 0, r = −n·(w − v)/L, the signed distance from the plane. So
//    |r| ≈ distance / L in both regimes (unit-free).
//
// Units / normalisation: L = 1/inv_length a fixed length (1 in the canonical
// frame); κ has units 1/length, n, n(e) and δ are unit-free.
//
// Invariances: rigid motions x → R x + t with n → R n, n(e) → R n(e), κ and δ
// unchanged (r unchanged); uniform scaling x → s x with κ → κ/s and
// inv_length → inv_length / s (r unchanged). (n, κ) → (−n, −κ) describes the
// same sphere and flips the sign of the co-sphericity residual, leaves the
// saddle residual unchanged; n(e) → −n(e) flips the strip residuals.
#ifndef ARCHGEO_ENERGIES_CO_SPHERICAL_H_
#define ARCHGEO_ENERGIES_CO_SPHERICAL_H_

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

// 1. A non-principal neighbour w on the sphere Σ(v).
struct CoSpherical {
  using Shape = CostShape<1, 3, 3, 1, 3>;

  // inv_length: 1/L > 0.
  explicit CoSpherical(double inv_length) : inv_length(inv_length) {}

  // v: 3 doubles (the vertex), n: 3 doubles (unit sphere normal at v),
  // kappa: 1 double (signed curvature, 1/length), w: 3 doubles (the
  // neighbour); residual: 1 double.
  template <typename T>
  bool operator()(const T* v_ptr, const T* n_ptr, const T* kappa_ptr,
                  const T* w_ptr, T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> v(v_ptr);
    const Eigen::Map<const Vec3> n(n_ptr);
    const Eigen::Map<const Vec3> w(w_ptr);
    const Vec3 d = (w - v) * T(inv_length);   // unit-free
    const T kappa = kappa_ptr[0] / T(inv_length);  // κ L, unit-free
    residual[0] = T(0.5) * kappa * d.squaredNorm() - n.dot(d);
    return true;
  }

  double inv_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_CO_SPHERICAL_H_
