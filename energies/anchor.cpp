// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/anchor.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

Anchor CheckedAnchor(const double target[3], double inv_length) {
  CHECK(target != nullptr);
  CHECK(std::isfinite(target[0]) && std::isfinite(target[1]) &&
        std::isfinite(target[2]))
      << "Anchor: non-finite target";
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "Anchor: inv_length must be finite and > 0, got " << inv_length;
  return Anchor(target, inv_length);
}


}  // namespace archgeo

// --- term `anchor` -------------------------------------------------------------

namespace archgeo::terms {
namespace {

void AddAnchor(TermContext& c, size_t i) {
  const int v = c.elements->Vertices(i)[0];
  AddAutoDiff(c, CheckedAnchor(c.Original(v), 1.0), {c.Position(v)});
}

}  // namespace

const TermSpec& anchor() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "anchor";
    t.summary = "pull towards each vertex's position at the start of the solve";
    t.paper = "[Shi 2014, §3.2, F_prox point part]";
    t.elements = "vertices";
    t.group = "proximity";
    t.add = &AddAnchor;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::Anchor)
