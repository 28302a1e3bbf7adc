// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/level_set_normalised.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/level_set_elements.h"

namespace archgeo {

LevelSetNormalised CheckedLevelSetNormalised(const double corners[6], const double v[2],
                                            double inv_total_area, double gradient_scale) {
  CHECK(corners != nullptr && v != nullptr);
  for (int i = 0; i < 6; ++i) CHECK(std::isfinite(corners[i])) << "LevelSetNormalised: corners";
  CHECK(std::isfinite(v[0]) && std::isfinite(v[1]) && (v[0] != 0.0 || v[1] != 0.0))
      << "LevelSetNormalised: v must be finite and nonzero";
  CHECK(std::isfinite(inv_total_area) && inv_total_area > 0.0)
      << "LevelSetNormalised: inv_total_area must be finite and > 0";
  CHECK(std::isfinite(gradient_scale) && gradient_scale > 0.0)
      << "LevelSetNormalised: gradient_scale must be finite and > 0";
  CHECK(TriangleGradient(corners).area > 0.0)
      << "LevelSetNormalised: corners must be counter-clockwise with positive area";
  return LevelSetNormalised(corners, v, inv_total_area, gradient_scale);
}

namespace terms {
namespace {

namespace ld = level_set_data;

// Element (level_set_faces): eq. 6 for g with v and for h with w (nothing
// where the field is undefined).
void AddLevelSetNormalised(TermContext& c, size_t i) {
  const double* d = c.elements->Data(i);
  const int k[3] = {int(d[ld::kWedges]), int(d[ld::kWedges + 1]), int(d[ld::kWedges + 2])};
  const double scale = c.Number("gradient_scale");
  for (const auto& [block, v] : {std::make_pair("level_set_g", d + ld::kV),
                                 std::make_pair("level_set_h", d + ld::kW)}) {
    if (v[0] == 0.0 && v[1] == 0.0) continue;
    AddAutoDiff(c, CheckedLevelSetNormalised(d + ld::kCorners, v, d[ld::kInvArea], scale), {c.Block(block, k[0]), c.Block(block, k[1]), c.Block(block, k[2])});
  }
}

}  // namespace

const TermSpec& level_set_normalised() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "level_set_normalised";
    t.summary = "level sets along the field, spacing free: Σ A_f/A_Φ ‖∇g/‖∇g‖ − R v̂‖² (eq. 6)";
    t.paper = "[Zadravec 2010, §5, eq. 6]";
    t.elements = "level_set_faces";
    t.reads = {"level_set_g", "level_set_h"};
    t.options = {NumberKey("gradient_scale", 1.0, 1e-9, 1e9,
                           "expected ‖∇g‖ (unit-free; 1 after eq. 5 with unit v): the "
                           "regularisation ε of ‖∇g‖ is 1e-6 times this")};
    t.add = &AddLevelSetNormalised;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::LevelSetNormalised)
