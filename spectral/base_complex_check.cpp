// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The base-complex path end to end and the figures that judge its output
// (spectral/base_complex_charts.h).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "spectral/base_complex_charts.h"

namespace archgeo {
namespace {

constexpr int kChartRefinements = 2;  // midpoint splits of the surface before giving up

double ChartSecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Each triangle split into four at its edge midpoints, then each triangle
// at a node into three at its centroid, so a node has twice the surface
// edges to leave by (new vertices after the old, so vertex ids stay): the
// same surface, finer.
void SplitTriangles(const std::vector<int>& nodes, std::vector<Eigen::Vector3d>& points,
                    std::vector<std::array<int, 3>>& triangles) {
  std::map<std::pair<int, int>, int> midpoint;
  auto mid = [&](int u, int v) {
    const auto [it, fresh] = midpoint.emplace(std::pair(std::min(u, v), std::max(u, v)), int(points.size()));
    if (fresh) points.push_back(0.5 * (points[u] + points[v]));
    return it->second;
  };
  std::vector<char> node(points.size(), 0);
  for (int v : nodes) node[size_t(v)] = 1;
  auto at_node = [&](int v) { return size_t(v) < node.size() && node[size_t(v)]; };
  std::vector<std::array<int, 3>> finer;
  finer.reserve(5 * triangles.size());
  auto add = [&](int a, int b, int c) {
    if (!at_node(a) && !at_node(b) && !at_node(c)) {
      finer.push_back({a, b, c});
      return;
    }
    const int g = int(points.size());
    points.push_back((points[a] + points[b] + points[c]) / 3);
    finer.push_back({a, b, g});
    finer.push_back({b, c, g});
    finer.push_back({c, a, g});
  };
  for (const auto& [a, b, c] : triangles) {
    const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    add(a, ab, ca);
    add(ab, b, bc);
    add(ca, bc, c);
    add(ab, bc, ca);
  }
  triangles = std::move(finer);
}

// Valences, boundary and non-manifold edges, and T-junctions: a vertex in
// the open interior of a boundary edge (within 1e-9 of the output's extent).
void CheckChartQuads(ChartQuadsResult& r, bool triangle_output) {
  const int inner = triangle_output ? 6 : 4, outer = triangle_output ? 4 : 3;
  const QuadExtraction& q = r.quads;
  std::map<std::pair<int, int>, int> faces_at;
  auto count = [&faces_at](const auto& face) {
    const int sides = int(face.size());
    for (int k = 0; k < sides; ++k) {
      const int u = face[k], v = face[(k + 1) % sides];
      ++faces_at[{std::min(u, v), std::max(u, v)}];
    }
  };
  for (const auto& quad : q.quads) count(quad);
  for (const auto& triangle : q.triangles) count(triangle);
  r.valence.assign(q.points.size(), 0);
  std::vector<std::pair<int, int>> boundary;
  for (const auto& [edge, count] : faces_at) {
    ++r.valence[edge.first];
    ++r.valence[edge.second];
    if (count == 1) boundary.push_back(edge);
    if (count > 2) ++r.non_manifold_edges;
  }
  r.boundary_edges = int(boundary.size());
  Eigen::Vector3d lo = q.points.empty() ? Eigen::Vector3d::Zero() : q.points[0], hi = lo;
  for (const Eigen::Vector3d& p : q.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double tolerance = 1e-9 * (hi - lo).norm();
  std::set<int> on_boundary;
  for (const auto& [u, v] : boundary) {
    on_boundary.insert(u);
    on_boundary.insert(v);
  }
  for (const auto& [u, v] : boundary) {
    const Eigen::Vector3d a = q.points[u], d = q.points[v] - a;
    for (int w : on_boundary) {
      if (w == u || w == v) continue;
      const double t = (q.points[w] - a).dot(d) / std::max(d.squaredNorm(), 1e-300);
      if (t > 0 && t < 1 && (q.points[w] - (a + t * d)).norm() <= tolerance) ++r.t_junctions;
    }
  }
  const std::set<int> strip(q.strip_boundary_vertex.begin(), q.strip_boundary_vertex.end());
  for (size_t v = 0; v < r.valence.size(); ++v) {
    const int regular = on_boundary.count(int(v)) && !strip.count(int(v)) ? outer : inner;
    if (r.valence[v] != regular) r.irregular.push_back(int(v));
  }
  // The base complex's prediction.
  std::vector<int> base_valence(q.node_vertex.size(), 0);
  std::vector<char> base_boundary(q.node_vertex.size(), 0);
  for (const BaseEdgePath& e : r.layout.edges) {
    ++base_valence[e.a];
    ++base_valence[e.b];
    if (e.boundary) {
      base_boundary[e.a] = base_boundary[e.b] = 1;
      r.expected_boundary_edges += r.n;
    }
  }
  for (size_t v = 0; v < base_valence.size(); ++v) {
    if (base_valence[v] != (base_boundary[v] ? outer : inner)) r.expected_irregular.push_back(q.node_vertex[v]);
  }
  for (int c : q.centre_vertex) {
    if (c >= 0) r.expected_irregular.push_back(c);
  }
  std::sort(r.expected_irregular.begin(), r.expected_irregular.end());
}

}  // namespace

int ChartSamples(const ChartLayout& layout, int n, double edge_length, ChartFill fill) {
  bool triangles = false;  // a triangle chart split into three quads
  for (size_t f = 0; f < layout.sides.size(); ++f) {
    triangles = triangles || (layout.sides[f].size() == 3 && fill != ChartFill::kTriangles &&
                              !StripChart(layout, int(f), fill));
  }
  if (n > 0) {
    if (triangles && n % 2 != 0) {
      throw std::invalid_argument(
          "must be even when the base complex has a triangle face off the boundary (each is "
          "split into three quads of n/2 × n/2)");
    }
    return n;
  }
  double total = 0;
  for (const BaseEdgePath& e : layout.edges) total += e.length;
  const double mean = total / std::max<size_t>(1, layout.edges.size());
  if (triangles) return 2 * std::max(1, int(std::lround(mean / (2 * edge_length))));
  return std::max(1, int(std::lround(mean / edge_length)));
}

ChartQuadsResult ChartQuads(const std::vector<Eigen::Vector3d>& input_points,
                            const std::vector<std::array<int, 3>>& input_triangles,
                            const BaseComplex& base, int n, double edge_length,
                            ChartWeights weights, ChartFill fill) {
  ChartQuadsResult r;
  auto start = std::chrono::steady_clock::now();
  std::vector<Eigen::Vector3d> points = input_points;
  std::vector<std::array<int, 3>> triangles = input_triangles;
  for (;; ++r.refinements) {
    try {
      r.layout = BuildChartLayout(points, triangles, base);
      break;
    } catch (const ChartRoomError&) {
      if (r.refinements == kChartRefinements) throw;
      SplitTriangles(base.nodes, points, triangles);
    }
  }
  r.n = ChartSamples(r.layout, n, edge_length, fill);
  for (size_t f = 0; f < r.layout.sides.size(); ++f) r.strips += StripChart(r.layout, int(f), fill);
  r.seconds_charts = ChartSecondsSince(start);
  start = std::chrono::steady_clock::now();
  r.min_area = std::numeric_limits<double>::infinity();
  for (size_t c = 0; c < r.layout.charts.size(); ++c) {
    r.maps.push_back(ParameteriseChart(points, triangles, r.layout, int(c), weights));
    r.flipped += r.maps.back().flipped;
    r.min_area = std::min(r.min_area, r.maps.back().min_area);
  }
  r.seconds_parameterisation = ChartSecondsSince(start);
  start = std::chrono::steady_clock::now();
  r.quads = ExtractQuads(points, triangles, base, r.layout, r.maps, r.n, fill);
  r.seconds_extraction = ChartSecondsSince(start);
  CheckChartQuads(r, fill == ChartFill::kTriangles);
  return r;
}

}  // namespace archgeo
