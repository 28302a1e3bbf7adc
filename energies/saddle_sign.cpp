// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/saddle_sign.h"

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

SaddleSign CheckedSaddleSign() {
  return SaddleSign();
}

namespace terms {
namespace {

// Element (principal_stars): (v, p0, p1, o0 … o3); at a saddle (block
// "saddle" of v is 1) one residual per principal neighbour p_k with its
// dummy δ_k (block "saddle_dummy" of v, 2 values).
void AddSaddleSign(TermContext& c, size_t i) {
  const int* s = c.elements->Vertices(i);
  if (c.Block("saddle", s[0])[0] == 0) return;
  double* delta = c.Block("saddle_dummy", s[0]);
  for (int k = 0; k < 2; ++k) {
    AddAutoDiff(c, CheckedSaddleSign(), {c.Position(s[0]), c.Block("sphere_normal", s[0]),
                             c.Block("sphere_curvature", s[0]), c.Position(s[1 + k]), delta + k});
  }
}

}  // namespace

const TermSpec& saddle_sign() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "saddle_sign";
    t.summary =
        "principal-symmetric saddles: principal neighbours across the tangent plane from the "
        "sphere";
    t.paper = "[Pellis 2019, §2.3, §5.2]";
    t.elements = "principal_stars";
    t.group = "principal_stars";
    t.reads = {"sphere_normal", "sphere_curvature", "saddle", "saddle_dummy"};
    t.add = &AddSaddleSign;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::SaddleSign)
