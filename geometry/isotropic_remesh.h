// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — incremental isotropic remeshing of a triangulated design surface
// (Gebreiter 2012, §3.1.2; Botsch & Kobbelt 2004, "A remeshing approach to
// multiresolution modeling", §4). For a target edge length L, each iteration
//  1. splits every edge longer than 4/3 L at its midpoint,
//  2. collapses every edge shorter than 4/5 L whose collapse makes no edge
//     longer than 4/3 L, keeps the link condition and turns no triangle by
//     more than 90°,
//  3. flips every interior edge whose flip brings the valences of its four
//     vertices closer to 6 (4 on the boundary) without folding,
//  4. moves every free vertex in its tangent plane to the area-weighted
//     centroid of its one ring (tangential relaxation) and back onto the
//     input surface (closest point; boundary vertices: the midpoint of their
//     boundary neighbours, then the closest point of the input's boundary
//     polylines).
// Feature edges (input edges whose faces' normals differ by more than
// `feature_angle`, or that lie along a user's feature curve) are kept like
// the boundary. Boundary corners (the boundary
// turning by more than `corner_angle`) and feature corners (ends and
// junctions of features, features meeting the boundary) keep their input
// position and are never removed; boundary and feature edges are split and
// collapsed only along their curve (vertices relaxed along it and projected
// back onto the input's boundary or their own feature chain), never
// flipped. Split and collapsed vertices go onto the input at once, and no
// split, collapse, flip or relaxation move turns over or flattens a triangle.
#pragma once

#include <vector>

#include "mesh/surface_mesh.h"

namespace archgeo {

struct RemeshOptions {
  double target_edge_length = 0;  // L, file units (> 0)
  int iterations = 10;
  double corner_angle_degrees = 30;  // boundary turning angle that makes a corner
  double feature_angle_degrees = 0;  // dihedral angle that makes an input edge a feature (0: none)
  // Curvature-adaptive targets: the largest chord deviation ε allowed, file
  // units; targets shrink to √(6ε/κ − 3ε²) (at least L/16) where the input
  // curves by κ. 0: every target is L.
  double tolerance = 0;
  // Feature curves from the user (an OBJ's polylines, points in order): an
  // interior input edge whose two ends and midpoint lie within
  // `curve_tolerance` (file units) of one curve's segments is a feature edge.
  std::vector<std::vector<Vec3>> feature_curves;
  double curve_tolerance = 0;
};

struct RemeshResult {
  Mesh mesh;  // triangles on the input surface
  int corners = 0;        // boundary and feature corners (kept in place)
  int feature_edges = 0;  // of the input
  std::vector<int> curve_edges;  // per feature curve: the input edges along it
  int splits = 0, collapses = 0, flips = 0;
};

// `input`: a manifold triangle or polygon mesh (polygons are triangulated as
// TriangulatedCopy does). Throws std::invalid_argument for a non-positive
// target or iteration count.
RemeshResult IsotropicRemesh(const Mesh& input, const RemeshOptions& options);

// Quality of a triangle mesh, as the remeshing acceptance reads it.
struct TriangleQuality {
  double min_angle_30_fraction = 0;  // share of triangles whose smallest angle is ≥ 30°
  double min_angle_degrees = 0;      // smallest angle of any triangle
  double edge_mean = 0, edge_cv = 0;  // mean edge length and its coefficient of variation
};
TriangleQuality MeasureTriangles(const Mesh& triangles);

}  // namespace archgeo
