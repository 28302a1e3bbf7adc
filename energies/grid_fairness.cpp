// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/grid_fairness.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeGridFairness(const Surface& surface, double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeGridFairness: inv_length must be finite and > 0, got " << inv_length;
  return new ceres::AutoDiffCostFunction<GridFairness, 3, 2, 2, 2>(
      new GridFairness(surface, inv_length));
}

}  // namespace archgeo

// --- term `grid_fairness` -----------------------------------------------------
#include "core/term.h"
#include "energies/grid_shared.h"

namespace archgeo::terms {
namespace {

// Element: three consecutive vertices (a, b, c) of a grid line of the grid
// problem (closed lines wrap); the variables are the vertices' "uv" blocks.
void AddGridFairness(TermContext& c, size_t i) {
  const GridShared g = SharedGrid(c);
  const int* v = c.elements->Vertices(i);
  c.Add(MakeGridFairness(*g.surface, 1.0 / g.length),
        {c.Block("uv", v[0]), c.Block("uv", v[1]), c.Block("uv", v[2])});
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
