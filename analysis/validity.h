// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — is a result buildable? The checks every output passes before
// `archgeo solve` may exit 0 (README, "Exit codes and guarantees"). A panel
// that cannot be built fails whether or not the input had it; each check
// counts apart the defects the input already had (`inherited`), so that a
// run can tell what the optimisation did from what it was given, and
// `allow_input_defects` (validity.allow_input_defects) exempts those:
//
//   hard:
//     finite            every coordinate finite
//     reflex_corners    panels (faces with ≥ 4 sides) with a corner bent inward
//                       by more than max_reflex_degrees (interior angle
//                       − 180°, in the plane of the face's Newell normal);
//                       inherited where the input's corner was bent so too
//     bow_ties          self-intersecting panels (two non-adjacent sides
//                       cross in that plane); inherited where the input's was
//     flipped_faces     faces whose normal turned by more than
//                       max_flip_degrees against the input's
//     short_edges       edges shorter than min_edge_relative × the input's mean
//                       edge length and than half their input length
//                       (collapsed by the solve); inherited: edges the input
//                       had shorter than 1e-3 × its mean edge length
//     creases           interior edges whose dihedral angle (between the face
//                       normals) grew by more than max_crease_increase_degrees
//                       over the input's
//     self_intersections  pairs of faces of the surface that intersect (CGAL
//                       Polygon_mesh_processing, on a triangulation, exact
//                       predicates), in the full check; only when the input
//                       has none (a surface that crosses itself, as a Klein
//                       bottle must, does so by design)
//   soft (reported as warnings; only what is new in the output):
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
  bool allow_input_defects = false;  // defects the input had too do not fail a check
};

struct ValidityCheck {
  std::string name;
  bool hard = true;
  int count = 0;         // elements that fail
  double worst = 0;      // the worst value found (degrees, ratio, ...), 0 if none
  double limit = 0;
  std::string unit;      // "degrees", "mean edge lengths", ...
  int example = -1;      // a failing element (face, edge or vertex index)
  int inherited = 0;     // elements failing in the input too (in `count` unless allowed)
  std::vector<int> elements;  // the failing elements in index order (at most kMaxListed)
  bool passed() const { return count == 0; }
  static constexpr size_t kMaxListed = 1000;
};

struct Validity {
  std::vector<ValidityCheck> checks;
  bool allow_input_defects = false;  // as checked
  bool valid() const;            // every hard check passed
  // Not valid, and only through defects the input had too: the optimisation
  // made nothing worse (the loop judges its rounds so).
  bool OnlyInherited() const;
  std::string Reason() const;    // the failed hard checks, one line each, with their
                                 // first elements ("" if valid)
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
