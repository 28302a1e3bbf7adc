// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/tcd_singularity_placement.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

TcdSingularityPlacement CheckedTcdSingularityPlacement(const double z_m[2]) {
  CHECK(z_m != nullptr);
  CHECK(std::isfinite(z_m[0]) && std::isfinite(z_m[1]))
      << "TcdSingularityPlacement: z_M must be finite";
  return TcdSingularityPlacement(z_m);
}

namespace terms {
namespace {

// Element (tcd_placements): a face chosen to hold a singularity (`face`);
// data: z_M (2, finite).
void AddTcdSingularityPlacement(TermContext& c, size_t i) {
  AddAutoDiff(c, CheckedTcdSingularityPlacement(c.elements->Data(i)), {c.Block("z_n", c.elements->face[i])});
}

}  // namespace

const TermSpec& tcd_singularity_placement() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "tcd_singularity_placement";
    t.summary = "places a singularity of a TCD field in a chosen face: z_N = z_M";
    t.paper = "[Zadravec 2010, §4]";
    t.elements = "tcd_placements";
    t.reads = {"z_n"};
    t.add = &AddTcdSingularityPlacement;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::TcdSingularityPlacement)
