// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Step regulariser, one 3-vector residual per vertex:
//
//   r = (v − v_prev) / L
//
//   [Pellis 2019, §5.1: R(X) = w_reg ‖X − X_prev‖² of the regulariser of
//    every design problem; the "regularizer" of the §5.3 weight iteration]
//
// v_prev is the vertex's position at the start of the round (a constant of
// the round), so the term damps each round's step without pulling the mesh
// back to its input (that is `anchor`). Functor: the Anchor of
// energies/anchor.h with the target v_prev; the same units, singular cases
// (none) and invariances.
#ifndef ARCHGEO_ENERGIES_STEP_H_
#define ARCHGEO_ENERGIES_STEP_H_

namespace archgeo {

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_STEP_H_
