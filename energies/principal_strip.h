// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Principal-symmetric triangle meshes [Pellis 2019, §2.3, §5.2]: the vertex
// spheres Σ(v) = (n(v), κ(v)) are those of energies/co_spherical.h.
//
// 2. Developable normal strips [§2.3 second condition; §5.2
//    n(e)ᵀ(v − w) = n(e)ᵀ(c(v) − v) = n(e)ᵀ(c(w) − w) = 0], three residuals
//    per principal edge e = vw with an auxiliary unit normal n(e)
//    (SphereManifold<3>):
//
//      r = ( n(e)·(v − w)/L,  n(e)·n(v),  n(e)·n(w) )
//
//    Why this is the paper's condition: c(v) − v = n(v)/κ(v) and
//    c(w) − w = n(w)/κ(w), so for κ(v), κ(w) ≠ 0 the paper's three equations
//    are ours multiplied by 1, 1/κ(v), 1/κ(w). A unit n(e) orthogonal to
//    w − v, n(v), n(w) exists iff these three vectors are linearly dependent,
//    i.e. iff the line vw and the normals n(v), n(w) lie in one plane
//    (det(w − v, n(v), n(w)) = 0): then the plane through v with normal n(e)
//    contains w, c(v) = v + n(v)/κ(v) and c(w) = w + n(w)/κ(w), so v, w,
//    c(v), c(w) are coplanar; conversely if the four points are coplanar (and
//    v ≠ w, κ ≠ 0, the points spanning a plane) its normal is such an n(e).
//    Our form also holds for flat spheres (κ = 0: the surface normals n(v),
//    n(w) still have to be coplanar with the edge), where c is undefined.
//    Consecutive principal edges then carry a strip of normal lines that is a
//    discrete developable (Fig. 5c).
//
//
// Units / normalisation: L = 1/inv_length a fixed length (1 in the canonical
// frame); κ has units 1/length, n, n(e) and δ are unit-free.
//
// Invariances: rigid motions x → R x + t with n → R n, n(e) → R n(e), κ and δ
// unchanged (r unchanged); uniform scaling x → s x with κ → κ/s and
// inv_length → inv_length / s (r unchanged). (n, κ) → (−n, −κ) describes the
// same sphere and flips the sign of the co-sphericity residual, leaves the
// saddle residual unchanged; n(e) → −n(e) flips the strip residuals.
#ifndef ARCHGEO_ENERGIES_PRINCIPAL_STRIP_H_
#define ARCHGEO_ENERGIES_PRINCIPAL_STRIP_H_

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

// 2. The developable normal strip along a principal edge vw.
struct PrincipalStrip {
  using Shape = CostShape<3, 3, 3, 3, 3, 3>;

  // inv_length: 1/L > 0.
  explicit PrincipalStrip(double inv_length) : inv_length(inv_length) {}

  // n_e: 3 doubles (unit normal of the strip's plane), v, w: 3 doubles each
  // (the edge's endpoints), n_v, n_w: 3 doubles each (the sphere normals of v
  // and w); residual: 3 doubles.
  template <typename T>
  bool operator()(const T* n_e_ptr, const T* v_ptr, const T* w_ptr,
                  const T* n_v_ptr, const T* n_w_ptr, T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> n_e(n_e_ptr);
    const Eigen::Map<const Vec3> v(v_ptr);
    const Eigen::Map<const Vec3> w(w_ptr);
    const Eigen::Map<const Vec3> n_v(n_v_ptr);
    const Eigen::Map<const Vec3> n_w(n_w_ptr);
    residual[0] = n_e.dot(v - w) * T(inv_length);
    residual[1] = n_e.dot(n_v);
    residual[2] = n_e.dot(n_w);
    return true;
  }

  double inv_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_PRINCIPAL_STRIP_H_
