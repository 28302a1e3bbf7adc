// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A polygon mesh from the crossings of two families of streamlines
// [Gebreiter 2012, §8.2]; see fields/streamline_mesh.h.
#include "fields/streamline_mesh.h"

#include <glog/logging.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_map>
#include <utility>

#include "core/segments.h"
#include "fields/layout_cleanup.h"

namespace archgeo {
namespace streamline_mesh_internal {
namespace {

using V3 = Eigen::Vector3d;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kLargestFace = 64;  // nodes

// Items (by id) hashed into cubic cells by their boxes.
class CellHash {
 public:
  explicit CellHash(double cell) : cell_(cell) {}
  void Add(int id, const V3& lo, const V3& hi) {
    ForCells(lo, hi, [&](std::uint64_t k) { cells_[k].push_back(id); });
  }
  // Calls f(id) for the ids in the cells the box meets (an id may repeat).
  template <class F>
  void Near(const V3& lo, const V3& hi, F f) const {
    ForCells(lo, hi, [&](std::uint64_t k) {
      const auto it = cells_.find(k);
      if (it == cells_.end()) return;
      for (int id : it->second) f(id);
    });
  }

 private:
  template <class F>
  void ForCells(const V3& lo, const V3& hi, F f) const {
    const Eigen::Array3i a = (lo / cell_).array().floor().cast<int>();
    const Eigen::Array3i b = (hi / cell_).array().floor().cast<int>();
    for (int x = a[0]; x <= b[0]; ++x)
      for (int y = a[1]; y <= b[1]; ++y)
        for (int z = a[2]; z <= b[2]; ++z) f(Key(x, y, z));
  }
  static std::uint64_t Key(int x, int y, int z) {
    auto u = [](int v) { return std::uint64_t(std::uint32_t(v + (1 << 20)) & 0x1fffff); };
    return (u(x) << 42) | (u(y) << 21) | u(z);
  }
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
};

// The index of the point of `points` nearest q (a hash of cells, searched in
// growing shells).
class NearestPoint {
 public:
  NearestPoint(const std::vector<V3>& points, double cell) : points_(points), cell_(cell), hash_(cell) {
    for (size_t i = 0; i < points.size(); ++i) hash_.Add(int(i), points[i], points[i]);
    V3 lo = V3::Constant(kInf), hi = -lo;
    for (const V3& p : points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    extent_ = points.empty() ? 0 : (hi - lo).norm();
  }
  int operator()(const V3& q) const {
    int best = -1;
    double dist = kInf;
    for (double r = cell_;; r *= 2) {
      hash_.Near(q - V3::Constant(r), q + V3::Constant(r), [&](int id) {
        const double d = (points_[size_t(id)] - q).norm();
        if (d < dist) {
          dist = d;
          best = id;
        }
      });
      if ((best >= 0 && dist <= r) || r > 2 * extent_ + 4 * cell_) break;
    }
    if (best < 0) {  // q far outside the points' box
      for (size_t i = 0; i < points_.size(); ++i) {
        const double d = (points_[i] - q).norm();
        if (d < dist) {
          dist = d;
          best = int(i);
        }
      }
    }
    return best;
  }

 private:
  const std::vector<V3>& points_;
  double cell_;
  CellHash hash_;
  double extent_ = 0;
};

struct UnionFind {
  std::vector<int> parent;
  int Find(int x) {
    while (parent[size_t(x)] != x) x = parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
    return x;
  }
  void Join(int a, int b) { parent[size_t(Find(a))] = Find(b); }
};

// A line as a polyline with arc positions (a closed line repeats its first point).
struct Poly {
  std::vector<V3> p;
  std::vector<double> s;
  int family = 0;
  bool closed = false;
  double Length() const { return s.empty() ? 0 : s.back(); }
  // The point at arc a (clamped; a closed line wraps).
  V3 At(double a) const {
    if (closed && Length() > 0) a -= Length() * std::floor(a / Length());
    if (a <= 0) return p.front();
    if (a >= Length()) return p.back();
    const size_t i = size_t(std::upper_bound(s.begin(), s.end(), a) - s.begin()) - 1;
    const double t = s[i + 1] > s[i] ? (a - s[i]) / (s[i + 1] - s[i]) : 0;
    return p[i] + t * (p[i + 1] - p[i]);
  }
};

struct Edge {
  int a = -1, b = -1;
  std::vector<V3> path;  // from a to b
  bool boundary = false;
  bool alive = true;
};

class Builder {
 public:
  Builder(const StreamlineInput& in, const std::vector<Streamline>& lines, double d_sep,
          const StreamlineMeshOptions& o)
      : in_(in), d_sep_(d_sep), o_(o), hash_(d_sep) {
    for (const Streamline& l : lines) {
      if (l.points.size() < 2) continue;
      Poly q;
      q.family = l.family;
      q.closed = l.closed;
      q.p = l.points;
      if (l.closed) q.p.push_back(l.points.front());
      q.s.push_back(0);
      for (size_t i = 1; i < q.p.size(); ++i) q.s.push_back(q.s.back() + (q.p[i] - q.p[i - 1]).norm());
      polys_.push_back(std::move(q));
    }
    events_.resize(polys_.size());
    BoundaryLoops();
    for (size_t l = 0; l < polys_.size(); ++l) {
      for (size_t i = 0; i + 1 < polys_[l].p.size(); ++i) {
        const int id = int(segs_.size());
        segs_.push_back({int(l), int(i)});
        hash_.Add(id, polys_[l].p[i].cwiseMin(polys_[l].p[i + 1]), polys_[l].p[i].cwiseMax(polys_[l].p[i + 1]));
      }
    }
    for (size_t e = 0; e < bedges_.size(); ++e) {
      const int id = int(segs_.size());
      segs_.push_back({-1, int(e)});
      hash_.Add(id, bedges_[e].a.cwiseMin(bedges_[e].b), bedges_[e].a.cwiseMax(bedges_[e].b));
    }
  }

