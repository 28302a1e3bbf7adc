// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — cancelling needless singularity pairs of a TCD field by local
// field surgery, a step of the field's pre-processing [Gebreiter 2012,
// §8.1.1: noise and curvature estimation give "an undesirable number or badly
// placed singularities"; §8.1.4; Zadravec 2010, §3–4 for the field].
//
// The field of a face is singular where z_N = z_M (proof of Prop. 3), so
// the singularities of a TCD field are the zeros of the spin-2 quantity
// d = z_N − z_M (transported between faces by R(2τ), like ζ = z_N − e1 in
// energies/tcd_dirichlet.h). A ± pair (indices +k and −k) is two zeros of
// opposite winding; around a loop enclosing both, d does not wind. The
// surgery replaces d inside a region U around the pair by the
// connection-harmonic extension of its values on the ring B of faces next
// to U (minimise Σ_e w_e |d_f − R(2τ_fg) d_g|² over the edges touching U,
// d fixed on B: a sparse linear solve) and sets z_N = z_M + d in U. Where d
// keeps to an open half-plane on B (the far field of a close pair does), the
// harmonic extension keeps to it as well (maximum principle), so d has no
// zero in U: the pair is gone and no singularity is created. Faces outside U
// keep z_N exactly.
//
// U: the faces joined to the pair's vertex stars through faces with K > 0
// (z_M inside the auxiliary circle: only there can a singularity be, Prop.
// 4) whose centroid is within r of the segment between the two singular
// vertices,
// r = region × the pair's distance (at least the two stars); tried with
// r/3, 2r/3, r and 2r, the smallest accepted. A try is accepted only if every other singular vertex on U's
// faces belongs to another pair found, with its partner (a cluster of close
// pairs, total index 0, is cancelled together), z_M is finite on U, every new z_N lies inside the auxiliary circle with a
// margin (a TCD pair exists: ‖z_N − e1‖ ≤ 1 − 1e-3) and the field's
// singularities afterwards are exactly the old ones without the pair or
// cluster (same vertices, same indices); otherwise the field is left as it was and the
// pair counts as found, not cancelled. Nothing is deleted from a count: the
// singularities are re-measured from the new field (fields/singularities.h).
//
// Pairs: every two singular vertices of opposite index (+k, −k) whose
// distance (straight, canonical units) is below `max_distance`, matched
// greedily closest first, each vertex in at most one pair; cancelled in that
// order, each on the field left by the previous ones.
//
// Include only where CGAL is acceptable (pulls in mesh/surface_mesh.h).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "fields/tcd_field.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

struct PairCancellationOptions {
  double max_distance = 0;  // pairs closer than this (canonical units); 0 = none
  double region = 1.5;      // U's radius in pair distances (first try)
  // A singularity left closer than this to the boundary (canonical units; 0
  // = none) is pushed out of the domain [Gebreiter 2012, §8.1.1]: the same
  // surgery on U around the segment to the nearest boundary vertex, where d
  // is free along the boundary (no ring there), accepted only if exactly
  // that singularity disappears.
  double boundary_distance = 0;
};

struct CancelledPair {
  int plus_vertex = -1, minus_vertex = -1;  // vertex indices
  double index = 0;                         // of the positive one (+k)
  double distance = 0;                      // canonical units
  bool cancelled = false;
  int faces_changed = 0;                    // |U| of the accepted try (0: none;
                                            // a cluster's pairs share their U)
  double radius = 0;                        // r of the accepted try (canonical units)
  std::string kept_because;                 // why the last try was refused ("" if cancelled)
};

struct PairCancellation {
  std::vector<Eigen::Vector2d> z_n;  // the field after the surgery, per face
  std::vector<CancelledPair> pairs;  // the pairs found, in the order tried
  int found = 0, cancelled = 0;
  int near_boundary = 0, pushed_out = 0;  // singularities closer than boundary_distance
  int faces_changed = 0;             // faces whose z_N changed (union over pairs)
};

// The pairs of `field` (evaluated on `mesh` with `geometry`) closer than
// options.max_distance, cancelled where the surgery succeeds (see above).
// Preconditions (CHECKed by the callees): a triangle mesh without garbage,
// `field` from EvaluateField on it.
PairCancellation CancelSingularityPairs(const Mesh& mesh, const FieldGeometry& geometry,
                                        const TcdField& field,
                                        const PairCancellationOptions& options);

// The ± pairs of `singularities` closer than `max_distance`, matched
// greedily closest first (each vertex in one pair at most); not cancelled.
std::vector<CancelledPair> CloseOppositePairs(const std::vector<Singularity>& singularities,
                                              double max_distance);

// Indices per vertex of the field z_n (the singularities EvaluateField
// would find), without the rest of the evaluation.
std::vector<double> FieldVertexIndices(const Mesh& mesh, const FieldGeometry& geometry,
                                       const std::vector<Eigen::Vector2d>& z_n);

}  // namespace archgeo
