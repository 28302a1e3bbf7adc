// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/grid_quad_equilaterality.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/grid_shared.h"

namespace archgeo {

GridQuadEquilaterality CheckedGridQuadEquilaterality(const Surface& surface, double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "GridQuadEquilaterality: inv_length must be finite and > 0, got " << inv_length;
  return GridQuadEquilaterality(surface, inv_length);
}

}  // namespace archgeo

// --- term `grid_quad_equilaterality` --------------------------------------------

namespace archgeo::terms {
namespace {

// Element: a grid quad (a, b, c, d) of the grid problem (seam quads
// included); the variables are the vertices' "uv" blocks.
void AddGridQuadEquilaterality(TermContext& c, size_t i) {
  const GridShared g = SharedGrid(c);
  const int* v = c.elements->Vertices(i);
  AddAutoDiff(c, CheckedGridQuadEquilaterality(*g.surface, 1.0 / g.length), {c.Block("uv", v[0]), c.Block("uv", v[1]), c.Block("uv", v[2]), c.Block("uv", v[3])});
}

}  // namespace

const TermSpec& grid_quad_equilaterality() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "grid_quad_equilaterality";
    t.summary = "local equilaterality: the four sides of each grid quad equal (any size)";
    t.paper = "[force-directed grids paper, §1 condition (2); eq. 6]";
    t.elements = "grid_quads";
    t.reads = {"uv"};
    t.add = &AddGridQuadEquilaterality;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::GridQuadEquilaterality)
