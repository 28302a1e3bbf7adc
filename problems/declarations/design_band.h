// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the deviation band: how far the result may leave the design
// (reference) surface, enforced by the loop.
//
// A façade brief names two numbers: panel flatness and the deviation from
// the architect's surface. A problem that moves vertices near a design gets
//   tolerance.surface_distance_max  the band b as a fraction of the input's
//                                   bounding-box diagonal (default per problem)
//   tolerance.surface_distance      the band in file units (> 0: replaces it)
// and three mechanisms:
//   - the term surface_band (energies/surface_band.h), implicit: within a
//     round every vertex lies on a bounded manifold around its closest
//     reference point and cannot leave the band along the reference normal
//     (on the boundary curve: a ball around the curve point), whatever step
//     the solver takes;
//   - after every round, a vertex the tangent-plane model let past the band
//     (where the surface curves away under it) is put back on the band's
//     edge towards its closest reference point;
//   - a bound on the measure surface_distance_relative (surface_distance),
//     the exact distance of every vertex (and face centroid, with a
//     `reference` of its own) from the reference: a round beyond it is
//     rejected like an invalid one (core/problem.h Tolerance::bound), so
//     the output never leaves the band; a solve ends early only when the
//     goals and the bound hold;
//   - the report's details.surface_band: the band, the output's deviation,
//     the largest deviation any round reached, how many vertices sit at the
//     band (≥ 0.8 b), and whether it binds (the goals missed with the output
//     or a round at the band; the output is the best valid round, which need
//     not be the one that pressed against the band), with the deviation a round
//     that met the goals needed, if one did; with `measure_need`, when it
//     binds and no round met the goals, the problem is solved once more
//     without the band and the report gives the deviation that run reached
//     and whether it met the goals (details.surface_band.unbounded);
//   - with `tighten` (planar_quads), when the rounds at the band pressed
//     against it and missed the goals and `tighten` says yes, a stage that
//     opens the band until they hold and then closes it towards the band
//     round by round (stall.band_tightening; details.surface_band.tightening).
#pragma once

#include <functional>

#include "core/problem.h"

namespace archgeo {

// Asked before the band tightening's first round: whether it may run (the
// net is one the goals can hold on with the band open).
using BandTighteningIf = std::function<bool(HookContext&)>;

// `d` with the band (default `relative` of the diagonal; 0 = off unless set);
// with `tighten`, the band tightening stage after the problem's stages.
ProblemDecl WithDesignBand(ProblemDecl d, double relative, bool measure_need = false,
                           BandTighteningIf tighten = {});

}  // namespace archgeo
