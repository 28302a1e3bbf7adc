// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Edge-length × dihedral energy, smoothed at flat edges and minimised
// directly (no reweighting between solves). One 4-vector residual per
// interior edge e = vw = f ∩ f′, d = n_f − n_f′ (so ‖d‖ = ℓ*_e):
//
//   r = sqrt(ℓ_e / (L s)) · (d, sqrt(s² + ε²)),   s = sqrt(‖d‖² + ε²)
//   ½‖r‖² = (ℓ_e / L) · sqrt(ℓ*²_e + ε²)                      (exact)
//   ℓ_e = sqrt(‖v − w‖² + (ε_ℓ L)²)
//
//   [Pellis 2019, §3: E = Σ_e ℓ_e ℓ*_e, ℓ*_e = ‖n_f − n_f′‖ = 2|sin(α_e/2)|;
//    §5.1: E as the target functional E_target of the regulariser R(X)]
//
// So Ceres (which minimises ½Σ‖r‖²) minimises E_ε / L with
//   E_ε = Σ_e ℓ_e sqrt(ℓ*²_e + ε²),   E ≤ E_ε ≤ E + ε Σ_e ℓ_e,
// the true E with |ℓ*| replaced by the smooth sqrt(ℓ*² + ε²) (a Huber-like
// rounding of the kink of |ℓ*| at flat edges, radius ε). Its gradient is E's
// wherever ℓ*_e ≫ ε; the extra ε Σ ℓ_e pulls every edge shorter with a
// force ε (unit-free), against forces of order |α_e| that E exerts on an edge
// bent by α_e (0.087 at 5°).
//
// Why this residual, not the IRLS one (energies/dihedral_energy.h): the IRLS
// surrogate ½ ℓ²ℓ*²/ω freezes ω for a whole solve and has to be renewed in
// rounds, and its rounds converge linearly (issue 14: 0.1–0.2% of E per round
// at 54k faces). Here the objective Ceres sees is E_ε itself, so every Ceres
// iteration (re)weights and a single solve converges to E_ε's minimum. The
// split of ½‖r‖² into four squares is chosen so that Gauss–Newton's model
// JᵀJ matches the Hessian of ℓ sqrt(‖d‖² + ε²) (as a function of d) exactly
// at flat edges (ℓ/ε · I) and across d for bent edges (ℓ/‖d‖ orthogonally to
// d); only along d does it add ℓ/(2‖d‖) where the Hessian is 0 (a convex
// majorant, as IRLS's ℓ/‖d‖). The plain scalar sqrt(2ℓ sqrt(‖d‖² + ε²))
// would give JᵀJ → 0 at flat edges.
//
// Face normals and polygons as in dihedral_energy.h (the hinge functors of
// dihedral_hinge.h, shared): a triangle's normal is
// RegularisedTriangleNormal of its vertices (ε_n = kDihedralNormalEpsilon
// relative to L²); a planar polygon (more than three vertices) contributes a
// unit-normal block (SphereManifold, kept on the face's plane by
// face_planarity). Orientation: for the edge v→w, f = (v, w, a, …) is the face
// on the left, f′ = (w, v, b, …) on the right; the residual's first three
// entries flip sign with the traversal, ‖r‖ does not.
//
// Units / normalisation: L = 1/inv_length is a fixed length (1 in the
// canonical frame of unit mean edge length), ε unit-free (an angle: ℓ* ≈ |α|
// for small α). ε = kSmoothedDihedralEpsilon = 1e-3 by default (0.057°).
//
// Singular configurations, none of which gives NaN (the functors never return
// false):
//  - ℓ*_e = 0 (coplanar faces): s = ε, r = sqrt(ℓ/(Lε)) (0, √2 ε), smooth.
//  - zero-length edge v = w: ℓ_e = ε_ℓ L = 1e-9 L, sqrt(ℓ_e) and its
//    derivative finite.
//  - degenerate triangle: regularised normal 0 (dihedral_energy.h), finite.
//  - folded flat (n_f′ = −n_f): ‖d‖ = 2, smooth.
//
// Invariances: rigid motions x → R x + t (d → R d, ‖r‖ and the fourth entry
// unchanged; polygon normal blocks n → R n); uniform scaling x → σx with
// inv_length → inv_length/σ (r unchanged); swapping f and f′ (traversing the
// edge as w→v) flips d and leaves ‖r‖.
#ifndef ARCHGEO_ENERGIES_SMOOTHED_DIHEDRAL_ENERGY_H_
#define ARCHGEO_ENERGIES_SMOOTHED_DIHEDRAL_ENERGY_H_

#include <cmath>

#include <Eigen/Core>

#include "energies/dihedral_hinge.h"  // the functors, ε_n, ε_ℓ

namespace archgeo {

// Smoothing radius ε of ℓ* (unit-free; see above).
inline constexpr double kSmoothedDihedralEpsilon = 1e-3;

// The residual r = sqrt(ℓ/(L s)) (d, sqrt(s² + ε²)), d = n_f − n_f′, 4 doubles,
// of the hinge functors (dihedral_hinge.h) from ℓ_e/L and the normals.
struct SmoothedDihedralResidual {
  static constexpr int kResiduals = 4;
  double epsilon;  // ε > 0 (unit-free)

  template <typename T>
  void Evaluate(const T& length, const Eigen::Matrix<T, 3, 1>& n_left,
                const Eigen::Matrix<T, 3, 1>& n_right, T* residual) const {
    using std::sqrt;
    const Eigen::Matrix<T, 3, 1> d = n_left - n_right;
    const T eps2(epsilon * epsilon);
    const T s2 = d.squaredNorm() + eps2;
    const T s = sqrt(s2);
    const T scale = sqrt(length / s);
    residual[0] = scale * d[0];
    residual[1] = scale * d[1];
    residual[2] = scale * d[2];
    residual[3] = scale * sqrt(s2 + eps2);
  }
};

// Edge between two triangles (v, w, a, b), a triangle and a polygon
// (v, w, a, n_right) and two polygons (v, w, n_left, n_right):
// dihedral_hinge.h.
using SmoothedDihedralTriTri = HingeTriTri<SmoothedDihedralResidual>;
using SmoothedDihedralTriPoly = HingeTriPoly<SmoothedDihedralResidual>;
using SmoothedDihedralPolyPoly = HingePolyPoly<SmoothedDihedralResidual>;

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_SMOOTHED_DIHEDRAL_ENERGY_H_
