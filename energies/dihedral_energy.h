// Edge-length × dihedral energy by iteratively reweighted least squares, one
// 3-vector residual per interior edge e = vw = f ∩ f′:
//
//   r = (ℓ_e / L) (n_f − n_f′) / sqrt(ω_e)
//   ℓ_e = sqrt(‖v − w‖² + (ε_ℓ L)²)
//   ω_e = (ℓ⁰_e / L) ℓ*⁰_e + ε_irls        (constant of the round)
//
//   [Pellis 2019, §3: E = Σ_e ℓ_e ℓ*_e, ℓ*_e = ‖n_f − n_f′‖ = 2|sin(α_e/2)|;
//    §5.1 (E as the target functional); IRLS as in §5.3 for C(Φ)]
//
// Why a vector residual: E is not a sum of squares and ℓ*_e is not
// differentiable where n_f = n_f′. The vector n_f − n_f′ is smooth everywhere,
// and ‖n_f − n_f′‖² = ℓ*²_e exactly, so Ceres (which minimises ½Σ‖r‖²) sees
//
//   ½‖r‖² = ½ (ℓ_e/L)² ℓ*²_e / ω_e                           (exact relation)
//
// With ω_e computed from the previous round's values (DihedralIrlsWeight),
// x_e = ℓ_e ℓ*_e / L, at a fixed point x_e = x⁰_e:
//
//   ½‖r‖² = ½ x_e² / (x_e + ε_irls) = ½ x_e · (1 − ε_irls / (x_e + ε_irls)),
//
// i.e. ½ ℓ_e ℓ*_e / L with relative error ε_irls / (x_e + ε_irls): the E-term
// in units of L, halved. Edges with x_e ≫ ε_irls are weighted exactly as in E;
// edges with x_e ≲ ε_irls (flat edges, the typical case at the optimum, §3.3)
// get the bounded weight 1/ε_irls, a Huber-like quadratic that keeps them
// flat without an infinite weight. ε_irls = kDihedralIrlsEpsilon = 1e-3: an
// edge of length L with a dihedral angle of 0.1° has x = 1.7e-3; edges above
// about 1° (x ≥ 1.7e-2) are weighted within 6% of E's own weight, and the
// largest weight ratio between edges stays ≲ 10³ (well-conditioned normal
// equations next to fairness and proximity terms). The builder reports the
// true E = Σ ℓ_e ℓ*_e separately; this term only drives the minimisation.
//
// Face normals. A triangle's normal is computed from its three vertices,
//   n = c / sqrt(‖c‖² + (ε_n L²)²),   c = cross product of two edge vectors,
// (regularised normalisation, ε_n = kDihedralNormalEpsilon). A planar polygon
// (more than three vertices) contributes a unit-normal parameter block n_f
// (the builder puts ceres::SphereManifold<3> on it); the same block is tied to
// the polygon's plane by the face_planarity energy (energies/face_planarity.h:
// n_f·(x − c_f) − d_f = 0 for every vertex x of the face), so n_f is the
// face's normal only as far as face_planarity holds. Composition for hybrid
// meshes (Pellis Fig. 18): quads and polygons are kept planar by
// face_planarity (the paper's "ℓ* = 0 on the diagonals of planar quads" is
// exactly planarity), their diagonals are not edges and get no term here, and
// every mesh edge between two faces gets one term from the factory matching
// its two faces (triangle–triangle, triangle–polygon, polygon–polygon).
//
// Orientation. All normals must point to the same side of the surface (a
// consistently oriented mesh: faces counter-clockwise seen from the side the
// normals point to). For the edge traversed from v to w, f is the face on the
// left (it contains the halfedge v→w) and f′ the face on the right (it
// contains w→v) [Pellis 2019, §5.3 item (3)]. For triangles:
//   f = (v, w, a): n_f ∝ (w − v) × (a − v),
//   f′ = (w, v, b): n_f′ ∝ (v − w) × (b − w).
// Swapping the roles of f and f′ flips the sign of r and leaves ‖r‖.
//
// Units / normalisation: L = 1/inv_length is a fixed length chosen by the
// builder (1 in the canonical frame of unit mean edge length), so r and ω_e
// are unit-free.
//
// Singular configurations, none of which gives NaN (the functors never return
// false):
//  - ℓ*_e = 0 (coplanar faces): r = 0, smooth (no square root of ℓ*).
//  - zero-length edge v = w: ℓ_e is regularised, ℓ_e = ε_ℓ L = 1e-9 L; the
//    triangles' normals are regularised (below).
//  - degenerate triangle (collinear or coincident vertices): c = 0, n = 0,
//    finite Jacobian of order 1/(ε_n L²) × ‖edge‖; the residual is then
//    ℓ_e(±n_other)/sqrt(ω_e), bounded.
//  For ‖c‖ ≫ ε_n L² the regularised normal is the unit normal to relative
//  precision ½(ε_n L²/‖c‖)², and ℓ_e the edge length to ½(ε_ℓ L/‖v − w‖)².
//
// Invariances: rigid motions x → R x + t (r → R r, ‖r‖ unchanged; polygon
// normal blocks n → R n); uniform scaling x → s x with inv_length →
// inv_length / s (r unchanged).
#ifndef ARCHGEO_ENERGIES_DIHEDRAL_ENERGY_H_
#define ARCHGEO_ENERGIES_DIHEDRAL_ENERGY_H_

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()

