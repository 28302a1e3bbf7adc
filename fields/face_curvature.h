// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — curvature per face of a triangle mesh: the second fundamental form
// M_f in the face frame, z_M,f, principal and asymptotic directions, the sign
// of the Gaussian curvature [Zadravec 2010, §2; osculating jets: Cazals &
// Pouget 2003, the steps of CGAL::Monge_via_jet_fitting with a QR solve].
//
// Method: a jet of degree d is fitted at every vertex to the vertex and its
// neighbourhood (vertices within `rings` edges, grown ring by ring until it
// has `min_points` points); its Monge form gives k1, k2, d1, d2 with the Monge
// normal turned to agree with the area-weighted vertex normal, i.e. the 3-D
// shape tensor S_v = k1 d1 d1ᵀ + k2 d2 d2ᵀ. A face takes the mean of its three
// vertex tensors (the value at the centroid of a linearly varying tensor, so
// second-order accurate) and M_f(i, j) = e_i,fᵀ S e_j,f in its frame
// (fields/face_frames.h). The paper fits jets per face; per-vertex fits are
// the usual use of jet fitting (the first point, where the Monge form is
// evaluated, lies on the surface) and need one fit per vertex instead of one
// per face.
//
// Sign convention: x3 = ½ xᵀ M_f x + … with x3 along the face normal n_f
// (counter-clockwise orientation). With outward normals a sphere of radius R
// has M = −I/R; K = det M does not depend on the orientation.
//
// Include only where CGAL is acceptable (pulls in mesh/surface_mesh.h).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "fields/face_frames.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

struct JetOptions {
  // d: degree of the fitted polynomial, 2..4 [Cazals & Pouget 2003]. 4 is
  // the most accurate here: with the default neighbourhood the curvature
  // tensor of a sphere (icosphere, edge ≈ R/15) is within 0.2% for d = 4
  // against 2% for d = 3 and 0.9% for d = 2, and the asymptotic directions of
  // z = xy within 0.3° (boundary faces included) against 0.9° and 1.2°
  // (tests/test_field_curvature.cpp).
  int degree = 4;
  // Initial neighbourhood: the vertices within `rings` edges of the vertex.
  int rings = 2;
  // Minimum number of points of a fit (0: 2 (d + 1)(d + 2)/2, twice the
  // number of jet coefficients); the neighbourhood grows ring by ring, up to
  // 8 rings, until it has that many points. CHECKed ≥ (d + 1)(d + 2)/2 when
  // given explicitly.
  int min_points = 0;
  // A face is flat when max(|k1|, |k2|) · L < flat_tolerance, L the
  // bounding-box diagonal of the mesh (unit-free).
  double flat_tolerance = 1e-6;
  // The Gaussian curvature sign is 0 when |k1 k2| ≤ sign_tolerance ·
  // max(|k1|, |k2|)² (one principal curvature below sign_tolerance times the
  // other); +1 or −1 otherwise.
  double sign_tolerance = 1e-3;
};

struct FaceCurvature {
  Eigen::Matrix2d M = Eigen::Matrix2d::Zero();  // in (e1, e2), symmetric
  double k1 = 0.0, k2 = 0.0;                    // principal curvatures, k1 ≥ k2
  Eigen::Vector2d d1{1.0, 0.0}, d2{0.0, 1.0};   // unit principal directions (frame)
  Eigen::Vector2d z_m{0.0, 0.0};                // Prop. 1 point (when z_m_finite)
  bool z_m_finite = false;                      // false: H = 0 relative to |M|, or M = 0
  int gaussian_sign = 0;                        // sign of K = det M (see JetOptions)
  bool flat = true;                             // see JetOptions::flat_tolerance
  int num_asymptotic = 0;                       // 2 if K < 0, 1 if K = 0 and M ≠ 0
  Eigen::Vector2d asymptotic[2];                // unit (first num_asymptotic valid)
};

// Everything derived from one matrix M (frame coordinates). `flat_curvature`
// is the absolute curvature below which M counts as flat (see JetOptions).
FaceCurvature CurvatureOfMatrix(const Eigen::Matrix2d& M, double flat_curvature,
                                double sign_tolerance);

// The 3-D shape tensor S_v per vertex (indexed by vertex index), w.r.t. the
// area-weighted vertex normal. Precondition (CHECKed): triangle mesh without
// garbage, at least (d + 1)(d + 2)/2 vertices in each connected component.
std::vector<Eigen::Matrix3d> VertexShapeTensors(const Mesh& mesh, const JetOptions& options = {});
// The same, fitted only at the vertices v with only[v.idx()] != 0 (the others
// stay 0): a measure over a sample of faces fits the jets it reads and no
// more. `only` has one entry per vertex index.
std::vector<Eigen::Matrix3d> VertexShapeTensors(const Mesh& mesh, const JetOptions& options,
                                                const std::vector<char>& only);

// Per face (indexed by face index): M_f and the derived data above.
std::vector<FaceCurvature> ComputeFaceCurvature(const Mesh& mesh, const FaceFrames& frames,
                                                const JetOptions& options = {});

// M_f for one face from vertex tensors (the mean of its corners' tensors,
// restricted to the face plane in the face frame).
Eigen::Matrix2d FaceMatrix(const Mesh& mesh, const FaceFrames& frames, FaceIndex f,
                           const std::vector<Eigen::Matrix3d>& vertex_tensors);

}  // namespace archgeo
