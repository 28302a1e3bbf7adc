// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/principal_strip.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

PrincipalStrip CheckedPrincipalStrip(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "PrincipalStrip: inv_length must be finite and > 0, got " << inv_length;
  return PrincipalStrip(inv_length);
}

namespace terms {
namespace {

// Element (principal_strips): (v, w), a principal edge whose endpoints both
// carry spheres; its strip normal is the edge block "strip_normal".
void AddStrip(TermContext& c, size_t i) {
  const int* e = c.elements->Vertices(i);
  double* n_e = c.Block("strip_normal", c.elements->edge[i]);
  AddAutoDiff(c, CheckedPrincipalStrip(1.0), {n_e, c.Position(e[0]), c.Position(e[1]),
                                  c.Block("sphere_normal", e[0]), c.Block("sphere_normal", e[1])});
}

void StripNormals(TermContext& c) {
  for (size_t i = 0; i < c.elements->size(); ++i) {
    c.SetUnit(c.Block("strip_normal", c.elements->edge[i]));
    c.SetUnit(c.Block("sphere_normal", c.elements->Vertices(i)[0]));
    c.SetUnit(c.Block("sphere_normal", c.elements->Vertices(i)[1]));
  }
}

}  // namespace

const TermSpec& principal_strip() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "principal_strip";
    t.summary = "principal-symmetric meshes: developable normal strips along principal edges";
    t.paper = "[Pellis 2019, §2.3, §5.2]";
    t.elements = "principal_strips";
    t.reads = {"sphere_normal", "strip_normal"};
    t.add = &AddStrip;
    t.finish = &StripNormals;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::PrincipalStrip)
