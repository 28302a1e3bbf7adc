// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the one check a soup still needs, after ReadMesh has oriented it
// (io/io.cpp), before its faces are added to a Surface_mesh (which needs a
// polygon mesh: CGAL's is_polygon_soup_a_polygon_mesh).
//
// PMP::is_polygon_soup_a_polygon_mesh checks three things: no face repeats a
// vertex, no ordered edge (a → b) occurs in two faces, and every edge and
// vertex is manifold. After CheckFaceIndices and a PMP::orient_polygon_soup
// that returned true and reported no non-manifold edge or vertex, only the
// second can still fail: an edge whose two faces could not be given opposite
// directions (a non-orientable surface that orient_polygon_soup cut without
// duplicating a vertex) is left as the same ordered edge in both faces, and
// without such edges the soup's edge map and vertex links are the ones
// orient_polygon_soup has already found manifold. tests/test_soup_halfedges.cpp
// checks the two verdicts agree on oriented and non-orientable soups.
//
// CGAL's check keeps the ordered edges in a std::set (a quarter of a second
// for 100k quads); this one sorts each vertex's outgoing edges in place.
#pragma once

#include <cstddef>
#include <vector>

namespace archgeo {

// true if no ordered edge (polygon[i], polygon[i + 1 mod n]) occurs twice in
// `polygons`, whose indices are < num_points.
bool EachOrderedEdgeOnce(const std::vector<std::vector<std::size_t>>& polygons,
                         std::size_t num_points);

}  // namespace archgeo
