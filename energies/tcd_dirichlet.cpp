// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/tcd_dirichlet.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

#include "core/term.h"

namespace archgeo {

ceres::CostFunction* MakeTcdDirichlet(double transport_angle, double weight) {
  CHECK(std::isfinite(transport_angle)) << "MakeTcdDirichlet: non-finite transport angle";
  CHECK(std::isfinite(weight) && weight >= 0.0)
      << "MakeTcdDirichlet: weight must be finite and >= 0, got " << weight;
  return new ceres::AutoDiffCostFunction<TcdDirichlet, 2, 2, 2>(
      new TcdDirichlet(transport_angle, weight));
}


namespace terms {
namespace {

// Element (tcd_edges): an interior edge with its faces f (`face`) and g
// (`other_face`); data: τ_fg, w_e (fields/face_frames.h EdgeTransport).
void AddTcdDirichlet(TermContext& c, size_t i) {
  const double* d = c.elements->Data(i);
  c.Add(MakeTcdDirichlet(d[0], d[1]),
        {c.Block("z_n", c.elements->face[i]), c.Block("z_n", c.elements->other_face[i])});
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
