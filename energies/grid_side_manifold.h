// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the parameters (u, v) of a grid vertex held on one side of its
// domain: one coordinate fixed, the other sliding along the side and never
// past its ends (no CGAL).
//
// Ambient size 2 (u, v), tangent size 1. With h the held coordinate, f the
// free one, the side [lo, hi] of f, m = (lo + hi)/2, r = (hi − lo)/2 and
// θ(x) = asin((x_f − m)/r) (the argument clamped to [−1, 1]):
//   Plus(x, δ):  y_h = x_h,  y_f = m + r sin(θ(x) + δ/r)
//   Minus(y, x): r (θ(y) − θ(x))
//   PlusJacobian: ∂y_f/∂δ = cos θ(x) (0 for the held coordinate);
//   MinusJacobian: 1/cos θ(x) (regularised at the ends, where cos θ = 0).
// A step of δ moves the vertex by δ near the middle of the side, and ever
// less towards its ends, which it reaches only in the limit: a boundary
// vertex slides along its side and cannot pass a corner (a vertex that did
// would fold the grid there). Plus(x, 0) = x up to rounding of x_f.
// Surfaces/grid_cover.h says which vertices are held where.
#pragma once

#include <ceres/manifold.h>

namespace archgeo {

class GridSideManifold : public ceres::Manifold {
 public:
  // held: 0 (u) or 1 (v); [lo, hi]: the side's extent in the other
  // coordinate. Precondition (CHECKed): lo < hi.
  GridSideManifold(int held, double lo, double hi);
  int AmbientSize() const override { return 2; }
  int TangentSize() const override { return 1; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;

 private:
  double Angle(const double* x) const;
  int held_, free_;
  double mid_, radius_;
};

// A new GridSideManifold (the caller, usually ceres::Problem, takes ownership).
ceres::Manifold* MakeGridSideManifold(int held, double lo, double hi);

}  // namespace archgeo
