// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/level_set_conjugacy.h"

#include <cmath>
#include <vector>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

#include "core/term.h"
#include "energies/level_set_elements.h"

namespace archgeo {

ceres::CostFunction* MakeLevelSetConjugacy(const double corners[6], const double m[3],
                                           double gradient_scale) {
  CHECK(corners != nullptr && m != nullptr);
  for (int i = 0; i < 6; ++i) CHECK(std::isfinite(corners[i])) << "MakeLevelSetConjugacy: corners";
  CHECK(std::isfinite(m[0]) && std::isfinite(m[1]) && std::isfinite(m[2]))
      << "MakeLevelSetConjugacy: non-finite M";
  CHECK(std::isfinite(gradient_scale) && gradient_scale > 0.0)
      << "MakeLevelSetConjugacy: gradient_scale must be finite and > 0";
  CHECK(TriangleGradient(corners).area > 0.0)
      << "MakeLevelSetConjugacy: corners must be counter-clockwise with positive area";
  return new ceres::AutoDiffCostFunction<LevelSetConjugacy, 1, 1, 1, 1, 1, 1, 1>(
      new LevelSetConjugacy(corners, m, gradient_scale));
}


namespace terms {
namespace {

namespace ld = level_set_data;

// Element (level_set_faces): eq. 7 for the pair (g, h); nothing where M_f = 0
// (every pair of directions is conjugate there).
void AddLevelSetConjugacy(TermContext& c, size_t i) {
  const double* d = c.elements->Data(i);
  const double* m = d + ld::kM;
  if (m[0] == 0.0 && m[1] == 0.0 && m[2] == 0.0) return;
  std::vector<double*> blocks;
  for (const char* block : {"level_set_g", "level_set_h"}) {
    for (int k = 0; k < 3; ++k) blocks.push_back(c.Block(block, int(d[ld::kWedges + k])));
  }
  c.Add(MakeLevelSetConjugacy(d + ld::kCorners, m, c.Number("gradient_scale")), blocks);
}

}  // namespace

const TermSpec& level_set_conjugacy() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "level_set_conjugacy";
    t.summary = "level sets of g and h conjugate: Σ A_f ((R∇g/‖∇g‖)ᵀ M_f (R∇h/‖∇h‖))² (eq. 7)";
    t.paper = "[Zadravec 2010, §5, eq. 7]";
    t.elements = "level_set_faces";
    t.reads = {"level_set_g", "level_set_h"};
    t.options = {NumberKey("gradient_scale", 1.0, 1e-9, 1e9,
                           "expected ‖∇g‖, ‖∇h‖ (unit-free): the regularisation ε is 1e-6 "
                           "times this")};
    t.add = &AddLevelSetConjugacy;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo
