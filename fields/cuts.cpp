#include "fields/cuts.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include <glog/logging.h>

namespace archgeo {
namespace {

double EdgeLength(const Mesh& mesh, HalfedgeIndex h) {
  const Point& a = mesh.point(mesh.source(h));
  const Point& b = mesh.point(mesh.target(h));
  return std::sqrt(CGAL::squared_distance(a, b));
}

// Halfedges into v, clockwise (CGAL's order around the target).
std::vector<HalfedgeIndex> Incoming(const Mesh& mesh, VertexIndex v) {
  std::vector<HalfedgeIndex> out;
  for (HalfedgeIndex h : mesh.halfedges_around_target(mesh.halfedge(v))) out.push_back(h);
  return out;
}

bool OnBoundary(const Mesh& mesh, VertexIndex v) {
  return !mesh.is_isolated(v) && mesh.is_border(v, /*check_all_incident_halfedges=*/true);
}

struct UnionFind {
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  size_t Find(size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void Union(size_t a, size_t b) { parent[Find(a)] = Find(b); }
  std::vector<size_t> parent;
};

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

namespace {

// Integer linear combination of the chains' jump constants k = α/Δw.
using Linear = std::map<int, long>;

Linear Combine(const Linear& a, long sa, const Linear& b, long sb) {
  Linear out;
  for (const auto& [c, v] : a) out[c] += sa * v;
  for (const auto& [c, v] : b) out[c] += sb * v;
  for (auto it = out.begin(); it != out.end();) it = it->second == 0 ? out.erase(it) : std::next(it);
  return out;
}

}  // namespace

std::vector<JumpConstraint> JumpConstraints(const CutGraph& cut,
                                            const std::vector<int>& chain_sign) {
  CHECK_EQ(chain_sign.size(), cut.chains.size());
  for (int s : chain_sign) CHECK(s == 1 || s == -1);
  const int n = cut.num_wedges;
  std::vector<std::vector<int>> incident(n);
  for (size_t r = 0; r < cut.relations.size(); ++r) {
    incident[cut.relations[r].left_wedge].push_back(static_cast<int>(r));
    if (cut.relations[r].right_wedge != cut.relations[r].left_wedge)
      incident[cut.relations[r].right_wedge].push_back(static_cast<int>(r));
  }
  // Every wedge of a related group as u = a + b·x, a symbolic in the k's.
  std::vector<Linear> a(n);
  std::vector<long> b(n, 0);
  std::vector<int> group(n, -1);
  int groups = 0;
  for (int w0 = 0; w0 < n; ++w0) {
    if (group[w0] >= 0 || incident[w0].empty()) continue;
    group[w0] = groups;
    b[w0] = 1;
    std::queue<int> queue;
    queue.push(w0);
    while (!queue.empty()) {
      const int w = queue.front();
      queue.pop();
      for (int r : incident[w]) {
        const JumpRelation& rel = cut.relations[r];
        const long s = chain_sign[rel.chain];
        const Linear e = {{rel.chain, 1}};
        const int other = rel.left_wedge == w ? rel.right_wedge : rel.left_wedge;
        if (group[other] >= 0) continue;
        group[other] = groups;
        if (rel.left_wedge == w) {  // u_R = s (u_L − k)
          a[other] = Combine(a[w], s, e, -s);
        } else {  // u_L = k + s u_R
          a[other] = Combine(e, 1, a[w], s);
        }
        b[other] = s * b[w];
        queue.push(other);
      }
    }
    ++groups;
  }
  // Each relation: (b_L − s b_R) x = k + s a_R − a_L.
  std::vector<bool> fixed(groups, false);
  std::vector<Linear> fixed_rhs(groups);
  std::vector<long> fixed_coef(groups, 0);
  std::vector<JumpConstraint> out;
  auto add = [&](const Linear& row, VertexIndex v) {
    if (row.empty()) return;
    JumpConstraint c;
    c.terms.assign(row.begin(), row.end());
    c.vertex = v;
    out.push_back(c);
  };
  for (const JumpRelation& rel : cut.relations) {
    const long s = chain_sign[rel.chain];
    const int L = rel.left_wedge, R = rel.right_wedge, id = group[L];
    const long coef = b[L] - s * b[R];
    const Linear rhs = Combine(Combine({{rel.chain, 1}}, 1, a[R], s), 1, a[L], -1);
    if (coef == 0) {
      add(rhs, rel.vertex);
    } else if (!fixed[id]) {
      fixed[id] = true;
      fixed_rhs[id] = rhs;
      fixed_coef[id] = coef;
    } else {  // rhs/coef == fixed_rhs/fixed_coef
      add(Combine(rhs, fixed_coef[id], fixed_rhs[id], -coef), rel.vertex);
    }
  }
  return out;
}

bool RoundJumps(const CutGraph& cut, const std::vector<int>& chain_sign,
                const std::vector<double>& alpha, double spacing, int parity,
                std::vector<double>* rounded, std::string* message) {
  CHECK_EQ(alpha.size(), cut.chains.size());
  CHECK(spacing > 0.0);
  CHECK(parity == 0 || parity == 1);
  const size_t nc = cut.chains.size();
  auto half_singular = [&](int c) { return cut.chains[c].from_singularity && chain_sign[c] < 0; };
  // Forward elimination: pivots (chain, expression over the other chains).
  std::vector<std::pair<int, Linear>> pivots;
  std::vector<bool> is_pivot(nc, false);
  bool ok = true;
  std::ostringstream notes;
  for (const JumpConstraint& c : JumpConstraints(cut, chain_sign)) {
    Linear row(c.terms.begin(), c.terms.end());
    for (const auto& [p, expr] : pivots) {  // substitute earlier pivots
      auto it = row.find(p);
      if (it == row.end()) continue;
      const long v = it->second;
      row.erase(it);
      row = Combine(row, 1, expr, v);
    }
    if (row.empty()) continue;  // implied by earlier constraints
    int pivot = -1;
    for (const auto& [chain, v] : row) {
      if (std::abs(v) != 1) continue;
      if (pivot < 0 || (half_singular(pivot) && !half_singular(chain))) pivot = chain;
    }
    if (pivot < 0) {
      ok = false;
      notes << "the jumps around vertex " << c.vertex.idx() << " have no unit coefficient; ";
      continue;
    }
    const long v = row[pivot];
    row.erase(pivot);
    Linear expr;  // k_pivot = −v Σ row (v = ±1)
    for (const auto& [chain, x] : row) expr[chain] = -v * x;
    pivots.push_back({pivot, expr});
    is_pivot[pivot] = true;
  }
  std::vector<double> k(nc);
  for (size_t c = 0; c < nc; ++c) {
    if (is_pivot[c]) continue;
    const double x = alpha[c] / spacing;
    if (half_singular(static_cast<int>(c))) {
      k[c] = parity == 0 ? 2.0 * std::round(0.5 * x) : 2.0 * std::floor(0.5 * x) + 1.0;
    } else {
      k[c] = std::round(x);
    }
  }
  for (auto it = pivots.rbegin(); it != pivots.rend(); ++it) {
    double value = 0.0;
    for (const auto& [chain, x] : it->second) value += static_cast<double>(x) * k[chain];
    k[it->first] = value;
    if (half_singular(it->first) && std::abs(std::fmod(std::abs(value), 2.0) - parity) > 0.5) {
      ok = false;
      notes << "chain " << it->first << " (from a singularity) is fixed by the others to "
            << value << " spacings, not of the requested parity; ";
    }
  }
  rounded->resize(nc);
  for (size_t c = 0; c < nc; ++c) (*rounded)[c] = k[c] * spacing;
  if (message != nullptr) *message = notes.str();
  return ok;
}

CutSurfaceTopology CutSurface(const Mesh& mesh, const CutGraph& cut) {
  UnionFind uf(mesh.number_of_faces());
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
    uf.Union(mesh.face(mesh.halfedge(e, 0)).idx(), mesh.face(mesh.halfedge(e, 1)).idx());
  }
  CutSurfaceTopology t;
  for (FaceIndex f : mesh.faces())
    if (uf.Find(f.idx()) == f.idx()) ++t.components;
  t.euler_characteristic =
      cut.num_wedges - edges + static_cast<int>(mesh.number_of_faces());
  return t;
}

FieldOrientation OrientField(const Mesh& mesh, const CutGraph& cut,
                             const std::vector<EdgeTransport>& transports,
                             const std::vector<int>& edge_to_transport,
                             const std::vector<Eigen::Vector2d>& direction) {
  const size_t nf = mesh.number_of_faces();
  CHECK_EQ(direction.size(), nf);
  CHECK_EQ(edge_to_transport.size(), mesh.number_of_edges());
  auto defined = [&](FaceIndex f) {
    const Eigen::Vector2d& d = direction[f.idx()];
    return d.allFinite() && d.squaredNorm() > 0.0;
  };
  auto rotate = [](const Eigen::Vector2d& x, double a) {
    return Eigen::Vector2d(std::cos(a) * x.x() - std::sin(a) * x.y(),
                           std::sin(a) * x.x() + std::cos(a) * x.y());
  };
  // A vector of g's frame expressed in f's frame.
  auto in_frame_of = [&](FaceIndex f, FaceIndex g, EdgeIndex e, const Eigen::Vector2d& x) {
    const int t = edge_to_transport[e.idx()];
    CHECK_GE(t, 0);
    return rotate(x, TransportAngle(transports[t], g, f));
  };
  FieldOrientation out;
  out.face_sign.assign(nf, 1);
  std::vector<Eigen::Vector2d> reference(nf, Eigen::Vector2d::Zero());  // oriented direction
  std::vector<bool> seen(nf, false);
  for (FaceIndex root : mesh.faces()) {
    if (seen[root.idx()]) continue;
    seen[root.idx()] = true;
    reference[root.idx()] = defined(root) ? direction[root.idx()] : Eigen::Vector2d(1, 0);
    std::queue<FaceIndex> queue;
    queue.push(root);
    while (!queue.empty()) {
      const FaceIndex f = queue.front();
      queue.pop();
      for (HalfedgeIndex h : mesh.halfedges_around_face(mesh.halfedge(f))) {
        const EdgeIndex e = mesh.edge(h);
        if (mesh.is_border(e) || cut.is_cut_edge[e.idx()]) continue;
        const FaceIndex g = mesh.face(mesh.opposite(h));
        if (seen[g.idx()]) continue;
        seen[g.idx()] = true;
        // f's reference in g's frame.
        const Eigen::Vector2d ref = in_frame_of(g, f, e, reference[f.idx()]);
        if (defined(g)) {
          out.face_sign[g.idx()] = ref.dot(direction[g.idx()]) >= 0.0 ? 1 : -1;
          reference[g.idx()] = out.face_sign[g.idx()] * direction[g.idx()];
        } else {
          reference[g.idx()] = ref;
        }
        queue.push(g);
      }
    }
  }
  auto matching = [&](EdgeIndex e) {  // +1 / −1: orientations across e agree / not
    const FaceIndex f = mesh.face(mesh.halfedge(e, 0)), g = mesh.face(mesh.halfedge(e, 1));
    return reference[f.idx()].dot(in_frame_of(f, g, e, reference[g.idx()])) >= 0.0 ? 1 : -1;
  };
  std::vector<int> votes(cut.chains.size(), 0);
  for (EdgeIndex e : mesh.edges()) {
    if (mesh.is_border(e)) continue;
    if (cut.is_cut_edge[e.idx()]) {
      votes[cut.edge_chain[e.idx()]] += matching(e);
    } else if (matching(e) < 0) {
      ++out.mismatched_edges;
    }
  }
  out.chain_sign.resize(cut.chains.size());
  for (size_t c = 0; c < cut.chains.size(); ++c) out.chain_sign[c] = votes[c] >= 0 ? 1 : -1;
  for (EdgeIndex e : mesh.edges()) {
    if (mesh.is_border(e) || !cut.is_cut_edge[e.idx()]) continue;
    if (matching(e) != out.chain_sign[cut.edge_chain[e.idx()]]) ++out.mismatched_cut_edges;
  }
  return out;
}

}  // namespace archgeo
