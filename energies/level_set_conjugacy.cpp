// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/level_set_conjugacy.h"

#include <cmath>
#include <vector>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/level_set_elements.h"

namespace archgeo {

LevelSetConjugacy CheckedLevelSetConjugacy(const double corners[6], const double m[3],
                                           double gradient_scale) {
  CHECK(corners != nullptr && m != nullptr);
  for (int i = 0; i < 6; ++i) CHECK(std::isfinite(corners[i])) << "LevelSetConjugacy: corners";
  CHECK(std::isfinite(m[0]) && std::isfinite(m[1]) && std::isfinite(m[2]))
      << "LevelSetConjugacy: non-finite M";
  CHECK(std::isfinite(gradient_scale) && gradient_scale > 0.0)
      << "LevelSetConjugacy: gradient_scale must be finite and > 0";
  CHECK(TriangleGradient(corners).area > 0.0)
      << "LevelSetConjugacy: corners must be counter-clockwise with positive area";
  return LevelSetConjugacy(corners, m, gradient_scale);
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
  BlocksOf<LevelSetConjugacy> blocks;
  for (int k = 0; k < 3; ++k) {
    blocks[k] = c.Block("level_set_g", int(d[ld::kWedges + k]));
    blocks[3 + k] = c.Block("level_set_h", int(d[ld::kWedges + k]));
  }
  AddAutoDiff(c, CheckedLevelSetConjugacy(d + ld::kCorners, m, c.Number("gradient_scale")), blocks);
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

ARCHGEO_AUTODIFF(archgeo::LevelSetConjugacy)
