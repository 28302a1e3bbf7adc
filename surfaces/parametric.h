// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — what every parametric surface provides (no CGAL, header only).
//
// A parametric surface is a map x : [u0, u1] × [v0, v1] → R³. Every surface
// type in surfaces/ is a small struct with
//
//   static constexpr const char* kName;            the factory name
//   ParameterDomain Domain() const;                the domain and its closure
//   template <typename T> Vec3T<T> Point(const T& u, const T& v) const;
//   template <typename T> void Tangents(const T& u, const T& v,
//                                       Vec3T<T>* xu, Vec3T<T>* xv) const;
//   ParameterValues Values() const;                its parameters by name
//
// Point and Tangents are written once, templated on the scalar, with analytic
// first derivatives, so a Ceres Jet passes through them (autodiff of a
// residual through x(u, v)) and Tangents<Jet> gives exact second derivatives
// (used by the Newton step of the closest parameter). The surfaces are
// defined by their formulas for all real (u, v); the domain says where the
// designed surface is, and which directions close up.
#pragma once

#include <map>
#include <string>

#include <Eigen/Core>

namespace archgeo {

template <typename T>
using Vec3T = Eigen::Matrix<T, 3, 1>;

// Parameter values by name (the factory's input and the report's output).
using ParameterValues = std::map<std::string, double>;

// The parameter domain [u0, u1] × [v0, v1] and how it closes.
//  periodic_u: x(u + P_u, v) = x(u, v), P_u = u1 − u0 — or, if
//              u_seam_flips_v, x(u + P_u, v) = x(u, v0 + v1 − v) (the gluing
//              of a Klein bottle: one turn in u reflects v);
//  periodic_v: x(u, v + P_v) = x(u, v), P_v = v1 − v0.
// A non-periodic direction is open: the surface ends at its two bounds.
struct ParameterDomain {
  double u0 = 0.0, u1 = 1.0, v0 = 0.0, v1 = 1.0;
  bool periodic_u = false;
  bool periodic_v = false;
  bool u_seam_flips_v = false;  // only with periodic_u

  double PeriodU() const { return u1 - u0; }
  double PeriodV() const { return v1 - v0; }
};

}  // namespace archgeo
