// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/proximity.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/anchor.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

Proximity CheckedProximity(const double point[3], const double normal[3], double inv_length) {
  CHECK(point != nullptr && normal != nullptr);
  for (int i = 0; i < 3; ++i) {
    CHECK(std::isfinite(point[i]) && std::isfinite(normal[i]))
        << "Proximity: non-finite point or normal";
  }
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "Proximity: inv_length must be finite and > 0, got " << inv_length;
  return Proximity(point, normal, inv_length);
}

}  // namespace archgeo

// --- term `proximity` ----------------------------------------------------------

namespace archgeo::terms {
namespace {

// Interior vertices (and boundary vertices not sent to the reference's
// boundary curve): the tangent-plane distance; every vertex: the distance to
// the closest point itself with `point_weight`.
void AddProximity(TermContext& c, size_t i) {
  const int v = c.elements->Vertices(i)[0];
  if (!c.OnBoundaryCurve(v)) {
    AddAutoDiff(c, CheckedProximity(c.ProjectedPoint(v), c.ProjectedDirection(v), 1.0),
                {c.Position(v)});
  }
  const double point_weight = c.Number("point_weight");
  if (point_weight > 0) {
    AddAutoDiff(c, CheckedAnchor(c.ProjectedPoint(v), 1.0), {c.Position(v)}, -1,
                "proximity_point", point_weight);
  }
}

}  // namespace

const TermSpec& proximity() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "proximity";
    t.summary =
        "distance to the reference's tangent plane at the closest point (+ point_weight × "
        "distance to that point), re-projected every round";
    t.paper = "[Zadravec 2010, §6, f_prox; Shi 2014, §3.2, F_prox]";
    t.elements = "vertices";
    t.group = "proximity";
    t.needs_projection = true;
    t.parts = {"proximity_point"};
    t.options = {NumberKey("point_weight", 0.0, 0, 1e12,
                           "weight of the distance to the closest point itself")};
    t.add = &AddProximity;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::Proximity)
