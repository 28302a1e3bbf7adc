// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/boundary_proximity.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

BoundaryProximity CheckedBoundaryProximity(const double point[3],
                                           const double tangent[3],
                                           double inv_length) {
  CHECK(point != nullptr && tangent != nullptr);
  for (int i = 0; i < 3; ++i) {
    CHECK(std::isfinite(point[i]) && std::isfinite(tangent[i]))
        << "BoundaryProximity: non-finite point or tangent";
  }
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "BoundaryProximity: inv_length must be finite and > 0, got "
      << inv_length;
  return BoundaryProximity(point, tangent, inv_length);
}

}  // namespace archgeo

// --- term `boundary_proximity` -------------------------------------------------

namespace archgeo::terms {
namespace {

void AddBoundaryProximity(TermContext& c, size_t i) {
  const int v = c.elements->Vertices(i)[0];
  if (!c.OnBoundaryCurve(v)) return;
  AddAutoDiff(c, CheckedBoundaryProximity(c.ProjectedPoint(v), c.ProjectedDirection(v), 1.0), {c.Position(v)});
}

}  // namespace

const TermSpec& boundary_proximity() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "boundary_proximity";
    t.summary =
        "boundary vertices: distance to the tangent line of the reference's boundary at the "
        "closest point (when the reference has a boundary)";
    t.paper = "[Zadravec 2010, §6, f∂_prox]";
    t.elements = "vertices";
    t.group = "proximity";
    t.needs_projection = true;
    t.add = &AddBoundaryProximity;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::BoundaryProximity)
