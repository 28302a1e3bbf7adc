// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — topology helpers: boundary, corners, mesh polylines.
#pragma once

#include <array>
#include <vector>

#include "mesh/surface_mesh.h"

namespace archgeo {

// Whether a and b are one mesh, perhaps moved: the same vertex, edge and
// face index ranges, and every face the same cycle of vertex indices (from
// any corner). Equal counts alone do not say it: a remeshed closed surface
// can have the input's counts.
bool SameConnectivity(const Mesh& a, const Mesh& b);

// true for each vertex (indexed by vertex index) on a boundary.
std::vector<bool> BoundaryVertices(const Mesh& mesh);

// Boundary vertices with a single incident face (quad-mesh corners) or where
// the boundary polyline turns by more than 60 degrees.
std::vector<VertexIndex> Corners(const Mesh& mesh);

// Maximal mesh polylines: a polyline continues straight through a regular
// vertex — across an interior vertex of valence 4 (entering by one edge,
// leaving by the opposite one) and along the boundary through a boundary
// vertex of valence 3 — and ends at any other vertex. Every edge lies on
// exactly one polyline. A closed polyline repeats its first vertex at the end.
std::vector<std::vector<VertexIndex>> MeshPolylines(const Mesh& mesh);

// BFS 2-colouring of the vertex graph: 0/1 per vertex index, each connected
// component starting with colour 0 at its smallest vertex index (isolated
// vertices: 0). Edges joining equal colours (an odd cycle) are appended to
// `monochrome_edges` if it is non-null; the colouring is proper iff there are none.
std::vector<int> TwoColouring(const Mesh& mesh, std::vector<int>* monochrome_edges = nullptr);

// Every run of k consecutive vertices along the polylines (k = 3: second
// differences, k = 4: third differences), wrapping around closed polylines;
// polylines with fewer than k distinct vertices give none.
std::vector<std::vector<VertexIndex>> PolylineTuples(
    const std::vector<std::vector<VertexIndex>>& polylines, size_t k);

// PolylineTuples(polylines, 3) as arrays (u, v, w).
std::vector<std::array<VertexIndex, 3>> PolylineTriples(
    const std::vector<std::vector<VertexIndex>>& polylines);

}  // namespace archgeo
