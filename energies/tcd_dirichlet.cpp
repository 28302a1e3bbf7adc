// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/tcd_dirichlet.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

TcdDirichlet CheckedTcdDirichlet(double transport_angle, double weight) {
  CHECK(std::isfinite(transport_angle)) << "TcdDirichlet: non-finite transport angle";
  CHECK(std::isfinite(weight) && weight >= 0.0)
      << "TcdDirichlet: weight must be finite and >= 0, got " << weight;
  return TcdDirichlet(transport_angle, weight);
}

namespace terms {
namespace {

// Element (tcd_edges): an interior edge with its faces f (`face`) and g
// (`other_face`); data: τ_fg, w_e (fields/face_frames.h EdgeTransport).
void AddTcdDirichlet(TermContext& c, size_t i) {
  const double* d = c.elements->Data(i);
  AddAutoDiff(c, CheckedTcdDirichlet(d[0], d[1]), {c.Block("z_n", c.elements->face[i]), c.Block("z_n", c.elements->other_face[i])});
}

}  // namespace

const TermSpec& tcd_dirichlet() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "tcd_dirichlet";
    t.summary = "smoothness of a TCD field: Dirichlet energy of z_N with the frame transport";
    t.paper = "[Zadravec 2010, §4, setup of global optimization]";
    t.elements = "tcd_edges";
    t.reads = {"z_n"};
    t.add = &AddTcdDirichlet;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::TcdDirichlet)
