// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the steps of spectral/morse_smale.h shared by its files.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "spectral/morse_smale.h"

namespace archgeo {
namespace morse_smale {

// One separatrix while the complex is built: from a saddle's wedge to an
// extremum, `guide` the path proposed (steepest, or rerouted through
// cancelled pairs).
struct Draft {
  int saddle = 0;  // node index
  bool ascending = true;
  std::vector<int> wedge;  // the ring vertices of its wedge
  std::vector<int> guide;  // vertices, the saddle's first
  int target = 0;          // node index
  bool alive = true;
  // On a double (MorseSmaleMirror): the side the arc runs on, 0 the
  // surface's inner vertices, 1 its boundary, 2 the mirror images' (the
  // arc placed as the image of draft `twin`'s).
  char lane = 0;
  int twin = -1;
  bool connection = false;  // lane 1 from a saddle to a saddle (MsTwins)
};

// f(u) > f(v), ties broken by index (as spectral/critical_points.h).
inline bool Above(const std::vector<double>& f, int u, int v) {
  return f[size_t(u)] > f[size_t(v)] || (f[size_t(u)] == f[size_t(v)] && u > v);
}

// The mesh the arcs are placed on: the input's vertices first, then those
// local refinement adds (edge midpoints, f linear along the edge).
struct ArcMesh {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<int>> rings;  // cyclic, in the input's orientation
  std::vector<double> f;
  MorseSmaleMirror mirror;  // empty unless the mesh is a double
};

// The vertex of the surface (side 0 or 1) among v and its mirror image.
inline int OnSurface(const MorseSmaleMirror& m, int v) {
  return m.side.empty() || m.side[size_t(v)] != 2 ? v : m.image[size_t(v)];
}

// Replaces the drafts' guides by paths that share no vertex with another
// arc or a node (shortest paths where the guide does not); appends the arcs
// to `complex` and counts rerouted and unresolved ones; `unplaced` gets the
// drafts left without a path.
// On a double, the drafts of lanes 0 and 1 are placed on their lanes and
// those of lane 2 as their twins' images.
void EmbedArcs(const ArcMesh& mesh, const std::vector<bool>& node_vertex,
               const std::vector<Draft>& drafts, const std::vector<int>& node_renumber,
               MorseSmaleComplex& complex, std::vector<size_t>& unplaced);

// Splits every edge between two vertices within `width` rings of `seeds`
// at its midpoint, f linear; the guides through a split edge go through
// its midpoint. The region's resolution doubles; no vertex's class changes
// and no midpoint is critical (see morse_smale_refine.cpp). On a double,
// the region and every split are mirrored.
void SplitAround(ArcMesh& mesh, const std::vector<int>& seeds, int width,
                 std::vector<Draft>& drafts);

// Splits the edges of v's link (between consecutive vertices of its ring)
// at their midpoints, as SplitAround: v's valence doubles, so twice as many
// arcs can reach it apart.
void SplitLink(ArcMesh& mesh, int v, std::vector<Draft>& drafts);

// Recomputes the wedges of the drafts' saddles from their (refined) rings;
// each draft keeps the wedge its guide's first step lies in.
void Rewedge(const ArcMesh& mesh, std::vector<Draft>& drafts);

// Whether triangle t's second corner follows its first in the ring of its
// first (v, r_i, r_{i+1} are triangles as oriented), or precedes it.
bool RingsFollowTriangles(const std::vector<std::vector<int>>& rings,
                          const std::array<int, 3>& t);

// The triangles of `rings`, each once: (v, r_i, r_{i+1}) when `forward`,
// (v, r_{i+1}, r_i) otherwise.
std::vector<std::array<int, 3>> TrianglesOfRings(const std::vector<std::vector<int>>& rings,
                                                 bool forward);

// The cells between the arcs and their check; sets shared_vertices,
// invalid_cells and valid. On a double (`mirror` not empty) the check is
// of the cells' halves on the surface's side, cut along the boundary: a
// half that meets the boundary off the arcs has one saddle (the half of a
// cell that is its own mirror image), and a connection along the boundary
// may have one cell of the double on both sides (its halves meet elsewhere
// on the boundary, as round a hole whose critical points are all saddles).
void BuildCells(int vertex_count, const std::vector<std::array<int, 3>>& triangles,
                const MorseSmaleMirror& mirror, MorseSmaleComplex& complex);

}  // namespace morse_smale
}  // namespace archgeo
