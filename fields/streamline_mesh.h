// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — a quad-dominant polygon mesh from the two families of evenly
// spaced streamlines of a conjugate field [Gebreiter 2012, §8.2
// "streamline-intersection" layout]: vertices where a line of one family
// crosses a line of the other, edges along the lines between crossings,
// faces walked around the planar graph they make on the surface.
//
// Plain Eigen and std (no CGAL), like fields/streamlines.h: the surface is
// the StreamlineInput the lines were traced on.
//
// Method:
//  1. Crossings. Every segment of a line is tested against the segments of
//     the other lines near it (a hash of cells of d_sep): two segments that
//     meet (closest distance below 1e-7 d_sep; segments of one triangle are
//     coplanar) give a node. Nodes closer than 1e-6 d_sep are one (a crossing
//     on a triangle edge is found from both sides; the separatrices of a
//     singularity meet at its vertex).
//  2. Line ends. An end on the boundary of the surface (within 1e-5 d_sep of
//     a boundary edge) is a node there. Any other end (a Jobard–Lefer line
//     stopped beside a line of its family, near a singularity, at its length
//     cap) is extended straight along its last segment by up to
//     `extend` · d_sep: the first line of the other family or boundary edge
//     the extension meets (closest distance below 0.05 d_sep + 0.2 of the
//     distance travelled, the surface curving away from the chord) gets a
//     node, a T-junction. An end that reaches none dangles.
//  3. Graph. Along each line (cyclically for a closed one) consecutive nodes
//     are joined by an edge; along each boundary loop, its nodes and its
//     corners (the boundary turning by more than corner_angle_deg) are joined
//     in the loop's order. Dangling edges (an end of degree 1) are removed,
//     repeatedly; an interior node left on two edges that continue each other
//     (within 30° of straight) is removed and its edges joined.
//  4. Faces. The edges at every node are ordered by angle in its tangent
//     plane (the area-weighted normal of the nearest mesh vertex); faces are
//     walked with the face on the left, taking at each node the first edge
//     clockwise from the one arrived by. Boundary edges are used only in the
//     boundary loop's direction (the surface on their left), so no outer face
//     appears. Cycles that visit a node twice are split into simple faces
//     (fields/layout_cleanup.h SimpleCycles); faces with fewer than three
//     nodes or more than 64 (a region the lines do not divide, e.g. around a
//     boundary loop no line reaches) are dropped and counted.
// A T-junction (a line stopped between two lines of the other family) makes
// a face of five nodes on its open side.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "fields/streamlines.h"

namespace archgeo {

struct StreamlineMeshOptions {
  double extend = 0.75;            // reach of a line end's extension, × d_sep
  double corner_angle_deg = 30.0;  // boundary vertices turning more stay nodes
};

struct StreamlineMesh {
  std::vector<Eigen::Vector3d> points;
  std::vector<bool> on_boundary, is_corner;  // per point
  std::vector<std::vector<int>> faces;       // oriented as the triangles
  // Diagnostics.
  int crossings = 0;          // nodes where two lines cross (after merging)
  int boundary_ends = 0;      // line ends on the boundary
  int extended_ends = 0;      // line ends extended to a line or the boundary (T-junctions)
  int dangling_ends = 0;      // line ends that reached nothing
  int pruned_edges = 0;       // dangling edges removed
  int joined_nodes = 0;       // interior nodes on two straight edges removed
  int dropped_faces = 0;      // cycles with fewer than three nodes, not closed, or too large
  int dropped_large_faces = 0;  // of those: more than 64 nodes (a region no line divides)
};

// Preconditions (CHECKed): d_sep > 0, the input's sizes consistent.
StreamlineMesh MeshFromStreamlines(const StreamlineInput& surface,
                                   const std::vector<Streamline>& lines, double d_sep,
                                   const StreamlineMeshOptions& options = {});

// The angle between the edges of a polygon mesh and the field of `surface`:
// per edge used by two faces (boundary edges excluded), its direction in the
// plane of the valid triangle whose centroid is nearest its midpoint, against
// the nearer of that triangle's lines v and w.
struct EdgeFieldAngle {
  double mean_deg = 0, max_deg = 0;
  int edges = 0;
};
EdgeFieldAngle MeasureEdgeFieldAngle(const StreamlineInput& surface,
                                     const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<std::vector<int>>& faces);

}  // namespace archgeo
