// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Planar-quad diagonal distance, one residual per quad face (b0, b1, b2, b3):
//
//   r = n·(b1 − b0) / L,   n = c / sqrt(‖c‖² + (ε L²)²),   c = (b2 − b0) × (b3 − b1)
//
//   [Zadravec 2010, §6 eq. 8, f_PQ = Σ_f diag_f²; Shi 2014, §3.2, F_quad]
//
// b0..b3 are the quad's vertices in cyclic order. For ε → 0, n is the unit
// common normal of the two diagonal lines b0b2 and b1b3 and n·(b1 − b0) is the
// signed distance diag_f between them; r = 0 iff the four points are coplanar.
//
// Units / normalisation: L = 1/inv_length is a fixed length chosen by the
// builder (the face's mean diagonal length at build time), so r is unit-free
// and comparable across faces of different size (δ_PQ,n of Zadravec Fig. 10).
// Ceres minimises ½Σr², so the term contributes ½ diag_f² / L².
//
// Singular configurations: parallel diagonals, or a diagonal of zero length,
// make c = 0 and the unit normal undefined. The normalisation is regularised
// with ε = kPqDiagonalEpsilon times L² (c has units of length²), so the
// regularisation is scale-invariant. For ‖c‖ ≫ ε L² (i.e. the sine of the
// angle between the diagonals ≫ ε for diagonals of length ≈ L) the residual
// equals the exact distance to relative precision ½(ε L²/‖c‖)²; at c = 0 the
// residual is 0 and its Jacobian finite (of order ‖b1 − b0‖/(ε L³) at most).
// The functor never returns false.
//
// Invariances: rigid motions (r unchanged); uniform scaling x → s x with
// inv_length → inv_length / s (r unchanged). Relabelling: a cyclic shift by one
// (b1, b2, b3, b0) flips the sign of r, a shift by two keeps it, and reversing
// the orientation (b0, b3, b2, b1) flips it. Only r² enters the energy.
#ifndef ARCHGEO_ENERGIES_PQ_DIAGONAL_H_
#define ARCHGEO_ENERGIES_PQ_DIAGONAL_H_

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()

#include "energies/autodiff.h"

namespace archgeo {

// Regularisation of the diagonal normal, relative to L² (see above).
inline constexpr double kPqDiagonalEpsilon = 1e-6;

struct PqDiagonal {
  using Shape = CostShape<1, 3, 3, 3, 3>;

  // inv_length: 1/L, L > 0 the face's reference length (mean initial diagonal).
  explicit PqDiagonal(double inv_length) : inv_length(inv_length) {}

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
    const Vec3 c = (b2 - b0).cross(b3 - b1);
    const double eps = kPqDiagonalEpsilon / (inv_length * inv_length);
    using std::sqrt;
    const T norm = sqrt(c.squaredNorm() + T(eps * eps));
    residual[0] = c.dot(b1 - b0) / norm * T(inv_length);
    return true;
  }

  double inv_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_PQ_DIAGONAL_H_