  StreamlineMesh Run() {
    Crossings();
    Ends();
    MergeNodes();
    LineEdges();
    BoundaryEdges();
    Prune();
    JoinStraightNodes();
    Faces();
    return std::move(out_);
  }

 private:
  struct SegRef {
    int line;   // −1: a boundary edge
    int index;  // segment of the line, or boundary edge
  };
  struct BEdge {
    V3 a, b;
    int loop, k;  // loop and position in it
  };

  std::pair<V3, V3> Seg(const SegRef& r) const {
    if (r.line < 0) return {bedges_[size_t(r.index)].a, bedges_[size_t(r.index)].b};
    const Poly& q = polys_[size_t(r.line)];
    return {q.p[size_t(r.index)], q.p[size_t(r.index) + 1]};
  }

  int NewNode(const V3& x, bool boundary = false, bool corner = false) {
    nodes_.push_back(x);
    node_boundary_.push_back(boundary);
    node_corner_.push_back(corner);
    return int(nodes_.size()) - 1;
  }

  // Directed boundary edges (the surface on their left: the triangles'
  // order), chained into loops.
  void BoundaryLoops() {
    std::map<std::pair<int, int>, int> directed;
    for (const auto& t : in_.triangles)
      for (int k = 0; k < 3; ++k) ++directed[{t[size_t(k)], t[size_t((k + 1) % 3)]}];
    std::multimap<int, int> from;  // vertex -> target
    for (const auto& [e, n] : directed) {
      if (directed.count({e.second, e.first}) == 0) from.insert({e.first, e.second});
    }
    while (!from.empty()) {
      std::vector<int> loop{from.begin()->first};
      auto it = from.begin();
      while (it != from.end()) {
        const int next = it->second;
        from.erase(it);
        if (next == loop.front()) break;
        loop.push_back(next);
        it = from.find(next);
      }
      const int id = int(loops_.size());
      for (size_t k = 0; k < loop.size(); ++k) {
        bedges_.push_back({in_.points[size_t(loop[k])], in_.points[size_t(loop[(k + 1) % loop.size()])],
                           id, int(k)});
      }
      loops_.push_back(loop);
    }
    bevents_.resize(bedges_.size());
  }

