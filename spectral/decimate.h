// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — decimation of a triangulated design surface to a base complex
// (Gebreiter 2012, §3.1.1, with the operations of §3.1.2): "vertices are
// eliminated in reverse order of geometric importance, [so] vertices of the
// coarse mesh will be aligned with features of the input mesh", by
// collapses that discourage anisotropy of the base complex's elements.
//
//  - Importance of a vertex v on the current mesh (recomputed after every
//    collapse on the vertices whose one ring changed), scale-free:
//        I(v) = |K_v| / A_v · h_v²  +  |H_v| · h_v
//    K_v the angle defect (2π − Σθ inside, π − Σθ on the boundary: the
//    turning of the boundary), A_v the barycentric area (a third of the
//    incident triangles'), H_v = (Hn_v · n_v) / (2 A_v) with the cotangent
//    mean-curvature normal Hn_v = ½ Σ_j (cot α_ij + cot β_ij)(x_v − x_j)
//    (Meyer et al. 2003; only its normal part, so a flat boundary scores 0),
//    h_v the mean length of the edges at v. Both terms are dimensionless.
//  - The error of a half-edge collapse u → v (Garland & Heckbert 1997, with
//    the kept vertex at v: the nodes stay input vertices, on the surface):
//    (Q_u + Q_v)(x_v), Q the sum of the plane quadrics of the input
//    vertices collapsed into the vertex, each the area-weighted squared
//    distance to the planes of its input triangles, plus, at a boundary
//    edge, 10 |e|² times that to the plane through the edge perpendicular to
//    its triangle (the boundary keeps its course).
//  - Order (`error_driven`, the default): the vertex u of least key
//        E(u) · (1 + importance_weight · I(u))  +  10⁻⁹ · I(u) · l⁴
//    goes first (E(u) the least error of an admissible collapse of u, l the
//    input's mean edge length: collapses of no error, on a plane or along a
//    straight crease, go by importance), into the neighbour of least error,
//    of those the one whose new triangles have the largest minimum angle.
//    With `error_driven` false, the order of the thesis alone: the least
//    important vertex first, into the neighbour whose new triangles have the
//    largest minimum angle (isotropy).
//  - A collapse is refused if it breaks the link
//    condition (N(u) ∩ N(v) = the vertices opposite edge uv; so a closed
//    surface keeps its genus and stays manifold), leaves a vertex of
//    valence < 3 (< 2 on the boundary) or v more than 2 above its input
//    valence, turns a triangle's normal by more than
//    `max_normal_turn_degrees`, puts it more than
//    `max_normal_deviation_degrees` from its corners' input vertex normals,
//    makes it degenerate, or makes a triangle's smallest angle less than
//    `min_angle_degrees` and less than it was. A boundary vertex collapses
//    only along a boundary edge (the boundary keeps its loops and its
//    vertices stay on it); a boundary corner (the boundary turns there by
//    more than `corner_degrees` on the input), a feature corner (an inner
//    vertex of angle defect above `corner_degrees`: a cube's corner) and any
//    vertex in `locked` never collapse. A vertex with no admissible collapse
//    waits until its one ring changes.
//  - The error level: the largest RMS distance sqrt(Q_v(x_v) / area of Q_v)
//    of a kept vertex after a collapse so far. Every flip below moves the
//    surface (the distance between the two diagonals) by less than
//    `flip_error_factor` times it, and every relocation leaves the node's
//    RMS distance within `relocation_error_factor` times it (or within its
//    own): the shape operations cost no more accuracy than the collapses
//    did (on a plane, no flip until a collapse has made an error).
//  - After each collapse, valence-improving flips on the edges around the
//    kept vertex (§3.1.2: "edges are flipped if the result leads to an
//    overall increase in regularity"): Σ (valence − ideal)² over the four
//    vertices drops (ideal 6 inside, 4 on the boundary) and the smallest
//    angle keeps 80%, or stays and the smallest angle grows; no valence
//    above the input's (the charts' paths leave a node along distinct
//    surface edges), normals within the bounds above.
//  - Every collapse removes one vertex: the target count is met exactly
//    unless every remaining vertex is refused (`reached` false).
//  - Then, for the charts (a sliver triangle gives a thin chart, sampled
//    into folded quads), `shape_rounds` rounds of two operations of §3.1.2
//    until one changes nothing: vertex relocation — each node not locked
//    moves to the input vertex of its own region (the input vertices
//    collapsed into it; a boundary node along the boundary only, an inner
//    one inside only; at least half as important on the input, so a node on
//    a feature stays there) whose triangles have the largest smallest angle,
//    when larger, within the normal and error-level bounds above and the
//    vertex's input valence —
//    and flips of slivers: an edge whose two triangles' smallest angle is
//    below `sliver_degrees` flips when that angle grows (valences from 3, 2
//    on the boundary, to 2 above the input's, as for the collapses; normals
//    and the surface's move within the bounds above).
//
// Plain arrays in, plain structs out (no CGAL): the nodes are surface vertex
// ids, as BaseComplex (spectral/base_complex_charts.h) takes them.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "spectral/base_complex_charts.h"

