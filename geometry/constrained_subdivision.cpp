// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — constrained Loop and Catmull–Clark subdivision, limit positions
// and reverse subdivision [Gebreiter 2012, §9.1.1, §9.1.2, §9.2.1–9.2.3];
// see geometry/constrained_subdivision.h for the rules.
#include "geometry/constrained_subdivision.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <glog/logging.h>

#include "core/dense_solve.h"
#include "core/segments.h"

namespace archgeo {
namespace {

using CsRow = std::vector<std::pair<int, double>>;  // fine vertex = Σ w · coarse vertex

long long CsKey(int a, int b) { return (static_cast<long long>(a) << 32) | static_cast<unsigned>(b); }

// Edges and incidences of a polygon mesh.
struct CsTopology {
  std::vector<std::array<int, 2>> edges;       // (a, b), a < b, in order of first appearance
  std::vector<std::array<int, 2>> edge_faces;  // −1: none (boundary)
  std::vector<std::vector<int>> face_edges;    // edge of (v_i, v_{i+1})
  std::vector<std::vector<int>> vertex_edges, vertex_faces;
  std::unordered_map<long long, int> index;

  explicit CsTopology(const PolyMesh& m) {
    const int n = static_cast<int>(m.points.size());
    vertex_edges.resize(n);
    vertex_faces.resize(n);
    face_edges.resize(m.faces.size());
    for (size_t f = 0; f < m.faces.size(); ++f) {
      const auto& face = m.faces[f];
      for (size_t i = 0; i < face.size(); ++i) {
        const int a = face[i], b = face[(i + 1) % face.size()];
        vertex_faces[a].push_back(static_cast<int>(f));
        const long long key = CsKey(std::min(a, b), std::max(a, b));
        auto it = index.find(key);
        int e;
        if (it == index.end()) {
          e = static_cast<int>(edges.size());
          index.emplace(key, e);
          edges.push_back({std::min(a, b), std::max(a, b)});
          edge_faces.push_back({static_cast<int>(f), -1});
          vertex_edges[a].push_back(e);
          vertex_edges[b].push_back(e);
        } else {
          e = it->second;
          edge_faces[e][1] = static_cast<int>(f);
        }
        face_edges[f].push_back(e);
      }
    }
  }
  int Find(int a, int b) const {
    auto it = index.find(CsKey(std::min(a, b), std::max(a, b)));
    return it == index.end() ? -1 : it->second;
  }
  bool Boundary(int e) const { return edge_faces[e][1] < 0; }
  int Other(int e, int v) const { return edges[e][0] == v ? edges[e][1] : edges[e][0]; }
  int BoundaryEdges(int v) const {
    int k = 0;
    for (int e : vertex_edges[v]) k += Boundary(e) ? 1 : 0;
    return k;
  }
};

enum class CsVertexRule { kSmooth, kCrease, kFixed };
enum class CsEdgeRule { kSmooth, kMidpoint };

void CsAdd(CsRow& row, int v, double w) { row.emplace_back(v, w); }
void CsAddCentroid(CsRow& row, const std::vector<int>& face, double w) {
  for (int v : face) row.emplace_back(v, w / static_cast<double>(face.size()));
}

// One level of connectivity and the masks as rows; crease vertices take the
// neighbours along their two crease edges (`crease_neighbours`).
struct CsRefinement {
  PolyMesh fine;  // positions from the rows
  std::vector<CsRow> rows;
  int face_points_begin = 0, edge_points_begin = 0;
};

CsRefinement CsRefine(const PolyMesh& m, const CsTopology& t, SubdivisionScheme scheme,
                      const std::vector<CsVertexRule>& vrule,
                      const std::vector<std::array<int, 2>>& crease_neighbours,
                      const std::vector<CsEdgeRule>& erule) {
  CsRefinement r;
  const int n = static_cast<int>(m.points.size());
  const int nf = static_cast<int>(m.faces.size());
  const int ne = static_cast<int>(t.edges.size());
  const bool cc = scheme == SubdivisionScheme::kCatmullClark;
  r.face_points_begin = n;
  r.edge_points_begin = cc ? n + nf : n;
  r.rows.resize(static_cast<size_t>(r.edge_points_begin + ne));
  for (int v = 0; v < n; ++v) {
    CsRow& row = r.rows[v];
    if (vrule[v] == CsVertexRule::kFixed) {
      CsAdd(row, v, 1);
    } else if (vrule[v] == CsVertexRule::kCrease) {
      CsAdd(row, v, 0.75);
      CsAdd(row, crease_neighbours[v][0], 0.125);
      CsAdd(row, crease_neighbours[v][1], 0.125);
    } else {
      const double k = static_cast<double>(t.vertex_edges[v].size());
      if (cc) {
        CsAdd(row, v, (k - 2) / k);
        for (int e : t.vertex_edges[v]) CsAdd(row, t.Other(e, v), 1 / (k * k));
        for (int f : t.vertex_faces[v]) CsAddCentroid(row, m.faces[f], 1 / (k * k));
      } else {
        const double beta = k == 3 ? 3.0 / 16 : 3.0 / (8 * k);
        CsAdd(row, v, 1 - k * beta);
        for (int e : t.vertex_edges[v]) CsAdd(row, t.Other(e, v), beta);
      }
    }
  }
  if (cc) {
    for (int f = 0; f < nf; ++f) CsAddCentroid(r.rows[n + f], m.faces[f], 1);
  }
  for (int e = 0; e < ne; ++e) {
    CsRow& row = r.rows[r.edge_points_begin + e];
    const int a = t.edges[e][0], b = t.edges[e][1];
    if (erule[e] == CsEdgeRule::kMidpoint || t.Boundary(e)) {
      CsAdd(row, a, 0.5);
      CsAdd(row, b, 0.5);
    } else if (cc) {
      CsAdd(row, a, 0.25);
      CsAdd(row, b, 0.25);
      CsAddCentroid(row, m.faces[t.edge_faces[e][0]], 0.25);
      CsAddCentroid(row, m.faces[t.edge_faces[e][1]], 0.25);
    } else {
      CsAdd(row, a, 0.375);
      CsAdd(row, b, 0.375);
      for (int side = 0; side < 2; ++side) {
        for (int v : m.faces[t.edge_faces[e][side]]) {
          if (v != a && v != b) CsAdd(row, v, 0.125);
        }
      }
    }
  }
  // Connectivity.
  for (int f = 0; f < nf; ++f) {
    const auto& face = m.faces[f];
    const int k = static_cast<int>(face.size());
    auto ep = [&](int i) { return r.edge_points_begin + t.face_edges[f][(i % k + k) % k]; };
    if (cc) {
      for (int i = 0; i < k; ++i) r.fine.faces.push_back({face[i], ep(i), n + f, ep(i - 1)});
    } else {
      CHECK_EQ(k, 3);
      for (int i = 0; i < 3; ++i) r.fine.faces.push_back({face[i], ep(i), ep(i + 2)});
      r.fine.faces.push_back({ep(0), ep(1), ep(2)});
    }
  }
  r.fine.points.assign(r.rows.size(), Eigen::Vector3d::Zero());
  for (size_t i = 0; i < r.rows.size(); ++i) {
    for (const auto& [v, w] : r.rows[i]) r.fine.points[i] += w * m.points[v];
  }
  return r;
}

// The standard rules: boundary creases, corners (a boundary vertex of one
// face, or not on exactly two boundary edges) fixed.
void CsStandardRules(const PolyMesh& m, const CsTopology& t, std::vector<CsVertexRule>& vrule,
                     std::vector<std::array<int, 2>>& nb, std::vector<CsEdgeRule>& erule) {
  const size_t n = m.points.size();
  vrule.assign(n, CsVertexRule::kSmooth);
  nb.assign(n, {-1, -1});
  erule.assign(t.edges.size(), CsEdgeRule::kSmooth);
  for (size_t v = 0; v < n; ++v) {
    const int boundary = t.BoundaryEdges(static_cast<int>(v));
    if (boundary == 0) continue;
    if (boundary != 2 || t.vertex_faces[v].size() < 2) {
      vrule[v] = CsVertexRule::kFixed;
      continue;
    }
    vrule[v] = CsVertexRule::kCrease;
    int k = 0;
    for (int e : t.vertex_edges[v]) {
      if (t.Boundary(e)) nb[v][k++] = t.Other(e, static_cast<int>(v));
    }
  }
}

double CsDiagonal(const std::vector<Eigen::Vector3d>& p) {
  if (p.empty()) return 1;
  Eigen::Vector3d lo = p[0], hi = p[0];
  for (const auto& x : p) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double d = (hi - lo).norm();
  return d > 0 ? d : 1;
}

// Closest point of segment [a, b] to x: parameter t ∈ [0, 1].
double CsSegmentParam(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = b - a;
  const double dd = d.squaredNorm();
  return dd > 0 ? std::clamp((x - a).dot(d) / dd, 0.0, 1.0) : 0.0;
}

std::string CsPoint(const Eigen::Vector3d& p) {
  std::ostringstream o;
  o << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return o.str();
}

}  // namespace

Eigen::Vector3d ConstrainedSubdivision::Curve::At(double s) const {
  const auto& p = input.points;
  const size_t m = p.size();
  if (input.closed) {
    s = std::fmod(s, length);
    if (s < 0) s += length;
  } else {
    s = std::clamp(s, 0.0, length);
  }
  const size_t segments = input.closed ? m : m - 1;
  size_t i = static_cast<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), s) -
                                 cumulative.begin());
  i = std::min(std::max<size_t>(i, 1), segments) - 1;
  const double len = cumulative[i + 1] - cumulative[i];
  const double u = len > 0 ? (s - cumulative[i]) / len : 0;
  return (1 - u) * p[i] + u * p[(i + 1) % m];
}

