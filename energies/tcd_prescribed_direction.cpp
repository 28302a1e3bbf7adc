// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/tcd_prescribed_direction.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

TcdPrescribedDirection CheckedTcdPrescribedDirection(const double m[3], const double direction[2]) {
  CHECK(m != nullptr && direction != nullptr);
  CHECK(std::isfinite(m[0]) && std::isfinite(m[1]) && std::isfinite(m[2]))
      << "TcdPrescribedDirection: non-finite M";
  CHECK(std::isfinite(direction[0]) && std::isfinite(direction[1]))
      << "TcdPrescribedDirection: non-finite direction";
  Eigen::Vector2d point, line;
  CHECK(TcdPrescribedLine(m, direction, &point, &line))
      << "TcdPrescribedDirection: every direction is conjugate to the prescribed one "
         "(M d = 0) or d = 0; check with TcdPrescribedLine first";
  return TcdPrescribedDirection(point, line);
}

namespace terms {
namespace {

// Element (tcd_prescribed): a face with a prescribed direction (`face`);
// data: m11, m12, m22 of M_f, the direction (2) in the face frame, a factor
// on the term's weight (e.g. lower for boundary tangents than for a user's
// directions); the problem only lists faces where TcdPrescribedLine succeeds.
void AddTcdPrescribedDirection(TermContext& c, size_t i) {
  const double* d = c.elements->Data(i);
  if (d[5] <= 0.0) return;
  AddAutoDiff(c, CheckedTcdPrescribedDirection(d, d + 3), {c.Block("z_n", c.elements->face[i])}, -1, nullptr, c.weight * d[5]);
}

}  // namespace

const TermSpec& tcd_prescribed_direction() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "tcd_prescribed_direction";
    t.summary = "a prescribed conjugate direction in chosen faces (distance of z_N from its line)";
    t.paper = "[Zadravec 2010, §4, Prop. 2]";
    t.elements = "tcd_prescribed";
    t.reads = {"z_n"};
    t.add = &AddTcdPrescribedDirection;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::TcdPrescribedDirection)
