// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — cuts for multivalued level-set functions [Zadravec 2010, §5
// "Quad meshes from a TCD field with singularities"]: a set of mesh edges
// that joins every singular vertex to the boundary and makes the surface
// simply connected, and the per-corner ("wedge") representation of functions
// that jump across it.
//
// Construction (ComputeCutGraph):
//  1. Singularity cuts. The singular vertices are taken in order of their
//     distance to the boundary; each is joined by a shortest edge path
//     (Dijkstra, edge lengths) to the nearest vertex of the boundary or of a
//     cut already made (on a closed surface the first singular vertex is the
//     root). Joining an existing cut instead of always running to the
//     boundary gives shorter cuts; the union is a forest in which every tree
//     touches the boundary in one vertex (or is the root's tree), so it does
//     not disconnect the surface.
//  2. Topology cuts (tree–cotree). A spanning tree of the dual graph (faces,
//     adjacent through interior edges that are not cut yet) is grown by
//     breadth-first search; the interior edges it does not cross are added to
//     the cut, which is then pruned: an added edge with an endpoint of cut
//     degree 1 that is neither on the boundary nor singular is removed,
//     repeatedly. What remains joins the holes to the outer boundary (and
//     contains 2g loops for genus g). Cutting along the result leaves a
//     topological disk per connected component.
//  3. Chains. The cut edges are split into chains at nodes: vertices of cut
//     degree ≠ 2, boundary vertices and singular vertices (a closed loop
//     without a node starts at its smallest vertex). A chain C is a sequence of
//     halfedges h_1 … h_k, source(h_{i+1}) = target(h_i); its left side is
//     face(h_i), its right side face(opposite(h_i)).
//
// Representation of a function that jumps across the cut (for the variable
// blocks of phase-2 solves and for fields/extract.h):
//  - Corners. The corner of face f at vertex v is the halfedge h with face(h)
//    = f and target(h) = v (CGAL's convention); corner_wedge[h] is its wedge.
//  - Wedges. The corners around a vertex are split into wedges by the cut
//    edges at v (and by the boundary): consecutive corners around v share a
//    wedge unless the edge between them is cut. A vertex off the cut has one
//    wedge; an interior vertex with k ≥ 1 cut edges has k wedges (the source
//    of a singularity cut, k = 1, has ONE wedge whose two sides meet at the
//    cut edge; a singular vertex that later cuts join has k > 1 wedges, whose
//    relations around it then fix their values the same way); a boundary
//    vertex with k interior cut edges has k + 1. A
//    function g is one value per wedge (g on face f is linear with the values
//    of its three corners' wedges).
//  - Relations. For every chain C and every vertex v of C, the wedge of the
//    left-side corner and the wedge of the right-side corner at v satisfy
//    g[left] = α_C + s_C · g[right] (level_set_jump.h), s_C = ±1 the field's
//    matching across C (fields/cut_jumps.h OrientField), α_C one constant per chain and function.
//    Relations are listed once per (left wedge, right wedge, chain); left ==
//    right (the source vertex of a singularity cut) is level_set_branch_point.h.
//    At a node where several chains meet, composing the relations around the
//    node constrains the α's of those chains (their combination must be the
//    identity for a regular node); a solve satisfies this softly, and the
//    rounding of α must respect it (fields/cut_jumps.h JumpConstraints,
//    RoundJumps).
//
// Include only where CGAL is acceptable (pulls in mesh/surface_mesh.h).
#pragma once

#include <vector>

#include "mesh/surface_mesh.h"

namespace archgeo {

struct CutChain {
  std::vector<HalfedgeIndex> halfedges;  // in chain order (see the file comment)
  VertexIndex start, end;                // source of the first, target of the last
  bool from_singularity = false;         // start or end is a singular vertex
};

struct JumpRelation {
  int left_wedge = -1, right_wedge = -1;  // equal at a branch point
  int chain = -1;
  VertexIndex vertex;
};

struct CutGraph {
  std::vector<bool> is_cut_edge;       // per edge index
  std::vector<int> edge_chain;         // per edge index: chain id, −1 if not cut
  std::vector<CutChain> chains;
  int num_wedges = 0;
  std::vector<int> corner_wedge;       // per halfedge index; −1 for border halfedges
  std::vector<VertexIndex> wedge_vertex;  // per wedge
  std::vector<JumpRelation> relations;
  std::vector<VertexIndex> singular_vertices;  // as given (deduplicated)
};

// The cut of the file comment. `singular_vertices`: the vertices with a
// nonzero index (fields/singularities.h); boundary vertices among them are
// ignored (no cut needed). Precondition (CHECKed): triangle mesh without
// garbage, valid vertex indices.
CutGraph ComputeCutGraph(const Mesh& mesh, const std::vector<VertexIndex>& singular_vertices);

// The wedges, chains and relations of a given set of cut edges (per edge
// index; boundary edges must be false). `singular_vertices` become nodes and
// mark chains from_singularity.
CutGraph CutGraphFromEdges(const Mesh& mesh, const std::vector<bool>& cut_edges,
                           const std::vector<VertexIndex>& singular_vertices = {});

// Number of connected components of the surface cut open along the cut, and
// its Euler characteristic V − E + F counted on the cut surface (wedges as
// vertices, cut edges twice): 1 per component when every component is a disk.
struct CutSurfaceTopology {
  int components = 0;
  int euler_characteristic = 0;
};
CutSurfaceTopology CutSurface(const Mesh& mesh, const CutGraph& cut);

}  // namespace archgeo