namespace ceres {
class CostFunction;
}  // namespace ceres

namespace archgeo {

// IRLS floor of ω_e (unit-free; see above).
inline constexpr double kDihedralIrlsEpsilon = 1e-3;
// Regularisation of triangle normals, relative to L².
inline constexpr double kDihedralNormalEpsilon = 1e-6;
// Regularisation of the edge length, relative to L.
inline constexpr double kDihedralLengthEpsilon = 1e-9;

// The IRLS weight ω_e = edge_length · inv_length · dual_edge_length + epsilon
// of one edge, from the previous round's edge length ℓ⁰_e (units of length,
// ≥ 0) and dual edge length ℓ*⁰_e = ‖n_f − n_f′‖ (unit-free, in [0, 2]).
// Returns a value ≥ epsilon > 0. Preconditions (CHECKed): all arguments
// finite, edge_length ≥ 0, dual_edge_length ≥ 0, inv_length > 0,
// epsilon > 0.   [Pellis 2019, §3 E; §5.3 weight iteration]
double DihedralIrlsWeight(double edge_length, double dual_edge_length,
                          double inv_length,
                          double epsilon = kDihedralIrlsEpsilon);

// Regularised unit normal of the triangle (p0, p1, p2), counter-clockwise
// seen from the side the normal points to:
//   n = c / sqrt(‖c‖² + eps²),   c = (p1 − p0) × (p2 − p0).
// eps has the units of c (length²). Shared with total_absolute_curvature.
template <typename T>
Eigen::Matrix<T, 3, 1> RegularisedTriangleNormal(
    const Eigen::Matrix<T, 3, 1>& p0, const Eigen::Matrix<T, 3, 1>& p1,
    const Eigen::Matrix<T, 3, 1>& p2, double eps) {
  const Eigen::Matrix<T, 3, 1> c = (p1 - p0).cross(p2 - p0);
  using std::sqrt;
  return c / sqrt(c.squaredNorm() + T(eps * eps));
}

// Common part: r = (ℓ_e/L)(n_f − n_f′)/sqrt(ω).
template <typename T>
void DihedralResidual(const T* v_ptr, const T* w_ptr,
                      const Eigen::Matrix<T, 3, 1>& n_left,
                      const Eigen::Matrix<T, 3, 1>& n_right, double inv_length,
                      double omega, T* residual_ptr) {
  using Vec3 = Eigen::Matrix<T, 3, 1>;
  const Eigen::Map<const Vec3> v(v_ptr);
  const Eigen::Map<const Vec3> w(w_ptr);
  const Vec3 e = (w - v) * T(inv_length);  // unit-free edge vector
  using std::sqrt;
  const T length = sqrt(e.squaredNorm() +
                        T(kDihedralLengthEpsilon * kDihedralLengthEpsilon));
  Eigen::Map<Vec3> residual(residual_ptr);
  residual = (length / std::sqrt(omega)) * (n_left - n_right);
}

// Edge between two triangles: f = (v, w, a) on the left of v→w, f′ = (w, v, b)
// on the right.
struct DihedralTriTri {
  // inv_length: 1/L > 0; omega: ω_e > 0 (DihedralIrlsWeight). The builder may
  // change `omega` between solves (IRLS rounds), never during one.
  DihedralTriTri(double inv_length, double omega)
      : inv_length(inv_length), omega(omega) {}

