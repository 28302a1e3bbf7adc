// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Product form of the wave's 4-vector at a vertex, 1 residual:
//
//   r = f_iᵀ H f_i = f1 f4 − f2 f3
//
//   [Gebreiter 2012, §8.3.1: (cos θ cos φ)(sin θ sin φ) − (cos θ sin φ)
//    (sin θ cos φ) = 0, the penalty w2 Σ (f_iᵀ H f_i)², w2 = 0.15]
//
// f is the tensor product (cos θ, sin θ) ⊗ (cos φ, sin φ) exactly when the
// 2 × 2 matrix [f1 f2; f3 f4] has rank one, i.e. its determinant r vanishes;
// with |f| = 1 (wave_norm) the angles θ, φ are then defined. Units:
// unit-free. Singular configurations: none. Invariances: f → (R(a) ⊗ R(b)) f
// (det of R(a) F R(b)ᵀ is det F) and the matchings of the transfer (a swap
// of θ and φ transposes F; a sign flip negates r, which is squared).
#ifndef ARCHGEO_ENERGIES_WAVE_PRODUCT_H_
#define ARCHGEO_ENERGIES_WAVE_PRODUCT_H_

#include "energies/autodiff.h"

namespace archgeo {

struct WaveProduct {
  using Shape = CostShape<1, 4>;

  // f: 4 doubles; residual: 1.
  template <typename T>
  bool operator()(const T* f, T* residual) const {
    residual[0] = f[0] * f[3] - f[1] * f[2];
    return true;
  }
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_WAVE_PRODUCT_H_
