// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Jump condition at a cut vertex whose two sides are one wedge (the source
// vertex of a cut from a singularity), 1 residual:
//
//   r = ((1 − s) g − α_C) / L,   s = ±1
//
//   [Zadravec 2010, §5: "For the source vertex v0, the two function values
//    coincide, which implies g(v0) = α_C/2."]
//
// This is level_set_jump.h with g_left = g_right = g (Ceres does not accept
// one parameter block twice in a residual block). s = −1 (a ±1/2 singularity)
// gives r = (2g − α_C)/L, i.e. g(v0) = α_C/2; s = +1 (an integer index, or a
// chain end where the field is continuous) gives r = −α_C/L, i.e. α_C = 0.
//
// Units / normalisation: L = 1/inv_length as in level_set_jump.h. Ceres
// minimises ½Σr².
//
// Singular configurations: none (affine). Never returns false.
//
// Invariances: scaling g, α and L together (r unchanged).
#ifndef ARCHGEO_ENERGIES_LEVEL_SET_BRANCH_POINT_H_
#define ARCHGEO_ENERGIES_LEVEL_SET_BRANCH_POINT_H_

#include "energies/autodiff.h"

namespace archgeo {

struct LevelSetBranchPoint {
  using Shape = CostShape<1, 1, 1>;

  // sign: s = ±1; inv_length: 1/L.
  LevelSetBranchPoint(int sign, double inv_length) : sign(sign), inv_length(inv_length) {}

  // g, alpha: 1 double each; residual: 1.
  template <typename T>
  bool operator()(const T* g, const T* alpha, T* residual) const {
    residual[0] = (T(1.0 - static_cast<double>(sign)) * g[0] - alpha[0]) * T(inv_length);
    return true;
  }

  int sign;
  double inv_length;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_LEVEL_SET_BRANCH_POINT_H_
