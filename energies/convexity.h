// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Convex panels: a one-sided (hinge) barrier on every corner of a face, one
// residual per corner (a, b, c) = (previous, corner, next vertex):
//
//   s = ((b − a) × (c − b)) · n / (‖b − a‖ ‖c − b‖)     (sine of the turn at b)
//   r = max(0, t − s)
//
//   [validity of a built panel: a quad is buildable as a flat glass pane only
//    if it is convex (Zadravec 2010, §6 and Fig. 13 show the reflex quads that
//    a planarity optimisation alone produces); the barrier keeps each corner's
//    interior angle θ = 180° − turn within [m, 180° − m]]
//
// n is the face's unit normal at the start of the round (Newell's normal of
// the face; a constant of the residual, refreshed every round) and fixes the
// side: walking the face in its orientation, a convex corner turns left
// (s > 0), a reflex corner (θ > 180°) turns right (s < 0). t = sin(m) for a
// margin m (terms.convexity.margin_degrees); where the input's corner is
// already outside the margin (a straight corner where two quads were joined,
// a dart), t = s_input − sin(m): the corner may get worse by about the margin
// and no more, so the barrier never asks for more than the input had. The residual
// is zero — no gradient, no effect on the solve — while every corner is
// inside the margin; it acts only when a corner is about to fold (an active
// set, like the bounds of a constrained solve).
//
// Units / normalisation: s is a sine, unit-free; the term's weight should be
// large against the goal terms (e.g. 1e3) so that it acts as a constraint.
//
// Singular configurations: a zero-length side makes s undefined; the lengths
// are regularised as sqrt(‖e‖² + ε²) with ε = 1e-9 (canonical frame: mean
// edge length 1), so r stays finite (a collapsed corner has s ≈ 0 and is
// penalised). The hinge is not differentiable at s = t (Ceres sees the
// one-sided derivative); never returns false.
//
// Invariances: rigid motions applied to a, b, c and n (r unchanged); uniform
// scaling (s depends only on angles, r unchanged).
#ifndef ARCHGEO_ENERGIES_CONVEXITY_H_
#define ARCHGEO_ENERGIES_CONVEXITY_H_

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "energies/autodiff.h"

namespace archgeo {

struct Convexity {
  using Shape = CostShape<1, 3, 3, 3>;

  // normal: 3 doubles, unit; threshold: t, the smallest allowed sine.
  Convexity(const double normal[3], double threshold)
      : normal(normal[0], normal[1], normal[2]), threshold(threshold) {}

  // a, b, c: 3 doubles each (previous, corner, next); residual: 1 double.
  template <typename T>
  bool operator()(const T* a_ptr, const T* b_ptr, const T* c_ptr, T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> a(a_ptr), b(b_ptr), c(c_ptr);
    const Vec3 u = b - a, v = c - b;
    const T eps2(1e-18);
    const T s = u.cross(v).dot(normal.cast<T>()) /
                (sqrt(u.squaredNorm() + eps2) * sqrt(v.squaredNorm() + eps2));
    const T gap = T(threshold) - s;
    residual[0] = gap > T(0) ? gap : T(0);
    return true;
  }

  Eigen::Vector3d normal;
  double threshold;
  // max(gap, 0): where the residual is 0 its derivatives are 0 too (its
  // batch differentiates only the elements that are not idle).
  static constexpr bool kFlatWhereZero = true;
};

// The sine s of the turn at b (as in Convexity), for thresholds and reports.
double CornerTurnSine(const double a[3], const double b[3], const double c[3],
                      const double normal[3]);

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_CONVEXITY_H_
