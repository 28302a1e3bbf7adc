// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — welding coincident vertices of a polygon soup on reading: a CAD
// export that gives every face its own corner vertices becomes one connected
// surface again.
//
// Two vertices are coincident when they lie within `distance` × the soup's
// mean edge length of each other (ReadLimits::weld_distance, spec
// limits.weld_distance; 0 turns welding off). Each vertex is welded to the
// first vertex (in file order) within that distance of it that is kept; the
// kept vertices keep their file order, renumbered without the welded ones.
// Found through a hash grid of cell size = the weld distance (the 27 cells
// around a vertex hold every candidate), so the work is linear in the
// vertex count.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace archgeo {

// Welds `points` and renumbers `polygons`; returns the number of vertices
// welded away (0: nothing changed). Vertices no face uses are not welded.
std::size_t WeldCoincidentVertices(std::vector<std::array<double, 3>>* points,
                                   std::vector<std::vector<std::size_t>>* polygons,
                                   double distance);

}  // namespace archgeo
