// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Total absolute curvature by iteratively reweighted least squares, two
// residuals per vertex v with one-ring w_1..w_k:
//
//   W′_v = ½ Σ_{e = vw = f ∩ f′} (n_f × n_f′)(w − v)ᵀ        (3×3)
//   S = ½(W′_v + W′_vᵀ),   P = I − N Nᵀ,   M = P S P,
//   λ_{1,2} = tr(M)/2 ± sqrt(½‖M − (tr(M)/2) P‖²_F + (ε_g L)²)
//   r_j = (λ_j / L) / sqrt(ω_j),   ω_j = |λ⁰_j| / L + ε_irls   (j = 1, 2)
//
//   [Pellis 2019, §5.3: W′_v (the normal-cycle shape operator of
//    Cohen-Steiner & Morvan 2003 with α_e replaced by sin α_e),
//    C(Φ) ≈ Σ_v |λ_{1,v}| + |λ_{2,v}|, and the weight iteration
//    E_target = Σ λ²_j / (|λ^{(i−1)}_j| + ε)]
//
// Faces and orientation. The one-ring w_1..w_k is ordered counter-clockwise
// seen from the side the normals point to, and the faces around v are the
// triangles (v, w_i, w_{i+1}), with unit normals n_i ∝ (w_i − v) × (w_{i+1} − v)
// (regularised as in dihedral_energy.h). For the edge traversed from v to w_i
// the face on the left (containing the halfedge v→w_i) is f = (v, w_i, w_{i+1})
// and the face on the right is f′ = (v, w_{i−1}, w_i), as in item (3) of §5.3,
// so s(v, w_i) = n_i × n_{i−1}; |s| = sin α_e and s is parallel to the edge.
//  - Interior vertex (closed = true): indices cyclic, k ≥ 3 faces and edges.
//  - Boundary vertex (closed = false): the ring is the open fan w_1..w_k from
//    one boundary neighbour to the other, k − 1 faces (v, w_i, w_{i+1}),
//    i = 1..k−1, k ≥ 2. Only edges with two incident faces contribute
//    (vw_2 .. vw_{k−1}); the boundary edges vw_1, vw_k have no dihedral angle
//    and are left out, as is any edge on the boundary in the normal cycle.
//
// Tangential eigenvalues. W′_v is symmetrised (it is symmetric only in the
// smooth limit) and restricted to the tangent plane with the vertex normal
// N = Σ_i n_i / ‖Σ_i n_i‖ (regularised). M = P S P kills N, and its two other
// eigenvalues are those of the 2×2 tangential restriction; they are computed in
// closed form without a tangent basis: tr(M) = λ1 + λ2, and M − (tr/2)P has the
// eigenvalues ±(λ1 − λ2)/2, 0, so ½‖M − (tr/2)P‖²_F = ((λ1 − λ2)/2)² is a sum
// of squares (never negative by rounding). λ1 ≥ λ2. Geometric meaning
// (§5.3): principal curvature × area of influence of v (units of length); on a
// sphere of radius R with outward normals λ1 ≈ λ2 ≈ A_v / R > 0, A_v the
// Voronoi area of v (for a regular valence-k star (k/4) tan(π/k) ℓ², which is
// one third of the star's area only for k = 6); on a cylinder λ1 ≈ A_v / R and
// λ2 = 0 (exactly, on a grid whose quads are planar). Each term
// (n_f × n_f′)(w − v)ᵀ is sin α_e ℓ_e êêᵀ, ê the edge direction, so a
// boundary fan with a single interior edge has λ2 = 0 identically. Reversing
// the orientation flips the signs of both.
//
// IRLS. Ceres minimises ½Σr², and exactly
//   ½‖r‖² = ½ (λ1² / ω1 + λ2² / ω2) / L².
// With ω_j from the previous round (TotalAbsoluteCurvatureIrlsWeight), at a
// fixed point y_j = |λ_j| / L: ½‖r‖² = ½ Σ_j y_j² / (y_j + ε_irls) ≈ ½ Σ_j |λ_j| / L
// with relative error ε_irls / (y_j + ε_irls). ε_irls =
// kTotalAbsoluteCurvatureIrlsEpsilon = 1e-3: with L the mean edge length,
// λ/L ≈ 0.9 κL, so vertices with |κ| L ≳ 0.02 are weighted within 6% of
// |λ|, and flat or cylindrical directions get the bounded weight 1/ε_irls. The
// weights belong to the ordered eigenvalues (λ1 ≥ λ2); near an umbilic the
// order may swap between rounds, where both weights are nearly equal anyway.
//
// Units / normalisation: L = 1/inv_length (1 in the canonical frame of unit
// mean edge length); all computations use (x − v)/L, so r is unit-free.
//
// Singular configurations, all finite (the functor never returns false):
//  - umbilic λ1 = λ2 (e.g. a symmetric star on a sphere, or a flat star):
//    the half-gap is regularised, sqrt(((λ1 − λ2)/2)² + (ε_g L)²) with
//    ε_g = kTotalAbsoluteCurvatureGapEpsilon = 1e-6; since the derivative of
//    the squared gap vanishes linearly with the gap, the Jacobian is bounded
//    independently of ε_g, and λ_j is shifted by at most ε_g L.
//  - degenerate triangles (coincident or collinear ring vertices, w_i = v):
//    regularised normals as in dihedral_energy.h (n = 0 for a zero-area face).
//  - Σ n_i = 0 (a folded star): N is regularised to 0, P = I.
//
// Invariances: rigid motions (r unchanged; W′ → R W′ Rᵀ); uniform scaling
// x → s x with inv_length → inv_length / s (r unchanged; W′ and λ scale by s);
// a cyclic relabelling of an interior vertex's ring (r unchanged).
#ifndef ARCHGEO_ENERGIES_TOTAL_ABSOLUTE_CURVATURE_H_
#define ARCHGEO_ENERGIES_TOTAL_ABSOLUTE_CURVATURE_H_

