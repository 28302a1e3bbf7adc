// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Transversality of a TCD field in one face, 1 residual:
//
//   r = ‖z_N − e1‖² = (z1 − 1)² + z2²,   so ½ r² = ½ φ(‖z_N − e1‖), φ(t) = t⁴
//
//   [Zadravec 2010, §4: λ_trans Σ_f φ(‖z_N,f − e1,f‖), φ(t) = t⁴; eq. 1:
//    cos ∠(v, w) ≤ ‖z_N − e1‖]
//
// The 4th power is written as the square of the squared distance, so no
// square root appears and the residual is a polynomial. By eq. 1 keeping z_N
// near the centre e1 of the auxiliary circle keeps the conjugate directions
// v, w apart; z_N = e1 (r = 0) is the principal pair (90°). "e1" is the point
// (1, 0) of the face's frame coordinates, not the 3-D frame vector.
//
// Units / normalisation: dimensionless (c has radius 1). Ceres minimises ½Σr²;
// λ_trans is the builder's weight.
//
// Singular configurations: none. At z_N = e1 the Jacobian 2(z_N − e1) is zero
// (a minimum of φ; Gauss–Newton is exact there). Never returns false.
//
// Invariances: rotations of the face frame (z − e1 turns about e1, its norm is
// kept); independent of the mesh geometry.
#ifndef ARCHGEO_ENERGIES_TCD_TRANSVERSALITY_H_
#define ARCHGEO_ENERGIES_TCD_TRANSVERSALITY_H_

#include "energies/autodiff.h"

namespace archgeo {

struct TcdTransversality {
  using Shape = CostShape<1, 2>;

  // z: 2 doubles (z_N of the face, own frame); residual: 1.
  template <typename T>
  bool operator()(const T* z, T* residual) const {
    const T a = z[0] - T(1.0);
    residual[0] = a * a + z[1] * z[1];
    return true;
  }
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_TCD_TRANSVERSALITY_H_
