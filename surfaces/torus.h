// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Ring torus (test surface):
//   x(u, v) = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v),
//   u, v ∈ [0, 2π), periodic in both.
// Stands for no Table 1 scene; a doubly curved surface closed both ways (the
// parameter lines are its lines of curvature: x_u · x_v = 0).
// Parameters: R > r > 0 — distance of the tube centre from the axis, tube radius.
#pragma once

#include <cmath>

#include "surfaces/parametric.h"

namespace archgeo {

struct Torus {
  static constexpr const char* kName = "torus";
  double R = 3.0;  // centre-line radius
  double r = 1.0;  // tube radius, 0 < r < R

  ParameterDomain Domain() const {
    return {0.0, 2.0 * M_PI, 0.0, 2.0 * M_PI, true, true, false};
  }

  template <typename T>
  Vec3T<T> Point(const T& u, const T& v) const {
    using std::cos;
    using std::sin;
    const T rho = R + r * cos(v);
    return Vec3T<T>(rho * cos(u), rho * sin(u), r * sin(v));
  }

  template <typename T>
  void Tangents(const T& u, const T& v, Vec3T<T>* xu, Vec3T<T>* xv) const {
    using std::cos;
    using std::sin;
    const T rho = R + r * cos(v);
    *xu = Vec3T<T>(-rho * sin(u), rho * cos(u), T(0.0));
    *xv = Vec3T<T>(-r * sin(v) * cos(u), -r * sin(v) * sin(u), r * cos(v));
  }
};

}  // namespace archgeo
