// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The hinge of an interior edge e = vw = f ∩ f′, shared by the two
// edge-length × dihedral energies (energies/dihedral_energy.h, IRLS;
// energies/smoothed_dihedral_energy.h, direct): the unit-free edge length
// ℓ_e / L and the two face normals n_f, n_f′, gathered once for each pair of
// face kinds; the energy supplies only the residual of (ℓ_e/L, n_f, n_f′).
//
//   ℓ_e / L = sqrt(‖(v − w)/L‖² + ε_ℓ²)
//   n = c / sqrt(‖c‖² + ε_n²),   c = cross product of two edge vectors over L
//                                                 [Pellis 2019, §3, §5.3 (3)]
//
// Face kinds (Pellis Fig. 18): a triangle's normal comes from its three
// vertices; a planar polygon (more than three vertices) contributes a
// unit-normal block (ceres::SphereManifold<3>, kept on the face's plane by
// face_planarity). Orientation: for the edge traversed from v to w, f is the
// face on the left (it contains v→w), f′ the one on the right (w→v):
//   f = (v, w, a): n_f ∝ (w − v) × (a − v),   f′ = (w, v, b): n_f′ ∝ (v − w) × (b − w).
// Normals are computed on unit-free coordinates (x − v)/L, so ε_n is relative
// to L² and ε_ℓ to L. Singular configurations (zero-length edge, degenerate
// triangle) give ℓ_e = ε_ℓ L and a bounded normal (0 for c = 0), never NaN.
//
// The residual is a policy type R, the base class of the functor (so its
// constant is the functor's member, next to inv_length = 1/L): an aggregate
// R{parameter} (ω for IRLS, ε smoothed) with
//   template <typename T> void Evaluate(const T& length,   // ℓ_e / L
//       const Eigen::Matrix<T, 3, 1>& n_left, const Eigen::Matrix<T, 3, 1>& n_right,
//       T* residual) const;
#ifndef ARCHGEO_ENERGIES_DIHEDRAL_HINGE_H_
#define ARCHGEO_ENERGIES_DIHEDRAL_HINGE_H_

#include <array>
#include <cmath>
#include <cstddef>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()

#include "energies/autodiff.h"

namespace archgeo {

// Regularisation of triangle normals, relative to L².
inline constexpr double kDihedralNormalEpsilon = 1e-6;
// Regularisation of the edge length, relative to L.
inline constexpr double kDihedralLengthEpsilon = 1e-9;

// Regularised unit normal of the triangle (p0, p1, p2), counter-clockwise
// seen from the side the normal points to:
//   n = c / sqrt(‖c‖² + eps²),   c = (p1 − p0) × (p2 − p0).
// eps has the units of c (length²). Shared with total_absolute_curvature.
template <typename T>
Eigen::Matrix<T, 3, 1> RegularisedTriangleNormal(
    const Eigen::Matrix<T, 3, 1>& p0, const Eigen::Matrix<T, 3, 1>& p1,
    const Eigen::Matrix<T, 3, 1>& p2, double eps) {
  const Eigen::Matrix<T, 3, 1> c = (p1 - p0).cross(p2 - p0);
  using std::sqrt;
  return c / sqrt(c.squaredNorm() + T(eps * eps));
}

// ℓ_e / L = sqrt(‖(w − v) inv_length‖² + ε_ℓ²) of the edge (v, w): 3 doubles
// each; inv_length = 1/L > 0.
template <typename T>
T RegularisedEdgeLength(const T* v_ptr, const T* w_ptr, double inv_length) {
  using Vec3 = Eigen::Matrix<T, 3, 1>;
  const Eigen::Map<const Vec3> v(v_ptr);
  const Eigen::Map<const Vec3> w(w_ptr);
  const Vec3 e = (w - v) * T(inv_length);  // unit-free edge vector
  using std::sqrt;
  return sqrt(e.squaredNorm() +
              T(kDihedralLengthEpsilon * kDihedralLengthEpsilon));
}

// The normal of the face on one side of the edge v→w, on unit-free
// coordinates (x − v)/L: a polygon's unit-normal block `face` as it is (not
// normalised here: the SphereManifold keeps it unit), or the regularised
// normal of the triangle with third vertex `face` — (v, w, face) on the left,
// (w, v, face) on the right.
template <bool kPolygon, bool kLeft, typename T>
Eigen::Matrix<T, 3, 1> HingeFaceNormal(const T* v_ptr, const T* w_ptr,
                                       const T* face_ptr, double inv_length) {
  using Vec3 = Eigen::Matrix<T, 3, 1>;
  const Eigen::Map<const Vec3> face(face_ptr);
  if constexpr (kPolygon) {
    return Vec3(face);
  } else {
    const Eigen::Map<const Vec3> v(v_ptr);
    const Eigen::Map<const Vec3> w(w_ptr);
    const T s(inv_length);
    const Vec3 zero = Vec3::Zero();
    const Vec3 wl = (w - v) * s, xl = (face - v) * s;
    return kLeft ? RegularisedTriangleNormal<T>(zero, wl, xl, kDihedralNormalEpsilon)
                 : RegularisedTriangleNormal<T>(wl, zero, xl, kDihedralNormalEpsilon);
  }
}

// The edge v→w between the face f on its left and f′ on its right, each a
// triangle or a planar polygon (kLeftPolygon, kRightPolygon), with the
// residual R. inv_length: 1/L > 0; parameter: R's constant.
template <typename Residual, bool kLeftPolygon, bool kRightPolygon>
struct DihedralHinge : Residual {
  using Shape = CostShape<Residual::kResiduals, 3, 3, 3, 3>;

