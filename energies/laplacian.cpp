// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/laplacian.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {
namespace {


}  // namespace

Laplacian CheckedLaplacian(const std::vector<double>& weights, double inv_length) {
  CHECK_GE(weights.size(), 1u) << "Laplacian: no neighbour";
  double sum = 0.0;
  for (double c : weights) {
    CHECK(std::isfinite(c)) << "Laplacian: non-finite weight";
    sum += c;
  }
  CHECK(sum > 0.0) << "Laplacian: the weights must have a "
                      "positive sum, got "
                   << sum;
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "Laplacian: inv_length must be finite and > 0, got "
      << inv_length;
  return Laplacian(weights, inv_length);
}

}  // namespace archgeo

// --- term `laplacian` ----------------------------------------------------------

namespace archgeo::terms {
namespace {

// (v; w_1 … w_n): r = (barycentre of the w_j − v)/L, L = 1; free v only.
void AddLaplacian(TermContext& c, size_t i) {
  const int* s = c.elements->Vertices(i);
  const int n = c.elements->Count(i) - 1;
  if (n < 1 || c.Fixed(s[0])) return;  // a support's umbrella is a reaction, not a condition
  std::vector<double*> blocks;
  for (int j = 0; j <= n; ++j) blocks.push_back(c.Position(s[j]));
  c.Add(MakeStarAutoDiff(CheckedLaplacian(std::vector<double>(n, 1.0), 1.0)), blocks);
}

}  // namespace

const TermSpec& laplacian() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "laplacian";
    t.summary = "Laplacian smoothing: each vertex towards the barycentre of its neighbours "
                "(select: interior keeps the boundary from shrinking)";
    t.paper = "[Gebreiter 2012, §10.1, §11.2.2; Taubin 1995 umbrella operator]";
    t.elements = "one_rings";
    t.element_choices = {"fans", "stars"};
    t.add = &AddLaplacian;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_STAR_AUTODIFF(archgeo::Laplacian)
