// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/level_set_alignment.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/level_set_elements.h"

namespace archgeo {

LevelSetAlignment CheckedLevelSetAlignment(const double corners[6], const double v[2],
                                           double inv_total_area) {
  CHECK(corners != nullptr && v != nullptr);
  for (int i = 0; i < 6; ++i) CHECK(std::isfinite(corners[i])) << "LevelSetAlignment: corners";
  CHECK(std::isfinite(v[0]) && std::isfinite(v[1])) << "LevelSetAlignment: non-finite v";
  CHECK(std::isfinite(inv_total_area) && inv_total_area > 0.0)
      << "LevelSetAlignment: inv_total_area must be finite and > 0";
  CHECK(TriangleGradient(corners).area > 0.0)
      << "LevelSetAlignment: corners must be counter-clockwise with positive area";
  return LevelSetAlignment(corners, v, inv_total_area);
}

namespace terms {
namespace {

namespace ld = level_set_data;

// Element (level_set_faces, energies/level_set_elements.h): eq. 5 for g with
// v and for h with w; where the field is undefined (v = 0) the residual is
// the Dirichlet energy of the function (λ_even).
void AddLevelSetAlignment(TermContext& c, size_t i) {
  const double* d = c.elements->Data(i);
  const int k[3] = {int(d[ld::kWedges]), int(d[ld::kWedges + 1]), int(d[ld::kWedges + 2])};
  for (const auto& [block, v] : {std::make_pair("level_set_g", d + ld::kV),
                                 std::make_pair("level_set_h", d + ld::kW)}) {
    AddAutoDiff(c, CheckedLevelSetAlignment(d + ld::kCorners, v, d[ld::kInvArea]), {c.Block(block, k[0]), c.Block(block, k[1]), c.Block(block, k[2])});
  }
}

}  // namespace

const TermSpec& level_set_alignment() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "level_set_alignment";
    t.summary = "level sets along the field with even spacing: Σ A_f/A_Φ ‖R v − ∇g‖² (eq. 5)";
    t.paper = "[Zadravec 2010, §5, eq. 5]";
    t.elements = "level_set_faces";
    t.reads = {"level_set_g", "level_set_h"};
    t.add = &AddLevelSetAlignment;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::LevelSetAlignment)
