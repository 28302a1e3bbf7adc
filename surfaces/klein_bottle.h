// Klein bottle, the figure-8 immersion (Table 1 scene "Klein Bottle", type C2,
// a grid closed in both directions; Figs. 5 and 6 of the paper lay a hall out
// on a Klein bottle and cut the result in half). With c = cos(u/2),
// s = sin(u/2):
//
//   w(u, v) = c sin v − s sin 2v,    ρ = R + a w,
//   x(u, v) = (ρ cos u,  ρ sin u,  a (s sin v + c sin 2v)),
//
// a figure-8 curve (sin v, sin 2v) of size a swept around a circle of radius R
// while turning by half a turn. It is an immersion (regular everywhere; the
// surface passes through itself along the central circle, where the figure 8
// crosses itself) of a closed non-orientable surface:
//   x(u, v + 2π) = x(u, v)         (periodic in v),
//   x(u + 2π, v) = x(u, −v)        (periodic in u with a reflection of v).
// The domain u ∈ [0, 2π), v ∈ [−π, π) centres that reflection (v0 + v1 = 0),
// so a grid closed in both directions wraps its u-seam with
// j → (n_v − j) mod n_v (surfaces/grid.h). The uniform grid is skewed (the
// half turn of the figure 8 makes x_u · x_v ≠ 0) and unequal (|x_v| varies by
// a factor 3 around the figure 8, |x_u| = ρ by (R + 1.25a)/(R − 1.25a) around
// the ring).
// Parameters: R > 1.25 a > 0 (ρ > 0: max |w| = 1.25), in file units.
// (The classical "bottle" immersion was not chosen: its neck is ten times
// thinner than its body, thinner than any grid edge of a uniform grid.)
#pragma once

#include <cmath>

#include "surfaces/parametric.h"

namespace archgeo {

struct KleinBottle {
  static constexpr const char* kName = "klein_bottle";
  double R = 3.0;  // radius of the circle the figure 8 is swept around
  double a = 1.0;  // size of the figure 8, R > 1.25 a

  ParameterDomain Domain() const { return {0.0, 2.0 * M_PI, -M_PI, M_PI, true, true, true}; }

  template <typename T>
  Vec3T<T> Point(const T& u, const T& v) const {
    using std::cos;
    using std::sin;
    const T c = cos(0.5 * u), s = sin(0.5 * u);
    const T s1 = sin(v), s2 = sin(2.0 * v);
    const T rho = R + a * (c * s1 - s * s2);
    return Vec3T<T>(rho * cos(u), rho * sin(u), a * (s * s1 + c * s2));
  }

  template <typename T>
  void Tangents(const T& u, const T& v, Vec3T<T>* xu, Vec3T<T>* xv) const {
    using std::cos;
    using std::sin;
    const T c = cos(0.5 * u), s = sin(0.5 * u);
    const T s1 = sin(v), s2 = sin(2.0 * v), c1 = cos(v), c2 = cos(2.0 * v);
    const T w = c * s1 - s * s2;
    const T rho = R + a * w;
    const T w_u = -0.5 * (s * s1 + c * s2);
    const T w_v = c * c1 - 2.0 * s * c2;
    const T cu = cos(u), su = sin(u);
    *xu = Vec3T<T>(a * w_u * cu - rho * su, a * w_u * su + rho * cu, 0.5 * a * w);
    *xv = Vec3T<T>(a * w_v * cu, a * w_v * su, a * (s * c1 + 2.0 * c * c2));
  }
};

}  // namespace archgeo
