// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Spring along a mesh edge (a, b) — the YAML term `spring`, two forms:
//
//   length spring  (L0 > 0):  r = (‖a − b‖_ε − L0) / L              1 residual
//   zero-length    (L0 = 0):  r = (a − b) / L                       3 residuals
//
//   ‖d‖_ε = sqrt(‖d‖² + (ε L)²),  ε = kSpringEpsilon
//
//   [Gebreiter 2012, §10.1 "Constrained force equalisation": springs along
//    mesh edges, target lengths zero → Laplacian smoothing / minimal surface;
//    §11.2.2 zero-length springs of the hanging net; §11.7.1 springs along
//    boundary edges and "contraction forces along edges"]
//
// Ceres minimises ½Σr², so a spring of weight w stores ½ w (‖a − b‖ − L0)²/L²:
// a linear spring of stiffness k = w/L² and rest length L0. Its force on a is
// k (‖a − b‖ − L0) unit(b − a) (towards b when stretched).
//
// Target length: L0 = rest_length is a constant chosen by the builder — an
// absolute target (e.g. the mean boundary edge length, to distribute boundary
// vertices evenly), or a fraction of the edge's length when the problem is
// built (L0 = fraction · ‖a − b‖; re-built every round this is the thesis'
// "contraction force", 0 < fraction < 1 shrinks every edge by that factor per
// round). L0 = 0 is the zero-length spring: the energy ½‖a − b‖²/L² is
// quadratic, so its residual is the 3-vector a − b, linear and smooth
// everywhere (the scalar form ‖a − b‖/L has the same energy but a cusp at
// a = b). The energy is continuous in L0 at 0: (‖d‖ − L0)² → ‖d‖².
//
// Units / normalisation: L = 1/inv_length is a fixed length chosen by the
// builder (the mean edge length at build time), so r is unit-free.
//
// Singular configurations: the length spring at a = b (direction undefined):
// the norm is regularised with ε L, so there r = (εL − L0)/L ≈ −L0/L with a
// zero Jacobian (finite; no NaN); for ‖d‖ ≫ εL the regularisation changes r
// by at most ½ε²L/‖d‖ ≤ ½ε² relative to ‖d‖ = L. The zero-length form has no
// singular set (Jacobian ±I/L). Never returns false.
//
// Invariances: rigid motions (the length spring's r unchanged; the
// zero-length r → R r, ‖r‖ unchanged); uniform scaling x → s x with
// L0 → s L0 and inv_length → inv_length / s (r unchanged). Swapping a and b
// keeps the length residual and negates the zero-length one.
#ifndef ARCHGEO_ENERGIES_SPRING_H_
#define ARCHGEO_ENERGIES_SPRING_H_

#include <cmath>

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

// Regularisation of ‖a − b‖, relative to L (see above).
inline constexpr double kSpringEpsilon = 1e-6;

// Length spring, L0 > 0: r = (‖a − b‖_ε − L0) / L.
struct Spring {
  using Shape = CostShape<1, 3, 3>;

  // rest_length: L0 > 0; inv_length: 1/L.
  Spring(double rest_length, double inv_length)
      : rest_length(rest_length), inv_length(inv_length) {}

  // a, b: 3 doubles each, the edge's end points; residual: 1 double.
  template <typename T>
  bool operator()(const T* a_ptr, const T* b_ptr, T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> a(a_ptr);
    const Eigen::Map<const Vec3> b(b_ptr);
    const double eps = kSpringEpsilon / inv_length;
    using std::sqrt;
    const T length = sqrt((a - b).squaredNorm() + T(eps * eps));
    residual[0] = (length - T(rest_length)) * T(inv_length);
    return true;
  }

  double rest_length;
  double inv_length;
};

// Zero-length spring: r = (a − b) / L.
struct ZeroLengthSpring {
  using Shape = CostShape<3, 3, 3>;

  // inv_length: 1/L.
  explicit ZeroLengthSpring(double inv_length) : inv_length(inv_length) {}

  // a, b: 3 doubles each; residual: 3 doubles.
  template <typename T>
  bool operator()(const T* a_ptr, const T* b_ptr, T* residual_ptr) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> a(a_ptr);
    const Eigen::Map<const Vec3> b(b_ptr);
    Eigen::Map<Vec3> residual(residual_ptr);
    residual = (a - b) * T(inv_length);
    return true;
  }

  double inv_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_SPRING_H_