#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()

#include "energies/dihedral_hinge.h"  // RegularisedTriangleNormal

namespace archgeo {

// IRLS floor of ω_j (unit-free; see above).
inline constexpr double kTotalAbsoluteCurvatureIrlsEpsilon = 1e-3;
// Regularisation of the half-gap (λ1 − λ2)/2, relative to L.
inline constexpr double kTotalAbsoluteCurvatureGapEpsilon = 1e-6;
// Regularisation of face normals (relative to L²) and of the vertex normal.
inline constexpr double kTotalAbsoluteCurvatureNormalEpsilon = 1e-6;

// The IRLS weight ω_j = |lambda| · inv_length + epsilon of one eigenvalue,
// from its previous-round value λ⁰_j (units of length). Returns a value
// ≥ epsilon > 0. Preconditions (CHECKed): all arguments finite,
// inv_length > 0, epsilon > 0.   [Pellis 2019, §5.3 weight iteration]
double TotalAbsoluteCurvatureIrlsWeight(
    double lambda, double inv_length,
    double epsilon = kTotalAbsoluteCurvatureIrlsEpsilon);

// The core computation, shared by the functor and the plain evaluation.
// v: 3 values; ring: `valence` pointers to 3 values each (w_1..w_k, order and
// `closed` as in the header comment). Outputs, all for the unit-free
// coordinates (x − v)·inv_length: `shape` the symmetrised W′_v / L, `normal`
// the regularised vertex normal N, `lambda1` ≥ `lambda2` the tangential
// eigenvalues / L with half-gap regularisation gap_epsilon (≥ 0; 0 gives the
// exact closed form). Preconditions: valence ≥ 3 if closed, ≥ 2 otherwise.
template <typename T>
void TangentialShapeOperator(const T* v_ptr, const T* const* ring, int valence,
                             bool closed, double inv_length,
                             double gap_epsilon,
                             Eigen::Matrix<T, 3, 3>* shape,
                             Eigen::Matrix<T, 3, 1>* normal, T* lambda1,
                             T* lambda2) {
  using Vec3 = Eigen::Matrix<T, 3, 1>;
  using Mat3 = Eigen::Matrix<T, 3, 3>;
  const Eigen::Map<const Vec3> v(v_ptr);
  const int k = valence;
  const int num_faces = closed ? k : k - 1;
  std::vector<Vec3> d(k);
  for (int i = 0; i < k; ++i) {
    d[i] = (Eigen::Map<const Vec3>(ring[i]) - v) * T(inv_length);
  }
  // n[i]: the face (v, w_i, w_{i+1}).
  std::vector<Vec3> n(num_faces);
  Vec3 sum = Vec3::Zero();
  for (int i = 0; i < num_faces; ++i) {
    n[i] = RegularisedTriangleNormal<T>(Vec3::Zero(), d[i], d[(i + 1) % k],
                                        kTotalAbsoluteCurvatureNormalEpsilon);
    sum += n[i];
  }
  using std::sqrt;
  const T eps_n(kTotalAbsoluteCurvatureNormalEpsilon);
  *normal = sum / sqrt(sum.squaredNorm() + eps_n * eps_n);
  // W′: the edge v→w_i has f = face i on its left, f′ = face i − 1 on its
  // right; interior edges only on the boundary.
  Mat3 w = Mat3::Zero();
  const int first = closed ? 0 : 1;
  const int last = closed ? k - 1 : k - 2;
  for (int i = first; i <= last; ++i) {
    const Vec3& left = n[i];
    const Vec3& right = n[(i + k - 1) % k];
    w += T(0.5) * left.cross(right) * d[i].transpose();
  }
  *shape = T(0.5) * (w + w.transpose());
  const Mat3 p = Mat3::Identity() - (*normal) * normal->transpose();
  const Mat3 m = p * (*shape) * p;
  const T half_trace = T(0.5) * m.trace();
  const T half_gap = sqrt(T(0.5) * (m - half_trace * p).squaredNorm() +
                          T(gap_epsilon * gap_epsilon));
  *lambda1 = half_trace + half_gap;
  *lambda2 = half_trace - half_gap;
}

// Functor over a vertex star (MakeStarAutoDiff): parameters[0] = v, parameters[i] =
// w_i (i = 1..valence), 3 doubles each; 2 residuals r_1, r_2 (λ1 ≥ λ2).
struct TotalAbsoluteCurvature {
  static constexpr int kResiduals = 2;
  static constexpr int kStride = 8;
  int NumBlocks() const { return valence + 1; }

