// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The designated size at a vertex, 2 residuals:
//
//   r = (w_μ (μ̃ − log μ_t), w_η (η̃ − log η_t)),   w_μ = √A_v / μ_t, w_η = √A_v / η_t
//
//   [Gebreiter 2012, §8.1.4: "constraints to penalise deviation from
//    designated size values", since the curl term alone fixes s̃ only up to
//    functions constant along the field; after Zhang et al. 2010]
//
// (μ̃, η̃) the vertex's log sizes, μ_t, η_t the size fields the user gave
// (wave.wavelength, wave.size_field, ...) there; A_v a third of the area of
// the vertex's triangles, so Σ r² is the area in target wavelengths² times
// the squared log ratio: unit-free. Singular
// configurations: none (linear). Invariances: none.
#ifndef ARCHGEO_ENERGIES_SIZE_TARGET_H_
#define ARCHGEO_ENERGIES_SIZE_TARGET_H_

#include "energies/autodiff.h"

namespace archgeo {

struct SizeTarget {
  using Shape = CostShape<2, 2>;

  // target_*: log μ_t, log η_t; weight_*: w_μ, w_η.
  SizeTarget(double target_mu, double target_eta, double weight_mu, double weight_eta)
      : target_mu(target_mu), target_eta(target_eta), weight_mu(weight_mu),
        weight_eta(weight_eta) {}

  // s: (μ̃, η̃); residual: 2.
  template <typename T>
  bool operator()(const T* s, T* residual) const {
    residual[0] = T(weight_mu) * (s[0] - T(target_mu));
    residual[1] = T(weight_eta) * (s[1] - T(target_eta));
    return true;
  }

  double target_mu, target_eta, weight_mu, weight_eta;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_SIZE_TARGET_H_
