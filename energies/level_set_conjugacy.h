// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Conjugacy of the level sets of two functions g, h in one triangle f,
// 1 residual:
//
//   r = sqrt(A_f) · t_gᵀ M_f t_h,   t_g = R ∇g / sqrt(‖∇g‖² + ε²),
//                                   t_h = R ∇h / sqrt(‖∇h‖² + ε²)
//
//   [Zadravec 2010, §5 eq. 7: Σ_f (area(f)/area(Φ)) ((R ∇g/‖∇g‖)_fᵀ M_f
//    (R ∇h/‖∇h‖)_f)² → min, augmented by λ_even Σ_f ‖(∇h)_f‖²]
//
// t_g, t_h are the unit tangents of the level sets of g and h (R the rotation
// by +90° in the face); r = 0 iff they are conjugate w.r.t. the second
// fundamental form M_f (frame coordinates, fields/face_curvature.h). In the
// paper g is given and h is solved for (planar sections, Fig. 9); here both
// are blocks and either may be held constant by the builder.
//
// Units / normalisation: M has units 1/length; the paper's weight
// area(f)/area(Φ) is multiplied by area(Φ) so that r = sqrt(A_f)·(1/length)
// is unit-free: Σr² = area(Φ) × the paper's eq. 7. The even-spacing term
// ("λ_even area(Φ) Σ_f ‖(∇h)_f‖²" in the text extraction; re-derived as the
// Dirichlet energy Σ_f (A_f/A_Φ)‖∇h_f‖², whose minimiser with two fixed
// values is harmonic and evenly spaced) is level_set_alignment with v = 0.
// Ceres minimises ½Σr².
//
// Singular configurations: ∇g = 0 or ∇h = 0; normalisations regularised with
// ε = kLevelSetGradientEpsilon · gradient_scale (level_set_normalised.h).
// Flat faces (M ≈ 0) contribute ≈ 0, as in the paper. Never returns false.
//
// Invariances: rigid motions of the face frame (corners turn, M → RᵀMR);
// uniform scaling x → s x (M → M/s, g → s g, h → s h: r unchanged);
// g → a g + b, h → c h + d with a, c > 0 (up to ε); swapping g and h.
#ifndef ARCHGEO_ENERGIES_LEVEL_SET_CONJUGACY_H_
#define ARCHGEO_ENERGIES_LEVEL_SET_CONJUGACY_H_

#include <cmath>

#include <Eigen/Core>

#include "energies/level_set_gradient.h"
#include "energies/level_set_normalised.h"  // kLevelSetGradientEpsilon

#include "energies/autodiff.h"

namespace archgeo {

struct LevelSetConjugacy {
  using Shape = CostShape<1, 1, 1, 1, 1, 1, 1>;

  // corners: 6 doubles (face frame, counter-clockwise); m: m11, m12, m22 (face
  // frame); gradient_scale: expected ‖∇g‖, ‖∇h‖ > 0.
  LevelSetConjugacy(const double corners[6], const double m[3], double gradient_scale)
      : gradient(corners),
        scale(std::sqrt(gradient.area)),
        epsilon(kLevelSetGradientEpsilon * gradient_scale) {
    // (R a)ᵀ M (R b) = aᵀ (Rᵀ M R) b with R the rotation by +90°.
    Eigen::Matrix2d M;
    M << m[0], m[1], m[1], m[2];
    Eigen::Matrix2d R;
    R << 0.0, -1.0, 1.0, 0.0;
    rotated = R.transpose() * M * R;
  }

  // g0, g1, g2, h0, h1, h2: 1 double each, corner values; residual: 1.
  template <typename T>
  bool operator()(const T* g0, const T* g1, const T* g2, const T* h0, const T* h1,
                  const T* h2, T* residual) const {
    using std::sqrt;
    const Eigen::Matrix<T, 2, 1> a = gradient(g0[0], g1[0], g2[0]);
    const Eigen::Matrix<T, 2, 1> b = gradient(h0[0], h1[0], h2[0]);
    const T na = sqrt(a.squaredNorm() + T(epsilon * epsilon));
    const T nb = sqrt(b.squaredNorm() + T(epsilon * epsilon));
    const T form = a.x() * (T(rotated(0, 0)) * b.x() + T(rotated(0, 1)) * b.y()) +
                   a.y() * (T(rotated(1, 0)) * b.x() + T(rotated(1, 1)) * b.y());
    residual[0] = T(scale) * form / (na * nb);
    return true;
  }

  TriangleGradient gradient;
  double scale;              // sqrt(A_f)
  double epsilon;
  Eigen::Matrix2d rotated;   // Rᵀ M R
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_LEVEL_SET_CONJUGACY_H_
