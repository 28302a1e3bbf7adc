// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — principal edges of triangle meshes [Pellis 2019, §2.3]: the two
// opposite edges of a valence-6 vertex that follow a principal curvature
// direction; the labels principal_symmetric reads, checks, makes by splitting
// quads, follows through Loop subdivision, and a principal-symmetric test
// torus.
//
// Edge-label file: one principal edge per line as two 0-based vertex indices
// "i j" (whitespace separated); '#' starts a comment; blank lines are ignored.
#pragma once

#include <array>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "mesh/surface_mesh.h"

namespace archgeo {

// An undirected edge as a pair of vertex indices (first < second).
using VertexPair = std::pair<int, int>;
VertexPair Pair(int a, int b);

// An interior valence-6 vertex with principal edges: its star split into the
// two principal and the four other neighbours.
struct PrincipalStar {
  VertexIndex v;
  std::array<VertexIndex, 2> principal;
  std::array<VertexIndex, 4> other;
};

// The stars of the interior valence-6 vertices with principal edges; an
// interior valence-6 vertex with principal edges must have exactly two,
// opposite in its star: the first violation goes to `problem` (if non-null;
// the result is then partial).
std::vector<PrincipalStar> PrincipalStars(const Mesh& mesh, const std::set<VertexPair>& principal,
                                          std::string* problem);

// Reads and validates an edge-label file for `mesh`: a line that is not two
// non-negative integers, names a vertex out of range, a pair that is not an
// edge, or an edge listed twice is an InputError(path, line, key, ...).
std::vector<VertexPair> ReadPrincipalEdges(const std::string& path, const std::string& key,
                                           const Mesh& mesh);

// The star rule above: "" or the first problem.
std::string CheckPrincipalStars(const Mesh& mesh, const std::vector<VertexPair>& principal);

// Splits every quad of `quads` by its first (v0–v2) or second (v1–v3)
// diagonal (`second_diagonal`); other faces are kept. `principal` selects the
// principal family: "diagonals" (the new diagonals), "first" or "second" (a
// family of quad edges, "first" being that of the first edge (v0–v1) of the
// first quad, propagated to opposite edges across quads); the labelled edges
// are returned in *labels (vertex indices are unchanged). Throws
// InputError(file, 0, key, ...) if a face has more than four sides or the
// quad-edge families are inconsistent (a singular vertex joins them).
Mesh SplitQuads(const Mesh& quads, bool second_diagonal, const std::string& principal,
                std::vector<VertexPair>* labels, const std::string& file, const std::string& key);

// Loop subdivision keeps the old vertices' indices and adds one vertex per
// old edge, adjacent to exactly two old vertices: the halves of a principal
// edge are principal. `mesh` is the finer mesh, `labels` the coarser's with
// `old_vertices` vertices. Throws InputError(file, 0, "multiresolution.scheme")
// if `mesh` is not a Loop subdivision.
std::vector<VertexPair> FollowLoopSubdivision(const Mesh& mesh, const std::vector<VertexPair>& labels,
                                              int old_vertices, const std::string& file);

// A principal-symmetric torus triangle mesh (R, r, 0 < r < R): n_v rings
// along the parallels v_j = 2π j/n_v, n_u vertices each at u = 2π(i + j/2)/n_u
// (every ring turned by half a step); vertex (i, j) has index j·n_u + i.
// The ring edges (parallels, curvature lines) are principal and returned in
// *principal; the other four neighbours of a vertex are symmetric to them
// about its meridian plane, hence co-spherical. Outward normals. If
// noise > 0, every vertex moves by a uniform random vector of length ≤ noise
// × the mean edge length (seeded by `seed`). Preconditions (InputError
// otherwise): 0 < r < R, n_u ≥ 3, n_v ≥ 4 even, noise ≥ 0.
Mesh PrincipalSymmetricTorus(double R, double r, int n_u, int n_v, double noise, unsigned seed,
                             std::vector<VertexPair>* principal);

}  // namespace archgeo
