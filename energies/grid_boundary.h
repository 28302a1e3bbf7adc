// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Grid boundary anti-folding, one residual per boundary vertex p0 of a grid
// (3 neighbours: p1, p2 along the boundary, p3 inside):
//
//   r = (x(p3) − x(p0)) · n / L,   n = (x(p2) − x(p1)) / √(‖x(p2) − x(p1)‖² + (ε L)²)
//
//   [force-directed grids paper, §3 eq. 2: F_b = d_b · SignedDist(p3, π) ·
//    (p2 − p1)*, π the plane through p0 with normal (p2 − p1)*]
//
// For ε → 0, r L is SignedDist(p3, π), the signed distance eq. 2 multiplies:
// r = 0 iff the transversal edge p0p3 is orthogonal to the boundary's
// direction p2 − p1, i.e. iff eq. 2 exerts no force. Its gradient with respect
// to p0 is along −n, the direction eq. 2 moves p0. x(u, v) is the surface map
// evaluated on the four parameter blocks.
//
// Units / normalisation: L = 1/inv_length a fixed reference length (the ideal
// edge length), so r is unit-free (≈ cos of the angle at p0 for |p0p3| ≈ L).
// Ceres minimises ½Σr².
//
// Singular configurations: p1 = p2 (a collapsed boundary) leaves n undefined;
// the norm is regularised with ε = kGridEpsilon times L, so r → 0 with a finite
// Jacobian there. Never returns false.
//
// Invariances: rigid motions of the surface (r unchanged); uniform scaling
// x → s x with inv_length → inv_length / s (r unchanged). Swapping p1 and p2
// flips the sign.
//
// Ownership: the functor holds a copy of the Surface.
#ifndef ARCHGEO_ENERGIES_GRID_BOUNDARY_H_
#define ARCHGEO_ENERGIES_GRID_BOUNDARY_H_

#include <cmath>

#include <Eigen/Core>

#include "energies/grid_orthogonality.h"  // kGridEpsilon
#include "surfaces/surface.h"

#include "energies/autodiff.h"

namespace archgeo {

struct GridBoundary {
  using Shape = CostShape<1, 2, 2, 2, 2>;

  // surface: copied; inv_length: 1/L, L > 0 the reference length.
  GridBoundary(const Surface& surface, double inv_length)
      : surface(surface), inv_length(inv_length) {}

  // p0, p1, p2, p3: 2 doubles each, the (u, v) of the boundary vertex, its
  // two boundary neighbours and its inner neighbour; residual: 1 double.
  template <typename T>
  bool operator()(const T* p0, const T* p1, const T* p2, const T* p3, T* residual) const {
    using std::sqrt;
    const Vec3T<T> x0 = surface.Point(p0[0], p0[1]);
    const Vec3T<T> along = surface.Point(p2[0], p2[1]) - surface.Point(p1[0], p1[1]);
    const Vec3T<T> inward = surface.Point(p3[0], p3[1]) - x0;
    const double eps = kGridEpsilon / inv_length;
    residual[0] = inward.dot(along) / sqrt(along.squaredNorm() + T(eps * eps)) * T(inv_length);
    return true;
  }

  Surface surface;
  double inv_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_GRID_BOUNDARY_H_
