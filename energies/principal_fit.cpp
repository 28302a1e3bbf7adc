// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/principal_fit.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

PrincipalFit CheckedPrincipalFit(double measured_angle, double weight) {
  CHECK(std::isfinite(measured_angle)) << "PrincipalFit: non-finite measured angle";
  CHECK(std::isfinite(weight) && weight >= 0.0)
      << "PrincipalFit: weight must be finite and >= 0, got " << weight;
  return PrincipalFit(measured_angle, weight);
}

namespace terms {
namespace {

// Element (principal_faces): a face (`face`); data: θ⁰_f, c_f.
void AddPrincipalFit(TermContext& c, size_t i) {
  const double* d = c.elements->Data(i);
  AddAutoDiff(c, CheckedPrincipalFit(d[0], d[1]), {c.Block("principal", c.elements->face[i])});
}

}  // namespace

const TermSpec& principal_fit() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "principal_fit";
    t.summary = "pre-processing of the principal field: the smoothed line field stays near the "
                "measured principal directions, weighted by their reliability (1 − ρ) w_f";
    t.paper = "[Gebreiter 2012, §8.1.4, R; Ray et al. 2006]";
    t.elements = "principal_faces";
    t.reads = {"principal"};
    t.add = &AddPrincipalFit;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::PrincipalFit)
