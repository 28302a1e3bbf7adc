// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/grid_metrics.h"

#include <cmath>

#include <glog/logging.h>

#include "mesh/topology.h"

namespace archgeo {
namespace {

nlohmann::json Number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); }

nlohmann::json MeasuresToJson(const QualityMeasures& q) {
  return {{"mdo", Number(q.mdo)}, {"ado", Number(q.ado)}, {"mde", Number(q.mde)},
          {"ade", Number(q.ade)}};
}

}  // namespace

GridNetwork GridNetworkOfMesh(const Mesh& mesh) {
  CHECK(!mesh.has_garbage()) << "GridNetworkOfMesh: mesh with removed elements";
  GridNetwork net;
  net.num_points = static_cast<int>(mesh.number_of_vertices());
  // Every edge's (line, segment).
  std::vector<std::array<int, 2>> segment_of(mesh.number_of_edges(), {-1, -1});
  for (const auto& polyline : MeshPolylines(mesh)) {
    GridNetwork::Line line;
    line.closed = polyline.size() > 3 && polyline.front() == polyline.back();
    for (size_t k = 0; k + (line.closed ? 1 : 0) < polyline.size(); ++k) {
      line.vertices.push_back(static_cast<int>(polyline[k].idx()));
    }
    const int l = static_cast<int>(net.lines.size());
    for (size_t s = 0; s + 1 < polyline.size(); ++s) {
      const HalfedgeIndex h = mesh.halfedge(polyline[s], polyline[s + 1]);
      CHECK(h != Mesh::null_halfedge());
      segment_of[mesh.edge(h).idx()] = {l, static_cast<int>(s)};
    }
    net.lines.push_back(std::move(line));
  }
  const std::vector<bool> boundary = BoundaryVertices(mesh);
  const auto node_of = [&](int l, int s, int vertex) {
    const auto& line = net.lines[l];
    const int n = static_cast<int>(line.vertices.size());
    return line.vertices[s] == vertex ? s : (s + 1) % n;
  };
  for (VertexIndex v : mesh.vertices()) {
    if (boundary[v.idx()] || mesh.degree(v) != 4) continue;
    GridNetwork::Crossing c;
    c.vertex = static_cast<int>(v.idx());
    std::array<std::array<int, 2>, 4> segments;
    int k = 0;
    for (HalfedgeIndex h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh)) {
      c.ring[k] = static_cast<int>(mesh.source(h).idx());
      segments[k] = segment_of[mesh.edge(h).idx()];
      ++k;
    }
    c.line_a = segments[0][0];
    c.node_a = node_of(segments[0][0], segments[0][1], c.vertex);
    c.line_b = segments[1][0];
    c.node_b = node_of(segments[1][0], segments[1][1], c.vertex);
    net.crossings.push_back(c);
  }
  for (FaceIndex f : mesh.faces()) {
    if (mesh.degree(f) != 4) continue;
    GridNetwork::Quad quad;
    int k = 0;
    for (HalfedgeIndex h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      quad.vertices[k] = static_cast<int>(mesh.source(h).idx());
      quad.sides[k] = segment_of[mesh.edge(h).idx()];
      ++k;
    }
    net.quads.push_back(quad);
  }
  return net;
}

GridQuality MeasureQuadGridMesh(const Mesh& mesh) {
  std::vector<Eigen::Vector3d> points(mesh.number_of_vertices());
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    points[v.idx()] = Eigen::Vector3d(p.x(), p.y(), p.z());
  }
  return MeasureGridNetwork(GridNetworkOfMesh(mesh), points);
}

nlohmann::json GridQualityToJson(const GridQuality& quality) {
  nlohmann::json j = MeasuresToJson(quality.Table1());
  j["spline"] = MeasuresToJson(quality.spline);
  j["discrete"] = MeasuresToJson(quality.discrete);
  j["crossings"] = quality.crossings;
  j["quads"] = quality.quads;
  return j;
}

}  // namespace archgeo
