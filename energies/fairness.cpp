// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/fairness.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

namespace {


void CheckFairness(const char* name, const double target[3], double inv_length) {
  CHECK(target != nullptr);
  CHECK(std::isfinite(target[0]) && std::isfinite(target[1]) &&
        std::isfinite(target[2]))
      << name << ": non-finite target";
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << name << ": inv_length must be finite and > 0, got " << inv_length;
}

Fairness CheckedFairness(const double target[3], double inv_length) {
  CheckFairness("Fairness", target, inv_length);
  return Fairness(target, inv_length);
}

FairnessThird CheckedFairnessThird(const double target[3], double inv_length) {
  CheckFairness("FairnessThird", target, inv_length);
  return FairnessThird(target, inv_length);
}

}  // namespace

}  // namespace archgeo

// --- term `fairness` -----------------------------------------------------------

namespace archgeo::terms {
namespace {

// Target Δ⁰ of a tuple: the differences of the positions at the start of the
// solve (relative_to_original), the normal part of the previous round's
// (normal_part: free; triples only), or 0.
void AddFairness(TermContext& c, size_t i) {
  const int* t = c.elements->Vertices(i);
  const int k = c.elements->Count(i);
  double target[3] = {0, 0, 0};
  if (c.Bool("relative_to_original")) {
    for (int a = 0; a < 3; ++a) {
      const auto o = [&](int j) { return c.Original(t[j])[a]; };
      target[a] = k == 3 ? o(0) - 2 * o(1) + o(2) : o(3) - 3 * o(2) + 3 * o(1) - o(0);
    }
  } else if (k == 3 && c.String("normal_part") == "free") {
    const double* n = c.VertexNormal(t[1]);
    const double* u = c.Previous(t[0]);
    const double* v = c.Previous(t[1]);
    const double* x = c.Previous(t[2]);
    double dn = 0;
    for (int a = 0; a < 3; ++a) dn += n[a] * (u[a] - 2 * v[a] + x[a]);
    for (int a = 0; a < 3; ++a) target[a] = dn * n[a];
  }
  if (k == 3) {
    AddAutoDiff(c, CheckedFairness(target, 1.0),
                                {c.Position(t[0]), c.Position(t[1]), c.Position(t[2])});
  } else {
    AddAutoDiff(c, CheckedFairnessThird(target, 1.0),
        {c.Position(t[0]), c.Position(t[1]), c.Position(t[2]), c.Position(t[3])});
  }
}

}  // namespace

const TermSpec& fairness() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "fairness";
    t.summary =
        "second (triples) or third (quadruples) differences of positions along mesh lines";
    t.paper = "[Zadravec 2010, eq. 8, f_fair; Shi 2014, §3.2; Pellis 2019, §5.3 umbrella]";
    t.elements = "polyline_triples";
    t.element_choices = {"polyline_quadruples", "straight_triples", "umbrella_triples"};
    t.options = {
        BoolKey("relative_to_original", false,
                "keep the input's differences (else differences towards 0)"),
        ChoiceKey("normal_part", "penalised", {"penalised", "free"},
                  "free: only the tangential part of a triple's second difference is "
                  "penalised (its normal part is kept from the previous round)")};
    t.add = &AddFairness;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::Fairness)
ARCHGEO_AUTODIFF(archgeo::FairnessThird)
