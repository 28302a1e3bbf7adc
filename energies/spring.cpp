// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/spring.h"

#include <cmath>

#include <glog/logging.h>

#include "core/magnitude.h"
#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

// A spring of rest length L0 = rest_length ≥ 0 (0: the zero-length spring)
// added to `c` over (a, b).
void AddSpringResidual(TermContext& c, double rest_length, double inv_length, double* a,
                       double* b) {
  CHECK(std::isfinite(rest_length) && rest_length >= 0.0)
      << "Spring: rest_length must be finite and >= 0, got " << rest_length;
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "Spring: inv_length must be finite and > 0, got " << inv_length;
  if (rest_length == 0.0) {
    AddAutoDiff(c, ZeroLengthSpring(inv_length), {a, b});
  } else {
    AddAutoDiff(c, Spring(rest_length, inv_length), {a, b});
  }
}

}  // namespace archgeo

// --- term `spring` -------------------------------------------------------------

namespace archgeo::terms {
namespace {

double Distance(const double* a, const double* b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

// The rest length of every selected edge this round, into the edge block
// spring_rest_length (canonical lengths): rest × fraction, rest one of the
// edge's length at the start of the round (current) or of the solve
// (original), the mean of those at the start of the round (mean), the
// option `length` (file units) or 0 (zero).
void BeginSpring(TermContext& c) {
  const ElementSet& e = *c.elements;
  const std::string& rest = c.String("rest");
  const double fraction = c.Number("fraction");
  double mean = 0;
  if (rest == "mean" && e.size() > 0) {
    for (size_t i = 0; i < e.size(); ++i) {
      mean += Distance(c.Previous(e.Vertices(i)[0]), c.Previous(e.Vertices(i)[1]));
    }
    mean /= double(e.size());
  }
  double length = c.Number("length");
  c.FromFile(FrameMap::kLength, &length, 1);
  for (size_t i = 0; i < e.size(); ++i) {
    const int a = e.Vertices(i)[0], b = e.Vertices(i)[1];
    double l0 = 0;
    if (rest == "current") l0 = Distance(c.Previous(a), c.Previous(b));
    if (rest == "original") l0 = Distance(c.Original(a), c.Original(b));
    if (rest == "mean") l0 = mean;
    if (rest == "length") l0 = length;
    c.Block("spring_rest_length", e.edge[i])[0] = rest == "zero" ? 0.0 : fraction * l0;
  }
}

// r = (‖a − b‖ − L0)/L with L = 1 (the input's mean edge length); L0 = 0:
// the zero-length spring (a − b)/L.
void AddSpring(TermContext& c, size_t i) {
  const int a = c.elements->Vertices(i)[0], b = c.elements->Vertices(i)[1];
  const double l0 = c.Block("spring_rest_length", c.elements->edge[i])[0];
  AddSpringResidual(c, l0, 1.0, c.Position(a), c.Position(b));
}

}  // namespace

const TermSpec& spring() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "spring";
    t.summary = "edge springs: each edge towards a rest length (mean, current, original, a "
                "length, or zero: a zero-length spring)";
    t.paper = "[Gebreiter 2012, §10.1 constrained force equalisation, §11.2.2, §11.7.1]";
    t.elements = "edges";
    t.element_choices = {"boundary_edges", "interior_edges"};
    t.declares = {{"spring_rest_length", Site::kEdge, 1, FrameMap::kLength, false,
                   Carry::kReinitialise, false, true,
                   "rest length of an edge's spring this round (spring)"}};
    t.options = {
        ChoiceKey("rest", "mean", {"mean", "current", "original", "length", "zero"},
                  "rest length: the mean length of the selected edges at the start of each "
                  "round (even spacing), each edge's length then (current: with fraction < 1 a "
                  "contraction), at the start of the solve (original), `length`, or zero"),
        NumberKey("fraction", 1, 0, 1e6,
                  "multiplies the rest length (mean, current, original, length)"),
        NumberKey("length", 0, 0, kMaxCoordinate, "rest length for rest: length (file units)")};
    t.begin = &BeginSpring;
    t.add = &AddSpring;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::ZeroLengthSpring)
ARCHGEO_AUTODIFF(archgeo::Spring)