  void Crossings() {
    const double tol = 1e-7 * d_sep_;
    for (size_t l = 0; l < polys_.size(); ++l) {
      const Poly& q = polys_[l];
      for (size_t i = 0; i + 1 < q.p.size(); ++i) {
        const V3 a = q.p[i], b = q.p[i + 1];
        std::vector<int> seen;
        hash_.Near(a.cwiseMin(b) - V3::Constant(tol), a.cwiseMax(b) + V3::Constant(tol), [&](int id) {
          const SegRef r = segs_[size_t(id)];
          if (r.line <= int(l)) return;  // each pair once; boundary edges elsewhere
          if (std::find(seen.begin(), seen.end(), id) != seen.end()) return;
          seen.push_back(id);
          const auto [c, d] = Seg(r);
          const auto [s, t] = ClosestSegmentParameters(a, b, c, d);
          const V3 x = a + s * (b - a), y = c + t * (d - c);
          if ((x - y).norm() > tol) return;
          const int node = NewNode(0.5 * (x + y));
          const Poly& o = polys_[size_t(r.line)];
          events_[l].push_back({q.s[i] + s * (q.s[i + 1] - q.s[i]), node});
          events_[size_t(r.line)].push_back({o.s[size_t(r.index)] + t * (o.s[size_t(r.index) + 1] - o.s[size_t(r.index)]), node});
        });
      }
    }
  }

  // The boundary edge within `tol` of x (and its parameter), or −1.
  std::pair<int, double> OnBoundary(const V3& x, double tol) const {
    int best = -1;
    double dist = tol, param = 0;
    hash_.Near(x - V3::Constant(tol), x + V3::Constant(tol), [&](int id) {
      const SegRef r = segs_[size_t(id)];
      if (r.line >= 0) return;
      const auto [a, b] = Seg(r);
      const double len2 = (b - a).squaredNorm();
      const double t = len2 > 0 ? std::clamp((x - a).dot(b - a) / len2, 0.0, 1.0) : 0.0;
      const double d = (a + t * (b - a) - x).norm();
      if (d <= dist) {
        dist = d;
        best = r.index;
        param = t;
      }
    });
    return {best, param};
  }

  void Ends() {
    for (size_t l = 0; l < polys_.size(); ++l) {
      const Poly& q = polys_[l];
      if (q.closed) continue;
      for (int end = 0; end < 2; ++end) {
        const double at = end == 0 ? 0.0 : q.Length();
        bool done = false;
        for (const auto& [s, node] : events_[l]) done = done || std::abs(s - at) < 1e-6 * d_sep_;
        if (done) continue;
        const V3 x = end == 0 ? q.p.front() : q.p.back();
        if (const auto [e, t] = OnBoundary(x, 1e-5 * d_sep_); e >= 0) {
          const int node = NewNode(x, true);
          events_[l].push_back({at, node});
          bevents_[size_t(e)].push_back({t, node});
          ++out_.boundary_ends;
          continue;
        }
        if (Extend(int(l), end)) {
          ++out_.extended_ends;
        } else {
          ++out_.dangling_ends;
        }
      }
    }
  }

  // Extends end `end` of line l along its last segment (see the header).
  bool Extend(int l, int end) {
    const Poly& q = polys_[size_t(l)];
    const size_t n = q.p.size();
    const V3 x = end == 0 ? q.p[0] : q.p[n - 1];
    V3 dir = end == 0 ? V3(q.p[0] - q.p[1]) : V3(q.p[n - 1] - q.p[n - 2]);
    if (dir.norm() <= 0) return false;
    dir.normalize();
    const double reach = o_.extend * d_sep_;
    const V3 y = x + reach * dir;
    const double pad = 0.05 * d_sep_ + 0.2 * reach;
    double best_u = kInf, best_t = 0;
    SegRef best{-2, 0};
    hash_.Near(x.cwiseMin(y) - V3::Constant(pad), x.cwiseMax(y) + V3::Constant(pad), [&](int id) {
      const SegRef r = segs_[size_t(id)];
      if (r.line == l) return;
      if (r.line >= 0 && polys_[size_t(r.line)].family == q.family) return;
      const auto [c, d] = Seg(r);
      const auto [u, t] = ClosestSegmentParameters(x, y, c, d);
      const double dist = ((x + u * (y - x)) - (c + t * (d - c))).norm();
      if (dist > 0.05 * d_sep_ + 0.2 * u * reach || u >= best_u) return;
      if (u * reach < 1e-9 * d_sep_ && r.line < 0) return;
      best_u = u;
      best_t = t;
      best = r;
    });
    if (best.line == -2) return false;
    const auto [c, d] = Seg(best);
    const V3 hit = c + best_t * (d - c);
    const int node = NewNode(hit, best.line < 0);
    if (best.line < 0) {
      bevents_[size_t(best.index)].push_back({best_t, node});
    } else {
      const Poly& o = polys_[size_t(best.line)];
      const size_t i = size_t(best.index);
      events_[size_t(best.line)].push_back({o.s[i] + best_t * (o.s[i + 1] - o.s[i]), node});
    }
    const double beyond = (hit - x).norm();
    events_[size_t(l)].push_back({end == 0 ? -beyond : q.Length() + beyond, node});
    return true;
  }

