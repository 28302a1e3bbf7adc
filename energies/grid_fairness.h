// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Grid fairness, one 3-vector residual per three consecutive vertices
// (a, b, c) of a grid line:
//
//   r = (x(a) − 2 x(b) + x(c)) / L
//
//   [force-directed grids paper, §3 eq. 1 (the "orthogonality" force is the
//    straightening of the grid lines at each vertex); the second-difference
//    fairness of DESIGN.md's `fairness` energy, here on the surface map]
//
// x(u, v) is the surface map evaluated on the three parameter blocks. r = 0
// iff b is the midpoint of a and c: the line is straight and evenly spaced
// there. On a curved surface r keeps a normal part ≈ κ_n h² / L (h the edge
// length, κ_n the normal curvature along the line), which no grid can remove;
// its tangential part is the discrete geodesic curvature plus the unevenness of
// the spacing, which is what eq. 1 drives to zero. Use it with a small weight
// as a regulariser beside grid_orthogonality and grid_equilaterality.
//
// Units / normalisation: L = 1/inv_length a fixed reference length (the ideal
// edge length): r is unit-free. Ceres minimises ½Σ‖r‖².
//
// Singular configurations: none; r is smooth in the positions. Never returns
// false.
//
// Invariances: rigid motions of the surface (r → Q r, ‖r‖ unchanged);
// uniform scaling x → s x with inv_length → inv_length / s (r unchanged);
// reversing the triple (c, b, a).
//
// Ownership: the functor holds a copy of the Surface.
#ifndef ARCHGEO_ENERGIES_GRID_FAIRNESS_H_
#define ARCHGEO_ENERGIES_GRID_FAIRNESS_H_

#include <Eigen/Core>

#include "surfaces/surface.h"

#include "energies/autodiff.h"

namespace archgeo {

struct GridFairness {
  using Shape = CostShape<3, 2, 2, 2>;

  // surface: copied; inv_length: 1/L, L > 0 the reference length.
  GridFairness(const Surface& surface, double inv_length)
      : surface(surface), inv_length(inv_length) {}

  // a, b, c: 2 doubles each, the (u, v) of three consecutive vertices of a
  // grid line; residual: 3 doubles.
  template <typename T>
  bool operator()(const T* a, const T* b, const T* c, T* residual_ptr) const {
    Eigen::Map<Vec3T<T>> residual(residual_ptr);
    residual = (surface.Point(a[0], a[1]) - T(2.0) * surface.Point(b[0], b[1]) +
                surface.Point(c[0], c[1])) *
               T(inv_length);
    return true;
  }

  Surface surface;
  double inv_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_GRID_FAIRNESS_H_
