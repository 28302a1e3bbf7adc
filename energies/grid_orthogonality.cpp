// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/grid_orthogonality.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/grid_shared.h"

namespace archgeo {

GridOrthogonality CheckedGridOrthogonality(const Surface& surface, double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "GridOrthogonality: inv_length must be finite and > 0, got " << inv_length;
  return GridOrthogonality(surface, inv_length);
}

}  // namespace archgeo

// --- term `grid_orthogonality` ------------------------------------------------

namespace archgeo::terms {
namespace {

// Element: a crossing (l0, l1, t0, t1) of the grid problem (the neighbours of
// a vertex with four); the variables are the vertices' "uv" blocks.
void AddGridOrthogonality(TermContext& c, size_t i) {
  const GridShared g = SharedGrid(c);
  const int* v = c.elements->Vertices(i);
  AddAutoDiff(c, CheckedGridOrthogonality(*g.surface, 1.0 / g.length), {c.Block("uv", v[0]), c.Block("uv", v[1]), c.Block("uv", v[2]), c.Block("uv", v[3])});
}

}  // namespace

const TermSpec& grid_orthogonality() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "grid_orthogonality";
    t.summary =
        "orthogonality of the two grid lines at each crossing: cos of their angle (central "
        "differences through the surface map)";
    t.paper = "[force-directed grids paper, §3 goal (1); eqs. 4–5]";
    t.elements = "grid_crossings";
    t.reads = {"uv"};
    t.add = &AddGridOrthogonality;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::GridOrthogonality)
