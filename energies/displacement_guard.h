// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Displacement guard, one 3-vector residual per guarded vertex:
//
//   r = (v − v⁰) / L,   weight g_v (the block "guard_weight")
//
// Keeps every vertex within a bound of its input position v⁰ (the stage's
// `guard_key`, e.g. smooth_mesh's tolerance.displacement_relative): after a
// round the loop gives each vertex beyond half the bound the weight g_v = 1,
// then ×10 every further round it stays there, and puts a vertex beyond the
// bound back inside it (core/loop.h, problems/runtime/model.h Guard). Vertices with
// g_v = 0 get no residual. Functor: the Anchor of energies/anchor.h; the same
// units, singular cases (none) and invariances.
//   [archgeo; the bounded-movement requirement of Pellis 2019, §5.1's
//    "close to the reference" made explicit]
#ifndef ARCHGEO_ENERGIES_DISPLACEMENT_GUARD_H_
#define ARCHGEO_ENERGIES_DISPLACEMENT_GUARD_H_

namespace archgeo {

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_DISPLACEMENT_GUARD_H_
