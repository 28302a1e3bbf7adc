// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/min_edge_length.h"

#include <algorithm>
#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

namespace {


MinEdgeLength CheckedMinEdgeLength(double min_length) {
  CHECK(std::isfinite(min_length) && min_length > 0.0)
      << "MinEdgeLength: min_length must be finite and > 0, got " << min_length;
  return MinEdgeLength(min_length);
}

}  // namespace

}  // namespace archgeo

// --- term `min_edge_length` --------------------------------------------------------

namespace archgeo::terms {
namespace {

// One residual per side of each face (an interior edge is seen from both of
// its faces: the barrier only needs to be active, not weighted evenly).
void AddMinEdgeLength(TermContext& c, size_t i) {
  const int* vs = c.elements->Vertices(i);
  const int k = c.elements->Count(i);
  const double fraction = c.Number("fraction");
  const double floor = std::min(fraction, c.Number("floor"));
  for (int j = 0; j < k; ++j) {
    const int a = vs[j], b = vs[(j + 1) % k];
    const double* p = c.Original(a);
    const double* q = c.Original(b);
    const double length = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                    (p[2] - q[2]) * (p[2] - q[2]));
    if (!(length > 0)) continue;  // an edge the input already collapsed
    // The canonical frame's unit is the input's mean edge length.
    const double min_length = std::min(fraction, std::max(floor, 0.5 * length));
    AddAutoDiff(c, CheckedMinEdgeLength(min_length), {c.Position(a), c.Position(b)});
  }
}

}  // namespace

const TermSpec& min_edge_length() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "min_edge_length";
    t.summary = "barrier: no edge shrinks below a fraction of the mean edge length (or half its own)";
    t.paper = "[mesh validity; analysis/validity.h short_edges]";
    t.elements = "faces";
    t.element_choices = {"quads", "non_triangles", "polygons", "triangles"};
    t.options = {NumberKey("fraction", 0.2, 1e-3, 1.0,
                           "each edge is kept at least this fraction of the input's mean edge "
                           "length (or half its own input length, if that is shorter)"),
                 NumberKey("floor", 0, 0, 1.0,
                           "and at least this fraction, however short it starts (a net the "
                           "problem made has no edge of its own to inherit: the validity "
                           "check against the design surface flags every edge under 0.1)")};
    t.barrier = true;
    t.add = &AddMinEdgeLength;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::MinEdgeLength)
