// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the Morse–Smale complex of a function on the vertices of a closed
// triangle mesh (Gebreiter 2012, §7.1; Edelsbrunner et al. 2001; Dong et al.
// 2006), built along mesh edges:
//  1. from each saddle one steepest ascending (descending) path per upper
//     (lower) wedge of its one-ring, each step to the highest (lowest)
//     neighbour, up to the maximum (minimum) it reaches;
//  2. saddle–extremum pairs joined by exactly one separatrix cancelled, the
//     least persistent |f(saddle) − f(extremum)| first, down to a threshold
//     or a number of extrema; the other saddles' arcs into the cancelled
//     extremum rerouted through the pair to its partner;
//  3. saddle–saddle connections: a path that runs onto another saddle s
//     (enters its ring from the other side) goes on round s's ring to the
//     neighbouring wedge and along s's separatrix from there, the side
//     chosen as a perturbation of the function would (the two ends of one
//     connection turn the same way round their rings);
//  4. the degeneracies of §7.1.3: arcs are placed one by one; an arc whose
//     path meets an arc already placed, a node or another saddle's one-ring
//     before its extremum (merging separatrices, saddle–saddle connections,
//     the rerouted arcs) keeps its path up to there and goes on by the
//     shortest path (edge lengths) over free vertices, alongside the rest of
//     its path first; what has no such path is left out and counted
//     `unresolved` (passes that place those saddles first try again, and
//     place an arc again when it cuts off one still to come from its
//     extremum); then the mesh is refined around those arcs' guides (edges
//     split at their midpoints, f linear: the same surface and critical
//     points; their extrema's valence doubled) and every arc placed again,
//     up to three rounds, the round with the fewest arcs left out kept;
//  5. cells: the triangles between the arcs, each checked to be a disc with
//     four distinct corners max, saddle, min, saddle.
// Plain arrays in, plain structs out.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

