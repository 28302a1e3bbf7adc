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
#ifndef ARCHGEO_ENERGIES_PRINCIPAL_SYMMETRIC_H_
#define ARCHGEO_ENERGIES_PRINCIPAL_SYMMETRIC_H_

#include <Eigen/Core>

namespace ceres {
class CostFunction;
}  // namespace ceres

namespace archgeo {

// 1. A non-principal neighbour w on the sphere Σ(v).
struct CoSpherical {
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

// 2. The developable normal strip along a principal edge vw.
struct PrincipalStrip {
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

// 3. A principal neighbour w of a saddle vertex v on the other side of the
// tangent plane than the sphere Σ(v). No constants.
struct SaddleSign {
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

// Factories; the caller (usually ceres::Problem) takes ownership.
// Returns AutoDiffCostFunction<CoSpherical, 1, 3, 3, 1, 3> (blocks v, n,
// kappa, w). Precondition (CHECKed): inv_length finite and > 0.
ceres::CostFunction* MakeCoSpherical(double inv_length);
// Returns AutoDiffCostFunction<PrincipalStrip, 3, 3, 3, 3, 3, 3> (blocks n_e,
// v, w, n_v, n_w). Precondition (CHECKed): inv_length finite and > 0.
ceres::CostFunction* MakePrincipalStrip(double inv_length);
// Returns AutoDiffCostFunction<SaddleSign, 1, 3, 3, 1, 3, 1> (blocks v, n,
// kappa, w, delta). A builder initialises δ = sqrt(max(0, −κ n·(w − v))).
ceres::CostFunction* MakeSaddleSign();

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_PRINCIPAL_SYMMETRIC_H_