  // v, w: 3 doubles each, the edge's endpoints; a, b: 3 doubles each, the
  // vertices opposite the edge in f and f′; residual: 3 doubles.
  template <typename T>
  bool operator()(const T* v_ptr, const T* w_ptr, const T* a_ptr,
                  const T* b_ptr, T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> v(v_ptr);
    const Eigen::Map<const Vec3> w(w_ptr);
    const Eigen::Map<const Vec3> a(a_ptr);
    const Eigen::Map<const Vec3> b(b_ptr);
    // Normals on unit-free coordinates (x − v)/L, so ε_n is relative to L².
    const T s(inv_length);
    const Vec3 zero = Vec3::Zero();
    const Vec3 wl = (w - v) * s, al = (a - v) * s, bl = (b - v) * s;
    const Vec3 n_left =
        RegularisedTriangleNormal<T>(zero, wl, al, kDihedralNormalEpsilon);
    const Vec3 n_right =
        RegularisedTriangleNormal<T>(wl, zero, bl, kDihedralNormalEpsilon);
    DihedralResidual(v_ptr, w_ptr, n_left, n_right, inv_length, omega,
                     residual);
    return true;
  }

  double inv_length;
  double omega;
};

// Edge between a triangle f = (v, w, a) on the left of v→w and a planar
// polygon f′ on the right with unit-normal block n_right (same side as the
// triangle's normal). For a polygon on the left and a triangle on the right,
// swap v and w (the triangle (w, v, a) is then on the left of w→v).
struct DihedralTriPoly {
  // As DihedralTriTri.
  DihedralTriPoly(double inv_length, double omega)
      : inv_length(inv_length), omega(omega) {}

  // v, w: 3 doubles each, the edge's endpoints; a: 3 doubles, the triangle's
  // third vertex; n_right: 3 doubles, the polygon's unit normal (not
  // normalised here: the SphereManifold keeps it unit); residual: 3 doubles.
  template <typename T>
  bool operator()(const T* v_ptr, const T* w_ptr, const T* a_ptr,
                  const T* n_right_ptr, T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> v(v_ptr);
    const Eigen::Map<const Vec3> w(w_ptr);
    const Eigen::Map<const Vec3> a(a_ptr);
    const Eigen::Map<const Vec3> n_right(n_right_ptr);
    const T s(inv_length);
    const Vec3 n_left = RegularisedTriangleNormal<T>(
        Vec3::Zero(), (w - v) * s, (a - v) * s, kDihedralNormalEpsilon);
    DihedralResidual(v_ptr, w_ptr, n_left, Vec3(n_right), inv_length, omega,
                     residual);
    return true;
  }

  double inv_length;
  double omega;
};

// Edge between two planar polygons: f on the left of v→w with unit normal
// block n_left, f′ on the right with n_right. v and w enter only through ℓ_e.
struct DihedralPolyPoly {
  // As DihedralTriTri.
  DihedralPolyPoly(double inv_length, double omega)
      : inv_length(inv_length), omega(omega) {}

  // v, w: 3 doubles each, the edge's endpoints; n_left, n_right: 3 doubles
  // each, the polygons' unit normals; residual: 3 doubles.
  template <typename T>
  bool operator()(const T* v_ptr, const T* w_ptr, const T* n_left_ptr,
                  const T* n_right_ptr, T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> n_left(n_left_ptr);
    const Eigen::Map<const Vec3> n_right(n_right_ptr);
    DihedralResidual(v_ptr, w_ptr, Vec3(n_left), Vec3(n_right), inv_length,
                     omega, residual);
    return true;
  }

  double inv_length;
  double omega;
};

// Factories. Each returns a new AutoDiffCostFunction<Functor, 3, 3, 3, 3, 3>
// with the blocks in the order of the functor's operator() (TriTri: v, w, a,
// b; TriPoly: v, w, a, n_right; PolyPoly: v, w, n_left, n_right); the caller
// (usually ceres::Problem) takes ownership. If `functor` is not null it
// receives a pointer to the functor owned by the cost function, so the
// builder can update `omega` between IRLS rounds. Preconditions (CHECKed):
// inv_length and omega finite and > 0.
ceres::CostFunction* MakeDihedralTriTri(double inv_length, double omega,
                                        DihedralTriTri** functor = nullptr);
ceres::CostFunction* MakeDihedralTriPoly(double inv_length, double omega,
                                         DihedralTriPoly** functor = nullptr);
ceres::CostFunction* MakeDihedralPolyPoly(double inv_length, double omega,
                                          DihedralPolyPoly** functor = nullptr);

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_DIHEDRAL_ENERGY_H_
