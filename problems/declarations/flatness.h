// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — panel flatness in millimetres, enforced by the loop.
//
// A glazing brief gives flatness as a length: "no corner more than 2 mm off
// the panel's plane". A problem whose stages drive δ_PQ,n
// (tolerance.pq_normalized_max) gets
//   tolerance.flatness_mm   the largest distance of a panel corner from the
//                           panel's best-fit plane, in millimetres (0 = off)
// converted through `units` (the mesh's unit; the spec is refused without
// it). It is a tolerance like the relative one, beside it: measured after
// every Ceres iteration (the measure flatness_mm, fabrication/panels.h
// PanelFlatness in file units × millimetres per unit), its stage runs until
// both hold, a round that misses it continues the planarity weights, and a
// run that ends short of it exits 4 with it in the report's `tolerances`.
#pragma once

#include "core/problem.h"

namespace archgeo {

// `d` with tolerance.flatness_mm on every stage that has a
// pq_normalized_max tolerance.
ProblemDecl WithFlatness(ProblemDecl d);

}  // namespace archgeo
