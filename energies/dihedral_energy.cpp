#include "energies/dihedral_energy.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {
namespace {

void CheckConstants(const char* name, double inv_length, double omega) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << name << ": inv_length must be finite and > 0, got " << inv_length;
  CHECK(std::isfinite(omega) && omega > 0.0)
      << name << ": omega must be finite and > 0, got " << omega;
}

template <typename Functor>
ceres::CostFunction* MakeDihedral(const char* name, double inv_length,
                                  double omega, Functor** functor) {
  CheckConstants(name, inv_length, omega);
  auto* f = new Functor(inv_length, omega);
  if (functor != nullptr) *functor = f;
  return new ceres::AutoDiffCostFunction<Functor, 3, 3, 3, 3, 3>(f);
}

}  // namespace

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

ceres::CostFunction* MakeDihedralTriTri(double inv_length, double omega,
                                        DihedralTriTri** functor) {
  return MakeDihedral("MakeDihedralTriTri", inv_length, omega, functor);
}

ceres::CostFunction* MakeDihedralTriPoly(double inv_length, double omega,
                                         DihedralTriPoly** functor) {
  return MakeDihedral("MakeDihedralTriPoly", inv_length, omega, functor);
}

ceres::CostFunction* MakeDihedralPolyPoly(double inv_length, double omega,
                                          DihedralPolyPoly** functor) {
  return MakeDihedral("MakeDihedralPolyPoly", inv_length, omega, functor);
}

}  // namespace archgeo

// --- term `dihedral_energy` ----------------------------------------------------
#include <array>

#include "core/term.h"

namespace archgeo {
namespace terms {
void InitFacePlaneNormal(TermContext& c, int face, const int* vs, int count);
}  // namespace terms

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

void InitPolygonNormals(TermContext& c) {
  const ElementSet& faces = c.Elements("faces");
  for (size_t i = 0; i < c.elements->size(); ++i) {
    for (int f : {c.elements->face[i], c.elements->other_face[i]}) {
      if (faces.Count(f) > 3) terms::InitFacePlaneNormal(c, f, faces.Vertices(f), faces.Count(f));
    }
  }
}

// Edge v→w with left face (v, w, a, …) and right face (w, v, b, …); the IRLS
// weight ω from the current edge length and normals (a round's constant).
void AddDihedral(TermContext& c, size_t i) {
  const ElementSet& e = *c.elements;
  const int* vs = e.Vertices(i);
  const int v = vs[0], w = vs[1], a = vs[2], b = vs[3];
  const int left = e.face[i], right = e.other_face[i];
  const ElementSet& faces = c.Elements("faces");
  const Vec nl = EnergyNormal(c, faces, left), nr = EnergyNormal(c, faces, right);
  const double length = Norm(Sub(c.Position(w), c.Position(v)));
  const double omega =
      DihedralIrlsWeight(length, Norm({nl[0] - nr[0], nl[1] - nr[1], nl[2] - nr[2]}), 1.0);
  const bool poly_l = e.Has(i, kLeftPolygon), poly_r = e.Has(i, kRightPolygon);
  if (!poly_l && !poly_r) {
    c.Add(MakeDihedralTriTri(1.0, omega),
          {c.Position(v), c.Position(w), c.Position(a), c.Position(b)});
  } else if (!poly_l && poly_r) {
    c.Add(MakeDihedralTriPoly(1.0, omega),
          {c.Position(v), c.Position(w), c.Position(a), c.Block("face_plane_normal", right)});
  } else if (poly_l && !poly_r) {
    // The triangle (w, v, b) is on the left of w→v.
    c.Add(MakeDihedralTriPoly(1.0, omega),
          {c.Position(w), c.Position(v), c.Position(b), c.Block("face_plane_normal", left)});
  } else {
    c.Add(MakeDihedralPolyPoly(1.0, omega), {c.Position(v), c.Position(w),
                                             c.Block("face_plane_normal", left),
                                             c.Block("face_plane_normal", right)});
  }
}

// Unit normals of the polygons an edge term used.
void SphereNormals(TermContext& c) {
  const ElementSet& faces = c.Elements("faces");
  for (size_t f = 0; f < faces.size(); ++f) {
    if (faces.Count(f) > 3) c.SetUnit(c.Block("face_plane_normal", int(f)));
  }
}

}  // namespace

const TermSpec& dihedral_energy() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "dihedral_energy";
    t.summary = "visual smoothness: edge length × dihedral angle (IRLS form of E = Σ ℓ ℓ*)";
    t.paper = "[Pellis 2019, §3, §5.1]";
    t.elements = "interior_edges";
    t.declares = {{"face_plane_normal", Site::kFace, 3, FrameMap::kDirection, true,
                   Carry::kReinitialise, false, false,
                   "unit normal of a face's plane (face_planarity, dihedral_energy)"}};
    t.init = &InitPolygonNormals;
    t.add = &AddDihedral;
    t.finish = &SphereNormals;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo
