// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/smoothed_dihedral_energy.h"

#include "core/term.h"
#include "energies/autodiff_impl.h"

// --- term `smoothed_dihedral_energy` ------------------------------------------

namespace archgeo {
namespace terms {
namespace {

// The smoothed residual's hinge functors, ε as their parameter.
constexpr HingeAdders kSmoothedDihedralAdders = {
    "smoothed_dihedral_energy", "epsilon",
    &AddHingeResidual<SmoothedDihedralTriTri>,
    &AddHingeResidual<SmoothedDihedralTriPoly>,
    &AddHingeResidual<SmoothedDihedralPolyPoly>};

// Edge v→w with left face (v, w, a, …) and right face (w, v, b, …).
void AddSmoothedDihedral(TermContext& c, size_t i) {
  AddHinge(c, i, kSmoothedDihedralAdders, c.Number("epsilon"));
}

}  // namespace

const TermSpec& smoothed_dihedral_energy() {
  static const TermSpec spec = [] {
    TermSpec t = HingeTermSpec();
    t.name = "smoothed_dihedral_energy";
    t.summary = "visual smoothness: E_ε = Σ ℓ sqrt(ℓ*² + ε²), E = Σ ℓ ℓ* rounded at flat edges, "
                "minimised directly (no IRLS rounds)";
    t.options = {NumberKey("epsilon", kSmoothedDihedralEpsilon, 1e-9, 1,
                           "ε: |ℓ*| is rounded to sqrt(ℓ*² + ε²) (unit-free, about the "
                           "dihedral angle in radians below which an edge counts as flat)")};
    t.add = &AddSmoothedDihedral;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::SmoothedDihedralTriTri)
ARCHGEO_AUTODIFF(archgeo::SmoothedDihedralTriPoly)
ARCHGEO_AUTODIFF(archgeo::SmoothedDihedralPolyPoly)
