// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/dihedral_energy.h"

#include <array>
#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

double DihedralIrlsWeight(double edge_length, double dual_edge_length,
                          double inv_length, double epsilon) {
  CHECK(std::isfinite(edge_length) && edge_length >= 0.0)
      << "DihedralIrlsWeight: edge_length must be finite and >= 0, got "
      << edge_length;
  CHECK(std::isfinite(dual_edge_length) && dual_edge_length >= 0.0)
      << "DihedralIrlsWeight: dual_edge_length must be finite and >= 0, got "
      << dual_edge_length;
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "DihedralIrlsWeight: inv_length must be finite and > 0, got "
      << inv_length;
  CHECK(std::isfinite(epsilon) && epsilon > 0.0)
      << "DihedralIrlsWeight: epsilon must be finite and > 0, got " << epsilon;
  return edge_length * inv_length * dual_edge_length + epsilon;
}

}  // namespace archgeo

// --- term `dihedral_energy` ----------------------------------------------------

namespace archgeo {
namespace terms {
namespace {

using Vec = std::array<double, 3>;

Vec Sub(const double* a, const double* b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double Norm(const Vec& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// The normal the IRLS weight uses for face f: a triangle's from its vertices
// (source, target, next of its first halfedge: the faces set lists target
// first), a polygon's from its plane block.
Vec EnergyNormal(TermContext& c, const ElementSet& faces, int f) {
  if (faces.Count(f) > 3) {
    const double* n = c.Block("face_plane_normal", f);
    return {n[0], n[1], n[2]};
  }
  const int* vs = faces.Vertices(f);
  const double* p0 = c.Position(vs[2]);
  const double* p1 = c.Position(vs[0]);
  const double* p2 = c.Position(vs[1]);
  const Vec a = Sub(p1, p0), b = Sub(p2, p0);
  const Vec n{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double length = Norm(n);
  return length > 0 ? Vec{n[0] / length, n[1] / length, n[2] / length} : Vec{0, 0, 0};
}

// The IRLS residual's hinge functors, ω as their parameter.
constexpr HingeAdders kDihedralAdders = {"dihedral_energy", "omega",
                                         &AddHingeResidual<DihedralTriTri>,
                                         &AddHingeResidual<DihedralTriPoly>,
                                         &AddHingeResidual<DihedralPolyPoly>};

// Edge v→w with left face (v, w, a, …) and right face (w, v, b, …); the IRLS
// weight ω from the current edge length and normals (a round's constant).
void AddDihedral(TermContext& c, size_t i) {
  const ElementSet& e = *c.elements;
  const int v = e.Vertices(i)[0], w = e.Vertices(i)[1];
  const int left = e.face[i], right = e.other_face[i];
  const ElementSet& faces = c.Elements("faces");
  const Vec nl = EnergyNormal(c, faces, left), nr = EnergyNormal(c, faces, right);
  const double length = Norm(Sub(c.Position(w), c.Position(v)));
  const double omega =
      DihedralIrlsWeight(length, Norm({nl[0] - nr[0], nl[1] - nr[1], nl[2] - nr[2]}), 1.0);
  AddHinge(c, i, kDihedralAdders, omega);
}

}  // namespace

const TermSpec& dihedral_energy() {
  static const TermSpec spec = [] {
    TermSpec t = HingeTermSpec();
    t.name = "dihedral_energy";
    t.summary = "visual smoothness: edge length × dihedral angle (IRLS form of E = Σ ℓ ℓ*)";
    t.add = &AddDihedral;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::DihedralTriTri)
ARCHGEO_AUTODIFF(archgeo::DihedralTriPoly)
ARCHGEO_AUTODIFF(archgeo::DihedralPolyPoly)
