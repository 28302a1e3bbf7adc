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

// The base edges (a < b) and each face's sides; the complex must be
// consistently oriented, and closed where the surface is. An edge is its
// pair of nodes, or its id (BaseComplex::edges) with the pair; an edge on one
// face only is a boundary edge (on an open surface).
void BaseSides(const BaseComplex& base, bool surface_open, ChartLayout& out) {
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
    if (directed.count(SideKey(id, v, u))) continue;
    if (!surface_open) {
      throw BaseComplexError(BaseEdgeName(u, v),
                             "is on " + BaseFaceName(f) +
                                 " only: the base complex must be closed, as the surface is");
    }
    out.edges[size_t(index.at(SideKey(id, std::min(u, v), std::max(u, v))))].boundary = true;
  }
}

struct ChartArc {
  int to = 0;
  double length = 0;
  bool boundary = false;  // a surface boundary edge
};

struct ChartGraph {
  std::vector<std::vector<ChartArc>> adjacent;
  std::unordered_map<ChartKey, int> triangle_of;  // directed halfedge -> triangle
  // Per vertex: its neighbours along the surface boundary, the triangles on
  // the left going to `next`; −1 inside.
  std::vector<int> boundary_next, boundary_previous;
  int n = 0;
};

ChartGraph MakeChartGraph(const std::vector<Eigen::Vector3d>& points,
                          const std::vector<std::array<int, 3>>& triangles) {
  ChartGraph g;
  g.n = int(points.size());
  g.adjacent.resize(points.size());
  g.boundary_next.assign(points.size(), -1);
  g.boundary_previous.assign(points.size(), -1);
  g.triangle_of.reserve(triangles.size() * 3);
  for (size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      g.triangle_of[ChartHalfedge(triangles[t][k], triangles[t][(k + 1) % 3], g.n)] = int(t);
    }
  }
  for (const auto& [h, t] : g.triangle_of) {
    const int u = int(h / g.n), v = int(h % g.n);
    const bool boundary = !g.triangle_of.count(ChartHalfedge(v, u, g.n));
    const double length = (points[u] - points[v]).norm();
    g.adjacent[u].push_back({v, length, boundary});
    if (boundary) {
      g.adjacent[v].push_back({u, length, true});
      g.boundary_next[u] = v;
      g.boundary_previous[v] = u;
    }
  }
  // Each undirected edge once per direction, in a fixed order.
  for (auto& list : g.adjacent) {
    std::sort(list.begin(), list.end(), [](const ChartArc& x, const ChartArc& y) { return x.to < y.to; });
    list.erase(std::unique(list.begin(), list.end(),
                           [](const ChartArc& x, const ChartArc& y) { return x.to == y.to; }),
               list.end());
  }
  return g;
}

// On an open surface: the nodes of the boundary edges, and only they, on the
// surface boundary.
void CheckBoundaryNodes(const ChartGraph& g, const BaseComplex& base, const ChartLayout& out) {
  std::vector<char> on_base_boundary(base.nodes.size(), 0);
  for (const BaseEdgePath& e : out.edges) {
    if (e.boundary) on_base_boundary[e.a] = on_base_boundary[e.b] = 1;
  }
  for (size_t i = 0; i < base.nodes.size(); ++i) {
    const bool on_surface_boundary = g.boundary_next[base.nodes[i]] >= 0;
    if (on_base_boundary[i] != on_surface_boundary) {
      throw BaseComplexError("base vertex " + std::to_string(i),
                             on_surface_boundary
                                 ? "is on the surface boundary but inside the base complex (every "
                                   "base vertex on the boundary ends base edges of one face each)"
                                 : "ends a base edge on one base face only, but is not on the "
                                   "surface boundary");
    }
  }
}

// Where a path may leave or enter a node: the ring vertices of its sector
// (null: anywhere).
using ChartSector = std::unordered_set<int>;

