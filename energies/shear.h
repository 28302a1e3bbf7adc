// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Shear of a quad face (b0, b1, b2, b3): its two diagonals of equal length —
// the YAML term `shear`, one residual per quad:
//
//   r = (‖b2 − b0‖² − ‖b3 − b1‖²) / (2 L²)
//     = (‖d1‖ − ‖d2‖)/L · (‖d1‖ + ‖d2‖)/(2L),   d1 = b2 − b0, d2 = b3 − b1
//
//   [Gebreiter 2012, §10.1 "spring forces … set up to act along quad
//    diagonals to simulate a primitive shear force"; §11.7.1 "shear forces
//    inside the quad panels"]
//
// b0..b3 are the quad's vertices in cyclic order. r = 0 iff the diagonals are
// equally long (a parallelogram with equal diagonals is a rectangle: the
// term removes shear distortion of the panels). With L the face's mean
// diagonal length at build time, (‖d1‖ + ‖d2‖)/(2L) = 1 there, so r is the
// relative difference of the diagonal lengths (‖d1‖ − ‖d2‖)/L_mean; it stays
// so to first order while the diagonals' mean length is near L. The
// difference of squares keeps r a polynomial: no square root, no
// regularisation, smooth everywhere.
//
// Units / normalisation: L = 1/inv_length is a fixed length chosen by the
// builder (the face's mean diagonal at build time), so r is unit-free; a
// fixed L (rather than the current mean diagonal) gives the solver no
// incentive to grow the quad to shrink r. Ceres minimises ½Σr².
//
// Singular configurations: none (r is a quadratic polynomial); a collapsed
// quad gives r = 0 with a zero Jacobian. Never returns false.
//
// Invariances: rigid motions (r unchanged); uniform scaling x → s x with
// inv_length → inv_length / s (r unchanged). Relabelling: a cyclic shift by
// one (b1, b2, b3, b0) flips the sign of r, a shift by two keeps it,
// reversing the orientation (b0, b3, b2, b1) keeps it.
#ifndef ARCHGEO_ENERGIES_SHEAR_H_
#define ARCHGEO_ENERGIES_SHEAR_H_

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

struct Shear {
  using Shape = CostShape<1, 3, 3, 3, 3>;

  // inv_length: 1/L, L > 0 the face's mean diagonal at build time.
  explicit Shear(double inv_length) : inv_length(inv_length) {}

  // b0..b3: 3 doubles each, the quad's vertices in cyclic order;
  // residual: 1 double.
  template <typename T>
  bool operator()(const T* b0_ptr, const T* b1_ptr, const T* b2_ptr,
                  const T* b3_ptr, T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> b0(b0_ptr);
    const Eigen::Map<const Vec3> b1(b1_ptr);
    const Eigen::Map<const Vec3> b2(b2_ptr);
    const Eigen::Map<const Vec3> b3(b3_ptr);
    residual[0] = ((b2 - b0).squaredNorm() - (b3 - b1).squaredNorm()) *
                  T(0.5 * inv_length * inv_length);
    return true;
  }

  double inv_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_SHEAR_H_
