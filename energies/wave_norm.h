// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Unit length of the wave's 4-vector at a vertex, 1 residual:
//
//   r = |f_i|² − 1
//
//   [Gebreiter 2012, §8.3.1: (cos θ cos φ)² + (cos θ sin φ)² + (sin θ cos φ)²
//    + (sin θ sin φ)² = 1, the penalty w1 Σ (f_iᵀ f_i − 1)², w1 = 0.15]
//
// Keeps the wave away from the trivial minimiser f = 0 of the transfer term.
// Units: unit-free. Singular configurations: none. Invariances: any
// orthogonal map of f (the transfer's C_ij and matchings among them).
#ifndef ARCHGEO_ENERGIES_WAVE_NORM_H_
#define ARCHGEO_ENERGIES_WAVE_NORM_H_

#include "energies/autodiff.h"

namespace archgeo {

struct WaveNorm {
  using Shape = CostShape<1, 4>;

  // f: 4 doubles; residual: 1.
  template <typename T>
  bool operator()(const T* f, T* residual) const {
    residual[0] = f[0] * f[0] + f[1] * f[1] + f[2] * f[2] + f[3] * f[3] - T(1.0);
    return true;
  }
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_WAVE_NORM_H_
