// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the named element sets terms act on (core/elements.h), built
// from a mesh. Every set, its vertex order and its site:
//
//   vertices             every vertex with a face; site: the vertex
//   faces                every face, vertices in face order; site: the face
//   triangles, quads     faces with 3 / 4 sides
//   polygons             faces with more than 4 sides
//   non_triangles        faces with more than 3 sides
//   interior_edges       (v, w, a, b): the edge v→w with the face left of it
//                        (`face`, third vertex a when a triangle) and the face
//                        right of it (`other_face`, third vertex b); flags
//                        kLeftPolygon / kRightPolygon when a side has > 3
//                        vertices; site: the edge
//   edge_quads           interior edges between two quads, Shi Fig. 2 labels
//                        (b0 … b5): left face (b0, b1, b2, b3) runs b3 → b0,
//                        right face (b0, b3, b4, b5) runs b0 → b3; site: edge
//   stars                vertices of valence ≥ 3 with their neighbours in
//                        order around them, a boundary gap last (kOpen); site: v
//   fans                 the one-ring of every vertex with an interior edge,
//                        counter-clockwise, an open one from one boundary
//                        neighbour to the other (kOpen); vertices with more
//                        than one boundary gap are left out; site: v
//   polyline_triples     three consecutive vertices along the mesh polylines
//                        (mesh/topology.h MeshPolylines); site: the middle one
//   polyline_quadruples  four consecutive vertices along them; site: 2nd vertex
//   straight_triples     at an interior vertex of even valence k, the k/2
//                        pairs of opposite neighbours (w_j, v, w_{j+k/2}); at a
//                        boundary vertex its two boundary neighbours; site: v
//   umbrella_triples     at every vertex of `fans`: closed, (w_i, v,
//                        w_{i+⌊k/2⌋}) for i < k/2 (k even) or i < k (k odd);
//                        open, (first, v, last); site: v
//   boundary_vertices    the vertices on the boundary; site: the vertex
//   edges                every edge (a, b); `face`: a face at it; site: the
//                        edge; kBoundary only when the edge itself is a
//                        border edge (not when one end is on the boundary)
//   boundary_edges       the border edges, (a, b) along the border halfedge,
//                        so the edges of a loop chain head to tail; site: edge
//   one_rings            every vertex with a face and all its neighbours in
//                        order around it (as `stars`, any valence); site: v
//   valence4_stars       `stars` at interior vertices of valence 4 none of
//                        whose faces is a triangle (conical meshes); site: v
//   triangle_fans        `fans` whose faces are all triangles; site: v
#pragma once

#include <string>
#include <vector>

#include "core/elements.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

// The names above.
const std::vector<std::string>& ElementSetNames();

// Builds the set `name` (one of ElementSetNames(); CHECKed). Sets with the
// kBoundary flag: every element whose site is on the mesh boundary (a
// boundary vertex; a face or edge with a boundary vertex; for `edges` and
// `boundary_edges` a border edge).
ElementSet BuildElementSet(const Mesh& mesh, const std::string& name);

}  // namespace archgeo