  // valence: k (≥ 3 if closed, ≥ 2 otherwise); closed: interior vertex;
  // inv_length: 1/L > 0; omega1, omega2: ω_1, ω_2 > 0
  // (TotalAbsoluteCurvatureIrlsWeight of λ1⁰, λ2⁰). The builder may change
  // `omega` between solves (IRLS rounds), never during one.
  TotalAbsoluteCurvature(int valence, bool closed, double inv_length,
                         double omega1, double omega2)
      : valence(valence),
        closed(closed),
        inv_length(inv_length),
        omega{omega1, omega2} {}

  template <typename T>
  bool operator()(T const* const* parameters, T* residual) const {
    Eigen::Matrix<T, 3, 3> shape;
    Eigen::Matrix<T, 3, 1> normal;
    T lambda1, lambda2;
    TangentialShapeOperator<T>(parameters[0], parameters + 1, valence, closed,
                               inv_length, kTotalAbsoluteCurvatureGapEpsilon,
                               &shape, &normal, &lambda1, &lambda2);
    residual[0] = lambda1 / std::sqrt(omega[0]);
    residual[1] = lambda2 / std::sqrt(omega[1]);
    return true;
  }

  int valence;
  bool closed;
  double inv_length;
  std::array<double, 2> omega;
};

// The functor after checking its input (CHECKs: valence ≥ 3 if closed, ≥ 2
// otherwise; inv_length, omega1, omega2 finite and > 0).
TotalAbsoluteCurvature CheckedTotalAbsoluteCurvature(int valence, bool closed, double inv_length,
                                                     double omega1, double omega2);

// Plain evaluation at given positions (for the metrics' discrete C(Φ) and for
// the builder's previous-round λ⁰). Units of length throughout.
struct VertexShapeOperator {
  Eigen::Matrix3d shape;   // symmetrised W′_v, units of length
  Eigen::Vector3d normal;  // vertex normal N (unit up to the regularisation,
                           // 0 if Σ n_f = 0)
  double lambda1 = 0.0;    // tangential eigenvalues, λ1 ≥ λ2, units of
  double lambda2 = 0.0;    // length (principal curvature × area)
};

// v: 3 doubles; ring: the one-ring positions (3 doubles each), order and
// `closed` as in the header comment. Computes with the same regularised
// normals as the functor, on coordinates scaled by the mean distance from v
// to its neighbours (so the result is scale-equivariant), but without the
// half-gap regularisation (exact eigenvalues). Preconditions (CHECKed):
// ring.size() ≥ 3 if closed, ≥ 2 otherwise; no null pointer.
VertexShapeOperator EvaluateVertexShapeOperator(
    const double* v, const std::vector<const double*>& ring, bool closed);

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_TOTAL_ABSOLUTE_CURVATURE_H_
