// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — topology helpers: boundary, corners, mesh polylines.
#include "mesh/topology.h"

#include <algorithm>
#include <cmath>
#include <queue>

#include <glog/logging.h>

namespace archgeo {
namespace {

constexpr double kCornerTurnDegrees = 60.0;

Vector Direction(const Mesh& mesh, HalfedgeIndex h) {
  return mesh.point(mesh.target(h)) - mesh.point(mesh.source(h));
}

// The halfedge leaving target(h) that continues the polyline arriving by h,
// or null if the polyline ends at target(h) (see MeshPolylines).
HalfedgeIndex Continuation(const Mesh& mesh, const std::vector<bool>& boundary, HalfedgeIndex h) {
  const VertexIndex v = mesh.target(h);
  const auto degree = mesh.degree(v);
  if (!boundary[v.idx()]) {
    if (degree != 4) return Mesh::null_halfedge();
    // Two steps around v from the outgoing opposite(h): the opposite edge.
    HalfedgeIndex out = mesh.opposite(h);
    for (int step = 0; step < 2; ++step) out = mesh.next(mesh.opposite(out));
    return out;
  }
  if (degree != 3 || !mesh.is_border(mesh.edge(h))) return Mesh::null_halfedge();
  // Along the boundary: the other border edge at v.
  int border_edges = 0;
  HalfedgeIndex other = Mesh::null_halfedge();
  for (HalfedgeIndex in : mesh.halfedges_around_target(mesh.halfedge(v))) {
    if (!mesh.is_border(mesh.edge(in))) continue;
    ++border_edges;
    if (mesh.edge(in) != mesh.edge(h)) other = mesh.opposite(in);
  }
  return border_edges == 2 ? other : Mesh::null_halfedge();
}

}  // namespace

bool SameConnectivity(const Mesh& a, const Mesh& b) {
  if (a.number_of_vertices() != b.number_of_vertices() ||
      a.number_of_faces() != b.number_of_faces() || a.number_of_edges() != b.number_of_edges() ||
      a.num_vertices() != b.num_vertices() || a.num_faces() != b.num_faces() ||
      a.num_edges() != b.num_edges()) {
    return false;
  }
  std::vector<VertexIndex> cycle, other;
  for (FaceIndex f : a.faces()) {
    if (b.is_removed(f)) return false;
    cycle.clear();
    other.clear();
    for (VertexIndex v : CGAL::vertices_around_face(a.halfedge(f), a)) cycle.push_back(v);
    for (VertexIndex v : CGAL::vertices_around_face(b.halfedge(f), b)) other.push_back(v);
    if (other.size() != cycle.size()) return false;
    const auto first = std::find(other.begin(), other.end(), cycle[0]);
    if (first == other.end()) return false;
    std::rotate(other.begin(), first, other.end());
    if (other != cycle) return false;
  }
  return true;
}

std::vector<bool> BoundaryVertices(const Mesh& mesh) {
  std::vector<bool> boundary(mesh.num_vertices(), false);
  for (HalfedgeIndex h : mesh.halfedges()) {
    if (mesh.is_border(h)) boundary[mesh.target(h).idx()] = true;
  }
  return boundary;
}

std::vector<VertexIndex> Corners(const Mesh& mesh) {
  const double min_cos = std::cos(kCornerTurnDegrees * M_PI / 180.0);
  std::vector<VertexIndex> corners;
  for (HalfedgeIndex h : mesh.halfedges()) {
    if (!mesh.is_border(h)) continue;
    const VertexIndex v = mesh.target(h);
    int faces = 0;
    for (FaceIndex f : mesh.faces_around_target(h)) faces += f != Mesh::null_face();
    const Vector in = Direction(mesh, h), out = Direction(mesh, mesh.next(h));
    const double norms = std::sqrt(in.squared_length() * out.squared_length());
    const bool turns = norms > 0 && in * out < min_cos * norms;
    if (faces == 1 || turns) corners.push_back(v);
  }
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  return corners;
}

std::vector<std::vector<VertexIndex>> MeshPolylines(const Mesh& mesh) {
  const std::vector<bool> boundary = BoundaryVertices(mesh);
  std::vector<bool> used(mesh.num_edges(), false);
  // Follows continuations from `start`, marking edges, until the polyline ends
  // or returns to `start`'s edge; appends the targets. Returns true if closed.
  const auto walk = [&](HalfedgeIndex start, std::vector<VertexIndex>& vertices) {
    for (HalfedgeIndex h = start;;) {
      used[mesh.edge(h).idx()] = true;
      vertices.push_back(mesh.target(h));
      h = Continuation(mesh, boundary, h);
      if (h == Mesh::null_halfedge()) return false;
      if (mesh.edge(h) == mesh.edge(start)) return true;
      CHECK(!used[mesh.edge(h).idx()]) << "MeshPolylines: continuation is not symmetric";
    }
  };
  std::vector<std::vector<VertexIndex>> polylines;
  for (EdgeIndex e : mesh.edges()) {
    if (used[e.idx()]) continue;
    const HalfedgeIndex h = mesh.halfedge(e);
    std::vector<VertexIndex> forward{mesh.source(h)};
    if (!walk(h, forward)) {
      std::vector<VertexIndex> backward;
      walk(mesh.opposite(h), backward);  // starts with source(h), already in `forward`
      forward.insert(forward.begin(), backward.rbegin(), backward.rend() - 1);
    }
    polylines.push_back(std::move(forward));
  }
  return polylines;
}

std::vector<int> TwoColouring(const Mesh& mesh, std::vector<int>* monochrome_edges) {
  std::vector<int> colour(mesh.num_vertices(), -1);
  for (VertexIndex root : mesh.vertices()) {
    if (colour[root.idx()] >= 0) continue;
    colour[root.idx()] = 0;
    std::queue<VertexIndex> queue;
    queue.push(root);
    while (!queue.empty()) {
      const VertexIndex v = queue.front();
      queue.pop();
      if (mesh.halfedge(v) == Mesh::null_halfedge()) continue;  // isolated vertex
      for (VertexIndex w : mesh.vertices_around_target(mesh.halfedge(v))) {
        if (colour[w.idx()] >= 0) continue;
        colour[w.idx()] = 1 - colour[v.idx()];
        queue.push(w);
      }
    }
  }
  if (monochrome_edges) {
    for (EdgeIndex e : mesh.edges()) {
      if (colour[mesh.vertex(e, 0).idx()] == colour[mesh.vertex(e, 1).idx()]) {
        monochrome_edges->push_back(int(e.idx()));
      }
    }
  }
  return colour;
}

std::vector<std::vector<VertexIndex>> PolylineTuples(
    const std::vector<std::vector<VertexIndex>>& polylines, size_t k) {
  std::vector<std::vector<VertexIndex>> tuples;
  for (const auto& line : polylines) {
    const bool closed = line.size() > 3 && line.front() == line.back();
    const size_t n = line.size() - (closed ? 1 : 0);  // distinct vertices
    if (n < k) continue;
    const size_t count = closed ? n : n - k + 1;
    for (size_t i = 0; i < count; ++i) {
      std::vector<VertexIndex> tuple;
      for (size_t j = 0; j < k; ++j) tuple.push_back(line[(i + j) % n]);
      tuples.push_back(std::move(tuple));
    }
  }
  return tuples;
}

std::vector<std::array<VertexIndex, 3>> PolylineTriples(
    const std::vector<std::vector<VertexIndex>>& polylines) {
  std::vector<std::array<VertexIndex, 3>> triples;
  for (const auto& t : PolylineTuples(polylines, 3)) triples.push_back({t[0], t[1], t[2]});
  return triples;
}

}  // namespace archgeo
