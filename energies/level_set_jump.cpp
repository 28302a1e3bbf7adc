// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/level_set_jump.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/level_set_elements.h"

namespace archgeo {

LevelSetJump CheckedLevelSetJump(int sign, double inv_length) {
  CHECK(sign == 1 || sign == -1) << "LevelSetJump: sign must be +1 or -1, got " << sign;
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "LevelSetJump: inv_length must be finite and > 0";
  return LevelSetJump(sign, inv_length);
}

namespace terms {
namespace {

namespace ld = level_set_data;

// Element (level_set_jumps): g[left] = α_g + s_g g[right] and the same for h.
void AddLevelSetJump(TermContext& c, size_t i) {
  const double* d = c.elements->Data(i);
  const int left = int(d[ld::kLeft]), right = int(d[ld::kRight]), chain = int(d[ld::kChain]);
  AddAutoDiff(c, CheckedLevelSetJump(int(d[ld::kSignG]), d[ld::kInvLength]), {c.Block("level_set_g", left), c.Block("level_set_g", right),
         c.Block("level_set_alpha_g", chain)});
  AddAutoDiff(c, CheckedLevelSetJump(int(d[ld::kSignH]), d[ld::kInvLength]), {c.Block("level_set_h", left), c.Block("level_set_h", right),
         c.Block("level_set_alpha_h", chain)});
}

}  // namespace

const TermSpec& level_set_jump() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "level_set_jump";
    t.summary = "jump of the level-set functions across a cut: g_left = α_C ± g_right";
    t.paper = "[Zadravec 2010, §5, quad meshes from a TCD field with singularities]";
    t.elements = "level_set_jumps";
    t.reads = {"level_set_g", "level_set_h", "level_set_alpha_g", "level_set_alpha_h"};
    t.add = &AddLevelSetJump;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::LevelSetJump)
