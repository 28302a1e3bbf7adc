// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A-net vertex-star planarity — the YAML term `anet_planarity`, two variants.
//
//   [Shi, Wang, Pottmann 2014, §3.2 step 1, eq. 10: F_anet = Σ_i F_p(b_i) + …;
//    F_p = planarity of the vertex star of b_i, options (i) and (ii)]
//
// An A-net (discrete asymptotic net) is a quad mesh whose vertex stars are
// planar: every vertex v lies in one plane with all its edge neighbours
// w_1 … w_n (n = valence, neighbours in cyclic order around v).
//
// (i) Vertex-normal variant [Shi 2014 §3.2 (i); Deng et al. 2011]: an
//     auxiliary unit vertex normal n_v per vertex (3 doubles; the builder owns
//     it and puts ceres::SphereManifold<3> on it so ‖n_v‖ = 1 exactly), and one
//     residual per neighbour w of v:
//
//       r = n_v·(w − v) / L
//
//     With ‖n_v‖ = 1 this is the signed distance of w from the plane through v
//     with normal n_v; the star of v is planar iff all n residuals of v vanish
//     for some n_v. Singular configurations: none — r is bilinear in
//     (n_v, w − v); the functor does not normalise n_v (the manifold does), so a
//     non-unit or zero n_v gives a finite r (0 for n_v = 0) and Jacobian.
//     Coincident v = w gives r = 0. Never returns false.
//     Invariances: rigid motion x → R x + t with n_v → R n_v leaves r
//     unchanged; uniform scaling x → s x with inv_length → inv_length / s
//     leaves r unchanged; n_v → −n_v flips the sign.
//
// (ii) Quad variant [Shi 2014 §3.2 (ii), F_quad]: planarity of n − 2 auxiliary
//     quads per vertex star, each measured by
//
//       F_quad(b0, b1, b2, b3) = (n·d)²,  n = unit(b02 × b13),
//       d = (b0 + b2 − b1 − b3) / 2,       b_ij = b_i − b_j.
//
//     n·d equals (up to sign) the diagonal distance of energies/pq_diagonal.h:
//     n ⊥ b02 gives n·b2 = n·b0 and n ⊥ b13 gives n·b3 = n·b1, hence
//     n·d = n·(b0 − b1), while PqDiagonal returns n·(b1 − b0)/L with the same
//     n (b02 × b13 = (b2 − b0) × (b3 − b1)). AnetStarQuad therefore reuses the
//     PqDiagonal functor (same regularisation ε = kPqDiagonalEpsilon L², same
//     fixed length L) and negates it, so that
//
//       r = n·d / L,  n = c / sqrt(‖c‖² + (ε L²)²),  c = b02 × b13.
//
//     Which quads: for a vertex v with neighbours w_0 … w_{n−1} in cyclic
//     order, the quads (b0, b1, b2, b3) = (v, w_i, w_{i+1}, w_{i+2}),
//     i = 0 … n − 3 (AnetStarQuadNeighbours below). Why they imply planarity:
//     quad i makes w_{i+2} coplanar with v, w_i, w_{i+1}; quad i + 1 shares the
//     three points v, w_{i+1}, w_{i+2} with quad i, so (when they are not
//     collinear) both quads lie in the plane they span, and by induction all
//     of v, w_0 … w_{n−1} lie in the plane of v, w_0, w_1. Conversely a planar
//     star makes every such quad planar, so r = 0 on all n − 2 quads iff the
//     star is planar (generic stars). The quad's diagonals are v w_{i+1} and
//     w_i w_{i+2}; on a valence-4 star of an asymptotic net they cross at a
//     right-ish angle near v, so c is far from 0.
//     Singular configurations: those of PqDiagonal — parallel diagonals
//     (v, w_{i+1} on a line parallel to w_i w_{i+2}, e.g. a collinear star) or a
//     diagonal of zero length make c = 0; the regularised normalisation gives
//     r → 0 with a finite Jacobian. Never returns false.
//     Invariances: rigid motions; uniform scaling with inv_length → inv_length
//     / s; reversing the cyclic order of the neighbours flips the sign of each
//     r (only r² enters the energy).
//
// Units / normalisation (both variants): L = 1/inv_length is a fixed length
// chosen by the builder (e.g. the mean edge length of the star at build time),
// so r is unit-free. Ceres minimises ½Σr².
#ifndef ARCHGEO_ENERGIES_ANET_PLANARITY_H_
#define ARCHGEO_ENERGIES_ANET_PLANARITY_H_

#include <array>
#include <vector>

#include <Eigen/Core>

#include "energies/pq_diagonal.h"

#include "energies/autodiff.h"

namespace archgeo {

// Variant (i): r = n_v·(w − v) / L.
struct AnetVertexNormal {
  using Shape = CostShape<1, 3, 3, 3>;

  // inv_length: 1/L, L > 0 a fixed length of the star.
  explicit AnetVertexNormal(double inv_length) : inv_length(inv_length) {}

  // n: 3 doubles, the vertex normal n_v (unit via the manifold);
  // v: 3 doubles, the star's centre vertex; w: 3 doubles, one neighbour of v;
  // residual: 1 double.
  template <typename T>
  bool operator()(const T* n_ptr, const T* v_ptr, const T* w_ptr,
                  T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> n(n_ptr);
    const Eigen::Map<const Vec3> v(v_ptr);
    const Eigen::Map<const Vec3> w(w_ptr);
    residual[0] = n.dot(w - v) * T(inv_length);
    return true;
  }

  double inv_length;
};

// Variant (ii): r = n·d / L for the auxiliary quad (b0, b1, b2, b3) =
// (v, w_i, w_{i+1}, w_{i+2}); equals −PqDiagonal(b0, b1, b2, b3).
struct AnetStarQuad {
  using Shape = CostShape<1, 3, 3, 3, 3>;

  // inv_length: 1/L, L > 0 a fixed length of the star.
  explicit AnetStarQuad(double inv_length) : diagonal(inv_length) {}

  // b0 = v, b1 = w_i, b2 = w_{i+1}, b3 = w_{i+2}: 3 doubles each;
  // residual: 1 double.
  template <typename T>
  bool operator()(const T* b0, const T* b1, const T* b2, const T* b3,
                  T* residual) const {
    diagonal(b0, b1, b2, b3, residual);
    residual[0] = -residual[0];
    return true;
  }

  PqDiagonal diagonal;
};

// The auxiliary quads of a star of the given valence (variant ii): entry k =
// (i, i+1, i+2) indexes the neighbours w_i, w_{i+1}, w_{i+2} (cyclic order,
// 0-based) of quad (v, w_i, w_{i+1}, w_{i+2}), k = i = 0 … valence − 3.
// Precondition (CHECKed): valence >= 3 (a valence-3 star gives one quad).
std::vector<std::array<int, 3>> AnetStarQuadNeighbours(int valence);

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_ANET_PLANARITY_H_
