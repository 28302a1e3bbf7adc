// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the conjugate pairs of a TCD field on a triangle mesh, their
// singularities with index, and the local move of a singularity
// [Zadravec 2010, §3 (Prop. 2, Def. 1, remark after Prop. 7), §4 eq. 4].
//
// Index [§3, eq. 2]: a face-based line field (the bisector of v and w, whose
// total rotation equals that of v and of w, Prop. 3) is measured along the
// dual loop through the faces around each interior vertex, counter-clockwise:
//   ind_v = (Σ_i Δ_i + K_v) / (2π),
//   Δ_i = wrap(β_{i+1} + τ_{i,i+1} − β_i) ∈ (−π/2, π/2],
// β the line angle in each face's frame, τ the frame transport
// (fields/face_frames.h), K_v = 2π − Σ(corner angles at v) the angle defect
// (the transport around v rotates by −K_v, so K_v restores the rotation
// relative to the surface). The indices are multiples of 1/2 and, on a closed
// mesh, sum to the Euler characteristic (discrete Poincaré–Hopf) exactly.
// The paper measures around each face's 1-neighbourhood; per-vertex dual
// loops partition the surface, so no singularity is counted twice, and the
// cuts of fields/cuts.h start at vertices. Boundary vertices have no loop:
// index 0. Faces where the field is undefined (NaN angle: an exactly singular
// face z_N = z_M, or z_N outside c) first take the line of the spin-2 mean of
// their neighbours' lines, so the indices still sum to χ; a singular face then
// shows as a singularity at one of its vertices.
//
// Include only where CGAL is acceptable (pulls in mesh/surface_mesh.h).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "fields/conjugate.h"
#include "fields/face_curvature.h"
#include "fields/face_frames.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

// The conjugate pair of every face for the per-face points z_n (frame
// coordinates, indexed by face index) [Prop. 2].
std::vector<ConjugatePair> TcdPairs(const std::vector<FaceCurvature>& curvature,
                                    const std::vector<Eigen::Vector2d>& z_n);

// Summary of a field's conjugacy and transversality over its valid faces.
struct TcdFieldStats {
  int valid_faces = 0, invalid_faces = 0;
  double max_conjugacy_error = 0.0;  // max |II(v, w)| / (|κ|max ‖v‖‖w‖)
  double min_angle_deg = 90.0;       // smallest angle between the lines of v and w
};
TcdFieldStats FieldStats(const std::vector<FaceCurvature>& curvature,
                         const std::vector<ConjugatePair>& pairs);

// Bisector line angle per face (BisectorAngle(v, w)), NaN where !valid.
std::vector<double> BisectorAngles(const std::vector<ConjugatePair>& pairs);

// Index of a face-based line field at every vertex (indexed by vertex index;
// boundary vertices 0), as a multiple of 1/2. `line_angle` per face in its
// frame (NaN: undefined); `transports` with `edge_to_transport` from
// ComputeTransports. Precondition (CHECKed): triangle mesh without garbage,
// sizes match.
std::vector<double> VertexIndices(const Mesh& mesh, const std::vector<EdgeTransport>& transports,
                                  const std::vector<int>& edge_to_transport,
                                  const std::vector<double>& line_angle);

struct Singularity {
  VertexIndex vertex;
  double index = 0.0;  // ±1/2, ±1, …
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

// The vertices with a nonzero index, in vertex order.
std::vector<Singularity> Singularities(const Mesh& mesh, const std::vector<double>& vertex_index);

// σ of eq. 4: 1 on [0, r1], ½ + ½ cos(π (t − r1)/(r2 − r1)) on [r1, r2], 0
// beyond. Precondition (CHECKed): 0 ≤ r1 < r2.
double SigmaBlend(double t, double r1, double r2);

// The local move of a singularity from face `from` (f0) to face `to` (f1)
// [§4, "Local correction: moving singularities"]:
//   z_N,f^new = z_N,f − β_f · T_{f←f1}(z_N,f1 − z_M,f1),   β_f = σ(dist(f, f0)),
// dist the shortest-path distance between face centroids through the dual
// graph (a geodesic distance estimate), T_{f←f1} the spin-2 transport (a
// rotation by twice the frame transport angle) along the dual shortest-path
// tree from f1: the paper subtracts the correction "in each face's local
// coordinate system", which with a non-parallel frame needs this transport.
// When β_f1 = 1 (dist(f1, f0) ≤ r1) the new field has z_N = z_M at f1.
struct SingularityMove {
  std::vector<Eigen::Vector2d> z_n;  // the blended field, per face
  std::vector<double> beta;          // β_f per face
  bool reached = false;              // β_f1 == 1
  std::string error;                 // non-empty: nothing moved (z_n is the input)
};
// z_M of the target face at infinity (mean curvature 0: no singularity can
// be placed there, cf. Prop. 4) is reported in `error`, the field returned
// unchanged. Preconditions (CHECKed): from/to valid faces, 0 ≤ r1 < r2,
// sizes match.
SingularityMove MoveSingularity(const Mesh& mesh, const FaceFrames& frames,
                                const std::vector<EdgeTransport>& transports,
                                const std::vector<FaceCurvature>& curvature,
                                const std::vector<Eigen::Vector2d>& z_n, FaceIndex from,
                                FaceIndex to, double r1, double r2);

}  // namespace archgeo
