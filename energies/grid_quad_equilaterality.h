// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Local equilaterality of a grid quad, four residuals per quad (a, b, c, d in
// cyclic order):
//
//   r_k = (s_k − s̄) / s̄,   s_k = √(‖x(k+1) − x(k)‖² + (ε L)²),   s̄ = ¼ Σ_k s_k
//
//   [force-directed grids paper, §1 condition (2) "locally have almost
//    constant grid size in both directions", measured per quad by MDE/ADE,
//    eq. 6: L_k / l_k, the quad's longest over its shortest side]
//
// x(u, v) is the surface map evaluated on the four parameter blocks; s_k are
// the quad's sides (chords, as eq. 6 is measured). r = 0 iff the four sides
// are equal (with orthogonal lines: a square), whatever their common length:
// unlike grid_equilaterality (every edge towards one ideal length L, Listing 1
// step 2) it lets the grid size vary across the surface, as §3 says curvature
// asks for ("high curvature results in locally small grid size"), and
// penalises only what MDE/ADE measure. For small deviations
// max_k s_k / min_k s_k − 1 ≈ max r − min r. It fixes no scale: use it with
// grid_equilaterality (L) or with a grid held by its boundary.
//
// Units / normalisation: relative (unit-free). Ceres minimises ½Σr².
//
// Singular configurations: a quad collapsed to a point (every side 0); the
// sides are regularised with ε = kGridEpsilon times L = 1/inv_length (a fixed
// reference length, the ideal edge length), so s̄ ≥ εL > 0 and r stays finite
// with a finite Jacobian (r = 0 there). Never returns false.
//
// Invariances: rigid motions of the surface (r unchanged); uniform scaling
// x → s x (r unchanged, exactly with inv_length → inv_length / s); a cyclic
// relabelling or reversal of the quad permutes the residuals.
//
// Ownership: the functor holds a copy of the Surface.
#ifndef ARCHGEO_ENERGIES_GRID_QUAD_EQUILATERALITY_H_
#define ARCHGEO_ENERGIES_GRID_QUAD_EQUILATERALITY_H_

#include <cmath>

#include <Eigen/Core>

#include "energies/grid_orthogonality.h"  // kGridEpsilon
#include "surfaces/surface.h"

#include "energies/autodiff.h"

namespace archgeo {

struct GridQuadEquilaterality {
  using Shape = CostShape<4, 2, 2, 2, 2>;

  // surface: copied; inv_length: 1/L, L > 0 the reference length.
  GridQuadEquilaterality(const Surface& surface, double inv_length)
      : surface(surface), inv_length(inv_length) {}

  // a, b, c, d: 2 doubles each, the (u, v) of the quad's vertices in cyclic
  // order; residual: 4 doubles.
  template <typename T>
  bool operator()(const T* a, const T* b, const T* c, const T* d, T* residual) const {
    using std::sqrt;
    const Vec3T<T> x[4] = {surface.Point(a[0], a[1]), surface.Point(b[0], b[1]),
                           surface.Point(c[0], c[1]), surface.Point(d[0], d[1])};
    const double eps = kGridEpsilon / inv_length;
    T side[4];
    T mean = T(0.0);
    for (int k = 0; k < 4; ++k) {
      side[k] = sqrt((x[(k + 1) % 4] - x[k]).squaredNorm() + T(eps * eps));
      mean += side[k];
    }
    mean *= T(0.25);
    for (int k = 0; k < 4; ++k) residual[k] = (side[k] - mean) / mean;
    return true;
  }

  Surface surface;
  double inv_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_GRID_QUAD_EQUILATERALITY_H_
