// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Circular cylinder (test surface):
//   x(u, v) = (R cos u, R sin u, v),   u ∈ [0, 2π) periodic, v ∈ [0, H] open.
// Stands for no Table 1 scene; it is developable, so a grid closed in u can be
// exactly orthogonal and equilateral (square cells of side 2πR/n_u): the
// analytic target of the force method's convergence test.
// Parameters: R > 0 radius, H > 0 height (file units).
#pragma once

#include <cmath>

#include "surfaces/parametric.h"

namespace archgeo {

struct Cylinder {
  static constexpr const char* kName = "cylinder";
  double R = 1.0;  // radius
  double H = 2.0;  // height: v ∈ [0, H]

  ParameterDomain Domain() const { return {0.0, 2.0 * M_PI, 0.0, H, true, false, false}; }

  template <typename T>
  Vec3T<T> Point(const T& u, const T& v) const {
    using std::cos;
    using std::sin;
    return Vec3T<T>(R * cos(u), R * sin(u), v);
  }

  template <typename T>
  void Tangents(const T& u, const T& /*v*/, Vec3T<T>* xu, Vec3T<T>* xv) const {
    using std::cos;
    using std::sin;
    *xu = Vec3T<T>(-R * sin(u), R * cos(u), T(0.0));
    *xv = Vec3T<T>(T(0.0), T(0.0), T(1.0));
  }
};

}  // namespace archgeo
