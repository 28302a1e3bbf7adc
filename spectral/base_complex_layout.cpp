// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Charts of a base complex: paths, flood fill, the disc check
// (spectral/base_complex_charts.h, step 1).
#include <algorithm>
#include <limits>
#include <map>
#include <queue>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "spectral/base_complex_charts.h"

namespace archgeo {
namespace {

using ChartKey = long long;

ChartKey ChartHalfedge(int u, int v, int n) { return ChartKey(u) * n + v; }

std::string BaseEdgeName(int a, int b) {
  return "base edge " + std::to_string(a) + "-" + std::to_string(b);
}
std::string BaseFaceName(int f) { return "base face " + std::to_string(f); }

void CheckBaseComplex(int surface_vertices, const BaseComplex& base) {
  std::unordered_map<int, int> seen;
  for (size_t i = 0; i < base.nodes.size(); ++i) {
    const int v = base.nodes[i];
    if (v < 0 || v >= surface_vertices) {
      throw BaseComplexError("base vertex " + std::to_string(i),
                             "surface vertex " + std::to_string(v) + " does not exist (the surface has " +
                                 std::to_string(surface_vertices) + ")");
    }
    auto [it, fresh] = seen.emplace(v, int(i));
    if (!fresh) {
      throw BaseComplexError("base vertex " + std::to_string(i),
                             "is on surface vertex " + std::to_string(v) + " as base vertex " +
                                 std::to_string(it->second) + " is");
    }
  }
  if (base.faces.empty()) throw BaseComplexError("base complex", "has no face");
  if (!base.edges.empty() && base.edges.size() != base.faces.size()) {
    throw BaseComplexError("base complex", "has edge ids for " + std::to_string(base.edges.size()) +
                                               " of its " + std::to_string(base.faces.size()) +
                                               " faces");
  }
  for (size_t f = 0; f < base.faces.size(); ++f) {
    const std::vector<int>& face = base.faces[f];
    if (face.size() != 3 && face.size() != 4) {
      throw BaseComplexError(BaseFaceName(int(f)), "has " + std::to_string(face.size()) +
                                                       " corners (triangles and quads only)");
    }
    if (!base.edges.empty() && base.edges[f].size() != face.size()) {
      throw BaseComplexError(BaseFaceName(int(f)), "has not one edge id per side");
    }
    for (size_t k = 0; k < face.size(); ++k) {
      if (face[k] < 0 || face[k] >= int(base.nodes.size())) {
        throw BaseComplexError(BaseFaceName(int(f)),
                               "names base vertex " + std::to_string(face[k]) + ", which does not exist");
      }
      for (size_t j = 0; j < k; ++j) {
        if (face[j] == face[k]) throw BaseComplexError(BaseFaceName(int(f)), "repeats a corner");
      }
    }
  }
}

// The base edges (a < b) and each face's sides; the complex must be closed
// and consistently oriented. An edge is its pair of nodes, or its id
// (BaseComplex::edges) with the pair.
void BaseSides(const BaseComplex& base, ChartLayout& out) {
  using SideKey = std::tuple<long, int, int>;  // (edge id or −1, from, to)
  std::map<SideKey, int> index;
  std::map<SideKey, int> directed;  // -> face
  out.sides.assign(base.faces.size(), {});
  for (size_t f = 0; f < base.faces.size(); ++f) {
    const std::vector<int>& face = base.faces[f];
    for (size_t k = 0; k < face.size(); ++k) {
      const int u = face[k], v = face[(k + 1) % face.size()];
      const long id = base.edges.empty() ? -1 : base.edges[f][k];
      if (!directed.emplace(SideKey(id, u, v), int(f)).second) {
        throw BaseComplexError(BaseFaceName(int(f)),
                               "runs along " + BaseEdgeName(u, v) + " in the same direction as " +
                                   BaseFaceName(directed[SideKey(id, u, v)]) +
                                   " (faces oriented inconsistently, or an edge on three faces)");
      }
      const SideKey key(id, std::min(u, v), std::max(u, v));
      auto [it, fresh] = index.emplace(key, int(out.edges.size()));
      if (fresh) {
        BaseEdgePath e;
        e.a = std::get<1>(key);
        e.b = std::get<2>(key);
        out.edges.push_back(e);
      }
      out.sides[f].push_back({it->second, u > v});
    }
  }
  for (const auto& [side, f] : directed) {
    const auto [id, u, v] = side;
    if (!directed.count(SideKey(id, v, u))) {
      throw BaseComplexError(BaseEdgeName(u, v),
                             "is on " + BaseFaceName(f) +
                                 " only: the base complex must be closed, as the surface is");
    }
  }
}

struct ChartGraph {
  std::vector<std::vector<std::pair<int, double>>> adjacent;  // (vertex, length)
  std::unordered_map<ChartKey, int> triangle_of;              // directed halfedge -> triangle
  int n = 0;
};

ChartGraph MakeChartGraph(const std::vector<Eigen::Vector3d>& points,
                          const std::vector<std::array<int, 3>>& triangles) {
  ChartGraph g;
  g.n = int(points.size());
  g.adjacent.resize(points.size());
  g.triangle_of.reserve(triangles.size() * 3);
  for (size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int u = triangles[t][k], v = triangles[t][(k + 1) % 3];
      g.triangle_of[ChartHalfedge(u, v, g.n)] = int(t);
      g.adjacent[u].push_back({v, (points[u] - points[v]).norm()});
    }
  }
  // Each undirected edge once per direction (a closed mesh lists it from both sides).
  for (auto& list : g.adjacent) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end(),
                           [](const auto& x, const auto& y) { return x.first == y.first; }),
               list.end());
  }
  return g;
}

