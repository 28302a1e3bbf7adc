// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/level_set_branch_point.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/level_set_elements.h"

namespace archgeo {

LevelSetBranchPoint CheckedLevelSetBranchPoint(int sign, double inv_length) {
  CHECK(sign == 1 || sign == -1) << "LevelSetBranchPoint: sign must be +1 or -1, got " << sign;
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "LevelSetBranchPoint: inv_length must be finite and > 0";
  return LevelSetBranchPoint(sign, inv_length);
}

namespace terms {
namespace {

namespace ld = level_set_data;

// Element (level_set_branch_points): the source vertex of a singularity cut,
// g = α_C / 2 (s = −1) or α_C = 0 (s = +1), for g and for h.
void AddLevelSetBranchPoint(TermContext& c, size_t i) {
  const double* d = c.elements->Data(i);
  const int wedge = int(d[ld::kLeft]), chain = int(d[ld::kChain]);
  AddAutoDiff(c, CheckedLevelSetBranchPoint(int(d[ld::kSignG]), d[ld::kInvLength]), {c.Block("level_set_g", wedge), c.Block("level_set_alpha_g", chain)});
  AddAutoDiff(c, CheckedLevelSetBranchPoint(int(d[ld::kSignH]), d[ld::kInvLength]), {c.Block("level_set_h", wedge), c.Block("level_set_alpha_h", chain)});
}

}  // namespace

const TermSpec& level_set_branch_point() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "level_set_branch_point";
    t.summary = "the source vertex of a singularity cut: g = α_C / 2";
    t.paper = "[Zadravec 2010, §5, quad meshes from a TCD field with singularities]";
    t.elements = "level_set_branch_points";
    t.reads = {"level_set_g", "level_set_h", "level_set_alpha_g", "level_set_alpha_h"};
    t.add = &AddLevelSetBranchPoint;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::LevelSetBranchPoint)
