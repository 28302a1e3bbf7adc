// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — a quad-dominant polygon mesh from two level-set functions on a
// triangle mesh [Zadravec 2010, §5]: vertices at the crossings of the level
// sets g = iΔw and h = jΔw', edges along the level sets between crossings,
// faces the cells between consecutive levels.
//
// Input: g and h per wedge of a cut graph (fields/cuts.h; per vertex without
// cut), the jump constants α per chain and the matching signs s per chain
// (g_left = α + s g_right), the spacings Δw, Δw'.
//
// Method (a slicing of the triangles, then a merge):
//  1. Consistency. Values are taken in spacing units (u = g/Δw, v = h/Δw');
//     every α_C/Δw must be an integer (the rounded jumps of §5). The wedge
//     values are projected onto the jump relations exactly (per connected
//     group of related wedges: all values as a + b·x, a integer, b = ±1, x the
//     group's least-squares value, or fixed by a branch point: x = k/2;
//     fields/cut_jumps.h ProjectOntoJumps); the
//     largest change must stay below `jump_tolerance` spacings. Values within
//     `snap_tolerance` of an integer are then set to it, so "on a level" is
//     exact and the same on both sides of a cut.
//  2. Crossings on edges. Every mesh edge gets its level crossings (u or v
//     integer strictly between the end values; a u- and a v-crossing closer
//     than 1e-10 in the edge parameter are one point), computed once from one
//     incident face; the other face maps their level indices through the
//     chain's transition (u → k + s u), so both sides agree exactly.
//  3. Slicing. Each triangle (as the polygon of its corners and edge
//     crossings) is split by the lines u = i, then v = j (a linear function on
//     a convex polygon: at most two sign changes; on-level points have exact
//     values). New points appear only where a v-level crosses a u-chord: the
//     crossings (i, j) inside triangles.
//  4. Faces. Pieces are merged across triangle edges unless the edge piece
//     lies on a level; each merged region is one face. Its boundary is walked
//     around vertices through the merged pieces and keeps only the output
//     vertices: crossings (i, j) (inside triangles, on edges, at mesh
//     vertices), points where a level meets the boundary, boundary corners
//     (turn > corner_angle_deg), and mesh vertices where a level line
//     branches or ends (level-set degree ∉ {0, 2}: singular vertices).
//     Slits (a level line ending inside a face, e.g. at a +1/2 singularity
//     with odd rounding) are removed (a, b, a → a). Faces with fewer than 3
//     vertices (a thin sliver between a level line and the boundary, or the
//     2-gon of a +1/2 singularity with both levels odd) are dropped; their
//     neighbours then share the edge. Regions with several boundary loops
//     that carry vertices (not disks) are dropped and counted; a boundary
//     that visits a vertex twice (a region pinched there) is split into
//     simple faces.
//     What a singularity becomes (tests/test_field_extract.cpp; the index of
//     a vertex of valence k is (4 − k)/4, of a face of degree k (4 − k)/4):
//       +1/2: g, h even: a valence-2 vertex; one odd: a triangle and a
//             valence-3 vertex; both odd: two valence-3 vertices (2-gon dropped);
//       −1/2: both even: a valence-6 vertex; one odd: a valence-3 vertex
//             between three pentagons; both odd: a hexagon.
//  5. Boundary: faces are clipped at the boundary of the surface — a face
//     along the boundary runs along it from one level-set end to the next
//     with a straight edge, keeping only corner vertices of the boundary.
//  6. Clean-up: output vertices joined by an edge shorter than merge_fraction
//     times the median edge length are merged (boundary vertices keep their
//     position); an interior vertex joined to a boundary vertex by an edge
//     shorter than boundary_snap_fraction times the median is moved onto the
//     nearest such vertex (a level crossing just inside the boundary: the
//     small triangle it cuts off disappears); a boundary edge shorter than
//     half that is collapsed (a corner keeps its place, else the midpoint);
//     a boundary vertex then used by a
//     single face with more than four vertices (not a boundary corner) is
//     dissolved from it; with merge_valence_two, an interior vertex on two
//     faces only (valence 2) is removed and the two faces merged into one
//     (two quads: a quad, whose corners at the valence-2 vertex's neighbours
//     then have valence 3 — the both-odd configuration of a +1/2
//     singularity); with cap_angle_deg, an interior triangle with a corner
//     above it (three vertices nearly on a line, e.g. between two
//     singularities closer than the spacing) is merged into the face across
//     its longest side; with slit_angle_deg, a corner whose two sides leave
//     within that angle of each other (two level lines side by side from a
//     singular vertex: a near-slit) leaves its face, the longer side split at
//     the shorter side's end in the face across; with reflex_margin_deg ≥ 0,
//     a face bent inward at an interior vertex by more than that is split
//     along a diagonal from the corner (both parts turning as the face does,
//     convex corners at both ends, parts of four vertices preferred;
//     fields/layout_cleanup.h); then the polygon soup becomes a CGAL Surface_mesh
//     (PMP::polygon_soup_to_polygon_mesh; non-manifold vertices are
//     duplicated by PMP::orient_polygon_soup and counted).
//
// The faces keep the orientation of the triangle mesh.
//
// Include only where CGAL is acceptable (pulls in mesh/surface_mesh.h).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fields/cuts.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