// Dijkstra from `from` to `to` over vertices not `blocked`; empty if none.
std::vector<int> ChartShortestPath(const ChartGraph& g, int from, int to,
                                   const std::vector<char>& blocked) {
  std::vector<double> dist(g.adjacent.size(), std::numeric_limits<double>::infinity());
  std::vector<int> previous(g.adjacent.size(), -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  dist[from] = 0;
  queue.push({0, from});
  while (!queue.empty()) {
    const auto [d, u] = queue.top();
    queue.pop();
    if (d > dist[u]) continue;
    if (u == to) break;
    for (const auto& [v, length] : g.adjacent[u]) {
      if (blocked[v] && v != to) continue;
      if (d + length < dist[v]) {
        dist[v] = d + length;
        previous[v] = u;
        queue.push({dist[v], v});
      }
    }
  }
  if (previous[to] < 0) return {};
  std::vector<int> path{to};
  while (path.back() != from) path.push_back(previous[path.back()]);
  std::reverse(path.begin(), path.end());
  return path;
}

// Places the paths in `order`; returns the edge that found no path (−1: all placed).
int ChartPlaceInOrder(const std::vector<Eigen::Vector3d>& points, const ChartGraph& g,
                      const BaseComplex& base, const std::vector<int>& order, ChartLayout& out) {
  std::vector<char> blocked(points.size(), 0);
  for (int v : base.nodes) blocked[v] = 1;
  for (BaseEdgePath& edge : out.edges) {
    edge.path.clear();
    edge.length = 0;
  }
  for (int e : order) {
    BaseEdgePath& edge = out.edges[e];
    edge.path = ChartShortestPath(g, base.nodes[edge.a], base.nodes[edge.b], blocked);
    if (edge.path.empty()) return e;
    for (size_t i = 1; i + 1 < edge.path.size(); ++i) blocked[edge.path[i]] = 1;
    for (size_t i = 1; i < edge.path.size(); ++i) {
      edge.length += (points[edge.path[i]] - points[edge.path[i - 1]]).norm();
    }
  }
  return -1;
}

// Shortest chord first; an edge whose way is barred by the paths placed
// before it is moved to the front and every path placed again (at most once
// per edge).
void PlacePaths(const std::vector<Eigen::Vector3d>& points, const ChartGraph& g,
                const BaseComplex& base, ChartLayout& out) {
  std::vector<int> order(out.edges.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = int(i);
  auto chord = [&](int e) {
    return (points[base.nodes[out.edges[e].a]] - points[base.nodes[out.edges[e].b]]).norm();
  };
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return chord(x) < chord(y); });
  std::vector<char> moved(out.edges.size(), 0);
  for (;;) {
    const int failed = ChartPlaceInOrder(points, g, base, order, out);
    if (failed < 0) return;
    if (moved[failed]) {
      throw BaseComplexError(BaseEdgeName(out.edges[failed].a, out.edges[failed].b),
                             "has no path on the surface between its nodes clear of the paths "
                             "of the other base edges (it would cross one)");
    }
    moved[failed] = 1;
    order.erase(std::find(order.begin(), order.end(), failed));
    order.insert(order.begin(), failed);
  }
}

