// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/grid_boundary.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/grid_shared.h"

namespace archgeo {

GridBoundary CheckedGridBoundary(const Surface& surface, double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "GridBoundary: inv_length must be finite and > 0, got " << inv_length;
  return GridBoundary(surface, inv_length);
}

}  // namespace archgeo

// --- term `grid_boundary` -----------------------------------------------------

namespace archgeo::terms {
namespace {

// Element: a boundary stencil (p0, p1, p2, p3) of the grid problem (a vertex
// with three neighbours); the variables are the vertices' "uv" blocks.
void AddGridBoundary(TermContext& c, size_t i) {
  const GridShared g = SharedGrid(c);
  const int* v = c.elements->Vertices(i);
  AddAutoDiff(c, CheckedGridBoundary(*g.surface, 1.0 / g.length), {c.Block("uv", v[0]), c.Block("uv", v[1]), c.Block("uv", v[2]), c.Block("uv", v[3])});
}

}  // namespace

const TermSpec& grid_boundary() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "grid_boundary";
    t.summary =
        "boundary anti-folding: the inner edge at a boundary vertex orthogonal to the boundary";
    t.paper = "[force-directed grids paper, §3, eq. 2]";
    t.elements = "grid_boundary_stencils";
    t.reads = {"uv"};
    t.add = &AddGridBoundary;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::GridBoundary)
