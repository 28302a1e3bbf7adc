// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Dupin-cyclide bridge (Table 1 scene "Bridge", type C0, Fig. 7: "a part of a
// Dupin cyclide which is enclosed with metallic rings"). The ring cyclide in
// its curvature-line parametrisation (α, β) [e.g. Wikipedia, "Dupin cyclide",
// parametric representation], b² = a² − c²,
//
//   D(α, β) = ( μ (c − a cos α cos β) + b² cos α,
//               b sin α (a − μ cos β),
//               b sin β (c cos α − μ) ) / (a − c cos α cos β),
//
// restricted to an open patch and sheared:
//
//   x(u, v) = D(u + shear · (v − v_lo), v),  u ∈ [u_lo, u_hi], v ∈ [v_lo, v_hi].
//
// α runs around the cyclide's ring (along the bridge), β around its tube; the
// default β ∈ [π, 2π] is the upper half of the tube (z ≥ 0: the arch) and the
// default α ∈ [π/2 − 0.3, π/2 + 0.3] a stretch of the ring (radius ≈ 100)
// along which the arch widens from radius 7.2 to 10.8: a gently curved
// bridge 60 long at the crown, its feet 54.5 (inner) and 65.3 (outer) long.
// shear = 0 gives the orthogonal curvature-line net; the default shear 0.05
// makes the uniform grid skewed by about 37° (the paper's input is an
// arbitrary non-orthogonal grid, §1).
// Parameters: a > c ≥ 0 and c < μ < a (a ring cyclide: the denominator
// a − c cos α cos β ≥ a − c > 0), u_lo < u_hi, v_lo < v_hi (radians), shear
// (radians of α per radian of β).
#pragma once

#include <cmath>

#include "surfaces/parametric.h"

namespace archgeo {

struct DupinCyclide {
  static constexpr const char* kName = "dupin_bridge";
  double a = 100.0, c = 6.0, mu = 9.0;
  double u_lo = 0.5 * M_PI - 0.3, u_hi = 0.5 * M_PI + 0.3;
  double v_lo = M_PI, v_hi = 2.0 * M_PI;
  double shear = 0.05;

  ParameterDomain Domain() const { return {u_lo, u_hi, v_lo, v_hi, false, false, false}; }

  template <typename T>
  Vec3T<T> Point(const T& u, const T& v) const {
    using std::cos;
    using std::sin;
    const T al = u + shear * (v - v_lo);
    const T ca = cos(al), sa = sin(al), cb = cos(v), sb = sin(v);
    const double b = B();
    const T w = a - c * ca * cb;
    return Vec3T<T>(mu * (c - a * ca * cb) + b * b * ca, b * sa * (a - mu * cb),
                    b * sb * (c * ca - mu)) /
           w;
  }

  // x_u = D_α, x_v = shear · D_α + D_β (chain rule of the shear).
  template <typename T>
  void Tangents(const T& u, const T& v, Vec3T<T>* xu, Vec3T<T>* xv) const {
    using std::cos;
    using std::sin;
    const T al = u + shear * (v - v_lo);
    const T ca = cos(al), sa = sin(al), cb = cos(v), sb = sin(v);
    const double b = B();
    const T w = a - c * ca * cb;
    const T w_a = c * sa * cb, w_b = c * ca * sb;
    const Vec3T<T> n(mu * (c - a * ca * cb) + b * b * ca, b * sa * (a - mu * cb),
                     b * sb * (c * ca - mu));
    const Vec3T<T> n_a(mu * a * sa * cb - b * b * sa, b * ca * (a - mu * cb), -b * c * sb * sa);
    const Vec3T<T> n_b(mu * a * ca * sb, b * mu * sa * sb, b * cb * (c * ca - mu));
    const T w2 = w * w;
    const Vec3T<T> d_a = (n_a * w - n * w_a) / w2;
    const Vec3T<T> d_b = (n_b * w - n * w_b) / w2;
    *xu = d_a;
    *xv = d_a * T(shear) + d_b;
  }

  double B() const { return std::sqrt(a * a - c * c); }
};

}  // namespace archgeo