// The path of side k of face f, from corner k to corner k + 1.
std::vector<int> SidePath(const ChartLayout& layout, int f, int k) {
  const auto [e, reversed] = layout.sides[f][k];
  std::vector<int> path = layout.edges[e].path;
  if (reversed) std::reverse(path.begin(), path.end());
  return path;
}

// Regions of triangles connected across edges that are on no path.
std::vector<int> FloodRegions(const std::vector<std::array<int, 3>>& triangles, const ChartGraph& g,
                              const ChartLayout& layout, int* regions) {
  std::unordered_set<ChartKey> cut;
  for (const BaseEdgePath& e : layout.edges) {
    for (size_t i = 1; i < e.path.size(); ++i) {
      cut.insert(ChartHalfedge(e.path[i - 1], e.path[i], g.n));
      cut.insert(ChartHalfedge(e.path[i], e.path[i - 1], g.n));
    }
  }
  std::vector<int> region(triangles.size(), -1);
  *regions = 0;
  for (size_t seed = 0; seed < triangles.size(); ++seed) {
    if (region[seed] >= 0) continue;
    std::vector<int> stack{int(seed)};
    region[seed] = *regions;
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int u = triangles[t][k], v = triangles[t][(k + 1) % 3];
        if (cut.count(ChartHalfedge(u, v, g.n))) continue;
        const auto it = g.triangle_of.find(ChartHalfedge(v, u, g.n));
        if (it == g.triangle_of.end() || region[it->second] >= 0) continue;
        region[it->second] = *regions;
        stack.push_back(it->second);
      }
    }
    ++*regions;
  }
  return region;
}

// The region left of every side of face f, or −1 if the sides disagree.
int LeftRegion(const ChartGraph& g, const ChartLayout& layout, const std::vector<int>& region,
               int f) {
  int found = -2;
  for (size_t k = 0; k < layout.sides[f].size(); ++k) {
    const std::vector<int> p = SidePath(layout, f, int(k));
    const auto it = g.triangle_of.find(ChartHalfedge(p[0], p[1], g.n));
    const int r = it == g.triangle_of.end() ? -1 : region[it->second];
    if (found == -2) found = r;
    if (r != found || r < 0) return -1;
  }
  return found;
}

void TurnFaces(ChartLayout& layout) {
  for (auto& sides : layout.sides) {
    std::reverse(sides.begin(), sides.end());
    for (auto& side : sides) side.second = !side.second;
  }
  layout.turned = !layout.turned;
}

