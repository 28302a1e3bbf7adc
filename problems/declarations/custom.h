// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `problem: custom`: the problem is the spec's own list of terms.
//
//   problem: custom
//   terms:                    # any registered terms (energies/registry.cpp), in
//     pq_diagonal: 10         # the order their residuals are added; a term
//     dihedral_energy: {weight: 1, on: interior_edges}   # given as a mapping
//     proximity: {weight: 2, point_weight: 0.01}          # without weight has 1
//   tolerance:
//     pq_normalized_max: 1e-3 # one key per measure a listed term drives to 0
//                             # (pq_diagonal, face_planarity: pq_normalized_max;
//                             # anet_planarity: star_planarity_max; conical:
//                             # conical_max; load: force_balance_max); 0 = off
//   continuation: {factor: 10, band: 0}   # weight growth of those terms per
//                             # round short of the tolerances; tolerance band
//
// One stage: rounds (schedule.outer_iterations) of re-projection, IRLS
// reweighting and continuation until every tolerance holds (each is also
// checked after every Ceres iteration: the solve stops the moment all hold),
// or, without one, until a round moves no vertex by more than 1e-6 mean edge
// lengths. Report: the planarity metrics, the `spreads` analysis (edge-length
// and boundary-spacing spread), `conical` with the conical term, `smoothness`
// with dihedral_energy or total_absolute_curvature; with the load term
// details.load (span, rise, force balance; the terminal shows them), with
// on_curve details.on_curve (how far its vertices are from their curves). A term
// that acts on elements the mesh does not have (a quad term on a triangle
// mesh) is an input error naming the term; terms that need a problem's own
// elements (e.g. co_spherical's labelled stars) cannot be composed here.
#pragma once

#include <string>

#include "core/custom_value.h"
#include "core/problem.h"

namespace archgeo {

// The declaration of the custom problem whose spec lists `terms` (its
// `terms:` section as read, null if it has none) in `file` (the spec, or
// "--set"). Throws InputError for an unknown or uncomposable term.
ProblemDecl CustomProblem(const CustomValue* terms, const std::string& file);

// The custom problem composing the terms of examples/planar_smooth.yaml with
// its weights: what `archgeo spec custom` prints, the terms being the one key
// a custom spec must give.
ProblemDecl CustomExample();

}  // namespace archgeo
