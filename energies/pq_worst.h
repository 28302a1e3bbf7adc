// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The worst quads' planarity, one residual per quad face (b0, b1, b2, b3):
//
//   r = s |s|^(p/2 − 1),   s = r_PQ / δ_worst,   so that ½ r² = ½ (|r_PQ| / δ_worst)^p
//
//   r_PQ = pq_diagonal's residual (energies/pq_diagonal.h): the signed distance
//   between the diagonals over the quad's mean initial diagonal, δ_PQ,n of
//   [Zadravec 2010, §6, eq. 8; Fig. 10]
//
// Summed over the quads this is the p-th power of the p-norm of δ_PQ,n
// relative to δ_worst, the largest |r_PQ| over the quads at the start of the
// round. For large p it approaches the maximum (the quantity the tolerance
// bounds): a quad at 0.8 of the worst counts 0.8^16 ≈ 3% as much as the worst
// one for p = 16, so the flatter quads give way to the worst ones, where
// pq_diagonal's sum of squares weighs every quad alike.
//
// Units / normalisation: s is relative to the round's worst quad (unit-free,
// ±1 for the worst quad at the round's start), so the weight does not depend
// on how far from planar the net is, and as the quads flatten the next
// round's δ_worst is smaller and the pull on the worst quads grows (as
// continuation would).
// Singular configurations: pq_diagonal's (its regularisation relative to L²
// is kept); at s = 0 the residual and its derivative are 0 (p > 2) or the
// residual is s (p = 2). Never returns false.
// Invariances: pq_diagonal's (rigid motions; scaling with inv_length);
// relabelling flips the sign of r as it flips r_PQ's.
#ifndef ARCHGEO_ENERGIES_PQ_WORST_H_
#define ARCHGEO_ENERGIES_PQ_WORST_H_

#include <cmath>

#include "energies/pq_diagonal.h"

namespace archgeo {

struct PqWorst {
  using Shape = PqDiagonal::Shape;

  // inv_length: 1/L as pq_diagonal's; inv_worst: 1/δ_worst > 0; power: p ≥ 2.
  PqWorst(double inv_length, double inv_worst, double power)
      : diagonal(inv_length), inv_worst(inv_worst), half_power(power / 2) {}

  template <typename T>
  bool operator()(const T* b0, const T* b1, const T* b2, const T* b3, T* residual) const {
    diagonal(b0, b1, b2, b3, residual);
    const T s = residual[0] * T(inv_worst);
    using std::abs;
    using std::pow;
    const T a = abs(s);
    residual[0] = half_power == 1 ? s : s * (a > T(0) ? pow(a, half_power - 1) : T(0));
    return true;
  }

  PqDiagonal diagonal;
  double inv_worst;
  double half_power;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_PQ_WORST_H_