// Builds chart f's vertices (boundary loop first), checks it is the disc
// bounded by the face's paths.
void MakeChart(const std::vector<std::array<int, 3>>& triangles, const ChartGraph& g,
               const ChartLayout& layout, int f, Chart& chart) {
  std::unordered_map<int, int> local;
  std::vector<ChartKey> expected;
  for (size_t k = 0; k < layout.sides[f].size(); ++k) {
    chart.corner_at.push_back(int(chart.boundary.size()));
    const std::vector<int> p = SidePath(layout, f, int(k));
    for (size_t i = 0; i + 1 < p.size(); ++i) {
      local.emplace(p[i], int(chart.vertices.size()));
      chart.boundary.push_back(int(chart.vertices.size()));
      chart.vertices.push_back(p[i]);
      expected.push_back(ChartHalfedge(p[i], p[i + 1], g.n));
    }
  }
  std::unordered_set<ChartKey> edges, boundary;
  std::unordered_map<int, int> outgoing;  // boundary halfedges leaving each vertex
  for (int t : chart.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int u = triangles[t][k], v = triangles[t][(k + 1) % 3];
      if (local.emplace(u, int(chart.vertices.size())).second) chart.vertices.push_back(u);
      edges.insert(ChartHalfedge(std::min(u, v), std::max(u, v), g.n));
      const auto it = g.triangle_of.find(ChartHalfedge(v, u, g.n));
      if (it == g.triangle_of.end() || layout.chart_of_triangle[it->second] != f) {
        boundary.insert(ChartHalfedge(u, v, g.n));
        ++outgoing[u];
      }
    }
  }
  chart.euler = int(chart.vertices.size()) - int(edges.size()) + int(chart.triangles.size());
  // Boundary loops: follow each boundary halfedge to the one leaving its end.
  bool simple = true;
  for (const auto& [v, count] : outgoing) simple = simple && count == 1;
  std::unordered_map<int, int> next;
  for (ChartKey h : boundary) next[int(h / g.n)] = int(h % g.n);
  std::unordered_set<int> visited;
  chart.boundary_loops = 0;
  for (const auto& [start, unused] : next) {
    if (visited.count(start)) continue;
    ++chart.boundary_loops;
    for (int v = start; visited.insert(v).second;) {
      const auto it = next.find(v);
      if (it == next.end()) break;
      v = it->second;
    }
  }
  bool bounded = simple && boundary.size() == expected.size();
  for (ChartKey h : expected) bounded = bounded && boundary.count(h);
  if (chart.euler != 1 || chart.boundary_loops != 1 || !bounded) {
    throw BaseComplexError(
        BaseFaceName(f),
        "its chart is not a disc bounded by its base edges: V - E + F = " +
            std::to_string(chart.euler) + ", " + std::to_string(chart.boundary_loops) +
            " boundary loop(s)" +
            (bounded ? std::string() : ", its boundary is not the paths of its base edges") +
            " (move its nodes, or split it)");
  }
}

}  // namespace

ChartLayout BuildChartLayout(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<std::array<int, 3>>& triangles,
                             const BaseComplex& base) {
  CheckBaseComplex(int(points.size()), base);
  ChartLayout out;
  BaseSides(base, out);
  const ChartGraph g = MakeChartGraph(points, triangles);
  PlacePaths(points, g, base, out);
  int regions = 0;
  const std::vector<int> region = FloodRegions(triangles, g, out, &regions);
  // The orientation with more faces whose sides all see one region on their left.
  int agree = 0, agree_turned = 0;
  for (size_t f = 0; f < base.faces.size(); ++f) agree += LeftRegion(g, out, region, int(f)) >= 0;
  TurnFaces(out);
  for (size_t f = 0; f < base.faces.size(); ++f) {
    agree_turned += LeftRegion(g, out, region, int(f)) >= 0;
  }
  if (agree_turned <= agree) TurnFaces(out);
  std::vector<int> region_face(size_t(regions), -1);
  for (size_t f = 0; f < base.faces.size(); ++f) {
    const int r = LeftRegion(g, out, region, int(f));
    if (r < 0) {
      throw BaseComplexError(BaseFaceName(int(f)),
                             "its base edges do not bound one region of the surface (a path runs "
                             "on the wrong side of another, or the face is not a disc)");
    }
    if (region_face[r] >= 0) {
      throw BaseComplexError(BaseFaceName(int(f)),
                             "bounds the same region of the surface as " +
                                 BaseFaceName(region_face[r]) + " (its chart is not a disc)");
    }
    region_face[r] = int(f);
  }
  for (int r = 0; r < regions; ++r) {
    if (region_face[r] < 0) {
      throw BaseComplexError("base complex", "its paths cut the surface into " +
                                                 std::to_string(regions) + " regions for " +
                                                 std::to_string(base.faces.size()) +
                                                 " faces (the surface is not covered by the faces)");
    }
  }
  out.chart_of_triangle.resize(triangles.size());
  out.charts.resize(base.faces.size());
  for (size_t t = 0; t < triangles.size(); ++t) {
    const int f = region_face[region[t]];
    out.chart_of_triangle[t] = f;
    out.charts[f].triangles.push_back(int(t));
  }
  for (size_t f = 0; f < base.faces.size(); ++f) {
    out.charts[f].face = int(f);
    MakeChart(triangles, g, out, int(f), out.charts[f]);
  }
  return out;
}

}  // namespace archgeo