  DihedralHinge(double inv_length, double parameter)
      : Residual{parameter}, inv_length(inv_length) {}

  // v, w: 3 doubles each, the edge's endpoints; left, right: 3 doubles each,
  // per face the vertex opposite the edge (a triangle: f = (v, w, a),
  // f′ = (w, v, b)) or the unit normal (a polygon, same side as a triangle's
  // normal); residual: as many doubles as R writes.
  template <typename T>
  bool operator()(const T* v_ptr, const T* w_ptr, const T* left_ptr,
                  const T* right_ptr, T* residual) const {
    this->Evaluate(
        RegularisedEdgeLength(v_ptr, w_ptr, inv_length),
        HingeFaceNormal<kLeftPolygon, true>(v_ptr, w_ptr, left_ptr, inv_length),
        HingeFaceNormal<kRightPolygon, false>(v_ptr, w_ptr, right_ptr, inv_length),
        residual);
    return true;
  }

  double inv_length;
};

// The three kinds of hinge, blocks (v, w, a, b), (v, w, a, n_right) and
// (v, w, n_left, n_right). For a polygon on the left and a triangle on the
// right, use HingeTriPoly with v and w swapped (the triangle (w, v, b) is then
// on the left of w→v).
template <typename Residual>
using HingeTriTri = DihedralHinge<Residual, false, false>;
template <typename Residual>
using HingeTriPoly = DihedralHinge<Residual, false, true>;
template <typename Residual>
using HingePolyPoly = DihedralHinge<Residual, true, true>;

// CHECKs (release builds too) the constants of a hinge functor made by the
// factory `name`: inv_length and the residual's `parameter` (named for the
// message) finite and > 0.
void CheckHingeConstants(const char* name, double inv_length,
                         const char* parameter, double value);

}  // namespace archgeo

// --- the builder of the hinge terms (dihedral_hinge.cpp) --------------------
namespace archgeo {

class TermContext;
struct TermSpec;

namespace terms {

// The adders of one residual's three hinge functors (dihedral_energy.h,
// smoothed_dihedral_energy.h): each adds, through the context, the residual
// of its functor with (inv_length, parameter) over the blocks (v, w, a, b),
// (v, w, a, n_right) or (v, w, n_left, n_right). AddHinge CHECKs the
// constants first (CheckHingeConstants, named by `term` and `parameter`).
struct HingeAdders {
  using Add = void (*)(TermContext& c, double inv_length, double parameter,
                       const std::array<double*, 4>& blocks);
  const char* term;       // e.g. "dihedral_energy"
  const char* parameter;  // the residual's parameter, e.g. "omega"
  Add tri_tri;
  Add tri_poly;
  Add poly_poly;
};

// The adder of the hinge functor `Functor` constructed from (inv_length,
// parameter) (instantiate it where energies/autodiff_impl.h is included).
template <typename Functor>
void AddHingeResidual(TermContext& c, double inv_length, double parameter,
                      const std::array<double*, 4>& blocks) {
  AddAutoDiff(c, Functor(inv_length, parameter), blocks);
}

// The builder of a hinge term: adds the residual of interior edge
// `element` (vertices v, w, a, b with left face (v, w, a, …) and right face
// (w, v, b, …), core/elements.h) in the canonical frame (inv_length 1), made
// by the adder matching its two faces with `parameter`.
void AddHinge(TermContext& c, std::size_t element, const HingeAdders& add, double parameter);

// A hinge term's declaration without name, summary and adder: its elements
// (interior_edges), paper, and the polygons' face_plane_normal blocks (shared
// with face_planarity), initialised from the faces and kept unit.
TermSpec HingeTermSpec();

}  // namespace terms
}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_DIHEDRAL_HINGE_H_