  // Nodes closer than 1e-6 d_sep are one.
  void MergeNodes() {
    const double tol = 1e-6 * d_sep_;
    UnionFind uf;
    uf.parent.resize(nodes_.size());
    std::iota(uf.parent.begin(), uf.parent.end(), 0);
    CellHash hash(std::max(tol * 100, 1e-300));
    for (size_t i = 0; i < nodes_.size(); ++i) {
      hash.Near(nodes_[i] - V3::Constant(tol), nodes_[i] + V3::Constant(tol), [&](int j) {
        if ((nodes_[size_t(j)] - nodes_[i]).norm() <= tol) uf.Join(int(i), j);
      });
      hash.Add(int(i), nodes_[i], nodes_[i]);
    }
    std::vector<int> rep(nodes_.size());
    for (size_t i = 0; i < nodes_.size(); ++i) {
      rep[i] = uf.Find(int(i));
      if (node_boundary_[i]) node_boundary_[size_t(rep[i])] = true;
    }
    for (auto& list : events_)
      for (auto& e : list) e.second = rep[size_t(e.second)];
    for (auto& list : bevents_)
      for (auto& e : list) e.second = rep[size_t(e.second)];
    for (size_t i = 0; i < nodes_.size(); ++i) {
      if (rep[i] == int(i) && !node_boundary_[i]) ++out_.crossings;
    }
  }

  void AddEdge(int a, int b, std::vector<V3> path, bool boundary) {
    if (a == b) return;
    edges_.push_back({a, b, std::move(path), boundary, true});
  }

  void LineEdges() {
    for (size_t l = 0; l < polys_.size(); ++l) {
      auto& ev = events_[l];
      std::sort(ev.begin(), ev.end());
      const Poly& q = polys_[l];
      const size_t m = ev.size();
      if (m == 0) continue;
      const size_t count = q.closed ? m : m - 1;
      for (size_t k = 0; k < count; ++k) {
        const auto [s0, a] = ev[k];
        double s1 = ev[(k + 1) % m].first;
        const int b = ev[(k + 1) % m].second;
        if (q.closed && k + 1 == m) s1 += q.Length();
        if (a == b) continue;
        std::vector<V3> path{nodes_[size_t(a)]};
        if (!q.closed) {
          for (size_t i = 0; i < q.p.size(); ++i)
            if (q.s[i] > s0 && q.s[i] < s1) path.push_back(q.p[i]);
        } else {
          // Arc positions in (s0, s1), wrapping once.
          for (int lap = 0; lap < 2; ++lap)
            for (size_t i = 0; i + 1 < q.p.size(); ++i) {
              const double s = q.s[i] + lap * q.Length();
              if (s > s0 && s < s1) path.push_back(q.p[i]);
            }
        }
        path.push_back(nodes_[size_t(b)]);
        AddEdge(a, b, std::move(path), false);
      }
    }
  }