namespace archgeo {

struct MorseSmaleNode {
  int vertex = 0;
  int kind = 0;          // +1 maximum, −1 minimum, 0 saddle
  int multiplicity = 0;  // saddles: m − 1 for 2m sign changes around the ring
};

struct MorseSmaleArc {
  int saddle = 0, extremum = 0;  // node indices
  bool ascending = true;
  std::vector<int> path;         // vertices, the saddle's first, the extremum's last
  std::array<int, 2> side_cells{{-1, -1}};  // the cells on either side of its first edge
  int side = 0;  // on a double: 0 on the surface, 1 along its boundary, 2 on the images
};

struct MorseSmaleCell {
  std::vector<int> corners;  // node indices on the cell's closure
  int euler = 0;             // V − E + F of the closure: 1 for a disc
  bool slit = false;         // an arc with this cell on both sides
  bool valid = false;        // a disc with corners max, min and two saddles (on a double: BuildCells)
};

struct MorseSmaleComplex {
  // The mesh the arcs and cells live on: the input's vertices (same indices)
  // followed by the midpoints local refinement added, on the input's edges
  // (`values`: f, linear along them), and its triangles (the input's when
  // nothing was refined).
  std::vector<Eigen::Vector3d> points;
  std::vector<double> values;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> mirror_image;  // on a double: per point its mirror image (MorseSmaleMirror)
  int refinements = 0;  // rounds of local refinement
  std::vector<MorseSmaleNode> nodes;  // the remaining nodes (cancelled ones dropped)
  std::vector<MorseSmaleArc> arcs;    // per saddle, in the cyclic order of its wedges
  std::vector<MorseSmaleCell> cells;
  std::vector<int> cell_of_triangle;
  int maxima = 0, minima = 0, saddles = 0;  // saddles counted by multiplicity
  int cancelled = 0;   // saddle–extremum pairs
  int rerouted = 0;    // arcs replaced by shortest paths
  int unresolved = 0;  // arcs with no path clear of the others (left out of `arcs`)
  int shared_vertices = 0;  // vertices on two arcs, or an arc through a node
  int invalid_cells = 0;
  bool valid = false;  // no unresolved arc, no shared vertex, every cell valid
};

struct MorseSmaleOptions {
  double persistence = 0;  // cancel pairs with |f(s) − f(e)| ≤ this
  int target_extrema = 0;  // or cancel until max + min ≤ this (0: no target)
};

// A closed mesh that is a surface with boundary doubled across it (a mirror
// copy glued along the boundary), f the same on a vertex and its image.
// Such a function's complex is mirror-symmetric, its arcs on the boundary
// run along it and none crosses it (the gradient is tangent to a mirror
// line); BuildMorseSmale builds it so: the nodes of the mirror images are
// the images of the surface's, the arcs from the surface's saddles are
// traced and placed on the surface alone (through its inner vertices), the
// arcs of the boundary saddles' wedges that hold a boundary vertex along the
// boundary alone, the mirror images' arcs are the images of the surface's,
// pairs are cancelled with their images and the local refinement is
// mirrored.
struct MorseSmaleMirror {
  std::vector<int> image;   // per vertex its mirror image (itself on the boundary)
  std::vector<char> side;   // per vertex 0 on the surface, 1 on its boundary, 2 an image
};

// `rings[v]`: v's neighbours in cyclic order, `triangles` the same mesh,
// which must be closed (throws std::invalid_argument otherwise); `mirror`
// when the mesh is a double (above).
MorseSmaleComplex BuildMorseSmale(const std::vector<Eigen::Vector3d>& points,
                                  const std::vector<std::array<int, 3>>& triangles,
                                  const std::vector<std::vector<int>>& rings,
                                  const Eigen::VectorXd& f, const MorseSmaleOptions& options,
                                  const MorseSmaleMirror* mirror = nullptr);

// The quasi-dual (§7.1.4): the extrema as vertices, one quad per simple
// saddle (its max, min, max, min in cyclic order), a multi-saddle's polygon
// split by diagonals from its first maximum into quads.
struct QuadBaseComplex {
  std::vector<Eigen::Vector3d> points;
  std::vector<int> nodes;  // per vertex: the mesh vertex of its extremum (a BaseComplex's nodes)
  std::vector<std::array<int, 4>> quads;
  // Per quad, per side k (corner k → k + 1): its edge (the cell of the
  // complex it crosses, or a diagonal); two saddles sharing their extrema
  // give two edges between the same vertices (BaseComplex::edges).
  std::vector<std::array<long, 4>> quad_edges;
  int degenerate_quads = 0;  // a corner repeated (a saddle's two arcs to one extremum)
  int missing_saddles = 0;     // saddles without all their arcs: no quad
  int edges = 0;               // one per cell of the complex (its max–min diagonal), and the diagonals
  int irregular_vertices = 0;  // valence ≠ 4
  int euler = 0;               // V − E + F
};

QuadBaseComplex QuasiDual(const MorseSmaleComplex& complex,
                          const std::vector<Eigen::Vector3d>& points);

// The arcs round each saddle in the cyclic order of its wedges, a maximum's
// first: the quasi-dual's polygon. Saddles joined by a connection along a
// double's boundary (arcs from saddle to saddle, both ways) make one
// polygon, their other arcs round the two (a multi-saddle of the summed
// multiplicity). `cells[k]` the cell between arcs k and k + 1 (−1: none);
// `complete` when the polygon has the 2 (multiplicity + 1) arcs it should.
struct MorseSmalePolygon {
  std::vector<int> arcs;
  std::vector<long> cells;
  bool complete = false;
};
std::vector<MorseSmalePolygon> SaddlePolygons(const MorseSmaleComplex& complex);

// The complex itself as a quad base complex (§7.1.2: every cell a quad max,
// saddle, min, saddle): all its nodes as vertices, one quad per cell,
// oriented as the quasi-dual's (the cyclic order of the saddles' arcs), its
// edges the arcs. For a valid complex whose quasi-dual repeats a corner (a
// saddle with two arcs to one extremum): the cells still have four distinct
// corners. `degenerate_quads` counts cells that are not.
QuadBaseComplex PrimalQuads(const MorseSmaleComplex& complex,
                            const std::vector<Eigen::Vector3d>& points);

}  // namespace archgeo
