// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/co_spherical.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

CoSpherical CheckedCoSpherical(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "CoSpherical: inv_length must be finite and > 0, got " << inv_length;
  return CoSpherical(inv_length);
}

namespace terms {
namespace {

// Element (principal_stars): (v, p0, p1, o0, o1, o2, o3), the principal
// neighbours p and the four others o; v's sphere is (sphere_normal,
// sphere_curvature).
void AddCoSpherical(TermContext& c, size_t i) {
  const int* s = c.elements->Vertices(i);
  for (int k = 3; k < 7; ++k) {
    AddAutoDiff(c, CheckedCoSpherical(1.0), {c.Position(s[0]), c.Block("sphere_normal", s[0]),
                                 c.Block("sphere_curvature", s[0]), c.Position(s[k])});
  }
}

void UnitVertexSphereNormals(TermContext& c) {
  for (size_t i = 0; i < c.elements->size(); ++i) {
    c.SetUnit(c.Block("sphere_normal", c.elements->Vertices(i)[0]));
  }
}

}  // namespace

const TermSpec& co_spherical() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "co_spherical";
    t.summary = "principal-symmetric stars: the four non-principal neighbours on the vertex sphere";
    t.paper = "[Pellis 2019, §2.3, §5.2]";
    t.elements = "principal_stars";
    t.group = "principal_stars";
    t.reads = {"sphere_normal", "sphere_curvature"};
    t.add = &AddCoSpherical;
    t.finish = &UnitVertexSphereNormals;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::CoSpherical)
