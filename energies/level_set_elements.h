// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The per-element data of the level-set terms (level_set_*.h), shared by the
// terms' adders and the problems that build their element sets
// (problems/declarations/level_sets.cpp). Not a cost functor.
//
// Blocks (global, declared by the problem): "level_set_g", "level_set_h" —
// one value per wedge of the cut graph (fields/cuts.h; one per vertex without
// a cut), lengths in the canonical frame; "level_set_alpha_g",
// "level_set_alpha_h" — one jump constant α_C per cut chain.
//
// Element sets:
//   level_set_faces          one per triangle; face = the triangle, site = the
//                            face; vertices = its corner vertices (h0, h1, h2
//                            of fields/face_frames.h FaceCorners2D); data below
//   level_set_jumps          one per jump relation g[left] = α_C + s g[right]
//                            with left ≠ right; site = the cut vertex
//   level_set_branch_points  one per relation with left = right (the source of
//                            a singularity cut); site = the vertex
//   level_set_boundary_edges one per boundary edge of a boundary row
//                            (fields/boundary_rows.h); site = the edge's face
#ifndef ARCHGEO_ENERGIES_LEVEL_SET_ELEMENTS_H_
#define ARCHGEO_ENERGIES_LEVEL_SET_ELEMENTS_H_

namespace archgeo::level_set_data {

// level_set_faces: corners (x0, y0, x1, y1, x2, y2) in the face frame,
// counter-clockwise; v and w, the (oriented) field directions for g and h in
// the face frame, (0, 0) where the field is undefined (the alignment terms
// then reduce to the Dirichlet energy, λ_even); the wedge of each corner;
// m11, m12, m22 of M_f; 1 / A_Φ (total area).
inline constexpr int kCorners = 0, kV = 6, kW = 8, kWedges = 10, kM = 13, kInvArea = 16;
inline constexpr int kFaceWidth = 17;

// level_set_jumps: left wedge, right wedge, chain, s for g, s for h, 1/L.
// level_set_branch_points: wedge, (unused), chain, s for g, s for h, 1/L.
inline constexpr int kLeft = 0, kRight = 1, kChain = 2, kSignG = 3, kSignH = 4, kInvLength = 5;
inline constexpr int kRelationWidth = 6;

// level_set_boundary_edges: the wedges of the edge's two corners in its face,
// the function held (0 = g, 1 = h), 1/L. Block "level_set_boundary_zero": one
// constant 0 (the α of a relation g_a = 0 + g_b).
inline constexpr int kWedgeA = 0, kWedgeB = 1, kFunction = 2, kBoundaryInvLength = 3;
inline constexpr int kBoundaryWidth = 4;

}  // namespace archgeo::level_set_data

#endif  // ARCHGEO_ENERGIES_LEVEL_SET_ELEMENTS_H_
