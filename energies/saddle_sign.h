// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Principal-symmetric triangle meshes [Pellis 2019, §2.3, §5.2]: the vertex
// spheres Σ(v) = (n(v), κ(v)) are those of energies/co_spherical.h.
//
// 3. Saddle sign [§2.3 third condition; §5.2 (v − c(v))ᵀ(v − w) = −δ²_{v,w}],
//    one residual per principal neighbour w of a saddle vertex v, with a
//    scalar dummy variable δ (1 double, unit-free):
//
//      r = κ n·(w − v) + δ²
//
//    Derivation: v − c(v) = −n/κ, so (v − c)·(v − w) = n·(w − v)/κ.
//    Multiplying the paper's condition (v − c)·(v − w) < 0 by κ² > 0 keeps
//    its direction and removes the division: κ n·(w − v) < 0, i.e. w lies
//    strictly on the other side of the tangent plane than the sphere (whose
//    centre is on the side of κ n). The paper's dummy δ_p (a length) becomes
//    δ = |κ| δ_p, and r = κ² ((v − c)·(v − w) + δ_p²). r can vanish iff
//    κ n·(w − v) ≤ 0; on the wrong side r ≥ κ n·(w − v) > 0 for every δ. As
//    κ → 0 the condition becomes vacuous (a plane has no "other side" of
//    itself), instead of forcing δ_p → ∞. r is unit-free (κ L times a height
//    over L); near a smooth saddle it is of order κ κ_1 ℓ² (second order in
//    the edge length ℓ): the builder weights it accordingly.
//
// Units / normalisation: L = 1/inv_length a fixed length (1 in the canonical
// frame); κ has units 1/length, n, n(e) and δ are unit-free.
//
// Invariances: rigid motions x → R x + t with n → R n, n(e) → R n(e), κ and δ
// unchanged (r unchanged); uniform scaling x → s x with κ → κ/s and
// inv_length → inv_length / s (r unchanged). (n, κ) → (−n, −κ) describes the
// same sphere and flips the sign of the co-sphericity residual, leaves the
// saddle residual unchanged; n(e) → −n(e) flips the strip residuals.
#ifndef ARCHGEO_ENERGIES_SADDLE_SIGN_H_
#define ARCHGEO_ENERGIES_SADDLE_SIGN_H_

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

// tangent plane than the sphere Σ(v). No constants.
struct SaddleSign {
  using Shape = CostShape<1, 3, 3, 1, 3, 1>;

  // v: 3 doubles, n: 3 doubles (unit sphere normal at v), kappa: 1 double,
  // w: 3 doubles (principal neighbour), delta: 1 double (dummy, unit-free);
  // residual: 1 double.
  template <typename T>
  bool operator()(const T* v_ptr, const T* n_ptr, const T* kappa_ptr,
                  const T* w_ptr, const T* delta_ptr, T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> v(v_ptr);
    const Eigen::Map<const Vec3> n(n_ptr);
    const Eigen::Map<const Vec3> w(w_ptr);
    residual[0] = kappa_ptr[0] * n.dot(w - v) + delta_ptr[0] * delta_ptr[0];
    return true;
  }
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_SADDLE_SIGN_H_