namespace archgeo {

struct DecimateOptions {
  int target_vertices = 0;               // vertices to keep (≥ 3)
  double corner_degrees = 30;            // boundary turning angle, or inner angle defect, that locks a vertex
  double max_normal_turn_degrees = 60;   // largest turn of a triangle normal in one collapse
  double max_normal_deviation_degrees = 60;  // triangle normal against its corners' input normals
  double min_angle_degrees = 10;         // no collapse makes a triangle sharper than this (and than before)
  int shape_rounds = 10;                 // rounds of node relocations and sliver flips after the collapses
  double sliver_degrees = 20;            // a triangle with a smaller angle is a sliver
  std::vector<int> locked;               // further surface vertex ids that stay
  bool error_driven = true;              // order by the collapses' quadric error (false: by I(v) alone)
  double importance_weight = 1;          // error-driven key: error · (1 + importance_weight · I(v))
  double flip_error_factor = 1;          // a flip moves the surface by less than this × the error level (< 0: off)
  double relocation_error_factor = 1;    // a relocation stays within this × the error level (< 0: off)
};

struct DecimateResult {
  std::vector<int> nodes;                       // surviving surface vertex ids, ascending
  std::vector<std::array<int, 3>> triangles;    // node indices, oriented as the input
  std::vector<int> representative;              // per input vertex: the node it went into (−1: unused)
  std::vector<double> importance;               // per input vertex: I(v) on the input
  std::vector<char> corner;                     // per input vertex: a locked boundary or feature corner
  int corners = 0;                              // locked boundary corners
  int feature_corners = 0;                      // locked inner vertices of angle defect > corner_degrees
  int boundary_loops = 0;                       // of the input (and of the result)
  bool reached = false;                         // nodes.size() == target_vertices
  int refused = 0;                              // collapse candidates refused on the way
  int flips = 0;                                // valence-improving flips
  int relocations = 0, shape_flips = 0;         // of the shape rounds

  // The result as a base complex for ChartQuads: nodes and triangles.
  BaseComplex Complex() const;
};

// `triangles`: a manifold, consistently oriented triangle mesh on `points`
// (closed or with boundary); vertices used by no triangle are ignored.
// Throws std::invalid_argument for a target below 3 or above the used
// vertex count, or an edge on more than two triangles.
DecimateResult Decimate(const std::vector<Eigen::Vector3d>& points,
                        const std::vector<std::array<int, 3>>& triangles,
                        const DecimateOptions& options);

// Per vertex of `triangles`: I(v) as above (0 for unused vertices).
std::vector<double> VertexImportance(const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<std::array<int, 3>>& triangles);

// How the decimated mesh's irregular vertices sit against the input's
// features (issue 43's acceptance). Irregular: valence ≠ 6 inside, ≠ 4 on the
// boundary. Curvature extrema: input vertices whose importance summed over
// the edge-graph ball of radius r/2 is the largest within radius r (ties to
// the lower id), r the decimated mesh's mean edge length. A node is near a
// feature when it or one of its decimated neighbours is the representative
// of a curvature extremum or is a locked boundary corner.
struct FeatureProximity {
  int nodes = 0, irregular = 0;
  int irregular_near = 0;  // irregular nodes near a feature
  int near = 0;            // all nodes near a feature (the chance level)
  int extrema = 0;         // curvature extrema on the input
};
FeatureProximity MeasureFeatureProximity(const std::vector<Eigen::Vector3d>& points,
                                         const std::vector<std::array<int, 3>>& triangles,
                                         const DecimateResult& result);

}  // namespace archgeo