  void BoundaryEdges() {
    const double cos_corner = std::cos(o_.corner_angle_deg * M_PI / 180);
    for (size_t loop = 0; loop < loops_.size(); ++loop) {
      const std::vector<int>& vs = loops_[loop];
      const size_t n = vs.size();
      // (position along the loop, node): k + t for boundary edge k.
      std::vector<std::pair<double, int>> on;
      size_t first = 0;
      while (first < bedges_.size() && bedges_[first].loop != int(loop)) ++first;
      for (size_t k = 0; k < n; ++k) {
        const V3 p = in_.points[size_t(vs[(k + n - 1) % n])], x = in_.points[size_t(vs[k])],
                 r = in_.points[size_t(vs[(k + 1) % n])];
        const V3 a = (x - p).normalized(), b = (r - x).normalized();
        if (a.dot(b) < cos_corner) on.push_back({double(k), NewNode(x, true, true)});
        for (const auto& [t, node] : bevents_[first + k]) on.push_back({k + t, node});
      }
      std::sort(on.begin(), on.end());
      // A corner where a line ends is that line's node.
      for (size_t j = 0; j + 1 < on.size();) {
        if (on[j + 1].first - on[j].first < 1e-6 &&
            (node_corner_[size_t(on[j].second)] || node_corner_[size_t(on[j + 1].second)])) {
          const size_t drop = node_corner_[size_t(on[j].second)] ? j : j + 1;
          node_corner_[size_t(on[drop == j ? j + 1 : j].second)] = true;
          on.erase(on.begin() + long(drop));
        } else {
          ++j;
        }
      }
      const size_t m = on.size();
      if (m < 2) continue;
      for (size_t j = 0; j < m; ++j) {
        const auto [s0, a] = on[j];
        double s1 = on[(j + 1) % m].first;
        const int b = on[(j + 1) % m].second;
        if (j + 1 == m) s1 += double(n);
        std::vector<V3> path{nodes_[size_t(a)]};
        for (size_t k = size_t(std::floor(s0)) + 1; double(k) < s1; ++k) {
          path.push_back(in_.points[size_t(vs[k % n])]);
        }
        path.push_back(nodes_[size_t(b)]);
        AddEdge(a, b, std::move(path), true);
      }
    }
  }

  std::vector<std::vector<int>> Incidence() const {
    std::vector<std::vector<int>> at(nodes_.size());
    for (size_t e = 0; e < edges_.size(); ++e) {
      if (!edges_[e].alive) continue;
      at[size_t(edges_[e].a)].push_back(int(e));
      at[size_t(edges_[e].b)].push_back(int(e));
    }
    return at;
  }

  void Prune() {
    std::vector<std::vector<int>> at = Incidence();
    std::vector<int> degree(nodes_.size());
    std::vector<int> stack;
    for (size_t v = 0; v < nodes_.size(); ++v) {
      degree[v] = int(at[v].size());
      if (degree[v] == 1) stack.push_back(int(v));
    }
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (int e : at[size_t(v)]) {
        Edge& edge = edges_[size_t(e)];
        if (!edge.alive || edge.boundary) continue;
        edge.alive = false;
        ++out_.pruned_edges;
        for (int w : {edge.a, edge.b}) {
          if (--degree[size_t(w)] == 1) stack.push_back(w);
        }
      }
    }
  }

  // The direction an edge leaves node v by (its path from v).
  V3 Leaving(const Edge& e, int v) const {
    const V3& x = nodes_[size_t(v)];
    const int n = int(e.path.size());
    for (int i = 1; i < n; ++i) {
      const V3& y = e.a == v ? e.path[size_t(i)] : e.path[size_t(n - 1 - i)];
      if ((y - x).norm() >= 0.05 * d_sep_ || i == n - 1) return (y - x).normalized();
    }
    return V3::Zero();
  }

  void JoinStraightNodes() {
    std::vector<std::vector<int>> at = Incidence();
    for (size_t v = 0; v < nodes_.size(); ++v) {
      if (node_boundary_[v]) continue;
      std::vector<int> live;
      for (int e : at[v])
        if (edges_[size_t(e)].alive) live.push_back(e);
      if (live.size() != 2 || live[0] == live[1]) continue;
      Edge& e0 = edges_[size_t(live[0])];
      Edge& e1 = edges_[size_t(live[1])];
      const int a = e0.a == int(v) ? e0.b : e0.a, b = e1.a == int(v) ? e1.b : e1.a;
      if (a == int(v) || b == int(v) || a == b) continue;
      if (Leaving(e0, int(v)).dot(Leaving(e1, int(v))) > -std::cos(M_PI / 6)) continue;
      std::vector<V3> path = e0.path;
      if (e0.a == int(v)) std::reverse(path.begin(), path.end());  // a … v
      std::vector<V3> tail = e1.path;
      if (e1.b == int(v)) std::reverse(tail.begin(), tail.end());  // v … b
      path.insert(path.end(), tail.begin() + 1, tail.end());
      e0.alive = e1.alive = false;
      const int id = int(edges_.size());
      edges_.push_back({a, b, std::move(path), false, true});
      for (int w : {a, b}) at[size_t(w)].push_back(id);
      ++out_.joined_nodes;
    }
  }

