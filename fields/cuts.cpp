// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fields/cuts.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <set>
#include <tuple>

#include <CGAL/Union_find.h>
#include <glog/logging.h>

namespace archgeo {
namespace {

// Halfedges into v, clockwise (CGAL's order around the target).
std::vector<HalfedgeIndex> Incoming(const Mesh& mesh, VertexIndex v) {
  std::vector<HalfedgeIndex> out;
  for (HalfedgeIndex h : mesh.halfedges_around_target(mesh.halfedge(v))) out.push_back(h);
  return out;
}

bool OnBoundary(const Mesh& mesh, VertexIndex v) {
  return !mesh.is_isolated(v) && mesh.is_border(v, /*check_all_incident_halfedges=*/true);
}

// Assigns wedges: consecutive corners around a vertex share a wedge unless the
// edge between them (edge of the second halfedge) is cut or a boundary edge.
void AssignWedges(const Mesh& mesh, CutGraph* cut) {
  cut->corner_wedge.assign(mesh.number_of_halfedges(), -1);
  cut->wedge_vertex.clear();
  cut->num_wedges = 0;
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_isolated(v)) continue;
    const std::vector<HalfedgeIndex> in = Incoming(mesh, v);
    const size_t k = in.size();
    auto breaks_before = [&](size_t i) {  // between corner i − 1 and corner i
      const HalfedgeIndex h = in[i % k];
      const EdgeIndex e = mesh.edge(h);
      return mesh.is_border(e) || cut->is_cut_edge[e.idx()];
    };
    size_t start = 0;
    bool any_break = false;
    for (size_t i = 0; i < k; ++i) {
      if (breaks_before(i)) {
        start = i;
        any_break = true;
        break;
      }
    }
    int wedge = -1;
    for (size_t step = 0; step < k; ++step) {
      const size_t i = (start + step) % k;
      if (wedge < 0 || (any_break && breaks_before(i))) {
        wedge = cut->num_wedges++;
        cut->wedge_vertex.push_back(v);
      }
      if (!mesh.is_border(in[i])) cut->corner_wedge[in[i].idx()] = wedge;
    }
  }
  // Wedges that hold no corner (the border "corner" of a boundary vertex
  // between two boundary edges) are dropped by renumbering.
  std::vector<int> used(cut->num_wedges, -1);
  int n = 0;
  std::vector<VertexIndex> vertex;
  for (HalfedgeIndex h : mesh.halfedges()) {
    const int w = cut->corner_wedge[h.idx()];
    if (w >= 0 && used[w] < 0) {
      used[w] = n++;
      vertex.push_back(cut->wedge_vertex[w]);
    }
  }
  for (int& w : cut->corner_wedge)
    if (w >= 0) w = used[w];
  cut->wedge_vertex = vertex;
  cut->num_wedges = n;
}

void BuildChains(const Mesh& mesh, CutGraph* cut) {
  std::vector<int> degree(mesh.number_of_vertices(), 0);
  for (EdgeIndex e : mesh.edges()) {
    if (!cut->is_cut_edge[e.idx()]) continue;
    ++degree[mesh.vertex(e, 0).idx()];
    ++degree[mesh.vertex(e, 1).idx()];
  }
  std::vector<bool> singular(mesh.number_of_vertices(), false);
  for (VertexIndex s : cut->singular_vertices) singular[s.idx()] = true;
  auto is_node = [&](VertexIndex v) {
    return degree[v.idx()] != 2 || OnBoundary(mesh, v) || singular[v.idx()];
  };
  cut->edge_chain.assign(mesh.number_of_edges(), -1);
  cut->chains.clear();
  auto walk = [&](HalfedgeIndex first) {
    CutChain chain;
    HalfedgeIndex h = first;
    const int id = static_cast<int>(cut->chains.size());
    while (true) {
      chain.halfedges.push_back(h);
      cut->edge_chain[mesh.edge(h).idx()] = id;
      const VertexIndex v = mesh.target(h);
      if (is_node(v) || v == mesh.source(first)) break;
      HalfedgeIndex next;
      for (HalfedgeIndex g : Incoming(mesh, v)) {
        const HalfedgeIndex out = mesh.opposite(g);  // source v
        const EdgeIndex e = mesh.edge(out);
        if (cut->is_cut_edge[e.idx()] && cut->edge_chain[e.idx()] < 0) {
          next = out;
          break;
        }
      }
      if (next == HalfedgeIndex()) break;  // closed loop returned to its start
      h = next;
    }
    chain.start = mesh.source(chain.halfedges.front());
    chain.end = mesh.target(chain.halfedges.back());
    chain.from_singularity = singular[chain.start.idx()] || singular[chain.end.idx()];
    cut->chains.push_back(chain);
  };
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_isolated(v) || degree[v.idx()] == 0 || !is_node(v)) continue;
    for (HalfedgeIndex g : Incoming(mesh, v)) {
      const HalfedgeIndex out = mesh.opposite(g);
      const EdgeIndex e = mesh.edge(out);
      if (cut->is_cut_edge[e.idx()] && cut->edge_chain[e.idx()] < 0) walk(out);
    }
  }
  // Closed loops without a node: start at their smallest vertex.
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_isolated(v) || degree[v.idx()] == 0) continue;
    for (HalfedgeIndex g : Incoming(mesh, v)) {
      const HalfedgeIndex out = mesh.opposite(g);
      const EdgeIndex e = mesh.edge(out);
      if (cut->is_cut_edge[e.idx()] && cut->edge_chain[e.idx()] < 0) walk(out);
    }
  }
}