double ConstrainedSubdivision::Curve::Interval(double from, double to) const {
  double d = to - from;
  if (input.closed && d <= 0) d += length;
  return d;
}

ConstrainedSubdivision::ConstrainedSubdivision(PolyMesh mesh, std::vector<SubdivisionCurve> curves,
                                               SubdivisionOptions options)
    : options_(options), mesh_(std::move(mesh)) {
  for (auto& c : curves) {
    Curve curve;
    curve.input = std::move(c);
    curves_.push_back(std::move(curve));
  }
  Tag();
}

void ConstrainedSubdivision::Tag() {
  const int n = static_cast<int>(mesh_.points.size());
  for (int v = 0; v < n; ++v) {
    if (!mesh_.points[v].allFinite()) {
      throw SubdivisionError("mesh vertex " + std::to_string(v) + " has a non-finite coordinate");
    }
  }
  if (options_.scheme == SubdivisionScheme::kLoop) {
    for (size_t f = 0; f < mesh_.faces.size(); ++f) {
      if (mesh_.faces[f].size() != 3) {
        throw SubdivisionError("Loop subdivision needs a triangle mesh; face " + std::to_string(f) +
                               " has " + std::to_string(mesh_.faces[f].size()) + " sides");
      }
    }
  }
  diagonal_ = CsDiagonal(mesh_.points);
  const double tol = options_.tolerance * diagonal_;
  const CsTopology t(mesh_);
  on_.assign(n, {});
  fixed_.assign(n, 0);
  locked_.assign(n, 0);
  tagged_.clear();
  std::vector<char> boundary_vertex(n, 0);
  for (size_t e = 0; e < t.edges.size(); ++e) {
    if (t.Boundary(static_cast<int>(e))) boundary_vertex[t.edges[e][0]] = boundary_vertex[t.edges[e][1]] = 1;
  }
  // Arc length; finite points.
  for (Curve& c : curves_) {
    const auto& p = c.input.points;
    for (size_t i = 0; i < p.size(); ++i) {
      if (!p[i].allFinite()) {
        throw SubdivisionError(c.input.name + ": point " + std::to_string(i) + " has a non-finite coordinate");
      }
    }
    if (p.size() < (c.input.closed ? 3u : 2u)) {
      throw SubdivisionError(c.input.name + ": too few points");
    }
    c.cumulative = {0};
    const size_t segments = c.input.closed ? p.size() : p.size() - 1;
    for (size_t i = 0; i < segments; ++i) {
      c.cumulative.push_back(c.cumulative.back() + (p[(i + 1) % p.size()] - p[i]).norm());
    }
    c.length = c.cumulative.back();
    if (!(c.length > tol)) throw SubdivisionError(c.input.name + ": shorter than the tolerance");
  }
  // Crossing curves: two curves closer than the tolerance away from the ends
  // of open curves.
  for (size_t k = 0; k < curves_.size(); ++k) {
    for (size_t j = k + 1; j < curves_.size(); ++j) {
      const Curve& a = curves_[k];
      const Curve& b = curves_[j];
      const auto& pa = a.input.points;
      const auto& pb = b.input.points;
      for (size_t i = 0; i + 1 < a.cumulative.size(); ++i) {
        const Eigen::Vector3d& a0 = pa[i];
        const Eigen::Vector3d& a1 = pa[(i + 1) % pa.size()];
        for (size_t l = 0; l + 1 < b.cumulative.size(); ++l) {
          const Eigen::Vector3d& b0 = pb[l];
          const Eigen::Vector3d& b1 = pb[(l + 1) % pb.size()];
          const double reach = 0.5 * ((a1 - a0).norm() + (b1 - b0).norm()) + tol;
          if ((0.5 * (a0 + a1) - 0.5 * (b0 + b1)).norm() > reach) continue;
          const auto [s, u] = ClosestSegmentParameters(a0, a1, b0, b1);
          const Eigen::Vector3d x = a0 + s * (a1 - a0), y = b0 + u * (b1 - b0);
          if ((x - y).norm() > tol) continue;
          const double sa = a.cumulative[i] + s * (a.cumulative[i + 1] - a.cumulative[i]);
          const double sb = b.cumulative[l] + u * (b.cumulative[l + 1] - b.cumulative[l]);
          const bool a_end = !a.input.closed && (sa <= tol || sa >= a.length - tol);
          const bool b_end = !b.input.closed && (sb <= tol || sb >= b.length - tol);
          if (a_end || b_end) continue;
          throw SubdivisionError(a.input.name + " and " + b.input.name + " cross at " + CsPoint(x) +
                                 " (curves may meet only at an end of one of them)");
        }
      }
    }
  }
  // Vertices on each curve, in arc-length order; consecutive ones must be
  // joined by an edge, which is tagged.
  std::set<int> tagged_edges;
  for (size_t k = 0; k < curves_.size(); ++k) {
    Curve& c = curves_[k];
    const auto& p = c.input.points;
    std::vector<std::pair<double, int>> on;  // (s, vertex)
    Eigen::Vector3d lo = p[0], hi = p[0];
    for (const auto& q : p) {
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
    lo.array() -= tol;
    hi.array() += tol;
    for (int v = 0; v < n; ++v) {
      if (c.input.boundary && !boundary_vertex[v]) continue;
      const Eigen::Vector3d& x = mesh_.points[v];
      if ((x.array() < lo.array()).any() || (x.array() > hi.array()).any()) continue;
      double best = std::numeric_limits<double>::infinity(), best_s = 0;
      for (size_t i = 0; i + 1 < c.cumulative.size(); ++i) {
        const Eigen::Vector3d& a = p[i];
        const Eigen::Vector3d& b = p[(i + 1) % p.size()];
        const double u = CsSegmentParam(mesh_.points[v], a, b);
        const double d = (mesh_.points[v] - (a + u * (b - a))).norm();
        if (d < best) {
          best = d;
          best_s = c.cumulative[i] + u * (c.cumulative[i + 1] - c.cumulative[i]);
        }
      }
      if (best <= tol) {
        if (c.input.closed && best_s >= c.length) best_s -= c.length;
        on.emplace_back(best_s, v);
      }
    }
    const size_t needed = c.input.closed ? 3 : 2;
    if (on.size() < needed) {
      std::ostringstream o;
      o << c.input.name << (c.input.boundary ? " is not on the mesh boundary: " : " is not on the mesh: ")
        << on.size() << (c.input.boundary ? " boundary" : "") << " vertices of the mesh lie within "
        << tol << " of it (at least " << needed << " needed)";
      throw SubdivisionError(o.str());
    }
    std::sort(on.begin(), on.end());
    const size_t pairs = c.input.closed ? on.size() : on.size() - 1;
    for (size_t i = 0; i < pairs; ++i) {
      const int a = on[i].second, b = on[(i + 1) % on.size()].second;
      const int e = t.Find(a, b);
      if (c.input.boundary && (e < 0 || !t.Boundary(e))) {
        throw SubdivisionError(c.input.name + " is not on the mesh boundary: its boundary vertices " +
                               std::to_string(a) + " and " + std::to_string(b) +
                               ", consecutive along it, are not joined by a boundary edge");
      }
      if (e < 0) {
        throw SubdivisionError(c.input.name + ": mesh vertices " + std::to_string(a) + " and " +
                               std::to_string(b) + ", consecutive along the curve, are not joined by an edge");
      }
      if (!tagged_edges.insert(e).second) {
        throw SubdivisionError(c.input.name + ": the edge " + std::to_string(a) + "–" + std::to_string(b) +
                               " lies on another curve too");
      }
      tagged_.push_back({a, b, static_cast<int>(k)});
    }
    for (const auto& [s, v] : on) {
      if (on_[v].empty()) mesh_.points[v] = c.At(s);
      on_[v].push_back({static_cast<int>(k), s});
    }
    // Kinks: polyline vertices turning more than the kink angle.
    const double cos_kink = std::cos(options_.kink_degrees * M_PI / 180);
    const size_t m = p.size();
    for (size_t i = 0; i < m; ++i) {
      if (!c.input.closed && (i == 0 || i + 1 == m)) continue;
      const Eigen::Vector3d din = (p[i] - p[(i + m - 1) % m]).normalized();
      const Eigen::Vector3d dout = (p[(i + 1) % m] - p[i]).normalized();
      if (din.dot(dout) >= cos_kink) continue;
      for (const auto& [s, v] : on) {
        double d = std::abs(s - c.cumulative[i]);
        if (c.input.closed) d = std::min(d, c.length - d);
        if (d <= tol) fixed_[v] = 1;
      }
    }
  }
  // Corners: on two curves, or not on exactly two tagged edges of its curve.
  std::vector<int> tagged_count(n, 0);
  for (const TaggedEdge& e : tagged_) {
    ++tagged_count[e.from];
    ++tagged_count[e.to];
  }
  for (int v = 0; v < n; ++v) {
    if (on_[v].size() > 1 || (on_[v].size() == 1 && tagged_count[v] != 2)) fixed_[v] = 1;
  }
  if (options_.boundary == SubdivisionBoundary::kLocked) {
    for (int v = 0; v < n; ++v) {
      if (!boundary_vertex[v]) continue;
      locked_[v] = 1;
      for (int e : t.vertex_edges[v]) locked_[t.Other(e, v)] = 1;
    }
  }
}

void ConstrainedSubdivision::Step() {
  const CsTopology t(mesh_);
  const int n = static_cast<int>(mesh_.points.size());
  std::vector<CsVertexRule> vrule;
  std::vector<std::array<int, 2>> nb;
  std::vector<CsEdgeRule> erule;
  CsStandardRules(mesh_, t, vrule, nb, erule);
  // Curve vertices: their tagged edges (prev: to == v, next: from == v).
  std::vector<int> prev(n, -1), next(n, -1);
  for (size_t i = 0; i < tagged_.size(); ++i) {
    next[tagged_[i].from] = static_cast<int>(i);
    prev[tagged_[i].to] = static_cast<int>(i);
    erule[t.Find(tagged_[i].from, tagged_[i].to)] = CsEdgeRule::kMidpoint;
  }
  const bool is_locked_mode = options_.boundary == SubdivisionBoundary::kLocked;
  for (int v = 0; v < n; ++v) {
    if (fixed_[v] || locked_[v]) {
      vrule[v] = CsVertexRule::kFixed;
    } else if (!on_[v].empty()) {
      vrule[v] = CsVertexRule::kCrease;
      nb[v] = {tagged_[prev[v]].from, tagged_[next[v]].to};
    }
  }
  for (size_t e = 0; e < t.edges.size(); ++e) {
    if (is_locked_mode && locked_[t.edges[e][0]] && locked_[t.edges[e][1]]) erule[e] = CsEdgeRule::kMidpoint;
  }
  CsRefinement r = CsRefine(mesh_, t, options_.scheme, vrule, nb, erule);
  const int total = static_cast<int>(r.fine.points.size());
  std::vector<std::vector<Entry>> on(total);
  std::vector<char> fixed(total, 0), locked(total, 0);
  // Old vertices: curve vertices move along their curve.
  for (int v = 0; v < n; ++v) {
    on[v] = on_[v];
    fixed[v] = fixed_[v];
    locked[v] = locked_[v];
    if (on_[v].empty() || fixed_[v] || locked_[v]) continue;
    const Curve& c = curves_[on_[v][0].curve];
    const double s = on_[v][0].s;
    auto param = [&](int u, int curve) {
      for (const Entry& en : on_[u]) {
        if (en.curve == curve) return en.s;
      }
      LOG(FATAL) << "vertex " << u << " is not on curve " << curve;
      return 0.0;
    };
    const int k = on_[v][0].curve;
    const double lp = c.Interval(param(tagged_[prev[v]].from, k), s);
    const double ln = c.Interval(s, param(tagged_[next[v]].to, k));
    double s_new = s + (ln - lp) / 8;
    if (c.input.closed) {
      s_new = std::fmod(s_new, c.length);
      if (s_new < 0) s_new += c.length;
    }
    on[v] = {{k, s_new}};
    r.fine.points[v] = c.At(s_new);
  }
  // Edge points of tagged edges: the arc-length halfway point.
  std::vector<TaggedEdge> tagged;
  for (const TaggedEdge& te : tagged_) {
    const Curve& c = curves_[te.curve];
    double sa = 0, sb = 0;
    for (const Entry& en : on_[te.from]) {
      if (en.curve == te.curve) sa = en.s;
    }
    for (const Entry& en : on_[te.to]) {
      if (en.curve == te.curve) sb = en.s;
    }
    double s = sa + c.Interval(sa, sb) / 2;
    if (c.input.closed && s >= c.length) s -= c.length;
    const int m = r.edge_points_begin + t.Find(te.from, te.to);
    r.fine.points[m] = c.At(s);
    on[m] = {{te.curve, s}};
    tagged.push_back({te.from, m, te.curve});
    tagged.push_back({m, te.to, te.curve});
  }
  // Locked ring: new vertices whose parents are all locked.
  if (is_locked_mode) {
    for (size_t f = 0; f < mesh_.faces.size() && options_.scheme == SubdivisionScheme::kCatmullClark; ++f) {
      bool all = true;
      for (int v : mesh_.faces[f]) all = all && locked_[v];
      if (all) locked[r.face_points_begin + static_cast<int>(f)] = 1;
    }
    for (size_t e = 0; e < t.edges.size(); ++e) {
      if (locked_[t.edges[e][0]] && locked_[t.edges[e][1]]) locked[r.edge_points_begin + static_cast<int>(e)] = 1;
    }
  }
  mesh_ = std::move(r.fine);
  on_ = std::move(on);
  fixed_ = std::move(fixed);
  locked_ = std::move(locked);
  tagged_ = std::move(tagged);
  ++levels_;
  if (options_.tangent) ImposeTangency(mesh_.points);
}

void ConstrainedSubdivision::ImposeTangency(std::vector<Eigen::Vector3d>& points) const {
  const CsTopology t(mesh_);
  const size_t n = points.size();
  // Per interior vertex: the planes (normal, point) of the curve vertices it neighbours.
  std::vector<std::vector<std::pair<Eigen::Vector3d, int>>> planes(n);
  Eigen::Vector3d normal;
  for (size_t b = 0; b < n; ++b) {
    if (on_[b].empty() || !options_.tangent(points[b], &normal)) continue;
    for (int e : t.vertex_edges[b]) {
      const int v = t.Other(e, static_cast<int>(b));
      if (on_[v].empty() && !fixed_[v] && !locked_[v]) planes[v].emplace_back(normal, static_cast<int>(b));
    }
  }
  // The shortest move into all of a vertex's planes: δ = −Nᵀ(N Nᵀ)⁻¹ r
  // (N the normals as rows, r the signed distances); with Loop a first-row
  // vertex neighbours two curve vertices and lands on their planes' line.
  for (size_t v = 0; v < n; ++v) {
    const size_t k = planes[v].size();
    if (k == 0) continue;
    Eigen::MatrixXd rows(static_cast<Eigen::Index>(k), 3);
    Eigen::VectorXd r(static_cast<Eigen::Index>(k));
    for (size_t i = 0; i < k; ++i) {
      rows.row(static_cast<Eigen::Index>(i)) = planes[v][i].first.transpose();
      r[static_cast<Eigen::Index>(i)] = planes[v][i].first.dot(points[v] - points[planes[v][i].second]);
    }
    const Eigen::MatrixXd gram = rows * rows.transpose();
    const Eigen::VectorXd y = SolveMinimumNorm(gram, r);
    points[v] -= rows.transpose() * y;
  }
}

TangencyMeasure ConstrainedSubdivision::Tangency(const std::vector<Eigen::Vector3d>& points) const {
  CHECK_EQ(points.size(), mesh_.points.size());
  TangencyMeasure out;
  if (!options_.tangent) return out;
  const CsTopology t(mesh_);
  Eigen::Vector3d normal;
  double sum = 0;
  for (size_t b = 0; b < points.size(); ++b) {
    if (on_[b].empty() || !options_.tangent(points[b], &normal)) continue;
    Eigen::Vector3d mesh_normal = Eigen::Vector3d::Zero();
    for (int f : t.vertex_faces[b]) {
      const auto& face = mesh_.faces[f];
      for (size_t i = 0; i < face.size(); ++i) {
        mesh_normal += points[face[i]].cross(points[face[(i + 1) % face.size()]]);  // Newell
      }
    }
    if (mesh_normal.norm() == 0) continue;
    const double cosine = std::min(1.0, std::abs(mesh_normal.normalized().dot(normal)));
    const double degrees = std::acos(cosine) * 180 / M_PI;
    out.max_degrees = std::max(out.max_degrees, degrees);
    sum += degrees;
    ++out.vertices;
  }
  out.mean_degrees = out.vertices ? sum / out.vertices : 0;
  return out;
}

std::vector<Eigen::Vector3d> ConstrainedSubdivision::LimitPositions() const {
  const CsTopology t(mesh_);
  const int n = static_cast<int>(mesh_.points.size());
  std::vector<int> prev(n, -1), next(n, -1);
  for (size_t i = 0; i < tagged_.size(); ++i) {
    next[tagged_[i].from] = static_cast<int>(i);
    prev[tagged_[i].to] = static_cast<int>(i);
  }
  const bool cc = options_.scheme == SubdivisionScheme::kCatmullClark;
  std::vector<Eigen::Vector3d> out(mesh_.points);
  for (int v = 0; v < n; ++v) {
    const Eigen::Vector3d& p = mesh_.points[v];
    if (fixed_[v] || locked_[v]) continue;
    if (!on_[v].empty()) {
      const int k = on_[v][0].curve;
      const Curve& c = curves_[k];
      auto param = [&](int u) {
        for (const Entry& en : on_[u]) {
          if (en.curve == k) return en.s;
        }
        return 0.0;
      };
      const double s = on_[v][0].s;
      const double lp = c.Interval(param(tagged_[prev[v]].from), s);
      const double ln = c.Interval(s, param(tagged_[next[v]].to));
      out[v] = c.At(s + (ln - lp) / 6);
      continue;
    }
    const int boundary = t.BoundaryEdges(v);
    if (boundary > 0) {
      if (boundary != 2 || t.vertex_faces[v].size() < 2) continue;
      Eigen::Vector3d sum = 4 * p;
      for (int e : t.vertex_edges[v]) {
        if (t.Boundary(e)) sum += mesh_.points[t.Other(e, v)];
      }
      out[v] = sum / 6;
      continue;
    }
    const double k = static_cast<double>(t.vertex_edges[v].size());
    Eigen::Vector3d neighbours = Eigen::Vector3d::Zero();
    for (int e : t.vertex_edges[v]) neighbours += mesh_.points[t.Other(e, v)];
    if (cc) {
      Eigen::Vector3d diagonal = Eigen::Vector3d::Zero();
      for (int f : t.vertex_faces[v]) {
        const auto& face = mesh_.faces[f];
        if (face.size() != 4) {
          throw SubdivisionError("the Catmull–Clark limit needs an all-quad mesh (subdivide once); face " +
                                 std::to_string(f) + " has " + std::to_string(face.size()) + " sides");
        }
        const size_t i = static_cast<size_t>(std::find(face.begin(), face.end(), v) - face.begin());
        diagonal += mesh_.points[face[(i + 2) % 4]];
      }
      out[v] = (k * k * p + 4 * neighbours + diagonal) / (k * (k + 5));  // [Gebreiter 2012, §9.1.2]
    } else {
      const double beta = k == 3 ? 3.0 / 16 : 3.0 / (8 * k);
      const double chi = 1 / (3 / (8 * beta) + k);
      out[v] = (1 - k * chi) * p + chi * neighbours;
    }
  }
  if (options_.tangent) ImposeTangency(out);  // the limit of the corrected scheme is tangent too
  return out;
}

int ConstrainedSubdivision::CurveVertexCount() const {
  int k = 0;
  for (const auto& e : on_) k += e.empty() ? 0 : 1;
  return k;
}

int ConstrainedSubdivision::CornerCount() const {
  int k = 0;
  for (char f : fixed_) k += f ? 1 : 0;
  return k;
}

std::vector<int> ConstrainedSubdivision::VertexKinds() const {
  std::vector<int> kinds(mesh_.points.size(), 0);
  for (size_t v = 0; v < kinds.size(); ++v) {
    if (fixed_[v] || locked_[v]) {
      kinds[v] = 2;
    } else if (!on_[v].empty()) {
      kinds[v] = 1;
    }
  }
  return kinds;
}

double ConstrainedSubdivision::MaxCurveDistance(const std::vector<Eigen::Vector3d>& points) const {
  CHECK_EQ(points.size(), mesh_.points.size());
  double worst = 0;
  for (size_t v = 0; v < on_.size(); ++v) {
    for (const Entry& en : on_[v]) {
      const Curve& c = curves_[en.curve];
      const auto& p = c.input.points;
      double best = std::numeric_limits<double>::infinity();
      for (size_t i = 0; i + 1 < c.cumulative.size(); ++i) {
        const Eigen::Vector3d& a = p[i];
        const Eigen::Vector3d& b = p[(i + 1) % p.size()];
        best = std::min(best, (points[v] - (a + CsSegmentParam(points[v], a, b) * (b - a))).norm());
      }
      worst = std::max(worst, best);
    }
  }
  return worst;
}

PolyMesh SubdivideStandard(const PolyMesh& mesh, SubdivisionScheme scheme) {
  const CsTopology t(mesh);
  std::vector<CsVertexRule> vrule;
  std::vector<std::array<int, 2>> nb;
  std::vector<CsEdgeRule> erule;
  CsStandardRules(mesh, t, vrule, nb, erule);
  return CsRefine(mesh, t, scheme, vrule, nb, erule).fine;
}

namespace {

// A candidate classification of a fine mesh: coarse vertex per old vertex,
// coarse faces, the fine vertex of each coarse edge and face.
struct CsClassified {
  std::vector<int> old_vertices;                // fine index of coarse vertex i
  std::vector<std::vector<int>> faces;          // coarse faces (coarse indices)
  std::map<std::pair<int, int>, int> edge_vertex;  // (a < b) coarse → fine
  std::vector<int> face_vertex;                 // CC: fine index of coarse face f
};

struct CsFine {
  const PolyMesh& m;
  std::vector<std::vector<int>> neighbours;
  std::unordered_map<long long, int> third;  // Loop: directed edge (u, v) → w of triangle (u, v, w)
  std::vector<std::vector<std::pair<int, int>>> corners;  // per vertex: (face, position)
  explicit CsFine(const PolyMesh& mesh) : m(mesh) {
    const size_t n = m.points.size();
    neighbours.resize(n);
    corners.resize(n);
    std::set<long long> seen;
    for (size_t f = 0; f < m.faces.size(); ++f) {
      const auto& face = m.faces[f];
      for (size_t i = 0; i < face.size(); ++i) {
        const int a = face[i], b = face[(i + 1) % face.size()];
        corners[a].emplace_back(static_cast<int>(f), static_cast<int>(i));
        if (seen.insert(CsKey(std::min(a, b), std::max(a, b))).second) {
          neighbours[a].push_back(b);
          neighbours[b].push_back(a);
        }
        if (face.size() == 3) third[CsKey(a, b)] = face[(i + 2) % 3];
      }
    }
  }
  int Third(int u, int v) const {
    auto it = third.find(CsKey(u, v));
    return it == third.end() ? -1 : it->second;
  }
  // Loop: the other old vertex of the edge vertex x whose old neighbour is a.
  int LoopOther(int x, int a) const {
    std::vector<int> forward;
    for (int u = a, k = 0; k < 8; ++k) {
      const int w = Third(x, u);
      if (w < 0 || w == a) break;
      forward.push_back(w);
      u = w;
    }
    const bool closed = Third(x, forward.empty() ? a : forward.back()) == a;
    if (closed) return forward.size() == 5 ? forward[2] : -1;
    std::vector<int> backward;
    for (int u = a, k = 0; k < 8; ++k) {
      const int w = Third(u, x);
      if (w < 0) break;
      backward.push_back(w);
      u = w;
    }
    if (forward.size() == 3 && backward.empty()) return forward[2];
    if (backward.size() == 3 && forward.empty()) return backward[2];
    return -1;
  }
};

// The coarse index of every fine vertex labelled 0 (an old vertex), in
// order, appended to out.old_vertices; −1 for the others. False when some
// vertex has no label.
bool CsNumberOldVertices(const std::vector<int>& label, std::vector<int>& coarse,
                         CsClassified& out) {
  coarse.assign(label.size(), -1);
  for (size_t v = 0; v < label.size(); ++v) {
    if (label[v] < 0) return false;
    if (label[v] == 0) {
      coarse[v] = static_cast<int>(out.old_vertices.size());
      out.old_vertices.push_back(static_cast<int>(v));
    }
  }
  return true;
}

bool CsClassifyLoop(const CsFine& fm, int seed, CsClassified& out) {
  const size_t n = fm.m.points.size();
  std::vector<int> label(n, -1);  // 0 old, 1 edge
  std::vector<std::pair<int, int>> parents(n, {-1, -1});
  std::deque<int> queue = {seed};
  label[seed] = 0;
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop_front();
    for (int x : fm.neighbours[v]) {
      if (label[x] == 0) return false;
      label[x] = 1;
      const int b = fm.LoopOther(x, v);
      if (b < 0 || label[b] == 1) return false;
      const std::pair<int, int> p(std::min(v, b), std::max(v, b));
      if (parents[x].first >= 0 && parents[x] != p) return false;
      parents[x] = p;
      if (label[b] < 0) {
        label[b] = 0;
        queue.push_back(b);
      }
    }
  }
  std::vector<int> coarse;
  if (!CsNumberOldVertices(label, coarse, out)) return false;
  for (size_t v = 0; v < n; ++v) {
    if (label[v] == 1) {
      out.edge_vertex[{coarse[parents[v].first], coarse[parents[v].second]}] = static_cast<int>(v);
    }
  }
  auto other = [&](int x, int v) { return parents[x].first == v ? parents[x].second : parents[x].first; };
  for (const auto& face : fm.m.faces) {
    if (face.size() != 3) return false;
    int olds = 0, at = -1;
    for (int i = 0; i < 3; ++i) {
      if (label[face[i]] == 0) {
        ++olds;
        at = i;
      }
    }
    if (olds > 1) return false;
    if (olds == 0) continue;
    const int v = face[at], x = face[(at + 1) % 3], y = face[(at + 2) % 3];
    const int b = other(x, v), c = other(y, v);
    if (v < b && v < c) out.faces.push_back({coarse[v], coarse[b], coarse[c]});
  }
  return out.faces.size() * 4 == fm.m.faces.size();
}

bool CsClassifyCatmullClark(const CsFine& fm, int seed, CsClassified& out) {
  const size_t n = fm.m.points.size();
  std::vector<int> label(n, -1);  // 0 old, 1 edge, 2 face
  std::deque<int> queue = {seed};
  label[seed] = 0;
  auto set = [&](int v, int l) {
    if (label[v] >= 0 && label[v] != l) return false;
    if (label[v] < 0 && l == 0) queue.push_back(v);
    label[v] = l;
    return true;
  };
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop_front();
    for (const auto& [f, i] : fm.corners[v]) {
      const auto& q = fm.m.faces[f];
      if (q.size() != 4) return false;
      if (!set(q[(i + 1) % 4], 1) || !set(q[(i + 3) % 4], 1) || !set(q[(i + 2) % 4], 2)) return false;
    }
    // The other old vertex of each edge vertex.
    for (int x : fm.neighbours[v]) {
      int other = -1;
      for (int y : fm.neighbours[x]) {
        if (y == v || label[y] == 2) continue;
        bool diagonal = false;
        for (const auto& [f, i] : fm.corners[v]) diagonal = diagonal || fm.m.faces[f][(i + 2) % 4] == y;
        if (diagonal) continue;
        if (other >= 0) return false;
        other = y;
      }
      if (other < 0 || !set(other, 0)) return false;
    }
  }
  std::vector<int> coarse, coarse_face(n, -1);
  if (!CsNumberOldVertices(label, coarse, out)) return false;
  for (size_t v = 0; v < n; ++v) {
    if (label[v] == 1) {
      std::vector<int> olds;
      for (int y : fm.neighbours[v]) {
        if (label[y] == 0) olds.push_back(coarse[y]);
      }
      if (olds.size() != 2) return false;
      out.edge_vertex[{std::min(olds[0], olds[1]), std::max(olds[0], olds[1])}] = static_cast<int>(v);
    }
  }
  size_t quads = 0;
  for (size_t v = 0; v < n; ++v) {
    if (label[v] != 2) continue;
    // Quads (old, e_next, face, e_prev): chain e_next → the quad whose e_prev it is.
    std::map<int, std::pair<int, int>> by_prev;  // e_prev → (old, e_next)
    for (const auto& [f, i] : fm.corners[v]) {
      const auto& q = fm.m.faces[f];
      by_prev[q[(i + 1) % 4]] = {q[(i + 2) % 4], q[(i + 3) % 4]};
    }
    if (by_prev.size() != fm.corners[v].size() || by_prev.size() < 3) return false;
    std::vector<int> face;
    int e = by_prev.begin()->first;
    for (size_t k = 0; k < by_prev.size(); ++k) {
      auto it = by_prev.find(e);
      if (it == by_prev.end() || label[it->second.first] != 0) return false;
      face.push_back(coarse[it->second.first]);
      e = it->second.second;
    }
    // CsRefine's quads (v_i, e(v_i, v_{i+1}), fp, e(v_{i−1}, v_i)): the chain
    // e(v_{i−1}, v_i) → v_i → e(v_i, v_{i+1}) visits the coarse face in its order.
    if (e != by_prev.begin()->first) return false;
    std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
    quads += face.size();
    out.face_vertex.push_back(static_cast<int>(v));
    out.faces.push_back(face);
  }
  return quads == fm.m.faces.size();
}

}  // namespace

