// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// What the grid problem (problems/declarations/grid.cpp) shares with its terms
// (grid_orthogonality, grid_equilaterality, grid_quad_equilaterality,
// grid_boundary, grid_fairness): the parametric surface and the ideal edge
// length L, both in file units, through TermContext::grid(). Not a cost
// functor: the terms' adders read these once per element.
#ifndef ARCHGEO_ENERGIES_GRID_SHARED_H_
#define ARCHGEO_ENERGIES_GRID_SHARED_H_

#include <glog/logging.h>

#include "core/term.h"

namespace archgeo {

class Surface;

struct GridShared {
  const Surface* surface = nullptr;  // the grid's surface (file units); null outside the grid problem
  double length = 0;                 // L > 0 (file units)
};

// The grid problem's shared surface and length. Precondition (CHECKed): the
// term runs in the grid problem (a custom problem cannot compose the grid
// terms: their element sets are the grid problem's own).
inline const GridShared& SharedGrid(const TermContext& c) {
  const GridShared& grid = c.grid();
  CHECK(grid.surface != nullptr)
      << c.term_name() << ": no grid surface (only the grid problem provides one)";
  return grid;
}

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_GRID_SHARED_H_
