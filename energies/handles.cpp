// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/handles.h"

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/anchor.h"

namespace archgeo {


namespace terms {
namespace {

// Element: the handle vertex; its data: the target (canonical frame).
void AddHandle(TermContext& c, size_t i) {
  const int v = c.elements->Vertices(i)[0];
  AddAutoDiff(c, CheckedAnchor(c.elements->Data(i), 1.0), {c.Position(v)});
}

}  // namespace

const TermSpec& handles() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "handles";
    t.summary = "pull handle vertices to their target positions (design by handles)";
    t.paper = "[Pellis 2019, §5.1, Fig. 12]";
    t.elements = "handles";
    t.add = &AddHandle;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo
