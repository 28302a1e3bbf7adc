// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/conical.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

Conical CheckedConical(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "Conical: inv_length must be finite and > 0, got " << inv_length;
  return Conical(inv_length);
}

}  // namespace archgeo

// --- term `conical` ------------------------------------------------------------

namespace archgeo::terms {
namespace {

// Star (v; w1 … w4) in cyclic order; L = its mean edge length at the start
// of the solve (it only scales the regularisation).
void AddConical(TermContext& c, size_t i) {
  const int* s = c.elements->Vertices(i);
  if (c.elements->Count(i) != 5 || c.elements->Has(i, kOpen)) return;
  double length = 0;
  const double* v = c.Original(s[0]);
  for (int k = 1; k <= 4; ++k) {
    const double* w = c.Original(s[k]);
    length += std::sqrt((w[0] - v[0]) * (w[0] - v[0]) + (w[1] - v[1]) * (w[1] - v[1]) +
                        (w[2] - v[2]) * (w[2] - v[2])) / 4;
  }
  AddAutoDiff(c, CheckedConical(length > 0 ? 1.0 / length : 1.0), {c.Position(s[0]), c.Position(s[1]), c.Position(s[2]), c.Position(s[3]),
         c.Position(s[4])});
}

}  // namespace

const TermSpec& conical() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "conical";
    t.summary = "conical meshes: at interior valence-4 vertices the sums of opposite face "
                "angles equal, (ω1 + ω3) − (ω2 + ω4) = 0 (radians)";
    t.paper = "[Liu et al. 2006, §3; Gebreiter 2012, §10.1 conical meshes]";
    t.elements = "valence4_stars";
    t.drives = "conical_max";
    t.add = &AddConical;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::Conical)