// The curves of a mesh subdivided with curve rules, as Reverse() sees them:
// per fine vertex its curve parameters and whether it is fixed, and the
// curves' arc-length maps.
struct CsCurveView {
  std::vector<std::vector<std::pair<int, double>>> on;  // per fine vertex: (curve, s)
  std::vector<char> fixed;
  std::function<Eigen::Vector3d(int, double)> at;            // curve k at parameter s
  std::function<double(int, double, double)> interval;       // forward arc length on curve k
};

namespace {

double CsParam(const std::vector<std::pair<int, double>>& on, int curve) {
  for (const auto& [k, s] : on) {
    if (k == curve) return s;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// The curve part of a reverse candidate: the coarse curve vertices (known
// positions) from the fine curve vertices by linear least squares in their
// parameters, s = t + d with t the parameter of the coarse vertex's fine
// old vertex: an old vertex moved to (s₋ + 6s + s₊)/8 and a tagged edge's
// point is at (s_a + s_b)/2 (Step's rules), so per old vertex
// ¾d + (d₋ + d₊)/8 = (Δ₋ − Δ₊)/8 and per tagged edge (d_a + d_b)/2 =
// τ − Δ_ab/2 (Δ the fine arc lengths between the vertices' parameters, τ
// from a to the edge point); corners keep d = 0. Marks the fine vertices
// the curve rules made (their rows are not masks) and returns the largest
// and summed squared distances of those from where the recovered curve
// parameters put them; false when the coarse curve vertices do not form
// chains of tagged edges.
bool CsReverseCurves(const CsCurveView& view, const PolyMesh& fine, const CsTopology& t, const CsRefinement& r,
                     const std::vector<int>& map, std::vector<char>& known, std::vector<Eigen::Vector3d>& coarse,
                     std::vector<char>& made, double& worst, double& squares) {
  const int nc = static_cast<int>(coarse.size());
  // Tagged coarse edges: their fine edge point and both ends on one curve.
  std::vector<std::array<int, 2>> prev(nc, {-1, -1}), next(nc, {-1, -1});  // (neighbour, fine edge point)
  std::vector<int> curve_of(nc, -1);
  for (size_t i = 0; i < r.rows.size(); ++i) {
    if (view.fixed[map[i]]) made[i] = 1;  // corners and a locked ring keep their positions
  }
  for (int a = 0; a < nc; ++a) {
    if (view.fixed[map[a]]) {
      known[a] = 1;
      coarse[a] = fine.points[map[a]];
      made[a] = 1;
    } else if (!view.on[map[a]].empty()) {
      curve_of[a] = view.on[map[a]][0].first;
      made[a] = 1;
    }
  }
  struct Tagged {
    int a, b, m, curve;  // a before b along the curve; m the fine edge point
  };
  std::vector<Tagged> tagged;
  for (size_t e = 0; e < t.edges.size(); ++e) {
    const int m = map[r.edge_points_begin + static_cast<int>(e)];
    for (const auto& [k, tm] : view.on[m]) {
      int a = t.edges[e][0], b = t.edges[e][1];
      const double ta = CsParam(view.on[map[a]], k), tb = CsParam(view.on[map[b]], k);
      if (std::isnan(ta) || std::isnan(tb)) continue;
      if (view.interval(k, ta, tm) > view.interval(k, ta, tb)) std::swap(a, b);
      tagged.push_back({a, b, m, k});
      made[r.edge_points_begin + static_cast<int>(e)] = 1;
      if (curve_of[a] == k) next[a] = {b, m};
      if (curve_of[b] == k) prev[b] = {a, m};
      break;
    }
  }
  std::vector<int> col(nc, -1);
  int unknowns = 0;
  for (int a = 0; a < nc; ++a) {
    if (curve_of[a] < 0) continue;
    if (prev[a][0] < 0 || next[a][0] < 0) return false;
    col[a] = unknowns++;
  }
  auto t_of = [&](int a, int k) { return CsParam(view.on[map[a]], k); };
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
  auto equation = [&](const std::vector<std::pair<int, double>>& terms, double value) {
    for (const auto& [a, wa] : terms) {
      if (col[a] < 0) continue;
      rhs[col[a]] += wa * value;
      for (const auto& [b, wb] : terms) {
        if (col[b] >= 0) triplets.emplace_back(col[a], col[b], wa * wb);
      }
    }
  };
  for (int a = 0; a < nc; ++a) {
    if (col[a] < 0) continue;
    const int k = curve_of[a];
    const int p = prev[a][0], n = next[a][0];
    const double dp = view.interval(k, t_of(p, k), t_of(a, k)), dn = view.interval(k, t_of(a, k), t_of(n, k));
    equation({{a, 0.75}, {p, 0.125}, {n, 0.125}}, (dp - dn) / 8);
  }
  for (const Tagged& g : tagged) {
    const double ta = t_of(g.a, g.curve);
    const double tau = view.interval(g.curve, ta, CsParam(view.on[g.m], g.curve));
    equation({{g.a, 0.5}, {g.b, 0.5}}, tau - view.interval(g.curve, ta, t_of(g.b, g.curve)) / 2);
  }
  Eigen::VectorXd d = Eigen::VectorXd::Zero(unknowns);
  if (unknowns > 0) {
    Eigen::SparseMatrix<double> normal(unknowns, unknowns);
    normal.setFromTriplets(triplets.begin(), triplets.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(normal);
    if (ldlt.info() != Eigen::Success) return false;
    d = ldlt.solve(rhs);
  }
  auto s_of = [&](int a, int k) { return t_of(a, k) + (col[a] >= 0 ? d[col[a]] : 0.0); };
  auto deviation = [&](const Eigen::Vector3d& q, int fine_vertex) {
    const double e = (q - fine.points[fine_vertex]).norm();
    worst = std::max(worst, e);
    squares += e * e;
  };
  for (int a = 0; a < nc; ++a) {
    if (col[a] < 0) continue;
    const int k = curve_of[a];
    const double s = s_of(a, k);
    known[a] = 1;
    coarse[a] = view.at(k, s);
    const double lp = view.interval(k, s_of(prev[a][0], k), s), ln = view.interval(k, s, s_of(next[a][0], k));
    deviation(view.at(k, s + (ln - lp) / 8), map[a]);
  }
  for (const Tagged& g : tagged) {
    const double sa = s_of(g.a, g.curve);
    deviation(view.at(g.curve, sa + view.interval(g.curve, sa, s_of(g.b, g.curve)) / 2), g.m);
  }
  return true;
}

ReverseResult CsReverse(const PolyMesh& fine, SubdivisionScheme scheme, const CsCurveView* curves) {
  if (fine.points.empty()) throw SubdivisionError("empty mesh");
  const CsFine fm(fine);
  std::vector<int> seeds = {0};
  for (int x : fm.neighbours[0]) seeds.push_back(x);
  for (const auto& [f, i] : fm.corners[0]) {
    const auto& face = fine.faces[f];
    seeds.push_back(face[(static_cast<size_t>(i) + face.size() / 2) % face.size()]);
  }
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  bool found = false;
  ReverseResult best;
  for (int seed : seeds) {
    CsClassified cl;
    const bool ok = scheme == SubdivisionScheme::kLoop ? CsClassifyLoop(fm, seed, cl)
                                                        : CsClassifyCatmullClark(fm, seed, cl);
    if (!ok) continue;
    PolyMesh coarse;
    coarse.faces = cl.faces;
    coarse.points.assign(cl.old_vertices.size(), Eigen::Vector3d::Zero());
    const CsTopology t(coarse);
    bool manifold = true;
    for (const auto& ef : t.edge_faces) manifold = manifold && ef[0] >= 0;
    if (!manifold || t.edges.size() != cl.edge_vertex.size()) continue;
    std::vector<CsVertexRule> vrule;
    std::vector<std::array<int, 2>> nb;
    std::vector<CsEdgeRule> erule;
    CsStandardRules(coarse, t, vrule, nb, erule);
    const CsRefinement r = CsRefine(coarse, t, scheme, vrule, nb, erule);
    if (r.rows.size() != fine.points.size()) continue;
    // Generated fine index → the given fine mesh's index.
    std::vector<int> map(r.rows.size(), -1);
    for (size_t i = 0; i < cl.old_vertices.size(); ++i) map[i] = cl.old_vertices[i];
    for (size_t f = 0; f < cl.face_vertex.size(); ++f) map[r.face_points_begin + f] = cl.face_vertex[f];
    bool complete = true;
    for (size_t e = 0; e < t.edges.size(); ++e) {
      auto it = cl.edge_vertex.find({t.edges[e][0], t.edges[e][1]});
      if (it == cl.edge_vertex.end()) {
        complete = false;
        break;
      }
      map[r.edge_points_begin + e] = it->second;
    }
    if (!complete) continue;
    // Known coarse vertices (curve rules) and the fine vertices those made.
    const int nc = static_cast<int>(coarse.points.size());
    std::vector<char> known(static_cast<size_t>(nc), 0), made(r.rows.size(), 0);
    std::vector<Eigen::Vector3d> fixed_positions(static_cast<size_t>(nc), Eigen::Vector3d::Zero());
    double worst = 0, squares = 0;
    if (curves && !CsReverseCurves(*curves, fine, t, r, map, known, fixed_positions, made, worst, squares)) continue;
    std::vector<int> col(static_cast<size_t>(nc), -1);
    int unknowns = 0;
    for (int v = 0; v < nc; ++v) {
      if (!known[v]) col[v] = unknowns++;
    }
    // Normal equations SᵀS·c = Sᵀp over the unknown coarse vertices,
    // assembled row by row (S: the masks, one row per fine vertex the masks
    // made; the known vertices' terms on the right), one right-hand side
    // per coordinate.
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::VectorXd rhs[3];
    for (auto& r3 : rhs) r3 = Eigen::VectorXd::Zero(unknowns);
    for (size_t i = 0; i < r.rows.size(); ++i) {
      if (made[i]) continue;
      Eigen::Vector3d p = fine.points[map[i]];
      for (const auto& [a, wa] : r.rows[i]) {
        if (known[a]) p -= wa * fixed_positions[a];
      }
      for (const auto& [a, wa] : r.rows[i]) {
        if (known[a]) continue;
        for (int k = 0; k < 3; ++k) rhs[k][col[a]] += wa * p[k];
        for (const auto& [b, wb] : r.rows[i]) {
          if (!known[b]) triplets.emplace_back(col[a], col[b], wa * wb);
        }
      }
    }
    Eigen::SparseMatrix<double> normal(unknowns, unknowns);
    normal.setFromTriplets(triplets.begin(), triplets.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(normal);
    if (unknowns > 0 && ldlt.info() != Eigen::Success) continue;
    ReverseResult result;
    result.coarse = coarse;
    for (int v = 0; v < nc; ++v) {
      if (known[v]) result.coarse.points[v] = fixed_positions[v];
    }
    for (int k = 0; k < 3 && unknowns > 0; ++k) {
      const Eigen::VectorXd x = ldlt.solve(rhs[k]);
      for (int v = 0; v < nc; ++v) {
        if (!known[v]) result.coarse.points[v][k] = x[col[v]];
      }
    }
    result.residual_max = worst;
    double sum = squares;
    for (size_t i = 0; i < r.rows.size(); ++i) {
      if (made[i]) continue;
      Eigen::Vector3d q = -fine.points[map[i]];
      for (const auto& [a, wa] : r.rows[i]) q += wa * result.coarse.points[a];
      result.residual_max = std::max(result.residual_max, q.norm());
      sum += q.squaredNorm();
    }
    result.residual_rms = std::sqrt(sum / static_cast<double>(fine.points.size()));
    if (unknowns > 0) {
      const Eigen::VectorXd d = ldlt.vectorD();
      result.unique = d.minCoeff() > 1e-12 * d.cwiseAbs().maxCoeff();
    }
    if (!found || result.residual_max < best.residual_max) best = std::move(result);
    found = true;
  }
  if (!found) {
    throw SubdivisionError(std::string("the mesh does not have the connectivity of a ") +
                           (scheme == SubdivisionScheme::kLoop ? "Loop" : "Catmull–Clark") +
                           "-subdivided mesh (every vertex classed as old, edge or face vertex), so it "
                           "cannot be reverse-subdivided");
  }
  return best;
}

}  // namespace

ReverseResult ReverseSubdivision(const PolyMesh& fine, SubdivisionScheme scheme) {
  return CsReverse(fine, scheme, nullptr);
}

ReverseResult ConstrainedSubdivision::Reverse() const {
  CsCurveView view;
  view.on.resize(on_.size());
  for (size_t v = 0; v < on_.size(); ++v) {
    for (const Entry& e : on_[v]) view.on[v].emplace_back(e.curve, e.s);
  }
  view.fixed.assign(fixed_.begin(), fixed_.end());
  for (size_t v = 0; v < locked_.size(); ++v) view.fixed[v] = view.fixed[v] || locked_[v];
  view.at = [this](int k, double s) { return curves_[k].At(s); };
  view.interval = [this](int k, double from, double to) { return curves_[k].Interval(from, to); };
  return CsReverse(mesh_, options_.scheme, &view);
}

}  // namespace archgeo
