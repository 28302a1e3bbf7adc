// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/boundary_proximity.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeBoundaryProximity(const double point[3],
                                           const double tangent[3],
                                           double inv_length) {
  CHECK(point != nullptr && tangent != nullptr);
  for (int i = 0; i < 3; ++i) {
    CHECK(std::isfinite(point[i]) && std::isfinite(tangent[i]))
        << "MakeBoundaryProximity: non-finite point or tangent";
  }
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeBoundaryProximity: inv_length must be finite and > 0, got "
      << inv_length;
  return new ceres::AutoDiffCostFunction<BoundaryProximity, 3, 3>(
      new BoundaryProximity(point, tangent, inv_length));
}

}  // namespace archgeo

// --- term `boundary_proximity` -------------------------------------------------
#include "core/term.h"

namespace archgeo::terms {
namespace {

void AddBoundaryProximity(TermContext& c, size_t i) {
  const int v = c.elements->Vertices(i)[0];
  if (!c.OnBoundaryCurve(v)) return;
  c.Add(MakeBoundaryProximity(c.ProjectedPoint(v), c.ProjectedDirection(v), 1.0),
        {c.Position(v)});
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
