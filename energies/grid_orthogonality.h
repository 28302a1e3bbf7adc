// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Grid orthogonality at an interior grid vertex, one residual per vertex:
//
//   r = a·b / √(‖a‖² ‖b‖² + (ε L²)²),   a = x(l1) − x(l0),   b = x(t1) − x(t0),
//
//   [force-directed grids paper, §3 goal (1) "all lines intersect
//    orthogonally", measured by MDO/ADO, eqs. 4–5]
//
// l0, l1 are the vertex's neighbours along its u-line (longitudinal), t0, t1
// along its v-line (transversal); x(u, v) is the surface map, evaluated inside
// the functor on the neighbours' parameter blocks, so autodiff runs through
// the surface. a and b are the central-difference tangents of the two grid
// lines at the vertex (the tangents of the parabolas through three
// consecutive vertices at equal spacing), the discrete counterpart of the
// spline tangents eqs. 4–5 are measured with; for ε → 0, r = cos θ, θ the
// angle between the lines, and r = 0 iff they cross at 90°. The vertex's own
// (u, v) does not enter: it sits where the lines cross.
// Relation to eq. 1: the paper's "orthogonality force" is the sum of unit
// edge vectors (l0 − p)* + (l1 − p)* + (t0 − p)* + (t1 − p)*, zero iff both
// lines pass straight through p (their straightening); orthogonality itself
// it measures only through MDO/ADO. This residual states the goal directly;
// straightness is energies/grid_fairness.h.
//
// Units / normalisation: r is a cosine (unit-free, in [−1, 1]); Ceres
// minimises ½Σr², and for small deviations δ = 90° − θ, r ≈ sin δ ≈ δ.
//
// Singular configurations: a = 0 or b = 0 (a folded line, l1 = l0) leaves
// the angle undefined; the denominator is regularised with ε = kGridEpsilon
// times L², L = 1/inv_length a fixed reference length (the ideal edge length),
// so r stays finite with a finite Jacobian (r = 0 there) and equals cos θ to
// relative precision ½(ε L²/(‖a‖‖b‖))² for lines of length ≈ L. Never returns
// false.
//
// Invariances: rigid motions of the surface (x → Q x + t: r unchanged);
// uniform scaling x → s x with inv_length → inv_length / s (r unchanged).
// Reversing one line (l0 ↔ l1, or t0 ↔ t1, as across the flipping seam of a
// Klein bottle grid) flips the sign; only r² enters the energy.
//
// Ownership: the functor holds a copy of the Surface (a few dozen doubles).
#ifndef ARCHGEO_ENERGIES_GRID_ORTHOGONALITY_H_
#define ARCHGEO_ENERGIES_GRID_ORTHOGONALITY_H_

#include <cmath>

#include <Eigen/Core>

#include "surfaces/surface.h"

#include "energies/autodiff.h"

namespace archgeo {

// Regularisation of the grid energies' norms, relative to L (lengths) or L²
// (products of lengths).
inline constexpr double kGridEpsilon = 1e-6;

struct GridOrthogonality {
  using Shape = CostShape<1, 2, 2, 2, 2>;

  // surface: copied; inv_length: 1/L, L > 0 the reference length.
  GridOrthogonality(const Surface& surface, double inv_length)
      : surface(surface), inv_length(inv_length) {}

  // l0, l1, t0, t1: 2 doubles each, the (u, v) of the four neighbours;
  // residual: 1 double.
  template <typename T>
  bool operator()(const T* l0, const T* l1, const T* t0, const T* t1, T* residual) const {
    using std::sqrt;
    const Vec3T<T> a = surface.Point(l1[0], l1[1]) - surface.Point(l0[0], l0[1]);
    const Vec3T<T> b = surface.Point(t1[0], t1[1]) - surface.Point(t0[0], t0[1]);
    const double eps = kGridEpsilon / (inv_length * inv_length);
    residual[0] = a.dot(b) / sqrt(a.squaredNorm() * b.squaredNorm() + T(eps * eps));
    return true;
  }

  Surface surface;
  double inv_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_GRID_ORTHOGONALITY_H_