void BuildRelations(const Mesh& mesh, CutGraph* cut) {
  std::set<std::tuple<int, int, int>> seen;
  cut->relations.clear();
  auto add = [&](HalfedgeIndex left, HalfedgeIndex right, int chain) {
    const int l = cut->corner_wedge[left.idx()], r = cut->corner_wedge[right.idx()];
    CHECK(l >= 0 && r >= 0);
    if (!seen.insert({l, r, chain}).second) return;
    cut->relations.push_back({l, r, chain, mesh.target(left)});
  };
  for (size_t c = 0; c < cut->chains.size(); ++c) {
    for (HalfedgeIndex h : cut->chains[c].halfedges) {
      const HalfedgeIndex o = mesh.opposite(h);
      // At source(h): left corner prev(h), right corner o; at target(h):
      // left corner h, right corner prev(o).
      add(mesh.prev(h), o, static_cast<int>(c));
      add(h, mesh.prev(o), static_cast<int>(c));
    }
  }
}

}  // namespace

CutGraph CutGraphFromEdges(const Mesh& mesh, const std::vector<bool>& cut_edges,
                           const std::vector<VertexIndex>& singular_vertices) {
  CHECK(!mesh.has_garbage());
  CHECK_EQ(cut_edges.size(), mesh.number_of_edges());
  CutGraph cut;
  cut.is_cut_edge = cut_edges;
  for (EdgeIndex e : mesh.edges())
    CHECK(!(cut_edges[e.idx()] && mesh.is_border(e))) << "boundary edge " << e.idx() << " in a cut";
  std::set<VertexIndex> unique(singular_vertices.begin(), singular_vertices.end());
  cut.singular_vertices.assign(unique.begin(), unique.end());
  AssignWedges(mesh, &cut);
  BuildChains(mesh, &cut);
  BuildRelations(mesh, &cut);
  return cut;
}

