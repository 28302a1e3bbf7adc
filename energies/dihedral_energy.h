// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Edge-length × dihedral energy by iteratively reweighted least squares, one
// 3-vector residual per interior edge e = vw = f ∩ f′:
//
//   r = (ℓ_e / L) (n_f − n_f′) / sqrt(ω_e)
//   ℓ_e = sqrt(‖v − w‖² + (ε_ℓ L)²)
//   ω_e = (ℓ⁰_e / L) ℓ*⁰_e + ε_irls        (constant of the round)
//
//   [Pellis 2019, §3: E = Σ_e ℓ_e ℓ*_e, ℓ*_e = ‖n_f − n_f′‖ = 2|sin(α_e/2)|;
//    §5.1 (E as the target functional); IRLS as in §5.3 for C(Φ)]
//
// Why a vector residual: E is not a sum of squares and ℓ*_e is not
// differentiable where n_f = n_f′. The vector n_f − n_f′ is smooth everywhere,
// and ‖n_f − n_f′‖² = ℓ*²_e exactly, so Ceres (which minimises ½Σ‖r‖²) sees
//
//   ½‖r‖² = ½ (ℓ_e/L)² ℓ*²_e / ω_e                           (exact relation)
//
// With ω_e computed from the previous round's values (DihedralIrlsWeight),
// x_e = ℓ_e ℓ*_e / L, at a fixed point x_e = x⁰_e:
//
//   ½‖r‖² = ½ x_e² / (x_e + ε_irls) = ½ x_e · (1 − ε_irls / (x_e + ε_irls)),
//
// i.e. ½ ℓ_e ℓ*_e / L with relative error ε_irls / (x_e + ε_irls): the E-term
// in units of L, halved. Edges with x_e ≫ ε_irls are weighted exactly as in E;
// edges with x_e ≲ ε_irls (flat edges, the typical case at the optimum, §3.3)
// get the bounded weight 1/ε_irls, a Huber-like quadratic that keeps them
// flat without an infinite weight. ε_irls = kDihedralIrlsEpsilon = 1e-3: an
// edge of length L with a dihedral angle of 0.1° has x = 1.7e-3; edges above
// about 1° (x ≥ 1.7e-2) are weighted within 6% of E's own weight, and the
// largest weight ratio between edges stays ≲ 10³ (well-conditioned normal
// equations next to fairness and proximity terms). The builder reports the
// true E = Σ ℓ_e ℓ*_e separately; this term only drives the minimisation.
//
// Face normals (the hinge functors of energies/dihedral_hinge.h, shared with
// smoothed_dihedral_energy). A triangle's normal is computed from its three
// vertices,
//   n = c / sqrt(‖c‖² + (ε_n L²)²),   c = cross product of two edge vectors,
// (regularised normalisation, ε_n = kDihedralNormalEpsilon). A planar polygon
// (more than three vertices) contributes a unit-normal parameter block n_f
// (the builder puts ceres::SphereManifold<3> on it); the same block is tied to
// the polygon's plane by the face_planarity energy (energies/face_planarity.h:
// n_f·(x − c_f) − d_f = 0 for every vertex x of the face), so n_f is the
// face's normal only as far as face_planarity holds. Composition for hybrid
// meshes (Pellis Fig. 18): quads and polygons are kept planar by
// face_planarity (the paper's "ℓ* = 0 on the diagonals of planar quads" is
// exactly planarity), their diagonals are not edges and get no term here, and
// every mesh edge between two faces gets one term from the factory matching
// its two faces (triangle–triangle, triangle–polygon, polygon–polygon).
//
// Orientation. All normals must point to the same side of the surface (a
// consistently oriented mesh: faces counter-clockwise seen from the side the
// normals point to). For the edge traversed from v to w, f is the face on the
// left (it contains the halfedge v→w) and f′ the face on the right (it
// contains w→v) [Pellis 2019, §5.3 item (3)]. For triangles:
//   f = (v, w, a): n_f ∝ (w − v) × (a − v),
//   f′ = (w, v, b): n_f′ ∝ (v − w) × (b − w).
// Swapping the roles of f and f′ flips the sign of r and leaves ‖r‖.
//
// Units / normalisation: L = 1/inv_length is a fixed length chosen by the
// builder (1 in the canonical frame of unit mean edge length), so r and ω_e
// are unit-free.
//
// Singular configurations, none of which gives NaN (the functors never return
// false):
//  - ℓ*_e = 0 (coplanar faces): r = 0, smooth (no square root of ℓ*).
//  - zero-length edge v = w: ℓ_e is regularised, ℓ_e = ε_ℓ L = 1e-9 L; the
//    triangles' normals are regularised (below).
//  - degenerate triangle (collinear or coincident vertices): c = 0, n = 0,
//    finite Jacobian of order 1/(ε_n L²) × ‖edge‖; the residual is then
//    ℓ_e(±n_other)/sqrt(ω_e), bounded.
//  For ‖c‖ ≫ ε_n L² the regularised normal is the unit normal to relative
//  precision ½(ε_n L²/‖c‖)², and ℓ_e the edge length to ½(ε_ℓ L/‖v − w‖)².
//
// Invariances: rigid motions x → R x + t (r → R r, ‖r‖ unchanged; polygon
// normal blocks n → R n); uniform scaling x → s x with inv_length →
// inv_length / s (r unchanged).
#ifndef ARCHGEO_ENERGIES_DIHEDRAL_ENERGY_H_
#define ARCHGEO_ENERGIES_DIHEDRAL_ENERGY_H_

