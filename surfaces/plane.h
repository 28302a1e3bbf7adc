// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Plane (test surface): x(u, v) = (u, v, 0) on [0, a] × [0, b], open in u and v.
// Stands for no Table 1 scene; used by the tests (an orthogonal equilateral
// grid on it is the analytic zero of every grid measure and energy).
// Parameters: a, b > 0 — side lengths of the domain (file units).
#pragma once

#include "surfaces/parametric.h"

namespace archgeo {

struct Plane {
  static constexpr const char* kName = "plane";
  double a = 10.0;  // domain length in u
  double b = 10.0;  // domain length in v

  ParameterDomain Domain() const { return {0.0, a, 0.0, b, false, false, false}; }

  template <typename T>
  Vec3T<T> Point(const T& u, const T& v) const {
    return Vec3T<T>(u, v, T(0.0));
  }

  template <typename T>
  void Tangents(const T& /*u*/, const T& /*v*/, Vec3T<T>* xu, Vec3T<T>* xv) const {
    *xu = Vec3T<T>(T(1.0), T(0.0), T(0.0));
    *xv = Vec3T<T>(T(0.0), T(1.0), T(0.0));
  }
};

}  // namespace archgeo
