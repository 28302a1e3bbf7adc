// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Grid equilaterality, one residual per grid edge (a, b):
//
//   r = (√(‖x(b) − x(a)‖² + (ε L)²) − L) / L
//
//   [force-directed grids paper, §3 goal (2) "locally have almost constant
//    grid size", Step 2 of Listing 1 (edge length towards the ideal length),
//    measured by MDE/ADE, eq. 6]
//
// x(u, v) is the surface map evaluated on the two end points' parameter
// blocks. L = ideal_length is the constant ideal edge length of §3 (the mean
// initial edge length, or the user's); a per-edge L (e.g. from curvature) is
// the builder's choice. For ε → 0, r = |e|/L − 1, the relative deviation of
// the edge from L: r = 0 iff |e| = L. It is the residual whose gradient
// descent is Listing 1's Step 2 (the force along e is ∝ L − |e|).
//
// Units / normalisation: relative (unit-free). Ceres minimises ½Σr².
//
// Singular configurations: a zero-length edge (x(a) = x(b)) has no direction;
// the length is regularised with ε = kGridEpsilon times L, so r ≈ −1 there with
// a finite (zero) Jacobian, and r equals |e|/L − 1 to ½ ε² L/|e| absolute.
// Never returns false.
//
// Invariances: rigid motions of the surface (r unchanged); uniform scaling
// x → s x with ideal_length → s · ideal_length (r unchanged); swapping a, b.
//
// Ownership: the functor holds a copy of the Surface.
#ifndef ARCHGEO_ENERGIES_GRID_EQUILATERALITY_H_
#define ARCHGEO_ENERGIES_GRID_EQUILATERALITY_H_

#include <cmath>

#include <Eigen/Core>

#include "energies/grid_orthogonality.h"  // kGridEpsilon
#include "surfaces/surface.h"

#include "energies/autodiff.h"

namespace archgeo {

struct GridEquilaterality {
  using Shape = CostShape<1, 2, 2>;

  // surface: copied; ideal_length: L > 0.
  GridEquilaterality(const Surface& surface, double ideal_length)
      : surface(surface), ideal_length(ideal_length) {}

  // a, b: 2 doubles each, the (u, v) of the edge's end points; residual: 1 double.
  template <typename T>
  bool operator()(const T* a, const T* b, T* residual) const {
    using std::sqrt;
    const Vec3T<T> e = surface.Point(b[0], b[1]) - surface.Point(a[0], a[1]);
    const double eps = kGridEpsilon * ideal_length;
    residual[0] = (sqrt(e.squaredNorm() + T(eps * eps)) - ideal_length) / ideal_length;
    return true;
  }

  Surface surface;
  double ideal_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_GRID_EQUILATERALITY_H_
