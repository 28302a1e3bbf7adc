// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the parameter store.
//
// One CGAL::Surface_mesh holds the topology and every optimisation variable.
// Vertex positions are the mesh's own points; auxiliary variables (face
// normals, offsets, vertex normals, per-face 2-D field variables, per-vertex
// scalars, per-face weights, ...) are property maps of fixed-size double
// blocks (Block<N>). Ceres parameter blocks are raw pointers into these maps,
// so every builder and every energy shares one store.
//
// Pointers stay valid while the topology is unchanged: anything that adds or
// removes elements (subdivision, remeshing, collect_garbage) reallocates the
// property vectors, and a Ceres problem built before must be rebuilt.
//
// Include this only from mesh/ and problems/ (it pulls in CGAL).
#pragma once

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <string>

namespace archgeo {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using VertexIndex = Mesh::Vertex_index;
using FaceIndex = Mesh::Face_index;
using EdgeIndex = Mesh::Edge_index;
using HalfedgeIndex = Mesh::Halfedge_index;

template <int N>
using Block = std::array<double, N>;
using Vec3 = Block<3>;

// Simple_cartesian<double> stores a point as std::array<double, 3> without a
// handle, so a point is three contiguous doubles Ceres can optimise in place.
static_assert(sizeof(Point) == 3 * sizeof(double), "Point_3 must be 3 packed doubles");

inline double* PositionBlock(Mesh& mesh, VertexIndex v) {
  return const_cast<double*>(&mesh.point(v).x());
}
inline const double* PositionBlock(const Mesh& mesh, VertexIndex v) { return &mesh.point(v).x(); }

inline Vec3 ToVec3(const Point& p) { return {p.x(), p.y(), p.z()}; }

// The length of halfedge `h`'s edge, and of edge `e`.
inline double EdgeLength(const Mesh& mesh, HalfedgeIndex h) {
  return std::sqrt(CGAL::squared_distance(mesh.point(mesh.source(h)), mesh.point(mesh.target(h))));
}
inline double EdgeLength(const Mesh& mesh, EdgeIndex e) { return EdgeLength(mesh, mesh.halfedge(e)); }
// The mean edge length (0 for a mesh without edges).
inline double MeanEdgeLength(const Mesh& mesh) {
  double sum = 0.0;
  for (EdgeIndex e : mesh.edges()) sum += EdgeLength(mesh, e);
  return mesh.number_of_edges() > 0 ? sum / mesh.number_of_edges() : 0.0;
}
inline Point ToPoint(const Vec3& v) { return Point(v[0], v[1], v[2]); }

// Adds (or finds) a per-element block property named `name`, initialised to
// `init`. Key is Mesh::Vertex_index, Face_index, Edge_index or Halfedge_index.
template <typename Key, int N>
typename Mesh::template Property_map<Key, Block<N>> AddBlocks(Mesh& mesh, const std::string& name,
                                                              const Block<N>& init = {}) {
  return mesh.template add_property_map<Key, Block<N>>(name, init).first;
}

}  // namespace archgeo
