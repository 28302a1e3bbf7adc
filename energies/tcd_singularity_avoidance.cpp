// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/tcd_singularity_avoidance.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

TcdSingularityAvoidance CheckedTcdSingularityAvoidance(const double z_m[2], double radius) {
  CHECK(z_m != nullptr);
  CHECK(std::isfinite(z_m[0]) && std::isfinite(z_m[1]))
      << "TcdSingularityAvoidance: z_M must be finite (skip faces with z_M at infinity)";
  CHECK(std::isfinite(radius) && radius > 0.0)
      << "TcdSingularityAvoidance: radius must be finite and > 0, got " << radius;
  return TcdSingularityAvoidance(z_m, radius);
}

namespace terms {
namespace {

// Element (tcd_faces): a face (`face`); data: z_M (2), 1 if z_M is finite
// else 0. Faces with z_M at infinity get no residual (Ψ = 0 there).
void AddTcdSingularityAvoidance(TermContext& c, size_t i) {
  const double* d = c.elements->Data(i);
  if (d[2] == 0.0) return;
  AddAutoDiff(c, CheckedTcdSingularityAvoidance(d, c.Number("radius")), {c.Block("z_n", c.elements->face[i])});
}

}  // namespace

const TermSpec& tcd_singularity_avoidance() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "tcd_singularity_avoidance";
    t.summary = "discourages singularities of a TCD field: Ψ(‖z_N − z_M‖/ρ) per face";
    t.paper = "[Zadravec 2010, §4, Ψ]";
    t.elements = "tcd_faces";
    t.reads = {"z_n"};
    t.options = {NumberKey("radius", 1.0, 1e-6, 1e6,
                           "ρ: Ψ acts where ‖z_N − z_M‖ < ρ (the auxiliary circle has radius 1)")};
    t.add = &AddTcdSingularityAvoidance;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::TcdSingularityAvoidance)
