// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Smoothing term of the principal-field pre-processing, one interior edge
// e = (f, g), 2 residuals:
//
//   r = sqrt(c_e) · ((cos 2θ_f, sin 2θ_f) − R(2 τ_fg) (cos 2θ_g, sin 2θ_g))
//
//   [Gebreiter 2012, §8.1.4 "Propagation and smoothing", second part of R:
//    ρ ‖(cos α_i⊕2, sin α_i⊕2) − R(β_i) (cos α_i⊕1, sin α_i⊕1)‖², β_i the
//    angle between the tangent planes' reference directions; Ray et al. 2006]
//
// The thesis compares the vectors at two corners of a triangle after turning
// one by the angle between their tangent planes' reference directions; here
// the field lives on faces and the angle between two adjacent faces' frames is
// the frame transport τ_fg (fields/face_frames.h: a tangent vector at angle α
// in g's frame has angle α + τ_fg in f's frame after unfolding). The field is
// a line field, so angles and the transport enter doubled (spin 2), as in
// tcd_dirichlet. c_e = ρ w_e, w_e = ℓ_e / d_e the face-based Dirichlet weight.
//
// Units / normalisation: θ, τ in radians; c_e ≥ 0 dimensionless; r unit-free.
// Ceres minimises ½Σr².
//
// Singular configurations: none. Never returns false.
//
// Invariances: θ_f → θ_f + π or θ_g → θ_g + π leaves r unchanged; rotating the
// frames of f and g by φ_f, φ_g (θ → θ − φ, τ_fg → τ_fg + φ_g − φ_f) turns r by
// R(−2φ_f): ‖r‖ unchanged; swapping f and g (τ → −τ) keeps ‖r‖.
#ifndef ARCHGEO_ENERGIES_PRINCIPAL_SMOOTHING_H_
#define ARCHGEO_ENERGIES_PRINCIPAL_SMOOTHING_H_

#include <cmath>

#include "energies/autodiff.h"

namespace archgeo {

struct PrincipalSmoothing {
  using Shape = CostShape<2, 1, 1>;

  // transport_angle: τ_fg (radians); weight: c_e ≥ 0.
  PrincipalSmoothing(double transport_angle, double weight)
      : cos2(std::cos(2.0 * transport_angle)),
        sin2(std::sin(2.0 * transport_angle)),
        sqrt_weight(std::sqrt(weight)) {}

  // theta_f, theta_g: 1 double each; residual: 2.
  template <typename T>
  bool operator()(const T* theta_f, const T* theta_g, T* residual) const {
    using std::cos;
    using std::sin;
    const T uf0 = cos(T(2.0) * theta_f[0]), uf1 = sin(T(2.0) * theta_f[0]);
    const T ug0 = cos(T(2.0) * theta_g[0]), ug1 = sin(T(2.0) * theta_g[0]);
    residual[0] = T(sqrt_weight) * (uf0 - (T(cos2) * ug0 - T(sin2) * ug1));
    residual[1] = T(sqrt_weight) * (uf1 - (T(sin2) * ug0 + T(cos2) * ug1));
    return true;
  }

  double cos2, sin2, sqrt_weight;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_PRINCIPAL_SMOOTHING_H_
