// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Klein bottle, the figure-8 immersion (Table 1 scene "Klein Bottle", type C2,
// a grid closed in both directions; Figs. 5 and 6 of the paper lay a hall out
// on a Klein bottle and cut the result in half). With c = cos(u/2),
// s = sin(u/2):
//
//   w(u, v) = c sin v − b s sin 2v,    ρ = R + a w,
//   x(u, v) = (ρ cos u,  ρ sin u,  a (s sin v + b c sin 2v)),
//
// a figure-8 curve (sin v, b sin 2v) of size a swept around a circle of
// radius R while turning by half a turn (b = 1 is the classical figure-8
// Klein bottle; a smaller b flattens the figure 8 and rounds its lobes: the
// radius of curvature at the lobes' tips is a/8 for b = 1 and a/4 for b = ½,
// the default, which a 60 × 24 grid resolves). It is an immersion (regular
// everywhere; the surface passes through itself along the central circle,
// where the figure 8 crosses itself) of a closed non-orientable surface:
//   x(u, v + 2π) = x(u, v)         (periodic in v),
//   x(u + 2π, v) = x(u, −v)        (periodic in u with a reflection of v).
// The domain u ∈ [0, 2π), v ∈ [−π, π) centres that reflection (v0 + v1 = 0),
// so a grid closed in both directions wraps its u-seam with
// j → (n_v − j) mod n_v (surfaces/grid.h). The uniform grid is skewed (the
// half turn of the figure 8 makes x_u · x_v ≠ 0) and unequal (|x_v| and
// |x_u| = ρ vary around the figure 8).
// Parameters: a > 0, b > 0, R > a·m(b), m = max |(sin v, b sin 2v)| =
// (1 + 4b²)/(4b) for b ≥ ½, 1 otherwise (ρ > 0); lengths in file units.
// Defaults: R = 3, a = 1, b = ½.
// (The classical "bottle" immersion was not chosen: its neck is ten times
// thinner than its body, thinner than any grid edge of a uniform grid.)
#pragma once

#include <cmath>

#include "surfaces/parametric.h"

namespace archgeo {

struct KleinBottle {
  static constexpr const char* kName = "klein_bottle";
  double R = 3.0;  // radius of the circle the figure 8 is swept around
  double a = 1.0;  // size of the figure 8
  double b = 0.5;  // height of the figure 8's lobes relative to their width

  // max |(sin v, b sin 2v)|: ρ > 0 iff R > a · MaxOffset().
  double MaxOffset() const { return b >= 0.5 ? (1.0 + 4.0 * b * b) / (4.0 * b) : 1.0; }

  ParameterDomain Domain() const { return {0.0, 2.0 * M_PI, -M_PI, M_PI, true, true, true}; }

  template <typename T>
  Vec3T<T> Point(const T& u, const T& v) const {
    using std::cos;
    using std::sin;
    const T c = cos(0.5 * u), s = sin(0.5 * u);
    const T s1 = sin(v), s2 = sin(2.0 * v);
    const T rho = R + a * (c * s1 - b * s * s2);
    return Vec3T<T>(rho * cos(u), rho * sin(u), a * (s * s1 + b * c * s2));
  }

  template <typename T>
  void Tangents(const T& u, const T& v, Vec3T<T>* xu, Vec3T<T>* xv) const {
    using std::cos;
    using std::sin;
    const T c = cos(0.5 * u), s = sin(0.5 * u);
    const T s1 = sin(v), s2 = sin(2.0 * v), c1 = cos(v), c2 = cos(2.0 * v);
    const T w = c * s1 - b * s * s2;
    const T rho = R + a * w;
    const T w_u = -0.5 * (s * s1 + b * c * s2);
    const T w_v = c * c1 - 2.0 * b * s * c2;
    const T cu = cos(u), su = sin(u);
    *xu = Vec3T<T>(a * w_u * cu - rho * su, a * w_u * su + rho * cu, 0.5 * a * w);
    *xv = Vec3T<T>(a * w_v * cu, a * w_v * su, a * (s * c1 + 2.0 * b * c * c2));
  }
};

}  // namespace archgeo