CutGraph ComputeCutGraph(const Mesh& mesh, const std::vector<VertexIndex>& singular_vertices) {
  CHECK(!mesh.has_garbage());
  const size_t nv = mesh.number_of_vertices();
  for (VertexIndex s : singular_vertices) CHECK(s.idx() < nv) << "singular vertex out of range";
  std::vector<bool> boundary(nv, false);
  for (VertexIndex v : mesh.vertices()) boundary[v.idx()] = OnBoundary(mesh, v);
  std::vector<bool> is_singular(nv, false);
  std::vector<VertexIndex> singular;
  for (VertexIndex s : singular_vertices) {
    if (is_singular[s.idx()] || boundary[s.idx()] || mesh.is_isolated(s)) continue;
    is_singular[s.idx()] = true;
    singular.push_back(s);
  }

  using Item = std::pair<double, int>;
  auto dijkstra = [&](const std::vector<int>& sources, const std::vector<bool>* stop_at,
                      std::vector<double>* dist, std::vector<HalfedgeIndex>* via) -> int {
    dist->assign(nv, std::numeric_limits<double>::infinity());
    via->assign(nv, HalfedgeIndex());
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    for (int s : sources) {
      (*dist)[s] = 0.0;
      queue.push({0.0, s});
    }
    while (!queue.empty()) {
      const auto [d, v] = queue.top();
      queue.pop();
      if (d > (*dist)[v]) continue;
      if (stop_at != nullptr && (*stop_at)[v] && d > 0.0) return v;
      for (HalfedgeIndex h : mesh.halfedges_around_target(mesh.halfedge(VertexIndex(v)))) {
        const HalfedgeIndex out = mesh.opposite(h);  // v → u
        const int u = mesh.target(out).idx();
        const double nd = d + EdgeLength(mesh, out);
        if (nd < (*dist)[u]) {
          (*dist)[u] = nd;
          (*via)[u] = out;
          queue.push({nd, u});
        }
      }
    }
    return -1;
  };

  // 1. Singularity cuts, nearest to the boundary first.
  std::vector<double> dist;
  std::vector<HalfedgeIndex> via;
  std::vector<int> boundary_vertices;
  for (size_t v = 0; v < nv; ++v)
    if (boundary[v]) boundary_vertices.push_back(static_cast<int>(v));
  dijkstra(boundary_vertices, nullptr, &dist, &via);
  std::stable_sort(singular.begin(), singular.end(), [&](VertexIndex a, VertexIndex b) {
    return dist[a.idx()] < dist[b.idx()];
  });
  std::vector<bool> target = boundary;
  std::vector<bool> cut(mesh.number_of_edges(), false);
  for (VertexIndex s : singular) {
    if (target[s.idx()]) continue;
    const int hit = dijkstra({static_cast<int>(s.idx())}, &target, &dist, &via);
    if (hit < 0) {  // no boundary and no cut in reach: s is a root
      target[s.idx()] = true;
      continue;
    }
    for (int v = hit; v != static_cast<int>(s.idx());) {
      const HalfedgeIndex h = via[v];
      cut[mesh.edge(h).idx()] = true;
      target[v] = true;
      v = mesh.source(h).idx();
    }
    target[s.idx()] = true;
  }
  std::vector<bool> singular_cut = cut;

  // 2. Tree–cotree: dual BFS through uncut interior edges, then prune.
  std::vector<bool> crossed(mesh.number_of_edges(), false), seen(mesh.number_of_faces(), false);
  for (FaceIndex root : mesh.faces()) {
    if (seen[root.idx()]) continue;
    seen[root.idx()] = true;
    std::queue<FaceIndex> queue;
    queue.push(root);
    while (!queue.empty()) {
      const FaceIndex f = queue.front();
      queue.pop();
      for (HalfedgeIndex h : mesh.halfedges_around_face(mesh.halfedge(f))) {
        const EdgeIndex e = mesh.edge(h);
        if (mesh.is_border(e) || cut[e.idx()]) continue;
        const FaceIndex g = mesh.face(mesh.opposite(h));
        if (seen[g.idx()]) continue;
        seen[g.idx()] = true;
        crossed[e.idx()] = true;
        queue.push(g);
      }
    }
  }
  std::vector<int> degree(nv, 0);
  for (EdgeIndex e : mesh.edges()) {
    if (mesh.is_border(e) || crossed[e.idx()]) continue;
    cut[e.idx()] = true;
    ++degree[mesh.vertex(e, 0).idx()];
    ++degree[mesh.vertex(e, 1).idx()];
  }
  auto prunable = [&](int v) { return degree[v] == 1 && !boundary[v] && !is_singular[v]; };
  std::queue<int> leaves;
  for (size_t v = 0; v < nv; ++v)
    if (prunable(static_cast<int>(v))) leaves.push(static_cast<int>(v));
  while (!leaves.empty()) {
    const int v = leaves.front();
    leaves.pop();
    if (!prunable(v)) continue;
    for (HalfedgeIndex h : mesh.halfedges_around_target(mesh.halfedge(VertexIndex(v)))) {
      const EdgeIndex e = mesh.edge(h);
      if (!cut[e.idx()]) continue;
      CHECK(!singular_cut[e.idx()]) << "a singularity cut has an unprotected end";
      cut[e.idx()] = false;
      --degree[v];
      const int u = mesh.source(h).idx();
      --degree[u];
      if (prunable(u)) leaves.push(u);
      break;
    }
  }
  return CutGraphFromEdges(mesh, cut, singular);
}

CutSurfaceTopology CutSurface(const Mesh& mesh, const CutGraph& cut) {
  // Faces joined across the edges that are neither cut nor on the boundary.
  CGAL::Union_find<FaceIndex> pieces;
  std::vector<CGAL::Union_find<FaceIndex>::handle> piece(mesh.number_of_faces());
  for (FaceIndex f : mesh.faces()) piece[f.idx()] = pieces.make_set(f);
  int edges = 0;
  for (EdgeIndex e : mesh.edges()) {
    if (mesh.is_border(e)) {
      ++edges;
      continue;
    }
    if (cut.is_cut_edge[e.idx()]) {
      edges += 2;
      continue;
    }
    ++edges;
    pieces.unify_sets(piece[mesh.face(mesh.halfedge(e, 0)).idx()],
                      piece[mesh.face(mesh.halfedge(e, 1)).idx()]);
  }
  CutSurfaceTopology t;
  t.components = static_cast<int>(pieces.number_of_sets());
  t.euler_characteristic =
      cut.num_wedges - edges + static_cast<int>(mesh.number_of_faces());
  return t;
}

}  // namespace archgeo
