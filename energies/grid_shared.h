// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// What the grid problem (problems/grid.cpp) shares with its four terms
// (grid_orthogonality, grid_equilaterality, grid_boundary, grid_fairness):
// the parametric surface and the ideal edge length L, both in file units,
// through TermContext::Shared ("surface": a Surface, "grid_length": a
// double). Not a cost functor: the terms' adders read these once per element.
#ifndef ARCHGEO_ENERGIES_GRID_SHARED_H_
#define ARCHGEO_ENERGIES_GRID_SHARED_H_

#include <any>

#include <glog/logging.h>

#include "core/term.h"
#include "surfaces/surface.h"

namespace archgeo {

struct GridShared {
  const Surface* surface;  // the grid's surface (file units)
  double length;           // L > 0 (file units)
};

// The grid problem's shared surface and length. Precondition (CHECKed): the
// term runs in the grid problem (a custom problem cannot compose the grid
// terms: their element sets are the grid problem's own).
inline GridShared SharedGrid(const TermContext& c) {
  const Surface* surface = std::any_cast<Surface>(&c.Shared("surface"));
  const double* length = std::any_cast<double>(&c.Shared("grid_length"));
  CHECK(surface != nullptr && length != nullptr)
      << c.term_name() << ": no grid surface (only the grid problem provides one)";
  return {surface, *length};
}

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_GRID_SHARED_H_
