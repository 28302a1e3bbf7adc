// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Jump condition of a level-set function across a cut, one pair of values of
// one cut vertex, 1 residual:
//
//   r = (g_left − α_C − s · g_right) / L,   s = ±1
//
//   [Zadravec 2010, §5 "Quad meshes from a TCD field with singularities":
//    g^left(v) = α_C − g^right(v) for cuts from singularities of index ±1/2,
//    g^left(v) = α_C + g^right(v) for the cuts that make Φ simply connected;
//    ±k/2: g^left = α_C + (−1)^k g^right]
//
// g_left, g_right are the two values of a vertex v on cut chain C (the values
// of its wedges on the left and right side of the chain, fields/cuts.h), α_C
// the chain's jump constant, a variable block (rounded to an integer multiple
// of the spacing Δw and held constant in the second solve). The sign s is the
// matching of the direction field across the chain (−1 when the field turns
// by an odd multiple of π around the chain's loop, fields/cuts.h
// OrientField). When both values are the same wedge (the source vertex of a
// cut from a singularity: g(v0) = α_C/2) use level_set_branch_point.h.
//
// Units / normalisation: L = 1/inv_length (e.g. the spacing Δw) makes r
// unit-free when g has the units of length. Ceres minimises ½Σr²; the builder
// weights the term strongly (a soft equality).
//
// Singular configurations: none (affine). Never returns false.
//
// Invariances: adding a constant c to g on both sides with α → α + (1 − s) c
// (r unchanged); scaling g, α and L together (r unchanged).
#ifndef ARCHGEO_ENERGIES_LEVEL_SET_JUMP_H_
#define ARCHGEO_ENERGIES_LEVEL_SET_JUMP_H_

#include "energies/autodiff.h"

namespace archgeo {

struct LevelSetJump {
  using Shape = CostShape<1, 1, 1, 1>;

  // sign: s = ±1; inv_length: 1/L.
  LevelSetJump(int sign, double inv_length) : sign(sign), inv_length(inv_length) {}

  // g_left, g_right, alpha: 1 double each; residual: 1.
  template <typename T>
  bool operator()(const T* g_left, const T* g_right, const T* alpha, T* residual) const {
    residual[0] = (g_left[0] - alpha[0] - T(static_cast<double>(sign)) * g_right[0]) *
                  T(inv_length);
    return true;
  }

  int sign;
  double inv_length;
};

// The functor after checking its arguments (CHECK: sign ±1, inv_length
// finite and > 0); defined in level_set_jump.cpp.
LevelSetJump CheckedLevelSetJump(int sign, double inv_length);

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_LEVEL_SET_JUMP_H_