  void Faces() {
    // Tangent planes: the normal of the nearest mesh vertex.
    std::vector<V3> vertex_normal(in_.points.size(), V3::Zero());
    for (const auto& t : in_.triangles) {
      const V3 n = (in_.points[size_t(t[1])] - in_.points[size_t(t[0])])
                       .cross(in_.points[size_t(t[2])] - in_.points[size_t(t[0])]);
      for (int v : t) vertex_normal[size_t(v)] += n;
    }
    const NearestPoint nearest(in_.points, d_sep_);
    // Per node its edge ends by angle: (angle, half-edge leaving or −1, edge).
    struct End {
      double angle;
      int out;
      int edge;
    };
    std::vector<std::vector<End>> ends(nodes_.size());
    for (size_t e = 0; e < edges_.size(); ++e) {
      const Edge& edge = edges_[e];
      if (!edge.alive) continue;
      for (int side = 0; side < 2; ++side) {
        const int v = side == 0 ? edge.a : edge.b;
        const V3 n = vertex_normal[size_t(nearest(nodes_[size_t(v)]))].normalized();
        const V3 u = n.unitOrthogonal(), w = n.cross(u);
        const V3 d = Leaving(edge, v);
        const int out = side == 0 ? int(2 * e) : (edge.boundary ? -1 : int(2 * e + 1));
        ends[size_t(v)].push_back({std::atan2(d.dot(w), d.dot(u)), out, int(e)});
      }
    }
    for (auto& list : ends)
      std::sort(list.begin(), list.end(), [](const End& x, const End& y) { return x.angle < y.angle; });
    // next(h): at h's head, the first leaving half-edge clockwise from h's edge.
    auto head = [&](int h) { return h % 2 == 0 ? edges_[size_t(h / 2)].b : edges_[size_t(h / 2)].a; };
    auto tail = [&](int h) { return h % 2 == 0 ? edges_[size_t(h / 2)].a : edges_[size_t(h / 2)].b; };
    auto next = [&](int h) {
      const int v = head(h);
      const std::vector<End>& list = ends[size_t(v)];
      const int m = int(list.size());
      int pos = -1;
      for (int i = 0; i < m; ++i) {
        // The end of h's edge at v (an edge with both ends at v cannot occur).
        if (list[size_t(i)].edge == h / 2) pos = i;
      }
      for (int k = 1; k <= m; ++k) {
        const End& e = list[size_t(((pos - k) % m + m) % m)];
        if (e.out >= 0) return e.out;
      }
      return -1;
    };
    std::vector<bool> used(2 * edges_.size(), false);
    std::vector<std::vector<int>> cycles;
    for (size_t e = 0; e < edges_.size(); ++e) {
      if (!edges_[e].alive) continue;
      for (int h0 : {int(2 * e), edges_[e].boundary ? -1 : int(2 * e + 1)}) {
        if (h0 < 0 || used[size_t(h0)]) continue;
        std::vector<int> cycle;
        int h = h0;
        bool closed = false;
        for (size_t steps = 0; steps <= 2 * edges_.size(); ++steps) {
          used[size_t(h)] = true;
          cycle.push_back(tail(h));
          h = next(h);
          if (h < 0) break;
          if (h == h0) {
            closed = true;
            break;
          }
          if (used[size_t(h)]) break;
        }
        if (!closed) {
          ++out_.dropped_faces;
          continue;
        }
        if (cycle.size() > size_t(kLargestFace)) {  // a region the lines do not divide
          ++out_.dropped_faces;
          ++out_.dropped_large_faces;
          continue;
        }
        SimpleCycles(cycle, &cycles, &out_.dropped_faces);
      }
    }
    // Compact the nodes the faces use.
    std::vector<int> index(nodes_.size(), -1);
    for (auto& f : cycles) {
      for (int& v : f) {
        if (index[size_t(v)] < 0) {
          index[size_t(v)] = int(out_.points.size());
          out_.points.push_back(nodes_[size_t(v)]);
          out_.on_boundary.push_back(node_boundary_[size_t(v)]);
          out_.is_corner.push_back(node_corner_[size_t(v)]);
        }
        v = index[size_t(v)];
      }
    }
    out_.faces = std::move(cycles);
  }

