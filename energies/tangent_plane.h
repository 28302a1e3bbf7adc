// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Distance to a prescribed tangent plane, one residual per (vertex, plane):
//
//   r = n·(v − p) / L
//
//   [Pellis 2019, §4 and Fig. 15: boundary conditions of form finding — the
//    tangent planes of the surface along its boundary are prescribed; here
//    every non-boundary neighbour w of a boundary vertex b keeps to the input's
//    tangent plane at b (point p = b, unit normal n = n_b)]
//
// The plane (p, n) is an element constant (problem-provided element set
// "tangent_planes", canonical frame), fixed for the whole solve. Functor: the
// Proximity of energies/proximity.h with that plane; the same units, singular
// cases (none) and invariances.
#ifndef ARCHGEO_ENERGIES_TANGENT_PLANE_H_
#define ARCHGEO_ENERGIES_TANGENT_PLANE_H_

namespace archgeo {

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_TANGENT_PLANE_H_
