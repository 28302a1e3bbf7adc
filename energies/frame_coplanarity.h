// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Frame-point coplanarity across an interior edge of an H-net — the YAML term
// `frame_coplanarity`, one residual per interior edge b0b3:
//
//   r = F_quad(b0, f1, b3, f4)^½ = n·d / L,
//   n = c / sqrt(‖c‖² + (ε L²)²),  c = (b0 − b3) × (f1 − f4),
//   d = (b0 + b3 − f1 − f4) / 2,
//   f1 = (w1 b1 + w2 b2) / (w1 + w2),   f4 = (w4 b4 + w5 b5) / (w4 + w5)
//
//   [Shi, Wang, Pottmann 2014, §3.2 step 3, F_frame = F_anet +
//    λ3 Σ_j F_quad(b0^j, f1^j, b3^j, f4^j); Prop. 1 / Remark 3, eqs. 5–6]
//
// Notation of Shi Fig. 2: the edge b0b3 is shared by the left patch
// (b0, b1, b2, b3) and the right patch (b0, b3, b4, b5). f1 is the frame point
// on the left patch's edge b1b2 (the edge opposite b0b3) and f4 the frame point
// on the right patch's edge b4b5; w1, w2 and w4, w5 are the rational bilinear
// patches' weights of those vertices, FIXED constants in this step (they come
// from the shape parameters of step 2). The variables are the six vertices.
// The functor evaluates the F_quad residual of energies/anet_planarity.h
// (= −PqDiagonal of energies/pq_diagonal.h) on the quad (b0, f1, b3, f4).
//
// Meaning: the isoparameter ruling through f1 meets b0b3 at the left patch's
// frame point f on b0b3, the ruling through f4 meets it at the right patch's.
// When both patches give b0 and b3 the same weight ratio w0 : w3 (e.g. the
// normalisation w0 = w1 = w3 = 1 of Shi Prop. 1), these frame points coincide,
// and the two tangent planes there, span(b3 − b0, f1 − f) and
// span(b3 − b0, f4 − f), agree iff b0, f1, b3, f4 are coplanar, i.e. iff r = 0
// (for c ≠ 0). Expanding det(b30, f1 − b0, f4 − b0) = 0 with b_ij = b_i − b_j:
//   w1w4 det(b30,b10,b40) + w1w5 det(b30,b10,b50)
//     + w2w4 det(b30,b20,b40) + w2w5 det(b30,b20,b50) = 0.
// Planar vertex stars at b0 (b0, b1, b3, b5 coplanar) and at b3 (b0, b2, b3, b4
// coplanar) cancel the 2nd and 3rd terms, leaving exactly Shi eq. (6),
//   w2 w5 det(b30, b50, b20) = w1 w4 det(b30, b10, b40),
// which is eq. (5) for w1 = w5 = 1. Tangent planes then agree at b0, b3 (planar
// stars) and at f, three points of the common ruling b0b3, which is the
// smooth-join condition of two ruled patches. So r = 0 together with planar
// stars at b0 and b3 is exactly the smooth-join condition (eqs. 5/6).
//
// Units / normalisation: L = 1/inv_length is a fixed length chosen by the
// builder (e.g. the mean diagonal of the quad (b0, f1, b3, f4) at build
// time), so r is unit-free. Ceres minimises ½Σr².
//
// Singular configurations: those of PqDiagonal on (b0, f1, b3, f4) — b0b3
// parallel to f1f4 (e.g. all six vertices collinear) or b0 = b3 or f1 = f4
// make c = 0; the normalisation is regularised with ε = kPqDiagonalEpsilon
// relative to L², so r → 0 there with a finite Jacobian. The weights are
// positive constants, so f1, f4 are always defined. Never returns false.
//
// Invariances: rigid motions; uniform scaling x → s x with inv_length →
// inv_length / s; scaling (w1, w2) or (w4, w5) by a common positive factor
// (only the ratios enter). Exchanging the two patches (b0, b1, b2, b3, b4, b5;
// w1, w2, w4, w5) → (b0, b5, b4, b3, b2, b1; w5, w4, w2, w1) flips the sign.
#ifndef ARCHGEO_ENERGIES_FRAME_COPLANARITY_H_
#define ARCHGEO_ENERGIES_FRAME_COPLANARITY_H_

#include <Eigen/Core>

#include "energies/pq_diagonal.h"

#include "energies/autodiff.h"

namespace archgeo {

struct FrameCoplanarity {
  using Shape = CostShape<1, 3, 3, 3, 3, 3, 3>;

  // w1, w2: weights of b1, b2 in the left patch; w4, w5: weights of b4, b5 in
  // the right patch (positive, fixed); inv_length: 1/L.
  FrameCoplanarity(double w1, double w2, double w4, double w5,
                   double inv_length)
      : t_left(w2 / (w1 + w2)), t_right(w5 / (w4 + w5)), diagonal(inv_length) {}

  // b0 … b5: 3 doubles each (Shi Fig. 2 labels); residual: 1 double.
  template <typename T>
  bool operator()(const T* b0, const T* b1_ptr, const T* b2_ptr, const T* b3,
                  const T* b4_ptr, const T* b5_ptr, T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> b1(b1_ptr);
    const Eigen::Map<const Vec3> b2(b2_ptr);
    const Eigen::Map<const Vec3> b4(b4_ptr);
    const Eigen::Map<const Vec3> b5(b5_ptr);
    // f1 = b1 + w2/(w1+w2) (b2 − b1), f4 = b4 + w5/(w4+w5) (b5 − b4).
    const Vec3 f1 = b1 + T(t_left) * (b2 - b1);
    const Vec3 f4 = b4 + T(t_right) * (b5 - b4);
    diagonal(b0, f1.data(), b3, f4.data(), residual);
    residual[0] = -residual[0];
    return true;
  }

  double t_left;   // w2 / (w1 + w2)
  double t_right;  // w5 / (w4 + w5)
  PqDiagonal diagonal;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_FRAME_COPLANARITY_H_
