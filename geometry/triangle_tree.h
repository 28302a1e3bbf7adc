// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the AABB tree of a triangle mesh's faces for closest-point
// queries (geometry/reference.cpp, analysis/metrics.cpp), built with CGAL's search
// tree for each query's first bound.
#pragma once

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include "mesh/surface_mesh.h"

namespace archgeo {

using TrianglePrimitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using TriangleTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, TrianglePrimitive>>;

// Fills `tree` (empty) with the faces of `triangles` (triangles only; it must
// outlive the tree) and builds it and its search tree (what
// accelerate_distance_queries() builds: a k-d tree of one point per
// triangle, the target of its halfedge) at once, each build serial on a
// thread of its own. The two write disjoint members of the tree (CGAL 5.5's
// build() its nodes and primitives, accelerate_distance_queries(first,
// beyond) its search tree).
void BuildTriangleTree(const Mesh& triangles, TriangleTree* tree);

}  // namespace archgeo
