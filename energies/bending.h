// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Bending at a vertex v between two opposite edges (u, v) and (v, w) — the
// YAML term `bending`, one 3-vector residual per triple (u, v, w):
//
//   r = t_out − t_in,   t_in = unit_ε(v − u),   t_out = unit_ε(w − v),
//   unit_ε(x) = x / sqrt(‖x‖² + (ε L)²),  ε = kBendingEpsilon
//
//   [Gebreiter 2012, §10.1 "Bending": "attempting to increase the cross
//    product between two opposing edges emanating from an even-valence
//    vertex"; §11.7.1 "bending forces which align opposing vertex edges"]
//
// u and w are opposite neighbours of v: at a vertex of even valence 2m with
// neighbours n_0 … n_{2m−1} in cyclic order, the pairs (n_k, n_{k+m}),
// k = 0 … m − 1; at an interior valence-4 vertex of a quad mesh, and along
// the boundary through a boundary vertex of valence 3, these are the
// consecutive triples of the mesh polylines (mesh/topology.h PolylineTriples).
//
// ‖r‖ = 2 sin(θ/2), θ the turning angle between the edge directions
// (θ = 0: u, v, w collinear with v between them). r = 0 iff the two edges are
// aligned; the energy ½‖r‖² = 1 − cos θ grows monotonically on [0, π].
// Relation to the thesis' wording: for the edge vectors a = u − v and
// b = w − v emanating from v, ‖unit(a) × unit(b)‖ = sin θ. Read literally,
// increasing that cross product would open the edges to a right angle; the
// intended effect (§11.7.1: "bending forces which align opposing vertex
// edges") is unit(a) → −unit(b), i.e. the cross product driven to zero with
// the edges pointing away from each other. We do not use the cross product as
// the residual: it also vanishes at θ = π (the edges folded onto each other), a
// second minimum of ½ sin²θ into which a strongly bent star would be pushed;
// t_out − t_in agrees with it to first order (2 sin(θ/2) = θ + O(θ³) =
// sin θ + O(θ³)) and has no false zero.
// Using unit directions (not the second difference u − 2v + w of
// energies/fairness.h) makes the term act on the angle only: it does not
// equalise the two edge lengths, so it combines with springs without
// double-counting spacing.
//
// Units / normalisation: r is unit-free (a difference of unit vectors);
// L = 1/inv_length (the builder's mean edge length) only scales the
// regularisation.
//
// Singular configurations: a zero-length edge (u = v or v = w) has no
// direction; unit_ε(0) = 0, so r is finite and its Jacobian of order
// 1/(εL) at most. For ‖x‖ ≫ εL, unit_ε differs from the unit vector by
// ½(εL/‖x‖)² relative. Never returns false.
//
// Invariances: rigid motions (r → R r, ‖r‖ unchanged); uniform scaling x → s x
// with inv_length → inv_length / s (r unchanged); reversing the triple
// (w, v, u) leaves r unchanged.
#ifndef ARCHGEO_ENERGIES_BENDING_H_
#define ARCHGEO_ENERGIES_BENDING_H_

#include <cmath>

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

// Regularisation of the edge directions, relative to L (see above).
inline constexpr double kBendingEpsilon = 1e-6;

struct Bending {
  using Shape = CostShape<3, 3, 3, 3>;

  // inv_length: 1/L, L > 0 the builder's mean edge length.
  explicit Bending(double inv_length) : inv_length(inv_length) {}

  // u, v, w: 3 doubles each, v the vertex and u, w its opposite neighbours;
  // residual: 3 doubles.
  template <typename T>
  bool operator()(const T* u_ptr, const T* v_ptr, const T* w_ptr,
                  T* residual_ptr) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> u(u_ptr);
    const Eigen::Map<const Vec3> v(v_ptr);
    const Eigen::Map<const Vec3> w(w_ptr);
    Eigen::Map<Vec3> residual(residual_ptr);
    const double eps = kBendingEpsilon / inv_length;
    using std::sqrt;
    const Vec3 in = v - u;
    const Vec3 out = w - v;
    residual = out / sqrt(out.squaredNorm() + T(eps * eps)) -
               in / sqrt(in.squaredNorm() + T(eps * eps));
    return true;
  }

  double inv_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_BENDING_H_
