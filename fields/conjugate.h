// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the conjugacy relation in one face, in the face's 2-D frame
// (e1, e2) [Zadravec 2010, §2–3]. Plain Eigen, no CGAL: used by the field
// code in fields/ and by tests with analytic second fundamental forms.
//
// Conventions (re-derived here because the text extraction of the paper is
// garbled in places):
//  - M is the second fundamental form in the frame: the surface is locally
//    x3 = ½ xᵀ M x + … with x3 along the face's positive unit normal
//    (CGAL's Monge form uses the same convention, z = ½(k1 x² + k2 y²) + …).
//  - The auxiliary circle c: (x1 − 1)² + x2² = 1 has centre e1 = (1, 0) and
//    radius 1. The line spanned by a direction at angle θ meets c (besides o)
//    in p(θ) = (1 + cos 2θ, sin 2θ) = e1 + (cos 2θ, sin 2θ).
//  - Prop. 1: v, w conjugate (vᵀ M w = 0) ⇔ p(θ_v), p(θ_w) and
//    z_M = 2/(m11 + m22) (m22, −m12) are collinear. Derivation: with
//    σ = θ_v + θ_w, δ = θ_v − θ_w, vᵀ M w = ½ tr M cos δ + ½(m11 − m22) cos σ
//    + m12 sin σ, and the chord of the unit circle (centred at e1) through
//    e^{2iθ_v}, e^{2iθ_w} is {ζ : ζx cos σ + ζy sin σ = cos δ} in ζ = z − e1;
//    the two equations agree iff ζ = ((m22 − m11), −2 m12)/tr M, i.e.
//    z = e1 + ζ = 2/(m11 + m22) (m22, −m12). |ζ_M| < 1 ⇔ det M > 0.
//  - z_N = e1 (ζ_N = 0) selects the chord through the centre: the orthogonal
//    conjugate pair, the principal directions (the paper's Prop. 3 reads
//    "z_N = o" there, an extraction error: o is on c).
//  - Under a rotation of the frame by φ, ζ = z − e1 turns by −2φ (a direction
//    at angle θ has p − e1 = e^{2iθ}): ζ_M, ζ_N are "spin-2" quantities. The
//    field energies therefore compare ζ's of neighbouring faces after a
//    rotation by twice the frame transport angle (fields/face_frames.h).
//  - Prop. 2 / proof of Prop. 3: the pair chosen by z_N consists of the
//    common conjugate directions of M and N, the eigenvectors of N⁻¹M, with
//    N normalised to n11 = 1: from z = 2/(n11 + n22)(n22, −n12) follows
//    n22 = z1/(2 − z1), n12 = −z2/(2 − z1), and det N > 0 ⇔ z inside c.
#pragma once

#include <Eigen/Core>

namespace archgeo {

// The point z_M of Prop. 1. Returns false (and leaves *z untouched) when z_M
// is at infinity or undefined: |m11 + m22| ≤ relative_tolerance·‖M‖_F (mean
// curvature zero relative to the curvature size, or M = 0).
bool ZOfMatrix(const Eigen::Matrix2d& M, Eigen::Vector2d* z,
               double relative_tolerance = 1e-9);

// Point of the auxiliary circle c on the line spanned by the nonzero vector d:
// p = e1 + (cos 2θ, sin 2θ), θ the angle of d.
Eigen::Vector2d CirclePoint(const Eigen::Vector2d& d);

// N of the proof of Prop. 3 (n11 = 1) for the point z_N.
// Precondition (CHECKed): z_N[0] ≠ 2.
Eigen::Matrix2d NOfZ(const Eigen::Vector2d& z_n);

// The eigen-decomposition of a symmetric 2 × 2 matrix: eigenvalues
// ascending, unit eigenvectors as the columns in the same order (Eigen's
// SelfAdjointEigenSolver, instantiated in conjugate.cpp alone: each
// instantiation costs seconds of compile time).
struct SymmetricEigen2 {
  Eigen::Vector2d values;
  Eigen::Matrix2d vectors;
};
SymmetricEigen2 EigenOfSymmetric2(const Eigen::Matrix2d& m);

// Principal curvatures and directions of M (k1 ≥ k2; d1, d2 unit, d2 = J d1
// with J the rotation by +90°).
struct Principal {
  double k1 = 0.0, k2 = 0.0;
  Eigen::Vector2d d1{1.0, 0.0}, d2{0.0, 1.0};
};
Principal PrincipalOf(const Eigen::Matrix2d& M);

// The asymptotic (self-conjugate) directions xᵀ M x = 0, unit vectors:
// returns 2 when det M < 0 (a, b symmetric about d1 at angles ±atan
// sqrt(k1/−k2) from d1), 1 when exactly one principal curvature is 0 (its
// direction), 0 when det M > 0 or M = 0. `relative_tolerance` decides
// "exactly 0": |k| ≤ relative_tolerance·max|k|.
int AsymptoticDirections(const Eigen::Matrix2d& M, Eigen::Vector2d out[2],
                         double relative_tolerance = 1e-9);

// The conjugate pair selected by z_N (Prop. 2).
struct ConjugatePair {
  // Unit vectors; v belongs to the larger generalised eigenvalue λ of
  // M x = λ N x, so the labelling is continuous away from singularities
  // (proof of Prop. 3). For z_N = e1, v and w are the directions of k1, k2.
  Eigen::Vector2d v{1.0, 0.0}, w{0.0, 1.0};
  // false when z_N is not strictly inside c (det N ≤ 0: no TCD pair in the
  // sense of Prop. 2) or when M is proportional to N (z_N = z_M, a
  // singularity, or M = 0): the generalised eigenvalues coincide to within
  // `relative_tolerance` of their size and the pair is undetermined.
  bool valid = false;
};
ConjugatePair ConjugatePairOf(const Eigen::Matrix2d& M, const Eigen::Vector2d& z_n,
                              double relative_tolerance = 1e-12);

// |vᵀ M w| / (max(|k1|, |k2|) ‖v‖ ‖w‖); 0 when M = 0 (every pair is conjugate).
double ConjugacyError(const Eigen::Matrix2d& M, const Eigen::Vector2d& v,
                      const Eigen::Vector2d& w);

// Angle in [0, π) of the line bisecting the lines of v and w that lies in the
// sector swept when turning the line of v counter-clockwise to the line of w
// (angle δ ∈ (0, π)): β = θ_v + δ/2 mod π. Continuous in (v, w) as long as the
// lines stay distinct, and turns by the same total angle as the line of v
// along a closed loop [Zadravec 2010, §3, remark after Prop. 7].
double BisectorAngle(const Eigen::Vector2d& v, const Eigen::Vector2d& w);

// Angle of a line (direction modulo π) in [0, π).
double LineAngle(const Eigen::Vector2d& d);

// x wrapped into (−π/2, π/2]: the smallest rotation between two lines.
double WrapLineAngle(double x);

}  // namespace archgeo
