// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Function graph (Table 1 scene "Function Graph", type C0): a roof over the
// rectangle [0, a] × [0, b], a dome plus a saddle,
//
//   x(u, v) = (u, v, f(u, v)),
//   f(u, v) = h sin(π u / a) sin(π v / b) + s (2u/a − 1)(2v/b − 1),
//
// open in u and v. The graph parametrisation is orthogonal only where
// f_u f_v = 0, so the uniform grid is skewed wherever the roof slopes both
// ways (most strongly towards the corners, where the saddle tilts it).
// Parameters: a, b > 0 plan lengths, h dome height, s saddle height
// (f = ±s at the corners), all in file units.
#pragma once

#include <cmath>

#include "surfaces/parametric.h"

namespace archgeo {

struct FunctionGraph {
  static constexpr const char* kName = "function_graph";
  double a = 10.0, b = 10.0;  // plan: [0, a] × [0, b]
  double h = 2.0;             // dome height
  double s = 3.0;             // saddle height

  ParameterDomain Domain() const { return {0.0, a, 0.0, b, false, false, false}; }

  template <typename T>
  Vec3T<T> Point(const T& u, const T& v) const {
    using std::sin;
    const T f = h * sin((M_PI / a) * u) * sin((M_PI / b) * v) +
                s * ((2.0 / a) * u - 1.0) * ((2.0 / b) * v - 1.0);
    return Vec3T<T>(u, v, f);
  }

  template <typename T>
  void Tangents(const T& u, const T& v, Vec3T<T>* xu, Vec3T<T>* xv) const {
    using std::cos;
    using std::sin;
    const T su = sin((M_PI / a) * u), cu = cos((M_PI / a) * u);
    const T sv = sin((M_PI / b) * v), cv = cos((M_PI / b) * v);
    const T fu = (h * M_PI / a) * cu * sv + (2.0 * s / a) * ((2.0 / b) * v - 1.0);
    const T fv = (h * M_PI / b) * su * cv + (2.0 * s / b) * ((2.0 / a) * u - 1.0);
    *xu = Vec3T<T>(T(1.0), T(0.0), fu);
    *xv = Vec3T<T>(T(0.0), T(1.0), fv);
  }
};

}  // namespace archgeo