  const StreamlineInput& in_;
  double d_sep_;
  StreamlineMeshOptions o_;
  std::vector<Poly> polys_;
  std::vector<SegRef> segs_;
  CellHash hash_;
  std::vector<std::vector<int>> loops_;
  std::vector<BEdge> bedges_;
  std::vector<std::vector<std::pair<double, int>>> events_, bevents_;  // (arc or t, node)
  std::vector<V3> nodes_;
  std::vector<bool> node_boundary_, node_corner_;
  std::vector<Edge> edges_;
  StreamlineMesh out_;
};

}  // namespace
}  // namespace streamline_mesh_internal

using streamline_mesh_internal::Builder;
using streamline_mesh_internal::NearestPoint;

StreamlineMesh MeshFromStreamlines(const StreamlineInput& surface,
                                   const std::vector<Streamline>& lines, double d_sep,
                                   const StreamlineMeshOptions& options) {
  CHECK(d_sep > 0 && std::isfinite(d_sep));
  CHECK_EQ(surface.directions.size(), surface.triangles.size());
  CHECK_EQ(surface.valid.size(), surface.triangles.size());
  for (const auto& t : surface.triangles)
    for (int v : t) CHECK(v >= 0 && v < int(surface.points.size()));
  Builder builder(surface, lines, d_sep, options);
  return builder.Run();
}

EdgeFieldAngle MeasureEdgeFieldAngle(const StreamlineInput& surface,
                                     const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<std::vector<int>>& faces) {
  using V3 = Eigen::Vector3d;
  EdgeFieldAngle r;
  std::vector<V3> centroids;
  std::vector<int> face_of;
  double mean_edge = 0;
  for (size_t f = 0; f < surface.triangles.size(); ++f) {
    if (!surface.valid[f]) continue;
    const auto& t = surface.triangles[f];
    const V3 a = surface.points[size_t(t[0])], b = surface.points[size_t(t[1])],
             c = surface.points[size_t(t[2])];
    centroids.push_back((a + b + c) / 3);
    face_of.push_back(int(f));
    mean_edge += ((b - a).norm() + (c - b).norm() + (a - c).norm()) / 3;
  }
  if (centroids.empty()) return r;
  mean_edge /= double(centroids.size());
  const NearestPoint nearest(centroids, std::max(mean_edge, 1e-300));
  std::map<std::pair<int, int>, int> uses;
  for (const auto& f : faces)
    for (size_t i = 0; i < f.size(); ++i) {
      const int a = f[i], b = f[(i + 1) % f.size()];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  double sum = 0;
  for (const auto& [e, n] : uses) {
    if (n != 2) continue;
    const V3 x = points[size_t(e.first)], y = points[size_t(e.second)];
    const int f = face_of[size_t(nearest(0.5 * (x + y)))];
    const auto& t = surface.triangles[size_t(f)];
    const V3 normal = (surface.points[size_t(t[1])] - surface.points[size_t(t[0])])
                          .cross(surface.points[size_t(t[2])] - surface.points[size_t(t[0])])
                          .normalized();
    V3 d = y - x;
    d -= d.dot(normal) * normal;
    if (d.norm() <= 0) continue;
    d.normalize();
    double best = 0;
    for (const V3& l : surface.directions[size_t(f)]) best = std::max(best, std::abs(d.dot(l.normalized())));
    const double angle = std::acos(std::min(1.0, best)) * 180 / M_PI;
    sum += angle;
    r.max_deg = std::max(r.max_deg, angle);
    ++r.edges;
  }
  r.mean_deg = r.edges > 0 ? sum / r.edges : 0;
  return r;
}

}  // namespace archgeo
