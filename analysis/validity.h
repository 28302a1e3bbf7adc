// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — is a result buildable? The checks every output passes before
// `archgeo solve` may exit 0 (README, "Exit codes and guarantees"), measured against the
// input it came from, so a defect the input already had is not blamed on
// the optimisation:
//
//   hard (a result failing one is not written):
//     finite            every coordinate finite
//     reflex_corners    panels (faces with ≥ 4 sides) with a corner bent inward
//                       by more than max_reflex_degrees (interior angle
//                       − 180°, in the plane of the face's Newell normal),
//                       where the input's corner was not
//     bow_ties          self-intersecting panels (two non-adjacent sides
//                       cross in that plane)
//     flipped_faces     faces whose normal turned by more than
//                       max_flip_degrees against the input's
//     short_edges       edges shorter than min_edge_relative × the input's mean
//                       edge length and than half their input length
//     creases           interior edges whose dihedral angle (between the face
//                       normals) grew by more than max_crease_increase_degrees
//                       over the input's
//     self_intersections  pairs of faces of the surface that intersect (CGAL
//                       Polygon_mesh_processing, on a triangulation; only when
//                       the input has none), in the full check
//   soft (reported as warnings):
//     small_corners     panel corners below min_corner_degrees (where the input
//                       had none there)
//     aspect            faces whose longest side exceeds max_aspect × their
//                       shortest (where the input's did not)
//
// Without an input of the same topology (after subdivision) the relative
// checks compare with nothing: every defect counts.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesh/surface_mesh.h"

namespace archgeo {

struct ValidityLimits {
  double max_reflex_degrees = 10;
  double max_flip_degrees = 90;
  double min_edge_relative = 0.1;
  double max_crease_increase_degrees = 30;
  double min_corner_degrees = 5;
  double max_aspect = 20;
  bool self_intersections = true;  // the full check (CGAL PMP; costs an AABB pass)
};

struct ValidityCheck {
  std::string name;
  bool hard = true;
  int count = 0;         // elements that fail
  double worst = 0;      // the worst value found (degrees, ratio, ...), 0 if none
  double limit = 0;
  std::string unit;      // "degrees", "mean edge lengths", ...
  int example = -1;      // a failing element (face, edge or vertex index)
  bool passed() const { return count == 0; }
};

struct Validity {
  std::vector<ValidityCheck> checks;
  bool valid() const;            // every hard check passed
  std::string Reason() const;    // the failed hard checks, one line each ("" if valid)
  std::string Warnings() const;  // the failed soft checks
  nlohmann::json ToJson() const;
};

// Checks `output` against `input` (null, or a different topology: no
// relative checks). `full` adds the self-intersection test.
Validity CheckValidity(const Mesh& output, const Mesh* input, const ValidityLimits& limits,
                       bool full);

// Absolute panel shape, whatever the input: faces with more than three sides
// that are not convex in the plane of their Newell normal (a corner bent
// inward, or a bow-tie), and the worst inward bend in degrees (0 if none).
struct PanelShapes {
  int panels = 0;     // faces with more than three sides
  int nonconvex = 0;
  double worst_reflex_degrees = 0;
};
PanelShapes MeasurePanelShapes(const Mesh& mesh);

}  // namespace archgeo
