// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/pq_diagonal.h"

#include <cmath>

#include <Eigen/Core>
#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

namespace {


PqDiagonal CheckedPqDiagonal(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "PqDiagonal: inv_length must be finite and > 0, got " << inv_length;
  return PqDiagonal(inv_length);
}

}  // namespace

}  // namespace archgeo

// --- term `pq_diagonal` --------------------------------------------------------

namespace archgeo::terms {
namespace {

// L = the quad's mean diagonal length at the start of the solve.
void AddPqDiagonal(TermContext& c, size_t i) {
  const int* q = c.elements->Vertices(i);
  using V = Eigen::Map<const Eigen::Vector3d>;
  const double d0 = (V(c.Original(q[2])) - V(c.Original(q[0]))).norm();
  const double d1 = (V(c.Original(q[3])) - V(c.Original(q[1]))).norm();
  AddAutoDiff(c, CheckedPqDiagonal(2.0 / (d0 + d1)),
                                {c.Position(q[0]), c.Position(q[1]), c.Position(q[2]), c.Position(q[3])},
                                c.band);
}

}  // namespace

const TermSpec& pq_diagonal() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "pq_diagonal";
    t.summary = "quad planarity: distance between the diagonals over the mean diagonal";
    t.paper = "[Zadravec 2010, §6, eq. 8, f_PQ; Shi 2014, §3.2, F_quad]";
    t.elements = "quads";
    t.supports_band = true;
    t.drives = "pq_normalized_max";
    t.add = &AddPqDiagonal;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::PqDiagonal)
