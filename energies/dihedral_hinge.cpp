// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/dihedral_hinge.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"

namespace archgeo {

void CheckHingeConstants(const char* name, double inv_length,
                         const char* parameter, double value) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << name << ": inv_length must be finite and > 0, got " << inv_length;
  CHECK(std::isfinite(value) && value > 0.0)
      << name << ": " << parameter << " must be finite and > 0, got " << value;
}

}  // namespace archgeo

// --- the builder of the hinge terms (dihedral_energy, smoothed_dihedral_energy)

namespace archgeo {
namespace terms {
void InitFacePlaneNormal(TermContext& c, int face, const int* vs, int count);

namespace {

void InitPolygonNormals(TermContext& c) {
  const ElementSet& faces = c.Elements("faces");
  for (size_t i = 0; i < c.elements->size(); ++i) {
    for (int f : {c.elements->face[i], c.elements->other_face[i]}) {
      if (faces.Count(f) > 3) terms::InitFacePlaneNormal(c, f, faces.Vertices(f), faces.Count(f));
    }
  }
}

// Unit normals of the polygons an edge term used.
void UnitFacePlaneNormals(TermContext& c) {
  const ElementSet& faces = c.Elements("faces");
  for (size_t f = 0; f < faces.size(); ++f) {
    if (faces.Count(f) > 3) c.SetUnit(c.Block("face_plane_normal", int(f)));
  }
}

}  // namespace

// Edge v→w with left face (v, w, a, …) and right face (w, v, b, …).
void AddHinge(TermContext& c, size_t i, const HingeAdders& add, double parameter) {
  CheckHingeConstants(add.term, 1.0, add.parameter, parameter);
  const ElementSet& e = *c.elements;
  const int* vs = e.Vertices(i);
  const int v = vs[0], w = vs[1], a = vs[2], b = vs[3];
  const int left = e.face[i], right = e.other_face[i];
  const bool poly_l = e.Has(i, kLeftPolygon), poly_r = e.Has(i, kRightPolygon);
  if (!poly_l && !poly_r) {
    add.tri_tri(c, 1.0, parameter, {c.Position(v), c.Position(w), c.Position(a), c.Position(b)});
  } else if (!poly_l && poly_r) {
    add.tri_poly(c, 1.0, parameter,
                 {c.Position(v), c.Position(w), c.Position(a), c.Block("face_plane_normal", right)});
  } else if (poly_l && !poly_r) {
    // The triangle (w, v, b) is on the left of w→v.
    add.tri_poly(c, 1.0, parameter,
                 {c.Position(w), c.Position(v), c.Position(b), c.Block("face_plane_normal", left)});
  } else {
    add.poly_poly(c, 1.0, parameter,
                  {c.Position(v), c.Position(w), c.Block("face_plane_normal", left),
                   c.Block("face_plane_normal", right)});
  }
}

TermSpec HingeTermSpec() {
  TermSpec t;
  t.paper = "[Pellis 2019, §3, §5.1]";
  t.elements = "interior_edges";
  t.declares = {{"face_plane_normal", Site::kFace, 3, FrameMap::kDirection, true,
                 Carry::kReinitialise, false, false,
                 "unit normal of a face's plane (face_planarity, dihedral_energy)"}};
  t.init = &InitPolygonNormals;
  t.finish = &UnitFacePlaneNormals;
  return t;
}

}  // namespace terms
}  // namespace archgeo