#include <cmath>

#include <Eigen/Core>

#include "energies/dihedral_hinge.h"  // the functors, ε_n, ε_ℓ

namespace archgeo {

// IRLS floor of ω_e (unit-free; see above).
inline constexpr double kDihedralIrlsEpsilon = 1e-3;

// The IRLS weight ω_e = edge_length · inv_length · dual_edge_length + epsilon
// of one edge, from the previous round's edge length ℓ⁰_e (units of length,
// ≥ 0) and dual edge length ℓ*⁰_e = ‖n_f − n_f′‖ (unit-free, in [0, 2]).
// Returns a value ≥ epsilon > 0. Preconditions (CHECKed): all arguments
// finite, edge_length ≥ 0, dual_edge_length ≥ 0, inv_length > 0,
// epsilon > 0.   [Pellis 2019, §3 E; §5.3 weight iteration]
double DihedralIrlsWeight(double edge_length, double dual_edge_length,
                          double inv_length,
                          double epsilon = kDihedralIrlsEpsilon);

// The residual r = (ℓ_e/L)(n_f − n_f′)/sqrt(ω), 3 doubles, of the hinge
// functors (dihedral_hinge.h) from ℓ_e/L and the normals n_f, n_f′.
struct DihedralResidual {
  static constexpr int kResiduals = 3;
  // ω_e > 0 (DihedralIrlsWeight). The builder may change `omega` between
  // solves (IRLS rounds), never during one.
  double omega;

  template <typename T>
  void Evaluate(const T& length, const Eigen::Matrix<T, 3, 1>& n_left,
                const Eigen::Matrix<T, 3, 1>& n_right, T* residual_ptr) const {
    Eigen::Map<Eigen::Matrix<T, 3, 1>> residual(residual_ptr);
    residual = (length / std::sqrt(omega)) * (n_left - n_right);
  }
};

// Edge between two triangles (v, w, a, b), a triangle and a polygon
// (v, w, a, n_right) and two polygons (v, w, n_left, n_right):
// dihedral_hinge.h.
using DihedralTriTri = HingeTriTri<DihedralResidual>;
using DihedralTriPoly = HingeTriPoly<DihedralResidual>;
using DihedralPolyPoly = HingePolyPoly<DihedralResidual>;

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_DIHEDRAL_ENERGY_H_
