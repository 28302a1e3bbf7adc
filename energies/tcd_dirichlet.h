// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// TCD field smoothness across one interior edge e = (f, g), 2 residuals:
//
//   r = sqrt(w_e) · (ζ_f − R(2 τ_fg) ζ_g),   ζ = z_N − e1,   e1 = (1, 0)
//
//   [Zadravec 2010, §4 "Setup of global optimization": the Dirichlet energy of
//    the vector field z_N, computed according to [FSDH07]]
//
// z_N,f, z_N,g are the per-face points of §3 in each face's own frame; τ_fg is
// the frame transport across e (fields/face_frames.h: a tangent vector at
// angle α in g's frame has angle α + τ_fg in f's frame after unfolding), w_e =
// ℓ_e / d_e the face-based Dirichlet weight, so ½Σ_e r² approximates ½∫|∇ζ|².
//
// Why ζ = z_N − e1 and a rotation by 2τ (re-derived; the paper's frame is a
// smooth field and the transport is left implicit): the line spanned by a
// direction at angle θ meets the auxiliary circle c in e1 + e^{2iθ}, so when
// the frame turns by φ every point of the construction (c, z_M, z_N, the
// chord of a conjugate pair) turns about e1 by −2φ. ζ is therefore a spin-2
// quantity and is compared after a rotation by twice the frame transport.
// ζ ≡ 0 (the principal field z_N = e1) has zero energy on every surface, and
// the energy does not depend on the choice of frames.
//
// Units / normalisation: z_N, ζ are dimensionless (c has radius 1); w_e is
// dimensionless; r is unit-free. Ceres minimises ½Σr².
//
// Singular configurations: none (r is linear in the blocks). Never returns
// false.
//
// Invariances: rotating the frames of f and g by φ_f, φ_g (z → e1 + R(−2φ)(z −
// e1), τ_fg → τ_fg + φ_g − φ_f) turns r by R(−2φ_f): ‖r‖ unchanged; rigid
// motions and scaling of the mesh do not change τ or w_e. Swapping f and g
// (τ → −τ) maps r to −R(−2τ) r: ‖r‖ unchanged.
#ifndef ARCHGEO_ENERGIES_TCD_DIRICHLET_H_
#define ARCHGEO_ENERGIES_TCD_DIRICHLET_H_

#include <cmath>

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

struct TcdDirichlet {
  using Shape = CostShape<2, 2, 2>;

  // transport_angle: τ_fg (radians); weight: w_e ≥ 0.
  TcdDirichlet(double transport_angle, double weight)
      : cos2(std::cos(2.0 * transport_angle)),
        sin2(std::sin(2.0 * transport_angle)),
        sqrt_weight(std::sqrt(weight)) {}

  // z_f, z_g: 2 doubles each (z_N of f and g, own frames); residual: 2.
  template <typename T>
  bool operator()(const T* z_f, const T* z_g, T* residual) const {
    const T zf0 = z_f[0] - T(1.0), zf1 = z_f[1];
    const T zg0 = z_g[0] - T(1.0), zg1 = z_g[1];
    residual[0] = T(sqrt_weight) * (zf0 - (T(cos2) * zg0 - T(sin2) * zg1));
    residual[1] = T(sqrt_weight) * (zf1 - (T(sin2) * zg0 + T(cos2) * zg1));
    return true;
  }

  double cos2, sin2, sqrt_weight;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_TCD_DIRICHLET_H_
