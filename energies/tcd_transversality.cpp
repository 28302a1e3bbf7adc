// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/tcd_transversality.h"

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

TcdTransversality CheckedTcdTransversality() {
  return TcdTransversality();
}

namespace terms {
namespace {

// Element (tcd_faces): a face (`face`).
void AddTcdTransversality(TermContext& c, size_t i) {
  AddAutoDiff(c, CheckedTcdTransversality(), {c.Block("z_n", c.elements->face[i])});
}

}  // namespace

const TermSpec& tcd_transversality() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "tcd_transversality";
    t.summary = "transversality of a TCD field: λ_trans ‖z_N − e1‖⁴ per face (eq. 1)";
    t.paper = "[Zadravec 2010, §4, eq. 1]";
    t.elements = "tcd_faces";
    t.reads = {"z_n"};
    t.add = &AddTcdTransversality;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::TcdTransversality)
