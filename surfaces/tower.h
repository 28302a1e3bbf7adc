// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Twisted hyperboloid tower (Table 1 scenes "Tower", type C1 — closed in one
// direction, Fig. 9(a) — and, as an open sector, "Tower (Rings)", type C0,
// Fig. 9(b)). A hyperboloid of one sheet around the z axis whose parameter
// lines are twisted:
//
//   x(u, v) = (ρ(v) cos φ, ρ(v) sin φ, v),   φ = u + τ v,   τ = twist / H,
//   ρ(v)    = a √(1 + ((v − z_w) / c)²),
//
// v ∈ [0, H] open (height), u ∈ [0, sector]: periodic when sector = 2π (the
// tower), open otherwise (a sector of it). The v-lines are helices, so the
// uniform parameter grid meets at angle atan(ρ τ) off orthogonal — the
// skewed input the paper's algorithm starts from ("different
// parameterizations", §1).
// Parameters (file units unless told): a > 0 waist radius, c > 0 the
// hyperboloid's axis parameter (ρ grows by a factor √2 at |v − z_w| = c),
// z_w waist height, H > 0 height, twist (radians over the height),
// sector ∈ (0, 2π] (radians). Defaults ("tower"): a = 8, c = 40, z_w = 35,
// H = 60, twist = 5 (the radius goes 10.6 → 8 → 9.4 from foot to top, the
// uniform grid is 41° off orthogonal); "tower_rings" (surface_factory.cpp):
// a = 6, c = 15, z_w = 30, H = 40, twist = π/2, sector = π.
#pragma once

#include <cmath>

#include "surfaces/parametric.h"

namespace archgeo {

struct Tower {
  static constexpr const char* kName = "tower";
  double a = 8.0;             // waist radius
  double c = 40.0;            // hyperboloid axis parameter
  double z_w = 35.0;          // waist height
  double H = 60.0;            // height: v ∈ [0, H]
  double twist = 5.0;         // turn of the v-lines over the height (radians)
  double sector = 2.0 * M_PI; // u ∈ [0, sector]; 2π closes the tower in u

  bool Closed() const { return sector >= 2.0 * M_PI; }

  ParameterDomain Domain() const { return {0.0, sector, 0.0, H, Closed(), false, false}; }

  template <typename T>
  Vec3T<T> Point(const T& u, const T& v) const {
    using std::cos;
    using std::sin;
    const T phi = u + (twist / H) * v;
    const T rho = Radius(v);
    return Vec3T<T>(rho * cos(phi), rho * sin(phi), v);
  }

  template <typename T>
  void Tangents(const T& u, const T& v, Vec3T<T>* xu, Vec3T<T>* xv) const {
    using std::cos;
    using std::sin;
    const double tau = twist / H;
    const T phi = u + tau * v;
    const T rho = Radius(v);
    const T drho = (a * a / (c * c)) * (v - z_w) / rho;  // ρ' = a² (v − z_w) / (c² ρ)
    const T cp = cos(phi), sp = sin(phi);
    *xu = Vec3T<T>(-rho * sp, rho * cp, T(0.0));
    *xv = Vec3T<T>(drho * cp - rho * tau * sp, drho * sp + rho * tau * cp, T(1.0));
  }

  template <typename T>
  T Radius(const T& v) const {
    using std::sqrt;
    const T w = (v - z_w) / c;
    return a * sqrt(1.0 + w * w);
  }
};

}  // namespace archgeo
