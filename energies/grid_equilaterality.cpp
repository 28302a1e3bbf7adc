// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/grid_equilaterality.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/grid_shared.h"

namespace archgeo {

GridEquilaterality CheckedGridEquilaterality(const Surface& surface, double ideal_length) {
  CHECK(std::isfinite(ideal_length) && ideal_length > 0.0)
      << "GridEquilaterality: ideal_length must be finite and > 0, got " << ideal_length;
  return GridEquilaterality(surface, ideal_length);
}

}  // namespace archgeo

// --- term `grid_equilaterality` -----------------------------------------------

namespace archgeo::terms {
namespace {

// Element: a grid edge (a, b) of the grid problem (seam edges included);
// the variables are the vertices' "uv" blocks.
void AddGridEquilaterality(TermContext& c, size_t i) {
  const GridShared g = SharedGrid(c);
  const int* v = c.elements->Vertices(i);
  AddAutoDiff(c, CheckedGridEquilaterality(*g.surface, g.length), {c.Block("uv", v[0]), c.Block("uv", v[1])});
}

}  // namespace

const TermSpec& grid_equilaterality() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "grid_equilaterality";
    t.summary = "edge length towards the ideal length L: (|e| − L)/L per grid edge";
    t.paper = "[force-directed grids paper, §3 goal (2), Listing 1 step 2; eq. 6]";
    t.elements = "grid_edges";
    t.reads = {"uv"};
    t.add = &AddGridEquilaterality;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::GridEquilaterality)
