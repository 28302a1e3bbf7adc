// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/pq_worst.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo::terms {
namespace {

using V = Eigen::Map<const Eigen::Vector3d>;

// 1/L, L the quad's mean diagonal length at the start of the solve (as pq_diagonal).
double InverseLength(TermContext& c, const int* q) {
  const double d0 = (V(c.Original(q[2])) - V(c.Original(q[0]))).norm();
  const double d1 = (V(c.Original(q[3])) - V(c.Original(q[1]))).norm();
  const double inv_length = 2.0 / (d0 + d1);
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "pq_worst: a quad with no diagonal length, 1/L = " << inv_length;
  return inv_length;
}

// |pq_diagonal's residual| of quad q at the start of the round.
double StartResidual(TermContext& c, const int* q) {
  const PqDiagonal f(InverseLength(c, q));
  double r = 0;
  f(c.Previous(q[0]), c.Previous(q[1]), c.Previous(q[2]), c.Previous(q[3]), &r);
  return std::abs(r);
}

// 1 / the worst selected quad's residual at the start of the round, into
// every selected face's pq_worst_scale (1 when every quad is planar).
void BeginPqWorst(TermContext& c) {
  const ElementSet& e = *c.elements;
  double worst = 0;
  for (size_t i = 0; i < e.size(); ++i) worst = std::max(worst, StartResidual(c, e.Vertices(i)));
  for (size_t i = 0; i < e.size(); ++i) {
    c.Block("pq_worst_scale", e.face[i])[0] = worst > 0 ? 1.0 / worst : 1.0;
  }
}

void AddPqWorst(TermContext& c, size_t i) {
  const int* q = c.elements->Vertices(i);
  const double scale = c.Block("pq_worst_scale", c.elements->face[i])[0];
  AddAutoDiff(c, PqWorst(InverseLength(c, q), scale, c.Number("power")),
              {c.Position(q[0]), c.Position(q[1]), c.Position(q[2]), c.Position(q[3])});
}

}  // namespace

const TermSpec& pq_worst() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "pq_worst";
    t.summary = "the worst quads' planarity: the p-norm of δ_PQ,n relative to the round's "
                "worst quad (approaches the maximum)";
    t.paper = "[Zadravec 2010, §6, eq. 8, f_PQ, as a p-norm]";
    t.elements = "quads";
    t.drives = "pq_normalized_max";
    t.declares = {{"pq_worst_scale", Site::kFace, 1, FrameMap::kInvariant, false,
                   Carry::kReinitialise, false, true,
                   "1 / the worst quad's pq_diagonal residual at the start of the round"}};
    t.options = {NumberKey("power", 16, 2, 64,
                           "p of the p-norm: 2 weighs every quad alike (pq_diagonal's sum, "
                           "relative to the worst quad), larger p the worst quads more")};
    t.begin = &BeginPqWorst;
    t.add = &AddPqWorst;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::PqWorst)
