// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Fitting term of the principal-field pre-processing, one face f, 2 residuals:
//
//   r = sqrt(c_f) · ((cos 2θ_f, sin 2θ_f) − (cos 2θ⁰_f, sin 2θ⁰_f))
//
//   [Gebreiter 2012, §8.1.4 "Propagation and smoothing", first part of R:
//    (1 − ρ) Σ_i w_i ‖(cos α_i, sin α_i) − (cos α⁰_i, sin α⁰_i)‖²;
//    Ray et al. 2006]
//
// θ_f is the angle of the smoothed direction of largest curvature in f's
// frame (fields/face_frames.h), θ⁰_f the measured one (fields/face_curvature.h
// d1). Principal directions are lines (θ and θ + π are the same), so both
// enter doubled: the residual is that of the thesis' cosine–sine vectors of
// the line field's spin-2 representation. c_f = (1 − ρ) w_f A_f / Ā, w_f the
// face's reliability (fields/principal_field.h), A_f / Ā its area over
// the mean face area.
//
// Units / normalisation: θ in radians; c_f ≥ 0 dimensionless; r unit-free.
// Ceres minimises ½Σr².
//
// Singular configurations: none (r is smooth in θ). Never returns false.
//
// Invariances: θ → θ + π leaves r unchanged; rotating f's frame by φ (θ → θ −
// φ, θ⁰ → θ⁰ − φ) turns r by R(−2φ): ‖r‖ unchanged.
#ifndef ARCHGEO_ENERGIES_PRINCIPAL_FIT_H_
#define ARCHGEO_ENERGIES_PRINCIPAL_FIT_H_

#include <cmath>

#include "energies/autodiff.h"

namespace archgeo {

struct PrincipalFit {
  using Shape = CostShape<2, 1>;

  // measured_angle: θ⁰ (radians); weight: c_f ≥ 0.
  PrincipalFit(double measured_angle, double weight)
      : cos0(std::cos(2.0 * measured_angle)),
        sin0(std::sin(2.0 * measured_angle)),
        sqrt_weight(std::sqrt(weight)) {}

  // theta: 1 double (θ_f); residual: 2.
  template <typename T>
  bool operator()(const T* theta, T* residual) const {
    using std::cos;
    using std::sin;
    residual[0] = T(sqrt_weight) * (cos(T(2.0) * theta[0]) - T(cos0));
    residual[1] = T(sqrt_weight) * (sin(T(2.0) * theta[0]) - T(sin0));
    return true;
  }

  double cos0, sin0, sqrt_weight;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_PRINCIPAL_FIT_H_
