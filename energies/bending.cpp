// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/bending.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

Bending CheckedBending(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "Bending: inv_length must be finite and > 0, got " << inv_length;
  return Bending(inv_length);
}

}  // namespace archgeo

// --- term `bending` ------------------------------------------------------------

namespace archgeo::terms {
namespace {

// (u, v, w): opposite neighbours u, w of v; r = unit(w − v) − unit(v − u).
void AddBending(TermContext& c, size_t i) {
  const int* t = c.elements->Vertices(i);
  AddAutoDiff(c, CheckedBending(1.0), {c.Position(t[0]), c.Position(t[1]), c.Position(t[2])});
}

}  // namespace

const TermSpec& bending() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "bending";
    t.summary = "bending: opposite edges at even-valence vertices aligned (unit directions, "
                "lengths free)";
    t.paper = "[Gebreiter 2012, §10.1 bending, §11.7.1]";
    t.elements = "straight_triples";
    t.element_choices = {"polyline_triples", "umbrella_triples"};
    t.add = &AddBending;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::Bending)
