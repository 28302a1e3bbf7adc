// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The term level_set_boundary (energies/level_set_boundary.h).
#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/level_set_elements.h"
#include "energies/level_set_boundary.h"

namespace archgeo {
namespace terms {
namespace {

namespace ld = level_set_data;

void AddLevelSetBoundary(TermContext& c, size_t i) {
  const double* d = c.elements->Data(i);
  const int function = int(d[ld::kFunction]);
  CHECK(function == 0 || function == 1) << "level_set_boundary: function must be 0 or 1";
  const char* block = function == 0 ? "level_set_g" : "level_set_h";
  AddAutoDiff(c, CheckedLevelSetJump(1, d[ld::kBoundaryInvLength]),
              {c.Block(block, int(d[ld::kWedgeA])), c.Block(block, int(d[ld::kWedgeB])),
               c.Block("level_set_boundary_zero", 0)});
}

}  // namespace

const TermSpec& level_set_boundary() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "level_set_boundary";
    t.summary = "a level-set function constant along a boundary row: g_a = g_b per boundary edge";
    t.paper = "[Gebreiter 2012, §8.3.2; Zadravec 2010, §5]";
    t.elements = "level_set_boundary_edges";
    t.reads = {"level_set_g", "level_set_h", "level_set_boundary_zero"};
    t.add = &AddLevelSetBoundary;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo
