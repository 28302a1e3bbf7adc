// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/direction_dirichlet.h"

#include <cmath>

#include "core/term.h"
#include "core/newell.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

DirectionDirichlet CheckedDirectionDirichlet() {
  return DirectionDirichlet();
}

namespace terms {
namespace {

// Element (interior_edges): the edge's left face (`face`) and right face
// (`other_face`).
void AddDirectionDirichlet(TermContext& c, size_t i) {
  double* f = c.Block("face_direction", c.elements->face[i]);
  double* g = c.Block("face_direction", c.elements->other_face[i]);
  AddAutoDiff(c, CheckedDirectionDirichlet(), {f, g});
  c.SetUnit(f);
  c.SetUnit(g);
}

// Starts each face at its unit normal (Newell), where not set already.
void InitDirections(TermContext& c) {
  const ElementSet& faces = c.Elements("faces");
  for (size_t f = 0; f < faces.size(); ++f) {
    double* d = c.Block("face_direction", int(f));
    if (d[0] != 0 || d[1] != 0 || d[2] != 0) continue;
    const int* vs = faces.Vertices(f);
    const int k = faces.Count(f);
    const Eigen::Vector3d n = NewellNormal(k, [&](int j) { return c.Position(vs[j]); });
    const bool degenerate = n.norm() == 0;
    for (int a = 0; a < 3; ++a) d[a] = degenerate ? (a == 2 ? 1.0 : 0.0) : n[a];
  }
}

}  // namespace

const TermSpec& direction_dirichlet() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "direction_dirichlet";
    t.summary = "smoothness of a per-face unit direction field (Dirichlet energy)";
    t.paper = "[Knöppel et al. 2013, §4]";
    t.elements = "interior_edges";
    t.declares = {{"face_direction", Site::kFace, 3, FrameMap::kDirection, true,
                   Carry::kReinitialise, true, false, "a unit direction per face"}};
    t.init = &InitDirections;
    t.add = &AddDirectionDirichlet;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::DirectionDirichlet)
