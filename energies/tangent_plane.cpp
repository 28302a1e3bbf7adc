// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/tangent_plane.h"

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/proximity.h"

namespace archgeo {


namespace terms {
namespace {

// Element: the vertex; its data: the plane's point and unit normal.
void AddTangentPlane(TermContext& c, size_t i) {
  const int v = c.elements->Vertices(i)[0];
  const double* plane = c.elements->Data(i);
  AddAutoDiff(c, CheckedProximity(plane, plane + 3, 1.0), {c.Position(v)});
}

}  // namespace

const TermSpec& tangent_plane() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "tangent_plane";
    t.summary = "keep vertices on prescribed planes (the input's boundary tangent planes)";
    t.paper = "[Pellis 2019, §4, Fig. 15]";
    t.elements = "tangent_planes";
    t.add = &AddTangentPlane;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo
