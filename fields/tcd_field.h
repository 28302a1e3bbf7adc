// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — a TCD field on a triangle mesh as the problems use it
// (problems/declarations/conjugate_field.cpp, level_sets.cpp, conjugate_layout.cpp): the
// geometry it lives on (face frames, frame transport, curvature per face) and
// its evaluation (the conjugate pair of every face, statistics,
// singularities) [Zadravec 2010, §2–3].
//
// Surfaces without curvature: on a plane every pair of directions is
// conjugate (M = 0) and z_M does not exist, so z_N selects nothing. When
// every face is flat (fields/face_curvature.h JetOptions::flat_tolerance),
// EvaluateField falls back to the smooth orthogonal field of the face frames
// (e1, e2: the smooth basis field of §2, [FSDH07]) and says so
// (smooth_fallback). Single flat faces of a curved surface have no pair
// (invalid), like exactly singular faces.
//
// Include only where CGAL is acceptable (pulls in mesh/surface_mesh.h).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "fields/conjugate.h"
#include "fields/face_curvature.h"
#include "fields/face_frames.h"
#include "fields/singularities.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

struct FieldGeometry {
  FaceFrames frames;                     // smooth frames (fields/face_frames.h)
  std::vector<EdgeTransport> transports;  // per interior edge
  std::vector<int> edge_to_transport;     // per edge: its transport, −1 on the boundary
  std::vector<FaceCurvature> curvature;   // per face (fields/face_curvature.h)
  double total_area = 0;                  // A_Φ
  int flat_faces = 0;                     // faces with FaceCurvature::flat
};

// Frames, transports and jets of `mesh`. Precondition (CHECKed by the
// callees): a triangle mesh without garbage, no face of zero area.
FieldGeometry ComputeFieldGeometry(const Mesh& mesh, const JetOptions& jets);

// Whether every face is flat (the smooth fallback of EvaluateField applies).
bool AllFlat(const FieldGeometry& geometry);

struct TcdField {
  std::vector<Eigen::Vector2d> z_n;   // per face, frame coordinates
  std::vector<ConjugatePair> pairs;   // per face: unit v, w in the face frame
  bool smooth_fallback = false;       // every face flat: pairs = (e1, e2) of the frames
  TcdFieldStats stats;                // conjugacy error and smallest angle over valid faces
  double mean_angle_deg = 0;          // mean angle between the lines of v and w
  std::vector<double> vertex_index;   // per vertex, multiples of 1/2 (boundary: 0)
  std::vector<Singularity> singularities;
  double index_sum = 0;               // Σ indices (= χ on a closed surface)
};

// The pairs of `z_n` (per face, frame coordinates) and everything derived
// from them. Precondition (CHECKed): one z_N per face.
TcdField EvaluateField(const Mesh& mesh, const FieldGeometry& geometry,
                       std::vector<Eigen::Vector2d> z_n);

}  // namespace archgeo
