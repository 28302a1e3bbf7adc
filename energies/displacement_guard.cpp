// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/displacement_guard.h"

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/anchor.h"

namespace archgeo {


namespace terms {
namespace {

void AddGuard(TermContext& c, size_t i) {
  const int v = c.elements->Vertices(i)[0];
  const double g = c.Block("guard_weight", v)[0];
  if (g <= 0) return;
  AddAutoDiff(c, CheckedAnchor(c.Original(v), 1.0), {c.Position(v)}, -1, nullptr, g * c.weight);
}

}  // namespace

const TermSpec& displacement_guard() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "displacement_guard";
    t.summary =
        "anchor vertices near the displacement bound to their input position (weights grow "
        "×10 per round there)";
    t.paper = "[archgeo; Pellis 2019, §5.1]";
    t.elements = "vertices";
    t.declares = {{"guard_weight", Site::kVertex, 1, FrameMap::kInvariant, false,
                   Carry::kReinitialise, false, true, "weight of a vertex's displacement guard"}};
    t.add = &AddGuard;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo
