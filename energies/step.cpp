// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/step.h"

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/anchor.h"

namespace archgeo {


namespace terms {
namespace {

void AddStep(TermContext& c, size_t i) {
  const int v = c.elements->Vertices(i)[0];
  AddAutoDiff(c, CheckedAnchor(c.Previous(v), 1.0), {c.Position(v)});
}

}  // namespace

const TermSpec& step() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "step";
    t.summary = "pull towards the previous round's positions (damps each round's step)";
    t.paper = "[Pellis 2019, §5.1, R(X) = w_reg ‖X − X_prev‖²]";
    t.elements = "vertices";
    t.add = &AddStep;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo
