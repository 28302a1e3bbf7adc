// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Curl of the wave's phase gradient in a triangle, linear in the log sizes, 1
// residual (one element per triangle and family):
//
//   r = √A (curl F + (n × F_T)·∇s̃),   ∇s̃ = Σ_k s̃_k ∇B_k
//
//   [Gebreiter 2012, §8.1.4: curl(X) ≈ (1/A) Σ_i X_{q_i}·(p_{i⊕1} − p_i)
//    (Polthier and Preuß 2003), μ̃ = log μ, ∇μ̃ = Σ μ̃_i ∇B_i, E_curl a sum of
//    squares over the triangles; after Zhang et al. 2010]
//
// The wave advances its phase by 2π F/s along a unit field F with the
// wavelength s = e^s̃ (F = X with μ, F = Y with η), so the phase gradient is
// curl-free when curl(F/s) = 0; with curl(e^{−s̃} F) = e^{−s̃} (curl F −
// n·(∇s̃ × F)) and n·(∇s̃ × F) = −(n × F)·∇s̃ that is r = 0 above
// (X: curl X + Y·∇μ̃; Y: curl Y − X·∇η̃). The thesis writes the condition for
// the field scaled by μ (curl(μX)); here μ is the wavelength, the field's
// magnitude is 1/μ, and the sign of ∇s̃ follows.
//
// The element's data (problems/declarations/wave_size_curl.cpp) are
// a = √A curl F (F matched to the triangle's first vertex at each corner,
// the midpoint rule of the circulation), g_k = √A (n × F_T)·∇B_k and which
// of corner k's log sizes (μ̃ or η̃) is the family's there. Units: r is
// unit-free (A in canonical lengths², curl in 1/length). Singular
// configurations: none (linear). Invariances: s̃ → s̃ + const (Σ ∇B_k = 0).
#ifndef ARCHGEO_ENERGIES_SIZE_CURL_H_
#define ARCHGEO_ENERGIES_SIZE_CURL_H_

#include <array>

#include "energies/autodiff.h"

namespace archgeo {

struct SizeCurl {
  using Shape = CostShape<1, 2, 2, 2>;

  // a: √A curl F; g: √A (n × F_T)·∇B_k per corner; source ∈ {0, 1} per
  // corner (0: μ̃, 1: η̃).
  SizeCurl(double a, const std::array<double, 3>& g, const std::array<int, 3>& source);

  // s0, s1, s2: (μ̃, η̃) at the corners; residual: 1.
  template <typename T>
  bool operator()(const T* s0, const T* s1, const T* s2, T* residual) const {
    residual[0] = T(a) + T(g[0]) * s0[source[0]] + T(g[1]) * s1[source[1]] +
                  T(g[2]) * s2[source[2]];
    return true;
  }

  double a = 0;
  std::array<double, 3> g{};
  std::array<int, 3> source{};
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_SIZE_CURL_H_
