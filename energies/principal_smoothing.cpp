// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/principal_smoothing.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

PrincipalSmoothing CheckedPrincipalSmoothing(double transport_angle, double weight) {
  CHECK(std::isfinite(transport_angle)) << "PrincipalSmoothing: non-finite transport angle";
  CHECK(std::isfinite(weight) && weight >= 0.0)
      << "PrincipalSmoothing: weight must be finite and >= 0, got " << weight;
  return PrincipalSmoothing(transport_angle, weight);
}

namespace terms {
namespace {

// Element (principal_edges): an interior edge with its faces f (`face`) and g
// (`other_face`); data: τ_fg, c_e.
void AddPrincipalSmoothing(TermContext& c, size_t i) {
  const double* d = c.elements->Data(i);
  AddAutoDiff(c, CheckedPrincipalSmoothing(d[0], d[1]),
              {c.Block("principal", c.elements->face[i]), c.Block("principal", c.elements->other_face[i])});
}

}  // namespace

const TermSpec& principal_smoothing() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "principal_smoothing";
    t.summary = "pre-processing of the principal field: smoothness of the line field across "
                "interior edges with the frame transport, weighted by ρ";
    t.paper = "[Gebreiter 2012, §8.1.4, R; Ray et al. 2006]";
    t.elements = "principal_edges";
    t.reads = {"principal"};
    t.add = &AddPrincipalSmoothing;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::PrincipalSmoothing)
