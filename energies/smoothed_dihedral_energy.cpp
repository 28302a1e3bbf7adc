#include "energies/smoothed_dihedral_energy.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {
namespace {

template <typename Functor>
ceres::CostFunction* MakeSmoothed(const char* name, double inv_length, double epsilon) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << name << ": inv_length must be finite and > 0, got " << inv_length;
  CHECK(std::isfinite(epsilon) && epsilon > 0.0)
      << name << ": epsilon must be finite and > 0, got " << epsilon;
  return new ceres::AutoDiffCostFunction<Functor, 4, 3, 3, 3, 3>(new Functor(inv_length, epsilon));
}

}  // namespace

ceres::CostFunction* MakeSmoothedDihedralTriTri(double inv_length, double epsilon) {
  return MakeSmoothed<SmoothedDihedralTriTri>("MakeSmoothedDihedralTriTri", inv_length, epsilon);
}

ceres::CostFunction* MakeSmoothedDihedralTriPoly(double inv_length, double epsilon) {
  return MakeSmoothed<SmoothedDihedralTriPoly>("MakeSmoothedDihedralTriPoly", inv_length,
                                               epsilon);
}

ceres::CostFunction* MakeSmoothedDihedralPolyPoly(double inv_length, double epsilon) {
  return MakeSmoothed<SmoothedDihedralPolyPoly>("MakeSmoothedDihedralPolyPoly", inv_length,
                                                epsilon);
}

}  // namespace archgeo

// --- term `smoothed_dihedral_energy` ------------------------------------------
#include "core/term.h"

namespace archgeo {
namespace terms {
void InitFacePlaneNormal(TermContext& c, int face, const int* vs, int count);
}  // namespace terms

namespace terms {
namespace {

void InitPolygonNormals(TermContext& c) {
  const ElementSet& faces = c.Elements("faces");
  for (size_t i = 0; i < c.elements->size(); ++i) {
    for (int f : {c.elements->face[i], c.elements->other_face[i]}) {
      if (faces.Count(f) > 3) terms::InitFacePlaneNormal(c, f, faces.Vertices(f), faces.Count(f));
    }
  }
}

// Edge v→w with left face (v, w, a, …) and right face (w, v, b, …).
void AddSmoothedDihedral(TermContext& c, size_t i) {
  const ElementSet& e = *c.elements;
  const int* vs = e.Vertices(i);
  const int v = vs[0], w = vs[1], a = vs[2], b = vs[3];
  const int left = e.face[i], right = e.other_face[i];
  const double epsilon = c.Number("epsilon");
  const bool poly_l = e.Has(i, kLeftPolygon), poly_r = e.Has(i, kRightPolygon);
  if (!poly_l && !poly_r) {
    c.Add(MakeSmoothedDihedralTriTri(1.0, epsilon),
          {c.Position(v), c.Position(w), c.Position(a), c.Position(b)});
  } else if (!poly_l && poly_r) {
    c.Add(MakeSmoothedDihedralTriPoly(1.0, epsilon),
          {c.Position(v), c.Position(w), c.Position(a), c.Block("face_plane_normal", right)});
  } else if (poly_l && !poly_r) {
    // The triangle (w, v, b) is on the left of w→v.
    c.Add(MakeSmoothedDihedralTriPoly(1.0, epsilon),
          {c.Position(w), c.Position(v), c.Position(b), c.Block("face_plane_normal", left)});
  } else {
    c.Add(MakeSmoothedDihedralPolyPoly(1.0, epsilon),
          {c.Position(v), c.Position(w), c.Block("face_plane_normal", left),
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

const TermSpec& smoothed_dihedral_energy() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "smoothed_dihedral_energy";
    t.summary = "visual smoothness: E_ε = Σ ℓ sqrt(ℓ*² + ε²), E = Σ ℓ ℓ* rounded at flat edges, "
                "minimised directly (no IRLS rounds)";
    t.paper = "[Pellis 2019, §3, §5.1]";
    t.elements = "interior_edges";
    t.declares = {{"face_plane_normal", Site::kFace, 3, FrameMap::kDirection, true,
                   Carry::kReinitialise, false, false,
                   "unit normal of a face's plane (face_planarity, dihedral_energy)"}};
    t.options = {NumberKey("epsilon", kSmoothedDihedralEpsilon, 1e-9, 1,
                           "ε: |ℓ*| is rounded to sqrt(ℓ*² + ε²) (unit-free, about the "
                           "dihedral angle in radians below which an edge counts as flat)")};
    t.init = &InitPolygonNormals;
    t.add = &AddSmoothedDihedral;
    t.finish = &SphereNormals;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo
