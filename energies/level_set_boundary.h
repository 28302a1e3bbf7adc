// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A level-set function constant along a boundary row (the term
// level_set_boundary): one of the level-set functions constant along a
// boundary row, one residual per boundary edge (a, b):
//
//   r = (g_a − g_b) / L
//
//   [Gebreiter 2012, §8.3.2: boundary vertices take an iso-value; as a soft
//    relation of Zadravec 2010, §5's form g_left = α + s g_right with α = 0,
//    s = +1, the functor of level_set_jump.h]
//
// g_a, g_b: the values of the function the row holds (fields/boundary_rows.h)
// at the wedges of the edge's two corners in its face; L the spacing Δw, so r
// is unit-free. Applied before the jumps are rounded, so that the level sets
// already run along the boundary when the rows are held on a level (a hard
// constraint) for the last solve. Singular configurations: none (affine).
// Invariances: g → g + c; scaling g and L together.
//
// No functor of its own: the residual is LevelSetJump's (energies/
// level_set_jump.h) with sign +1 and the constant block
// "level_set_boundary_zero" as α (elements: energies/level_set_elements.h,
// level_set_boundary_edges).
#ifndef ARCHGEO_ENERGIES_LEVEL_SET_BOUNDARY_H_
#define ARCHGEO_ENERGIES_LEVEL_SET_BOUNDARY_H_

#include "energies/level_set_jump.h"

#endif  // ARCHGEO_ENERGIES_LEVEL_SET_BOUNDARY_H_
