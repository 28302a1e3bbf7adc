// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Mean-curvature (area-gradient) smoothing of a vertex v of a triangle mesh
// with its one-ring w_1 … w_n — the YAML term `mean_curvature_flow`, one
// 3-vector residual per vertex:
//
//   r = −∇_v A / L = ½ Σ_k n̂_k × (w_k − w_{k+1}) / L
//     = ½ Σ_j (cot α_j + cot β_j)(w_j − v) / L
//   n̂_k = c_k / sqrt(‖c_k‖² + (ε L²)²),  c_k = (w_k − v) × (w_{k+1} − v),
//   ε = kMeanCurvatureFlowEpsilon
//
//   [Gebreiter 2012, §10.1 "Curvature operators … diffusion flow, whereby
//    minimal surfaces can be achieved by locally trying to reduce curvature";
//    Pinkall & Polthier 1993, eq. for the area gradient; Desbrun, Meyer,
//    Schröder, Barr 1999, eq. 7 (mean-curvature normal); Meyer et al. 2003]
//
// A = Σ_k area(v, w_k, w_{k+1}) is the area of v's triangle fan (k = 1 … n,
// w_{n+1} = w_1, for an interior vertex; k = 1 … n − 1 at a boundary vertex,
// whose ring runs from one boundary neighbour to the other). ∇_v A of one
// triangle is ½ n̂ × (w_{k+1} − w_k); summed it equals the cotangent formula
// above (α_j, β_j the angles opposite the edge v w_j), the discrete
// mean-curvature normal times the vertex area (2 H n A_v). r = 0 iff v is a
// critical point of the area with its ring fixed: with the boundary held,
// r = 0 at every free vertex characterises a discrete minimal surface
// [Pinkall & Polthier 1993]. The weights are live (recomputed from the
// current positions inside the functor, differentiated by autodiff);
// written with n̂ × edge it needs no cotangent and stays bounded for obtuse
// or needle triangles. Least squares on the live gradient can stall in a
// critical point of Σ‖∇A‖² that is not minimal (a 6 × 6 triangulated bump
// with its boundary fixed stalled at 0.28 of its height with the live term
// alone; with the damping term `step` it converges, halving each round).
//
// Frozen alternative (the term's default): CotangentWeights below evaluates
// c_j = ½(cot α_j + cot β_j) at given positions; energies/laplacian.h
// The Laplacian with those weights, re-computed every round, is the
// linearised flow (Desbrun 1999's implicit fairing; Pinkall–Polthier's
// iteration): each round is linear (one Gauss-Newton step), and its fixed
// point is the same minimal surface (the bump above: flat to 1e-11 in one
// round).
//
// Only triangle fans: at a vertex of a quad mesh use `laplacian` (or a
// triangulated mesh).
//
// Units / normalisation: ∇A has units of length; L = 1/inv_length (the
// builder's mean edge length) makes r unit-free. Ceres minimises ½Σ‖r‖².
//
// Singular configurations: a degenerate triangle (c_k = 0) has no normal;
// the regularised n̂_k → 0 there (its area gradient drops out), finite
// Jacobian of order 1/(εL). Never returns false.
//
// Invariances: rigid motions (r → R r, ‖r‖ unchanged); uniform scaling
// x → s x with inv_length → inv_length / s (r unchanged). Reversing the ring
// order flips every n̂_k and every edge w_k − w_{k+1}: r unchanged.
#ifndef ARCHGEO_ENERGIES_MEAN_CURVATURE_FLOW_H_
#define ARCHGEO_ENERGIES_MEAN_CURVATURE_FLOW_H_

#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()

namespace archgeo {

// Regularisation of the triangle normals, relative to L² (see above).
inline constexpr double kMeanCurvatureFlowEpsilon = 1e-8;

// Functor over a vertex star (MakeStarAutoDiff): parameters[0] = v,
// parameters[j] = w_j (j = 1 … n, cyclic order around v), 3 doubles each;
// 3 residuals.
struct MeanCurvatureFlow {
  static constexpr int kResiduals = 3;
  static constexpr int kStride = 12;
  int NumBlocks() const { return valence + 1; }

  // valence: n; closed: interior vertex (n triangles) or boundary vertex
  // (n − 1 triangles); inv_length: 1/L.
  MeanCurvatureFlow(int valence, bool closed, double inv_length)
      : valence(valence), closed(closed), inv_length(inv_length) {}

  template <typename T>
  bool operator()(T const* const* parameters, T* residual_ptr) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    using std::sqrt;
    const Eigen::Map<const Vec3> v(parameters[0]);
    const double eps = kMeanCurvatureFlowEpsilon / (inv_length * inv_length);
    const int triangles = closed ? valence : valence - 1;
    Vec3 sum = Vec3::Zero();
    for (int k = 0; k < triangles; ++k) {
      const Eigen::Map<const Vec3> a(parameters[1 + k]);
      const Eigen::Map<const Vec3> b(parameters[1 + (k + 1) % valence]);
      const Vec3 c = (a - v).cross(b - v);
      const Vec3 n = c / sqrt(c.squaredNorm() + T(eps * eps));
      sum += n.cross(a - b);
    }
    Eigen::Map<Vec3> residual(residual_ptr);
    residual = sum * T(0.5 * inv_length);
    return true;
  }

  int valence;
  bool closed;
  double inv_length;
};

// The functor after checking its input (CHECKs: valence ≥ 3 if closed, ≥ 2
// otherwise; inv_length finite and > 0).
MeanCurvatureFlow CheckedMeanCurvatureFlow(int valence, bool closed, double inv_length);

// Cotangent weights c_j = ½(cot α_j + cot β_j) of the edges v w_j at the given
// positions (v: 3 doubles; ring: the w_j, 3 doubles each, same order and
// `closed` as above; at a boundary vertex the end edges have one angle
// only). Each cotangent is cos/max(sin, 1e-6), so a degenerate triangle gives
// a large but finite weight. For a fan of non-degenerate triangles Σ_j c_j =
// ½ Σ_k (cot + cot of the base angles) > 0; if the sum is not positive (a
// collapsed fan) the uniform weights 1 are returned instead, so the result
// can always be passed to CheckedLaplacian. Preconditions (CHECKed):
// ring.size() ≥ 3 if closed, ≥ 2 otherwise; no null pointer.
std::vector<double> CotangentWeights(const double* v,
                                     const std::vector<const double*>& ring,
                                     bool closed);

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_MEAN_CURVATURE_FLOW_H_
