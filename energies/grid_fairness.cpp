// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/grid_fairness.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/grid_shared.h"

namespace archgeo {

GridFairness CheckedGridFairness(const Surface& surface, double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "GridFairness: inv_length must be finite and > 0, got " << inv_length;
  return GridFairness(surface, inv_length);
}

}  // namespace archgeo

// --- term `grid_fairness` -----------------------------------------------------

namespace archgeo::terms {
namespace {

// Element: three consecutive vertices (a, b, c) of a grid line of the grid
// problem (closed lines wrap); the variables are the vertices' "uv" blocks.
void AddGridFairness(TermContext& c, size_t i) {
  const GridShared g = SharedGrid(c);
  const int* v = c.elements->Vertices(i);
  AddAutoDiff(c, CheckedGridFairness(*g.surface, 1.0 / g.length), {c.Block("uv", v[0]), c.Block("uv", v[1]), c.Block("uv", v[2])});
}

}  // namespace

const TermSpec& grid_fairness() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "grid_fairness";
    t.summary =
        "second differences along the grid lines through the surface map (straight, evenly "
        "spaced lines)";
    t.paper = "[force-directed grids paper, §3 eq. 1 (straightening)]";
    t.elements = "grid_line_triples";
    t.reads = {"uv"};
    t.add = &AddGridFairness;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::GridFairness)
