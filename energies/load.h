// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Load with force balance at a free vertex (hanging-net form finding) — the
// YAML term `load`, one 3-vector residual per free vertex v with neighbours
// w_1 … w_n joined to v by springs:
//
//   r = ( f + Σ_j k_j s_j ) / F,     d_j = w_j − v,
//   s_j = d_j                               (zero-length spring, L0_j = 0)
//   s_j = (1 − L0_j / ‖d_j‖_ε) d_j          (length spring, L0_j > 0)
//   ‖d‖_ε = sqrt(‖d‖² + (ε L0_j)²),  ε = kLoadEpsilon
//
//   [Gebreiter 2012, §11.2.2: boundary vertices fixed, a zero-length spring
//    on every edge, an inverted gravitational force — the hanging net;
//    §10.1 dynamic relaxation [Barnes 1977]: nodes oscillate about the
//    equilibrium of the stiffness terms and the global forces]
//
// r·F is the resultant force on v: the external load f plus the forces of the
// springs of v's star (spring j of stiffness k_j and rest length L0_j pulls v
// towards w_j with k_j (‖d_j‖ − L0_j)). r = 0 exactly at equilibrium, which is
// what dynamic relaxation converges to (its damped oscillation ends where the
// residual forces vanish).
//
// Why a force residual and not the potential: the equilibrium minimises
// Π(x) = Σ_e ½ k_e (‖d_e‖ − L0_e)² − Σ_v f_v·x_v, but −f·x is linear, not a
// sum of squares, and Ceres minimises ½Σ‖r‖². One residual per free vertex
// and coordinate makes a square system (3 residuals per 3 unknowns) whose
// least-squares minimum is 0 exactly at a stationary point of Π; for
// zero-length springs it is linear (a discrete Poisson problem: one
// Gauss-Newton step solves it) and, with every free vertex connected to a
// fixed one, has a unique solution. Rejected alternative: for zero-length
// springs Π equals ½Σ_e ‖√k_e d_e − g_e‖² + const when the edge vectors g_e
// carry the loads to the supports (Dᵀg = f); that needs a global load path
// and does not extend to length springs. Consequences for composing terms:
// this term already contains the springs of the net — do not add `spring`
// terms on the same edges (they would pull the net towards zero length and
// bias the equilibrium); other terms added with it trade force imbalance
// against their own residuals (report the imbalance, analysis/goal_metrics.h
// MeasureForceBalance). Only free vertices get this residual: fixed vertices
// take reactions; a vertex bound to a curve or surface would need the
// tangential part of r only (not provided here).
//
// Load: f is a constant chosen by the builder, e.g. gravity by tributary area
// f_v = A_v q (A_v = v's share of its faces' area, analysis/goal_metrics.h
// TributaryAreas, from the positions at build time; q = load per area,
// pointing up for a compression vault found as an inverted hanging net).
//
// Units / normalisation: f and k_j·length are forces (any consistent unit);
// F = 1/inv_force is a fixed force scale chosen by the builder (the mean
// |f_v| over the free vertices), so r is unit-free and ‖r‖ ≤ 1e-6 means
// "residual force ≤ 1e-6 of the load".
//
// Singular configurations: a length spring with w_j = v has no direction;
// with the regularised norm s_j is 0 there and its Jacobian finite (of order
// 1/ε). Zero-length springs: none (linear). Never returns false.
//
// Invariances: rigid motions with the load rotated too (f → R f: r → R r,
// ‖r‖ unchanged); uniform scaling x → s x with L0 → s L0 and k → k/s (forces
// unchanged, r unchanged); any order of the neighbours.
#ifndef ARCHGEO_ENERGIES_LOAD_H_
#define ARCHGEO_ENERGIES_LOAD_H_

#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace archgeo {

// Regularisation of a length spring's ‖d‖, relative to its rest length.
inline constexpr double kLoadEpsilon = 1e-6;

// Functor over a vertex star (MakeStarAutoDiff): parameters[0] = v,
// parameters[j] = w_j (j = 1 … n), 3 doubles each; 3 residuals.
struct LoadEquilibrium {
  static constexpr int kResiduals = 3;
  static constexpr int kStride = 12;
  int NumBlocks() const { return int(stiffness.size()) + 1; }

  // force: 3 doubles, the load f on v; stiffness, rest_length: k_j and L0_j
  // of the spring to neighbour j (n entries each, L0_j = 0: zero-length);
  // inv_force: 1/F.
  LoadEquilibrium(const double force[3], std::vector<double> stiffness,
                  std::vector<double> rest_length, double inv_force)
      : force(force[0], force[1], force[2]),
        stiffness(std::move(stiffness)),
        rest_length(std::move(rest_length)),
        inv_force(inv_force) {}

  template <typename T>
  bool operator()(T const* const* parameters, T* residual_ptr) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> v(parameters[0]);
    Vec3 sum = force.cast<T>();
    using std::sqrt;
    for (size_t j = 0; j < stiffness.size(); ++j) {
      const Vec3 d = Eigen::Map<const Vec3>(parameters[j + 1]) - v;
      const double l0 = rest_length[j];
      if (l0 == 0.0) {
        sum += T(stiffness[j]) * d;
      } else {
        const double eps = kLoadEpsilon * l0;
        const T length = sqrt(d.squaredNorm() + T(eps * eps));
        sum += T(stiffness[j]) * (T(1.0) - T(l0) / length) * d;
      }
    }
    Eigen::Map<Vec3> residual(residual_ptr);
    residual = sum * T(inv_force);
    return true;
  }

  Eigen::Vector3d force;
  std::vector<double> stiffness;
  std::vector<double> rest_length;
  double inv_force;
};

// The functor after checking its input (CHECKs: force finite; n ≥ 1;
// rest_length.size() = n; every k_j finite and > 0, every L0_j finite and
// ≥ 0; inv_force finite and > 0).
LoadEquilibrium CheckedLoadEquilibrium(const double force[3], const std::vector<double>& stiffness,
                                       const std::vector<double>& rest_length, double inv_force);

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_LOAD_H_
