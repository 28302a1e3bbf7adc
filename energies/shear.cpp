// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/shear.h"

#include <cmath>

#include <Eigen/Core>
#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

Shear CheckedShear(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "Shear: inv_length must be finite and > 0, got " << inv_length;
  return Shear(inv_length);
}

}  // namespace archgeo

// --- term `shear` --------------------------------------------------------------

namespace archgeo::terms {
namespace {

// L = the quad's mean diagonal length at the start of the solve.
void AddShear(TermContext& c, size_t i) {
  const int* q = c.elements->Vertices(i);
  using V = Eigen::Map<const Eigen::Vector3d>;
  const double d0 = (V(c.Original(q[2])) - V(c.Original(q[0]))).norm();
  const double d1 = (V(c.Original(q[3])) - V(c.Original(q[1]))).norm();
  if (!(d0 + d1 > 0)) return;  // a collapsed quad has no diagonal to compare
  AddAutoDiff(c, CheckedShear(2.0 / (d0 + d1)), {c.Position(q[0]), c.Position(q[1]), c.Position(q[2]), c.Position(q[3])});
}

}  // namespace

const TermSpec& shear() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "shear";
    t.summary = "quad shear: the two diagonals of each quad equally long";
    t.paper = "[Gebreiter 2012, §10.1 springs along quad diagonals, §11.7.1 shear forces]";
    t.elements = "quads";
    t.add = &AddShear;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::Shear)
