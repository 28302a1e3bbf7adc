// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Design handles, one 3-vector residual per handle vertex:
//
//   r = (v − h) / L
//
//   [Pellis 2019, §5.1 and Fig. 12: design by moving handles, the mesh
//    following under the smoothness target and the regularisers]
//
// h is the handle's target position (given in file units in the spec, moved
// to the canonical frame by the problem; an element constant of the
// problem-provided element set "handles"). Functor: the Anchor of
// energies/anchor.h with the target h; the same units, singular cases (none)
// and invariances (h moves with the mesh).
#ifndef ARCHGEO_ENERGIES_HANDLES_H_
#define ARCHGEO_ENERGIES_HANDLES_H_

namespace archgeo {

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_HANDLES_H_
