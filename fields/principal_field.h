// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — pre-processing of the principal field before a TCD field is
// built on it [Gebreiter 2012, §8.1.4 "Propagation and smoothing"; Ray et
// al. 2006].
//
// A TCD field is principal where z_N = e1 (Zadravec 2010, §3), and its
// Dirichlet energy (tcd_dirichlet) is zero for the principal field however
// its directions turn from face to face. Where the two principal curvatures
// are nearly equal (near-umbilic) or both nearly zero (near-flat), the
// measured directions are noise, and the field keeps that noise: ± pairs of
// singularities a fraction of a panel apart. The thesis' remedy, here per
// face:
//   1. Reliability. A face with K > 0 is unreliable when its anisotropy
//      a_f = (κ1 − κ2) / (|κ1| + |κ2|) (κ1 ≥ κ2; 0 at an umbilic, 1 where
//      K ≤ 0) is below `anisotropy`, or when its curvature (|κ1| + |κ2|)/2 is
//      below `flat` times the median face's; a flat face (no curvature
//      measured) is unreliable too. Faces with K ≤ 0 are always reliable:
//      there the conjugate directions are held by the asymptotic ones and
//      along parabolic lines one of them is the principal direction of zero
//      curvature (Zadravec 2010, Props. 4–5), so turning their principal
//      directions would only break conjugacy. A reliable face has the
//      weight w_f = a_f (Ray et al.'s |κmax/κmin| turned into a bounded
//      measure), an unreliable one 0.
//   2. Propagation. The unreliable faces' directions are the connection-
//      harmonic extension of the reliable ones' (the line field as the
//      spin-2 vector (cos 2θ, sin 2θ), Σ_e w_e |u_f − R(2τ_fg) u_g|², the
//      reliable faces held; a sparse linear solve). Where no reliable face
//      is near (the thesis' sphere, Fig. 11), the smoothest field there.
//   3. Smoothing. From there, R = (1 − ρ) Σ_f w_f A_f/Ā |u_f − u⁰_f|² +
//      ρ Σ_e w_e |u_f − R(2τ_fg) u_g|² is minimised over the angles θ_f (the
//      registered terms principal_fit and principal_smoothing, solved by the
//      engine: problems/declarations/conjugate_field.cpp).
//   4. The curvature of every face becomes M̃_f = κ1 d̃1 d̃1ᵀ + κ2 d̃2 d̃2ᵀ with
//      the measured κ1, κ2 and the smoothed directions d̃1 = (cos θ_f,
//      sin θ_f), d̃2 ⟂ d̃1. M̃_f − M_f is at most |κ1 − κ2| sin 2|θ_f − θ⁰_f|:
//      small exactly where the directions were unreliable; everything
//      after (z_M, the TCD field, its level sets) uses M̃.
//
// Include only where CGAL is acceptable (pulls in mesh/surface_mesh.h).
#pragma once

#include <vector>

#include "fields/face_curvature.h"
#include "fields/face_frames.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

struct PrincipalReliability {
  std::vector<double> weight;  // per face: w_f = a_f if reliable, else 0
  std::vector<char> reliable;  // per face
  int umbilic = 0;             // unreliable for their anisotropy
  int flat = 0;                // unreliable for their small curvature (and not umbilic)
};

// Step 1. `anisotropy` in [0, 1], `flat` ≥ 0 (a fraction of the median
// face's curvature).
PrincipalReliability Reliability(const std::vector<FaceCurvature>& curvature, double anisotropy,
                                 double flat);

// The measured direction of largest curvature, d1, as an angle in the face
// frame (radians).
double PrincipalAngle(const FaceCurvature& k);

// Step 2: per face the angle θ_f, θ⁰_f on reliable faces and the propagated
// direction on the others; on a connected set of unreliable faces that no
// reliable face touches, the smoothest line field of the set (the
// eigenvector of the smallest eigenvalue of its connection Laplacian, as
// Knöppel et al. 2013 find the globally smoothest field).
std::vector<double> PropagatedAngles(const Mesh& mesh, const std::vector<EdgeTransport>& transports,
                                     const std::vector<FaceCurvature>& curvature,
                                     const PrincipalReliability& reliability);

// Step 4: the face's curvature with its principal directions turned to θ
// (the same κ1, κ2, flatness and sign of K).
FaceCurvature TurnedCurvature(const FaceCurvature& k, double theta, double sign_tolerance);

}  // namespace archgeo
