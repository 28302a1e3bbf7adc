// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Catenoid (test surface; a minimal surface of revolution):
//   x(u, v) = (c cosh(v/c) cos u, c cosh(v/c) sin u, v),
//   u ∈ [0, 2π) periodic, v ∈ [−H/2, H/2] open.
// Stands for no Table 1 scene; negative Gaussian curvature, closed in u.
// Parameters: c > 0 waist radius, H > 0 height (file units).
#pragma once

#include <cmath>

#include "surfaces/parametric.h"

namespace archgeo {

struct Catenoid {
  static constexpr const char* kName = "catenoid";
  double c = 1.0;  // waist radius
  double H = 3.0;  // height: v ∈ [−H/2, H/2]

  ParameterDomain Domain() const {
    return {0.0, 2.0 * M_PI, -0.5 * H, 0.5 * H, true, false, false};
  }

  template <typename T>
  Vec3T<T> Point(const T& u, const T& v) const {
    using std::cos;
    using std::cosh;
    using std::sin;
    const T rho = c * cosh(v / c);
    return Vec3T<T>(rho * cos(u), rho * sin(u), v);
  }

  template <typename T>
  void Tangents(const T& u, const T& v, Vec3T<T>* xu, Vec3T<T>* xv) const {
    using std::cos;
    using std::cosh;
    using std::sin;
    using std::sinh;
    const T rho = c * cosh(v / c);
    const T drho = sinh(v / c);
    *xu = Vec3T<T>(-rho * sin(u), rho * cos(u), T(0.0));
    *xv = Vec3T<T>(drho * cos(u), drho * sin(u), T(1.0));
  }
};

}  // namespace archgeo
