// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Feature constraint of the standing wave at a boundary vertex, 3 residuals:
//
//   sin φ = 0:  r = (f2, f4, 0)        (= sin φ · (cos θ, sin θ))
//   sin θ = 0:  r = (f3, f4, 0)        (= sin θ · (cos φ, sin φ))
//   corner:     r = (f2, f3, f4)
//
//   [Gebreiter 2012, §8.3.2: boundary vertices sin φ_i = 0 or sin θ_i = 0;
//    corners cos θ sin φ = sin θ cos φ = sin θ sin φ = 0; Zhang et al. 2010]
//
// On a feature along an iso-line of φ (the guidance field's X along the
// boundary) sin φ = 0, so the boundary is a line of the quad layout; the
// squared norm of r is sin² φ |f|². Weighted strongly by the problem (a soft
// equality). Units: unit-free. Singular configurations: none (linear).
#ifndef ARCHGEO_ENERGIES_WAVE_FEATURE_H_
#define ARCHGEO_ENERGIES_WAVE_FEATURE_H_

#include "energies/autodiff.h"

namespace archgeo {

struct WaveFeature {
  using Shape = CostShape<3, 4>;

  // kind: wave_data::kSinTheta, kSinPhi or kCorner (energies/wave_elements.h).
  explicit WaveFeature(int kind);

  // f: 4 doubles; residual: 3.
  template <typename T>
  bool operator()(const T* f, T* residual) const {
    for (int r = 0; r < 3; ++r) residual[r] = pick[r] < 0 ? T(0.0) : f[pick[r]];
    return true;
  }

  int pick[3] = {-1, -1, -1};  // the component of f per residual (-1: none)
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_WAVE_FEATURE_H_
