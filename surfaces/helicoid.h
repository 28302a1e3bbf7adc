// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Helicoid (test surface; a ruled minimal surface):
//   x(u, v) = (v cos u, v sin u, c u),
//   u ∈ [0, angle] open (the turning angle), v ∈ [−radius, radius] open.
// Stands for no Table 1 scene; regular on the axis (|x_u × x_v| = √(c² + v²)).
// Parameters: c ≠ 0 rise per radian (file units), radius > 0, angle > 0 (radians).
#pragma once

#include <cmath>

#include "surfaces/parametric.h"

namespace archgeo {

struct Helicoid {
  static constexpr const char* kName = "helicoid";
  double c = 0.5;            // rise per radian of turn
  double radius = 2.0;       // v ∈ [−radius, radius]
  double angle = 2.0 * M_PI; // u ∈ [0, angle]

  ParameterDomain Domain() const { return {0.0, angle, -radius, radius, false, false, false}; }

  template <typename T>
  Vec3T<T> Point(const T& u, const T& v) const {
    using std::cos;
    using std::sin;
    return Vec3T<T>(v * cos(u), v * sin(u), c * u);
  }

  template <typename T>
  void Tangents(const T& u, const T& v, Vec3T<T>* xu, Vec3T<T>* xv) const {
    using std::cos;
    using std::sin;
    *xu = Vec3T<T>(-v * sin(u), v * cos(u), T(c));
    *xv = Vec3T<T>(cos(u), sin(u), T(0.0));
  }
};

}  // namespace archgeo