struct LevelSetFunctions {
  const CutGraph* cut = nullptr;       // nullptr: no cut, one value per vertex
  std::vector<double> g, h;            // per wedge (per vertex without cut)
  std::vector<double> alpha_g, alpha_h;  // per chain, in function units
  std::vector<int> sign_g, sign_h;       // per chain, ±1
  double spacing_g = 1.0, spacing_h = 1.0;  // Δw, Δw' > 0
};

struct ExtractOptions {
  // Output vertices joined by an edge shorter than this fraction of the median
  // output edge length are merged (no zero-length edges).
  double merge_fraction = 0.05;
  // Boundary vertices where the boundary turns by more than this (degrees)
  // are kept as vertices of the boundary faces.
  double corner_angle_deg = 30.0;
  // Largest change (in spacings) the projection onto the jump relations may
  // make before the input is rejected.
  double jump_tolerance = 0.05;
  // Values within this (in spacings) of an integer are set to it.
  double snap_tolerance = 1e-9;
  // An interior vertex joined to a boundary vertex by an edge shorter than
  // this fraction of the median edge length is moved onto it (step 6): the
  // small triangle a level crossing near the boundary cuts off disappears and
  // its neighbours become quads. 0: off.
  double boundary_snap_fraction = 0.0;
  // Interior vertices of valence 2 are removed by merging their two faces
  // (step 6): no two corners of about 180° at one vertex.
  bool merge_valence_two = false;
  // A triangle with a corner above this (degrees: its vertices nearly on a
  // line) is merged into the face across its longest side (step 6). 0: off.
  double cap_angle_deg = 0.0;
  // A corner whose two sides leave within this angle (degrees) of each other
  // is removed from its face, the longer side split at the shorter side's
  // end in the face across (step 6). 0: off.
  double slit_angle_deg = 0.0;
  // A face whose corner at an interior vertex exceeds 180° + this (degrees,
  // in the plane of its Newell normal) is split along a diagonal from that
  // corner (step 6). Negative: off.
  double reflex_margin_deg = -1.0;
};

struct Extraction {
  bool ok = false;
  std::string error;  // why !ok (jumps not integral or inconsistent, no face cut out)
  Mesh mesh;          // the quad-dominant mesh
  int quads = 0, triangles = 0, pentagons = 0, other_faces = 0;
  std::map<int, int> face_degrees;               // degree → count
  std::map<int, int> valence;                    // all vertices: valence → count
  std::map<int, int> interior_valence;           // interior vertices only
  std::vector<VertexIndex> irregular_interior_vertices;  // valence ≠ 4
  std::vector<FaceIndex> irregular_interior_faces;       // degree ≠ 4, no boundary vertex
  // Diagnostics.
  double max_jump_correction = 0.0;  // in spacings (step 1)
  int merged_vertices = 0;           // removed by step 6 (short edges)
  int snapped_vertices = 0;          // moved onto the boundary by step 6
  int dissolved_vertices = 0;        // boundary vertices left on one face only (step 6)
  int merged_valence_two = 0;        // interior valence-2 vertices removed (step 6)
  int merged_caps = 0;               // cap triangles merged into a neighbour (step 6)
  int removed_slits = 0;             // near-slit corners removed (step 6)
  int split_reflex_corners = 0;      // faces split at a reflex corner (step 6)
  int collapsed_boundary_edges = 0;  // boundary edges < boundary_snap_fraction / 2 (step 6)
  int dropped_small_faces = 0;       // fewer than 3 vertices (step 4)
  int dropped_non_disk_regions = 0;  // several loops with vertices (step 4)
  int duplicated_vertices = 0;       // non-manifold fixes (step 6)
  int anomalies = 0;                 // numerically inconsistent splits or gluings (should be 0)
};

// Preconditions (CHECKed): a triangle mesh without garbage; sizes of g, h,
// alpha_*, sign_* match the cut (or the vertex count); spacings > 0; signs ±1.
Extraction ExtractQuadMesh(const Mesh& triangles, const LevelSetFunctions& functions,
                           const ExtractOptions& options = {});

// Steps 6 and the counts for a layout made otherwise (e.g. the crossings of
// streamlines, fields/streamline_mesh.h): a polygon soup whose faces are
// oriented as the surface, per point whether it lies on the boundary and is a
// boundary corner. Not ok when no face is left.
Extraction LayoutFromSoup(std::vector<Eigen::Vector3d> points, std::vector<bool> on_boundary,
                          std::vector<bool> is_corner, std::vector<std::vector<int>> faces,
                          const ExtractOptions& options = {});

}  // namespace archgeo
