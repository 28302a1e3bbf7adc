// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/frame_coplanarity.h"

#include <cmath>

#include <Eigen/Core>
#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

FrameCoplanarity CheckedFrameCoplanarity(double w1, double w2, double w4,
                                          double w5, double inv_length) {
  for (double w : {w1, w2, w4, w5}) {
    CHECK(std::isfinite(w) && w > 0.0)
        << "FrameCoplanarity: weights must be finite and > 0, got " << w;
  }
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "FrameCoplanarity: inv_length must be finite and > 0, got "
      << inv_length;
  return FrameCoplanarity(w1, w2, w4, w5, inv_length);
}

}  // namespace archgeo

// --- term `frame_coplanarity` --------------------------------------------------

namespace archgeo::terms {
namespace {

// Patches with a shape parameter outside (kShapeMin, 1/kShapeMin) are nearly
// degenerate (their frame points sit on their corners): no term there.
constexpr double kShapeMin = 1e-3;

using V = Eigen::Map<const Eigen::Vector3d>;

// Element: b0 … b5 (Shi Fig. 2) of an interior edge; the block
// "frame_weights" of the edge holds (W_l, W_r), the shape parameters of the
// left patch for its diagonal b0b2 and of the right patch for b0b4 (NaN: no
// smooth join exists across this edge). L: the mean of |b3 − b0| and
// |f4 − f1| at the start of the round.
void AddFrame(TermContext& c, size_t i) {
  const int* b = c.elements->Vertices(i);
  const double* W = c.Block("frame_weights", c.elements->edge[i]);
  const double wl = W[0], wr = W[1];
  if (!(wl > kShapeMin && wl < 1 / kShapeMin) || !(wr > kShapeMin && wr < 1 / kShapeMin)) return;
  const Eigen::Vector3d f1 = (V(c.Position(b[1])) + wl * V(c.Position(b[2]))) / (1 + wl);
  const Eigen::Vector3d f4 = (wr * V(c.Position(b[4])) + V(c.Position(b[5]))) / (1 + wr);
  const double length = 0.5 * ((V(c.Position(b[3])) - V(c.Position(b[0]))).norm() + (f4 - f1).norm());
  if (!(length > 0)) return;
  AddAutoDiff(c, CheckedFrameCoplanarity(1.0, wl, wr, 1.0, 1.0 / length), {c.Position(b[0]), c.Position(b[1]), c.Position(b[2]), c.Position(b[3]),
         c.Position(b[4]), c.Position(b[5])});
}

}  // namespace

const TermSpec& frame_coplanarity() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "frame_coplanarity";
    t.summary =
        "H-nets: frame points of the two patches at an edge coplanar with the edge (smooth "
        "join), with the shape parameters of the net's H-net extension fixed";
    t.paper = "[Shi 2014, §3.2 step 3, eqs. 5–6]";
    t.elements = "edge_quads";
    t.reads = {"frame_weights"};
    t.add = &AddFrame;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::FrameCoplanarity)