// Dijkstra from `from` to `to` over interior edges and vertices not
// `blocked`, leaving `from` into `leave` and entering `to` from `enter`;
// empty if there is no such path.
std::vector<int> ChartShortestPath(const ChartGraph& g, int from, int to,
                                   const std::vector<char>& blocked, const ChartSector* leave,
                                   const ChartSector* enter) {
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
    for (const ChartArc& arc : g.adjacent[u]) {
      const int v = arc.to;
      if (arc.boundary || (blocked[v] && v != to)) continue;
      if ((u == from && leave && !leave->count(v)) || (v == to && enter && !enter->count(u))) {
        continue;
      }
      if (d + arc.length < dist[v]) {
        dist[v] = d + arc.length;
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

// The surface boundary from `from` to `to`, with the triangles on its left
// (`forward`) or on its right; empty if the walk meets another node (or its
// start) first.
std::vector<int> BoundaryArc(const ChartGraph& g, const std::vector<char>& node, int from, int to,
                             bool forward) {
  std::vector<int> path{from};
  for (int x = from;;) {
    x = forward ? g.boundary_next[x] : g.boundary_previous[x];
    if (x < 0) return {};
    path.push_back(x);
    if (x == to) return path;
    if (node[x] || x == from) return {};
  }
}

// The rotation of base edges and surface vertices around each node, and the
// paths placed so far (Praun et al. 2001: a path leaves and enters its nodes
// in the cyclic order of the base complex).
struct PlaceState {
  std::vector<std::unordered_map<int, int>> base_next, base_previous;  // per base vertex: edge -> edge
  std::vector<std::vector<int>> ring;  // per base vertex: its surface neighbours, counter-clockwise
  std::vector<char> ring_closed;       // per base vertex: inside the surface (else its fan ends)
  std::vector<char> placed;            // per base edge
};

PlaceState MakePlaceState(const std::vector<std::array<int, 3>>& triangles, const ChartGraph& g,
                          const BaseComplex& base, const ChartLayout& out, bool turned) {
  PlaceState st;
  const size_t nodes = base.nodes.size();
  st.base_next.resize(nodes);
  st.base_previous.resize(nodes);
  for (size_t f = 0; f < base.faces.size(); ++f) {
    const size_t m = base.faces[f].size();
    for (size_t k = 0; k < m; ++k) {
      const int into = out.sides[f][(k + m - 1) % m].first, away = out.sides[f][k].first;
      st.base_next[base.faces[f][k]][away] = into;
      st.base_previous[base.faces[f][k]][into] = away;
    }
  }
  std::unordered_map<int, int> index;
  for (size_t i = 0; i < nodes; ++i) index[base.nodes[i]] = int(i);
  std::vector<std::unordered_map<int, int>> around(nodes);  // x -> y for triangles (node, x, y)
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const auto it = index.find(t[k]);
      if (it != index.end()) around[it->second][t[(k + 1) % 3]] = t[(k + 2) % 3];
    }
  }
  st.ring.resize(nodes);
  st.ring_closed.assign(nodes, 1);
  for (size_t i = 0; i < nodes; ++i) {
    if (around[i].empty()) continue;
    const int b = g.boundary_next[base.nodes[i]];
    st.ring_closed[i] = b < 0;
    const int start = b >= 0 ? b : around[i].begin()->first;
    for (int x = start;;) {
      st.ring[i].push_back(x);
      const auto it = around[i].find(x);
      if (it == around[i].end() || it->second == start || st.ring[i].size() > around[i].size()) break;
      x = it->second;
    }
    if (turned) std::reverse(st.ring[i].begin(), st.ring[i].end());
  }
  st.placed.assign(out.edges.size(), 0);
  return st;
}

// The surface neighbour of base vertex x on edge e's path.
int RingVertexOf(const ChartLayout& out, int x, int e) {
  const std::vector<int>& p = out.edges[e].path;
  return out.edges[e].a == x ? p[1] : p[p.size() - 2];
}

// The sector of node x where base edge e's path may run: strictly between
// the paths of the nearest placed base edges before and after e around x.
// False when no edge at x is placed yet (anywhere will do).
bool NodeSector(const PlaceState& st, const ChartLayout& out, int x, int e, ChartSector* sector) {
  auto nearest = [&](const std::unordered_map<int, int>& step) {
    for (auto it = step.find(e); it != step.end() && it->second != e; it = step.find(it->second)) {
      if (st.placed[it->second]) return it->second;
    }
    return -1;
  };
  const int after = nearest(st.base_next[x]), before = nearest(st.base_previous[x]);
  if (after < 0 || before < 0) return false;
  const std::vector<int>& ring = st.ring[x];
  const int from = RingVertexOf(out, x, before), to = RingVertexOf(out, x, after);
  const auto at = std::find(ring.begin(), ring.end(), from);
  if (at == ring.end()) return false;
  const size_t i = size_t(at - ring.begin());
  for (size_t s = 1; s <= ring.size(); ++s) {
    if (!st.ring_closed[x] && i + s >= ring.size()) break;  // a boundary node's fan ends
    const int v = ring[(i + s) % ring.size()];
    if (v == to) break;
    sector->insert(v);
  }
  return true;
}

// Side u → v (base vertices) of the one face of each boundary base edge.
std::vector<std::pair<int, int>> BoundarySides(const ChartLayout& out) {
  std::vector<std::pair<int, int>> side(out.edges.size(), {-1, -1});
  for (const auto& sides : out.sides) {
    for (const auto& [e, reversed] : sides) {
      const BaseEdgePath& edge = out.edges[size_t(e)];
      if (edge.boundary) side[size_t(e)] = reversed ? std::pair(edge.b, edge.a) : std::pair(edge.a, edge.b);
    }
  }
  return side;
}

// Places every path: the boundary edges' along the surface boundary (their
// faces on the left of the surface's triangles, or on the right if
// `turned`), then the others in `order`, each in its sectors of the nodes.
// Returns the edge that found no path (−1: all placed).
int ChartPlaceInOrder(const std::vector<Eigen::Vector3d>& points, const ChartGraph& g,
                      const BaseComplex& base, const std::vector<int>& order,
                      const std::vector<std::pair<int, int>>& boundary_side, PlaceState& st,
                      bool turned, ChartLayout& out) {
  std::vector<char> blocked(points.size(), 0), node(points.size(), 0);
  for (int v : base.nodes) blocked[v] = node[v] = 1;
  for (size_t v = 0; v < points.size(); ++v) blocked[v] |= g.boundary_next[v] >= 0;
  std::fill(st.placed.begin(), st.placed.end(), 0);
  for (BaseEdgePath& edge : out.edges) {
    edge.path.clear();
    edge.length = 0;
  }
  for (int e : order) {
    BaseEdgePath& edge = out.edges[e];
    const int from = base.nodes[edge.a], to = base.nodes[edge.b];
    if (edge.boundary) {
      const auto [u, v] = boundary_side[size_t(e)];
      edge.path = BoundaryArc(g, node, base.nodes[u], base.nodes[v], !turned);
      if (u != edge.a) std::reverse(edge.path.begin(), edge.path.end());
    } else {
      ChartSector leave, enter;
      const bool at_a = NodeSector(st, out, edge.a, e, &leave);
      const bool at_b = NodeSector(st, out, edge.b, e, &enter);
      edge.path = ChartShortestPath(g, from, to, blocked, at_a ? &leave : nullptr,
                                    at_b ? &enter : nullptr);
    }
    if (edge.path.empty()) return e;
    st.placed[e] = 1;
    for (size_t i = 1; i + 1 < edge.path.size(); ++i) blocked[edge.path[i]] = 1;
    for (size_t i = 1; i < edge.path.size(); ++i) {
      edge.length += (points[edge.path[i]] - points[edge.path[i - 1]]).norm();
    }
  }
  return -1;
}

// The boundary edges; then a spanning tree of the rest, shortest chord
// first (paths of a tree enclose no region, so none can shut a node out);
// then the remaining edges, shortest chord first.
std::vector<int> PathOrder(const std::vector<Eigen::Vector3d>& points, const BaseComplex& base,
                           const ChartLayout& out) {
  std::vector<int> root(base.nodes.size());
  for (size_t i = 0; i < root.size(); ++i) root[i] = int(i);
  auto find = [&](int x) {
    while (root[x] != x) x = root[x] = root[root[x]];
    return x;
  };
  std::vector<int> order, inner, rest;
  for (size_t e = 0; e < out.edges.size(); ++e) {
    if (out.edges[e].boundary) {
      order.push_back(int(e));
      root[find(out.edges[e].a)] = find(out.edges[e].b);
    } else {
      inner.push_back(int(e));
    }
  }
  auto chord = [&](int e) {
    return (points[base.nodes[out.edges[e].a]] - points[base.nodes[out.edges[e].b]]).norm();
  };
  std::stable_sort(inner.begin(), inner.end(), [&](int x, int y) { return chord(x) < chord(y); });
  for (int e : inner) {
    const int x = find(out.edges[e].a), y = find(out.edges[e].b);
    if (x != y) {
      root[x] = y;
      order.push_back(e);
    } else {
      rest.push_back(e);
    }
  }
  order.insert(order.end(), rest.begin(), rest.end());
  return order;
}

// PathOrder; an inner edge whose way is barred by the paths placed before it
// is moved to the front of the inner edges and every path placed again (at
// most once per edge). The base faces taken as oriented like the surface,
// else as turned. Returns whether they were turned. When both fail, the
// orientation whose boundary edges all fit the surface boundary names the
// inner edge without room (ChartRoomError: a finer mesh may have it).
bool PlacePaths(const std::vector<Eigen::Vector3d>& points,
                const std::vector<std::array<int, 3>>& triangles, const ChartGraph& g,
                const BaseComplex& base, ChartLayout& out) {
  const std::vector<std::pair<int, int>> boundary_side = BoundarySides(out);
  int failed = -1;
  for (bool turned : {false, true}) {
    PlaceState st = MakePlaceState(triangles, g, base, out, turned);
    std::vector<int> order = PathOrder(points, base, out);
    const auto inner = std::find_if(order.begin(), order.end(),
                                    [&](int e) { return !out.edges[e].boundary; }) - order.begin();
    std::vector<char> moved(out.edges.size(), 0);
    for (;;) {
      const int e = ChartPlaceInOrder(points, g, base, order, boundary_side, st, turned, out);
      if (e < 0) return turned;
      if (failed < 0 || (out.edges[failed].boundary && !out.edges[e].boundary)) failed = e;
      if (out.edges[e].boundary || moved[e]) break;
      moved[e] = 1;
      order.erase(std::find(order.begin(), order.end(), e));
      order.insert(order.begin() + inner, e);
    }
  }
  const BaseEdgePath& edge = out.edges[failed];
  if (edge.boundary) {
    throw BaseComplexError(BaseEdgeName(edge.a, edge.b),
                           "is on one base face only, but its nodes are not neighbours along the "
                           "surface boundary (another base vertex lies between them)");
  }
  throw ChartRoomError(BaseEdgeName(edge.a, edge.b),
                       "has no path on the surface between its nodes clear of the paths of the "
                       "other base edges and in the cyclic order of the base complex (it would "
                       "cross one)");
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
    throw ChartRoomError(
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
  const ChartGraph g = MakeChartGraph(points, triangles);
  const bool open = std::any_of(g.boundary_next.begin(), g.boundary_next.end(), [](int v) { return v >= 0; });
  BaseSides(base, open, out);
  if (open) CheckBoundaryNodes(g, base, out);
  if (PlacePaths(points, triangles, g, base, out)) TurnFaces(out);
  int regions = 0;
  const std::vector<int> region = FloodRegions(triangles, g, out, &regions);
  std::vector<int> region_face(size_t(regions), -1);
  for (size_t f = 0; f < base.faces.size(); ++f) {
    const int r = LeftRegion(g, out, region, int(f));
    if (r < 0) {
      throw ChartRoomError(BaseFaceName(int(f)),
                           "its base edges do not bound one region of the surface (a path runs "
                             "on the wrong side of another, or the face is not a disc)");
    }
    if (region_face[r] >= 0) {
      throw ChartRoomError(BaseFaceName(int(f)),
                           "bounds the same region of the surface as " +
                                 BaseFaceName(region_face[r]) + " (its chart is not a disc)");
    }
    region_face[r] = int(f);
  }
  for (int r = 0; r < regions; ++r) {
    if (region_face[r] < 0) {
      throw ChartRoomError("base complex", "its paths cut the surface into " +
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
