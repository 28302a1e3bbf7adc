// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Dirichlet energy of a per-face unit direction field, one 3-vector residual
// per interior edge between faces f and g:
//
//   r = d_f − d_g
//
//   [the discrete Dirichlet energy Σ_e ‖d_f − d_g‖² of a piecewise-constant
//    field on the faces; Knöppel, Crane, Pinkall, Schröder 2013, §4, for its
//    role in smoothest direction fields; here with unit blocks in R³]
//
// d_f, d_g are the faces' unit directions (the per-face block
// "face_direction", optimised on the unit sphere). Unit-free; ½‖r‖² =
// 1 − cos θ with θ the angle between the two directions, so the energy is
// zero exactly for a constant field. The field is not projected onto the
// faces' planes: on a curved surface the minimiser is the constant field, so
// this is the engine's smallest example of a per-face variable block (its
// test, tests/test_engine.cpp), not a tangent-field energy (those are the
// TCD field energies of Zadravec 2010, energies/tcd_*.h).
// Singular configurations: none (r is linear in the blocks). Invariances:
// a rotation applied to every direction rotates r (‖r‖ unchanged).
#ifndef ARCHGEO_ENERGIES_DIRECTION_DIRICHLET_H_
#define ARCHGEO_ENERGIES_DIRECTION_DIRICHLET_H_

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

struct DirectionDirichlet {
  using Shape = CostShape<3, 3, 3>;

  // d_f, d_g: 3 doubles each; residual: 3 doubles.
  template <typename T>
  bool operator()(const T* d_f, const T* d_g, T* residual) const {
    for (int k = 0; k < 3; ++k) residual[k] = d_f[k] - d_g[k];
    return true;
  }
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_DIRECTION_DIRICHLET_H_
