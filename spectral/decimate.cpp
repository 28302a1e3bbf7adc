// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — decimation to a base complex (Gebreiter 2012, §3.1.1; the
// importance and the collapse rules are in spectral/decimate.h).
#include "spectral/decimate.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "core/segments.h"

namespace archgeo {
namespace {

using V3 = Eigen::Vector3d;
using Quadric = Eigen::Matrix4d;

// The current mesh: triangles with an alive flag, the alive triangles at each
// vertex (cleaned as they die).
struct DcMesh {
  const std::vector<V3>& p;
  std::vector<std::array<int, 3>> tri;
  std::vector<char> tri_alive;
  std::vector<std::vector<int>> at;  // triangles at each vertex
  std::vector<V3> normal0;           // the input's unit vertex normals (area-weighted)
  double cos_input = -1;             // least cosine of a triangle normal to its corners' normal0
  double min_angle = 0;              // collapses do not make a triangle sharper than this
  double error_level = 0;            // the largest RMS distance of a collapse so far
  double flip_factor = -1;           // flips move the surface by less than this times error_level (< 0: any)
  double relocation_factor = -1;     // relocations: RMS distance to the node's planes within this times it
  std::vector<Quadric> quadric;      // per vertex: the input quadrics of the vertices collapsed into it
  DcMesh(const std::vector<V3>& points, const std::vector<std::array<int, 3>>& t)
      : p(points), tri(t), tri_alive(t.size(), 1), at(points.size()) {
    for (size_t f = 0; f < t.size(); ++f) {
      for (int v : t[f]) at[size_t(v)].push_back(int(f));
    }
    normal0.assign(points.size(), V3::Zero());
    for (const auto& f : t) {
      const V3 n = (p[size_t(f[1])] - p[size_t(f[0])]).cross(p[size_t(f[2])] - p[size_t(f[0])]);
      for (int v : f) normal0[size_t(v)] += n;
    }
    for (V3& n : normal0) {
      if (n.norm() > 0) n.normalize();
    }
  }

  // Whether the triangle (a, b, c) faces within the bound of its corners' input normals.
  bool FacesAsInput(int a, int b, int c, const V3& n) const {
    const double l = n.norm();
    for (int v : {a, b, c}) {
      if (n.dot(normal0[size_t(v)]) < cos_input * l) return false;
    }
    return true;
  }

  // Position of v in triangle f.
  int Slot(int f, int v) const {
    const auto& t = tri[size_t(f)];
    return t[0] == v ? 0 : t[1] == v ? 1 : 2;
  }

  // Neighbours of v with, per neighbour, how often it follows v (next) and
  // precedes v (prev) in v's triangles: a boundary edge v→a has next 1, prev 0.
  struct Ring {
    std::vector<int> vertex, next, prev;
  };
  Ring RingOf(int v) const {
    Ring r;
    auto add = [&r](int w, bool is_next) {
      size_t i = 0;
      while (i < r.vertex.size() && r.vertex[i] != w) ++i;
      if (i == r.vertex.size()) {
        r.vertex.push_back(w);
        r.next.push_back(0);
        r.prev.push_back(0);
      }
      (is_next ? r.next : r.prev)[i]++;
    };
    for (int f : at[size_t(v)]) {
      const int k = Slot(f, v);
      add(tri[size_t(f)][size_t((k + 1) % 3)], true);
      add(tri[size_t(f)][size_t((k + 2) % 3)], false);
    }
    return r;
  }

  static bool OnBoundary(const Ring& r) {
    for (size_t i = 0; i < r.vertex.size(); ++i) {
      if (r.next[i] + r.prev[i] == 1) return true;
    }
    return false;
  }
};

double Angle(const V3& a, const V3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

double MinAngle(const V3& a, const V3& b, const V3& c) {
  return std::min({Angle(b - a, c - a), Angle(c - b, a - b), Angle(a - c, b - c)});
}

// I(v) on the current mesh (spectral/decimate.h).
double Importance(const DcMesh& m, int v) {
  const V3& x = m.p[size_t(v)];
  double angles = 0, area = 0;
  V3 hn = V3::Zero(), normal = V3::Zero();
  for (int f : m.at[size_t(v)]) {
    const int k = m.Slot(f, v);
    const V3& a = m.p[size_t(m.tri[size_t(f)][size_t((k + 1) % 3)])];
    const V3& b = m.p[size_t(m.tri[size_t(f)][size_t((k + 2) % 3)])];
    const V3 n = (a - x).cross(b - x);
    const double twice_area = n.norm();
    angles += Angle(a - x, b - x);
    area += twice_area / 6;
    normal += n;
    if (twice_area <= 0) continue;
    // Cotangents of the angles at a (opposite edge xb) and b (opposite xa).
    const double cot_a = (x - a).dot(b - a) / twice_area, cot_b = (x - b).dot(a - b) / twice_area;
    hn += 0.5 * (cot_b * (x - a) + cot_a * (x - b));
  }
  const DcMesh::Ring r = m.RingOf(v);
  if (r.vertex.empty() || !(area > 0)) return 0;
  double h = 0;
  for (int w : r.vertex) h += (m.p[size_t(w)] - x).norm();
  h /= double(r.vertex.size());
  const double defect = (DcMesh::OnBoundary(r) ? M_PI : 2 * M_PI) - angles;
  const double nn = normal.norm();
  const double mean = nn > 0 ? std::abs(hn.dot(normal / nn)) / (2 * area) : 0;
  return std::abs(defect) / area * h * h + mean * h;
}

// The boundary turning angle at v (radians) on the mesh as given, 0 inside.
double BoundaryTurn(const DcMesh& m, int v) {
  const DcMesh::Ring r = m.RingOf(v);
  int next = -1, prev = -1;
  for (size_t i = 0; i < r.vertex.size(); ++i) {
    if (r.next[i] == 1 && r.prev[i] == 0) next = r.vertex[i];
    if (r.prev[i] == 1 && r.next[i] == 0) prev = r.vertex[i];
  }
  if (next < 0 || prev < 0) return 0;
  const V3& x = m.p[size_t(v)];
  return M_PI - Angle(m.p[size_t(next)] - x, m.p[size_t(prev)] - x);
}

// Plane quadrics (Garland & Heckbert 1997) of the input, per vertex: the
// area-weighted squared distance to the planes of its triangles, plus, on
// the boundary, to the planes through each boundary edge perpendicular to
// its triangle (weighted by the edge's squared length times
// kBoundaryQuadricWeight), so that the boundary keeps its course.
constexpr double kBoundaryQuadricWeight = 10;

Quadric PlaneQuadric(const V3& n, const V3& x, double weight) {
  const Eigen::Vector4d plane(n.x(), n.y(), n.z(), -n.dot(x));
  return weight * plane * plane.transpose();
}

std::vector<Quadric> InputQuadrics(const std::vector<V3>& p, const std::vector<std::array<int, 3>>& t) {
  std::vector<Quadric> q(p.size(), Quadric::Zero());
  std::map<std::pair<int, int>, int> use;
  for (const auto& f : t) {
    for (int k = 0; k < 3; ++k) {
      const int a = f[size_t(k)], b = f[size_t((k + 1) % 3)];
      ++use[{std::min(a, b), std::max(a, b)}];
    }
  }
  for (const auto& f : t) {
    const V3 &a = p[size_t(f[0])], &b = p[size_t(f[1])], &c = p[size_t(f[2])];
    const V3 n = (b - a).cross(c - a);
    const double twice_area = n.norm();
    if (!(twice_area > 0)) continue;
    const V3 unit = n / twice_area;
    const Quadric face = PlaneQuadric(unit, a, twice_area / 2);
    for (int k = 0; k < 3; ++k) {
      const int i = f[size_t(k)], j = f[size_t((k + 1) % 3)];
      q[size_t(i)] += face;
      if (use[{std::min(i, j), std::max(i, j)}] != 1) continue;
      const V3 e = p[size_t(j)] - p[size_t(i)];
      const V3 side = e.cross(unit);
      if (!(side.norm() > 0)) continue;
      const Quadric edge = PlaneQuadric(side.normalized(), p[size_t(i)], kBoundaryQuadricWeight * e.squaredNorm());
      q[size_t(i)] += edge;
      q[size_t(j)] += edge;
    }
  }
  return q;
}

double QuadricError(const Quadric& q, const V3& x) {
  const Eigen::Vector4d h(x.x(), x.y(), x.z(), 1);
  return std::max(0.0, h.dot(q * h));
}

// The angle defect at an inner vertex v (radians): 2π − Σθ.
double AngleDefect(const DcMesh& m, int v) {
  double angles = 0;
  for (int f : m.at[size_t(v)]) {
    const int k = m.Slot(f, v);
    const V3& x = m.p[size_t(v)];
    angles += Angle(m.p[size_t(m.tri[size_t(f)][size_t((k + 1) % 3)])] - x,
                    m.p[size_t(m.tri[size_t(f)][size_t((k + 2) % 3)])] - x);
  }
  return 2 * M_PI - angles;
}

struct Candidate {
  bool ok = false;
  double min_angle = -1;  // smallest angle of the new triangles
};

// Whether u may collapse into its neighbour v (the rules of decimate.h) and
// the shape of the triangles it leaves.
Candidate Evaluate(const DcMesh& m, int u, int v, const DcMesh::Ring& ru, double cos_turn,
                   const std::vector<int>& cap) {
  Candidate c;
  const DcMesh::Ring rv = m.RingOf(v);
  const bool bu = DcMesh::OnBoundary(ru), bv = DcMesh::OnBoundary(rv);
  // Triangles on edge uv and their opposite vertices.
  std::vector<int> opposite;
  for (int f : m.at[size_t(u)]) {
    const auto& t = m.tri[size_t(f)];
    if (t[0] != v && t[1] != v && t[2] != v) continue;
    for (int w : t) {
      if (w != u && w != v) opposite.push_back(w);
    }
  }
  if (opposite.empty() || opposite.size() > 2) return c;
  const bool boundary_edge = opposite.size() == 1;
  if (bu && !boundary_edge) return c;  // boundary vertices move along the boundary only
  // Link condition: the common neighbours are exactly the opposite vertices.
  int common = 0;
  for (int w : ru.vertex) {
    if (w == v) continue;
    if (std::find(rv.vertex.begin(), rv.vertex.end(), w) == rv.vertex.end()) continue;
    if (std::find(opposite.begin(), opposite.end(), w) == opposite.end()) return c;
    ++common;
  }
  if (common != int(opposite.size())) return c;
  // Valences after the collapse.
  for (int w : opposite) {
    const DcMesh::Ring rw = m.RingOf(w);
    if (int(rw.vertex.size()) - 1 < (DcMesh::OnBoundary(rw) ? 2 : 3)) return c;
  }
  const int valence_v = int(ru.vertex.size() + rv.vertex.size()) - 2 - common;
  if (valence_v < ((bu || bv) ? 2 : 3) || valence_v > cap[size_t(v)] + 2) return c;
  // A boundary loop of three vertices would close up.
  if (boundary_edge) {
    for (size_t i = 0; i < ru.vertex.size(); ++i) {
      if (ru.vertex[i] == v || ru.next[i] + ru.prev[i] != 1) continue;
      for (size_t j = 0; j < rv.vertex.size(); ++j) {
        if (rv.vertex[j] == ru.vertex[i] && rv.next[j] + rv.prev[j] == 1) return c;
      }
    }
  }
  // The triangles of u that stay, with v for u.
  const V3& xv = m.p[size_t(v)];
  double min_angle = M_PI, old_min_angle = M_PI;
  for (int f : m.at[size_t(u)]) {
    const auto& t = m.tri[size_t(f)];
    if (t[0] == v || t[1] == v || t[2] == v) continue;
    const int k = m.Slot(f, u);
    const V3& a = m.p[size_t(t[size_t((k + 1) % 3)])];
    const V3& b = m.p[size_t(t[size_t((k + 2) % 3)])];
    const V3 n0 = (a - m.p[size_t(u)]).cross(b - m.p[size_t(u)]);
    const V3 n1 = (a - xv).cross(b - xv);
    const double l0 = n0.norm(), l1 = n1.norm();
    if (!(l1 > 1e-12 * (a - xv).squaredNorm()) || !(l0 > 0)) return c;
    if (n0.dot(n1) < cos_turn * l0 * l1) return c;
    if (!m.FacesAsInput(v, t[size_t((k + 1) % 3)], t[size_t((k + 2) % 3)], n1)) return c;
    min_angle = std::min(min_angle, MinAngle(xv, a, b));
    old_min_angle = std::min(old_min_angle, MinAngle(m.p[size_t(u)], a, b));
  }
  if (min_angle < m.min_angle && min_angle < old_min_angle) return c;
  c.ok = true;
  c.min_angle = min_angle;
  return c;
}

// Collapse u into v: u's triangles on edge uv die, the others take v.
void Collapse(DcMesh& m, int u, int v) {
  for (int f : m.at[size_t(u)]) {
    auto& t = m.tri[size_t(f)];
    if (t[0] == v || t[1] == v || t[2] == v) {
      m.tri_alive[size_t(f)] = 0;
      for (int w : t) {
        if (w == u) continue;
        auto& list = m.at[size_t(w)];
        list.erase(std::remove(list.begin(), list.end(), f), list.end());
      }
    } else {
      t[size_t(m.Slot(f, u))] = v;
      m.at[size_t(v)].push_back(f);
    }
  }
  m.at[size_t(u)].clear();
}

// The distance between the segments pq and rs (core/segments.h): how far a
// flip of pq into rs moves the surface where the two cross.
double SegmentDistance(const V3& p, const V3& q, const V3& r, const V3& s) {
  const auto [sc, tc] = ClosestSegmentParameters(p, q, r, s);
  return (p + sc * (q - p) - (r + tc * (s - r))).norm();
}

// Valence-improving flip of edge ab (Gebreiter 2012, §3.1.2: "edges are
// flipped if the result leads to an overall increase in regularity of the
// vertices affected"): triangles (a, b, c) and (b, a, d) become (c, a, d)
// and (d, b, c) when Σ (valence − ideal)² over a, b, c, d drops (ideal 6
// inside, 4 on the boundary) and the smaller minimum angle keeps 80%, or
// stays and the smaller minimum angle grows; not if c-d is an edge already,
// a valence leaves [3, cap] (2 on the boundary), or a new triangle is
// degenerate, turns from the old normals by more than the collapse bound or
// leaves its corners' input normals by more than theirs. With `sliver` > 0
// (radians) the flip is for shape instead: when the two triangles' smallest
// angle is below `sliver` and grows, whatever the valences do (within the
// same bounds, but up to cap + 2, as the collapses). Returns whether it
// flipped.
bool TryFlip(DcMesh& m, int a, int b, double cos_turn, const std::vector<int>& cap,
             double sliver = 0) {
  int f1 = -1, f2 = -1;
  for (int f : m.at[size_t(a)]) {
    const auto& t = m.tri[size_t(f)];
    const int k = m.Slot(f, a);
    if (t[size_t((k + 1) % 3)] == b) f1 = f;
    if (t[size_t((k + 2) % 3)] == b) f2 = f;
  }
  if (f1 < 0 || f2 < 0) return false;
  const int c = m.tri[size_t(f1)][size_t((m.Slot(f1, a) + 2) % 3)];
  const int d = m.tri[size_t(f2)][size_t((m.Slot(f2, a) + 1) % 3)];
  if (c == d) return false;
  const DcMesh::Ring rc = m.RingOf(c);
  if (std::find(rc.vertex.begin(), rc.vertex.end(), d) != rc.vertex.end()) return false;
  const DcMesh::Ring ra = m.RingOf(a), rb = m.RingOf(b), rd = m.RingOf(d);
  const int va = int(ra.vertex.size()), vb = int(rb.vertex.size()), vc = int(rc.vertex.size()),
            vd = int(rd.vertex.size());
  const bool ba = DcMesh::OnBoundary(ra), bb = DcMesh::OnBoundary(rb), bc = DcMesh::OnBoundary(rc),
             bd = DcMesh::OnBoundary(rd);
  if (va - 1 < (ba ? 2 : 3) || vb - 1 < (bb ? 2 : 3)) return false;
  const int slack = sliver > 0 ? 2 : 0;  // shape flips may raise a valence as far as collapses do
  if (vc + 1 > cap[size_t(c)] + slack || vd + 1 > cap[size_t(d)] + slack) return false;
  auto dev = [](int valence, bool boundary) {
    const int e = valence - (boundary ? 4 : 6);
    return e * e;
  };
  const int before = dev(va, ba) + dev(vb, bb) + dev(vc, bc) + dev(vd, bd);
  const int after = dev(va - 1, ba) + dev(vb - 1, bb) + dev(vc + 1, bc) + dev(vd + 1, bd);
  if (sliver == 0 && after > before) return false;
  const V3 &xa = m.p[size_t(a)], &xb = m.p[size_t(b)], &xc = m.p[size_t(c)], &xd = m.p[size_t(d)];
  const V3 n1 = (xa - xc).cross(xd - xc), n2 = (xb - xd).cross(xc - xd);
  const V3 o1 = (xb - xa).cross(xc - xa), o2 = (xa - xb).cross(xd - xb);
  const double scale = (xc - xd).squaredNorm();
  if (!(n1.norm() > 1e-12 * scale) || !(n2.norm() > 1e-12 * scale)) return false;
  for (const V3* n : {&n1, &n2}) {
    for (const V3* o : {&o1, &o2}) {
      if (n->dot(*o) < cos_turn * n->norm() * o->norm()) return false;
    }
  }
  if (!m.FacesAsInput(c, a, d, n1) || !m.FacesAsInput(d, b, c, n2)) return false;
  if (m.flip_factor >= 0 && !(SegmentDistance(xa, xb, xc, xd) < m.flip_factor * m.error_level)) return false;
  const double angle_before = std::min(MinAngle(xa, xb, xc), MinAngle(xb, xa, xd));
  const double angle_after = std::min(MinAngle(xc, xa, xd), MinAngle(xd, xb, xc));
  if (sliver > 0) {
    if (!(angle_before < sliver && angle_after > angle_before)) return false;
  } else if (after == before ? !(angle_after > angle_before)
                             : !(angle_after > 0.8 * angle_before)) {
    // Fewer irregular valences at a small loss of shape, or the same with a better one.
    return false;
  }
  m.tri[size_t(f1)] = {c, a, d};
  m.tri[size_t(f2)] = {d, b, c};
  auto drop = [&m](int v, int f) {
    auto& list = m.at[size_t(v)];
    list.erase(std::remove(list.begin(), list.end(), f), list.end());
  };
  drop(a, f2);
  drop(b, f1);
  m.at[size_t(c)].push_back(f2);
  m.at[size_t(d)].push_back(f1);
  return true;
}


// The RMS distance to the planes of quadric q at x: its error over its area
// (the trace of its 3 × 3 part: the weights of its unit-normal planes).
double RmsDistance(const Quadric& q, const V3& x) {
  const double area = q.topLeftCorner<3, 3>().trace();
  return area > 0 ? std::sqrt(QuadricError(q, x) / area) : 0;
}

constexpr double kKeepImportance = 0.5;  // a relocated node keeps this share of its importance
constexpr double kTieBreak = 1e-9;       // collapses of no error go by importance

// The smallest angle of v's triangles with v at x (−1: one would be
// degenerate, turn from its normal by more than the collapse bound, or leave
// its corners' input normals, x's taken as v's).
double FanAngle(const DcMesh& m, int v, int x, double cos_turn) {
  double smallest = M_PI;
  for (int f : m.at[size_t(v)]) {
    const auto& t = m.tri[size_t(f)];
    const int k = m.Slot(f, v);
    const int ia = t[size_t((k + 1) % 3)], ib = t[size_t((k + 2) % 3)];
    const V3 &a = m.p[size_t(ia)], &b = m.p[size_t(ib)], &xv = m.p[size_t(x)];
    const V3 n0 = (a - m.p[size_t(v)]).cross(b - m.p[size_t(v)]), n1 = (a - xv).cross(b - xv);
    const double l0 = n0.norm(), l1 = n1.norm();
    if (!(l1 > 1e-12 * (a - xv).squaredNorm()) || !(l0 > 0)) return -1;
    if (n0.dot(n1) < cos_turn * l0 * l1 || !m.FacesAsInput(x, ia, ib, n1)) return -1;
    smallest = std::min(smallest, MinAngle(xv, a, b));
  }
  return smallest;
}

// Node relocation (§3.1.2, "a mesh vertex v_i is relocated"): node v moves
// to the input vertex of its region (the vertices collapsed into it) whose
// triangles have the largest smallest angle, when larger than v's; a
// boundary node only along the boundary, an inner one only inside; the
// node's valence within the vertex's input valence; the vertex at least
// half as important on the input (a node on a feature stays on it).
// Returns whether it moved.
bool Relocate(DcMesh& m, int v, const std::vector<int>& region, const std::vector<char>& boundary,
              const std::vector<double>& importance, const std::vector<int>& cap, double cos_turn,
              std::vector<int>& parent) {
  const size_t valence = m.RingOf(v).vertex.size();
  double best_angle = FanAngle(m, v, v, cos_turn);
  int best = -1;
  for (int w : region) {
    if (w == v || boundary[size_t(w)] != boundary[size_t(v)] || int(valence) > cap[size_t(w)] ||
        importance[size_t(w)] < kKeepImportance * importance[size_t(v)]) {
      continue;
    }
    if (m.relocation_factor >= 0 &&
        RmsDistance(m.quadric[size_t(v)], m.p[size_t(w)]) >
            std::max(m.relocation_factor * m.error_level, RmsDistance(m.quadric[size_t(v)], m.p[size_t(v)]))) {
      continue;  // it would leave the node's planes by more than the collapses did
    }
    const double angle = FanAngle(m, v, w, cos_turn);
    if (angle > best_angle + 1e-12) {
      best_angle = angle;
      best = w;
    }
  }
  if (best < 0) return false;
  for (int f : m.at[size_t(v)]) m.tri[size_t(f)][size_t(m.Slot(f, v))] = best;
  m.at[size_t(best)] = std::move(m.at[size_t(v)]);
  m.at[size_t(v)].clear();
  m.quadric[size_t(best)] = m.quadric[size_t(v)];
  parent[size_t(best)] = -1;
  parent[size_t(v)] = best;
  return true;
}

// Rounds of relocations of the nodes not locked, then flips of the slivers'
// edges (TryFlip for shape), until a round changes nothing.
void ImproveShapes(DcMesh& m, const DecimateOptions& options, const std::vector<char>& locked,
                   const std::vector<char>& boundary, const std::vector<int>& cap, double cos_turn,
                   std::vector<int>& parent, DecimateResult& out) {
  const double sliver = options.sliver_degrees * M_PI / 180;
  for (int round = 0; round < options.shape_rounds; ++round) {
    std::vector<std::vector<int>> region(m.at.size());
    for (size_t u = 0; u < m.at.size(); ++u) {
      int r = int(u);
      while (parent[size_t(r)] >= 0) r = parent[size_t(r)];
      if (!m.at[size_t(r)].empty()) region[size_t(r)].push_back(int(u));
    }
    int changed = 0;
    for (size_t v = 0; v < m.at.size(); ++v) {
      if (m.at[v].empty() || locked[v]) continue;
      changed += Relocate(m, int(v), region[v], boundary, out.importance, cap, cos_turn, parent);
    }
    out.relocations += changed;
    for (size_t a = 0; a < m.at.size(); ++a) {
      if (m.at[a].empty()) continue;
      for (int b : m.RingOf(int(a)).vertex) {
        if (int(a) < b && TryFlip(m, int(a), b, cos_turn, cap, sliver)) {
          ++out.shape_flips;
          ++changed;
        }
      }
    }
    if (changed == 0) break;
  }
}

int BoundaryLoops(const DcMesh& m) {
  // Boundary halfedges a→b (b follows a in a triangle, no triangle has b→a).
  std::map<int, int> next;
  for (size_t v = 0; v < m.at.size(); ++v) {
    const DcMesh::Ring r = m.RingOf(int(v));
    for (size_t i = 0; i < r.vertex.size(); ++i) {
      if (r.next[i] == 1 && r.prev[i] == 0) next[int(v)] = r.vertex[i];
    }
  }
  int loops = 0;
  std::map<int, char> seen;
  for (const auto& [start, ignored] : next) {
    if (seen[start]) continue;
    ++loops;
    for (int v = start; !seen[v]; v = next[v]) seen[v] = 1;
  }
  return loops;
}

}  // namespace

BaseComplex DecimateResult::Complex() const {
  BaseComplex b;
  b.nodes = nodes;
  for (const auto& t : triangles) b.faces.push_back({t[0], t[1], t[2]});
  return b;
}

std::vector<double> VertexImportance(const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<std::array<int, 3>>& triangles) {
  const DcMesh m(points, triangles);
  std::vector<double> out(points.size(), 0);
  for (size_t v = 0; v < points.size(); ++v) {
    if (!m.at[v].empty()) out[v] = Importance(m, int(v));
  }
  return out;
}

DecimateResult Decimate(const std::vector<Eigen::Vector3d>& points,
                        const std::vector<std::array<int, 3>>& triangles,
                        const DecimateOptions& options) {
  DcMesh m(points, triangles);
  m.cos_input = std::cos(options.max_normal_deviation_degrees * M_PI / 180);
  m.min_angle = options.min_angle_degrees * M_PI / 180;
  std::map<std::pair<int, int>, int> edge_use;
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[size_t(k)], b = t[size_t((k + 1) % 3)];
      if (a < 0 || b < 0 || size_t(a) >= points.size() || size_t(b) >= points.size() || a == b) {
        throw std::invalid_argument("decimation: a triangle has a bad or repeated vertex id");
      }
      if (++edge_use[{std::min(a, b), std::max(a, b)}] > 2) {
        throw std::invalid_argument("decimation: edge " + std::to_string(a) + "-" +
                                    std::to_string(b) + " is on more than two triangles");
      }
    }
  }
  int count = 0;
  for (const auto& list : m.at) count += !list.empty();
  if (options.target_vertices < 3 || options.target_vertices > count) {
    throw std::invalid_argument("decimation: the target of " +
                                std::to_string(options.target_vertices) +
                                " vertices is not between 3 and the mesh's " +
                                std::to_string(count));
  }
  DecimateResult out;
  const size_t n = points.size();
  out.importance.assign(n, 0);
  out.corner.assign(n, 0);
  std::vector<char> locked(n, 0);
  for (int v : options.locked) {
    if (v >= 0 && size_t(v) < n) locked[size_t(v)] = 1;
  }
  // A node's base edges leave it along distinct surface edges (the charts'
  // paths share no vertex but their nodes): its valence stays within the
  // input's.
  std::vector<int> cap(n, 0);
  std::vector<char> input_boundary(n, 0);
  for (size_t v = 0; v < n; ++v) {
    const DcMesh::Ring r = m.RingOf(int(v));
    cap[v] = int(r.vertex.size());
    input_boundary[v] = DcMesh::OnBoundary(r);
  }
  const double corner_turn = options.corner_degrees * M_PI / 180;
  for (size_t v = 0; v < n; ++v) {
    if (m.at[v].empty()) continue;
    out.importance[v] = Importance(m, int(v));
    if (BoundaryTurn(m, int(v)) > corner_turn) {
      out.corner[v] = 1;
      locked[v] = 1;
      ++out.corners;
    } else if (!input_boundary[v] && std::abs(AngleDefect(m, int(v))) > corner_turn) {
      out.corner[v] = 1;  // a feature corner: the surface's cone point (a cube's corner)
      locked[v] = 1;
      ++out.feature_corners;
    }
  }
  out.boundary_loops = BoundaryLoops(m);
  const double cos_turn = std::cos(options.max_normal_turn_degrees * M_PI / 180);

  // Cheapest first; stale entries (an older stamp) are skipped. The key of
  // u: error-driven, the least quadric error of a collapse of u into a
  // neighbour (admissible or not: a lower bound, made exact when popped)
  // times 1 + importance_weight · I(u); otherwise I(u) alone.
  m.quadric = InputQuadrics(points, triangles);
  std::vector<Quadric>& quadric = m.quadric;
  m.flip_factor = options.flip_error_factor;
  m.relocation_factor = options.relocation_error_factor;
  const bool by_error = options.error_driven;
  const double weight = options.importance_weight;
  auto collapse_error = [&](int u, int v) {
    return QuadricError(quadric[size_t(u)] + quadric[size_t(v)], points[size_t(v)]);
  };
  double scale4 = 0;  // the input's mean edge length to the fourth: an error's units
  {
    double length = 0;
    for (const auto& t : triangles) {
      for (int k = 0; k < 3; ++k) length += (points[size_t(t[size_t(k)])] - points[size_t(t[size_t((k + 1) % 3)])]).norm();
    }
    length /= 3.0 * double(triangles.size());
    scale4 = std::pow(length, 4);
  }
  auto key_of = [&](int u, double error) {
    const double importance = Importance(m, u);
    return by_error ? error * (1 + weight * importance) + kTieBreak * importance * scale4 : importance;
  };
  auto estimate = [&](int u) {
    double least = INFINITY;
    if (by_error) {
      for (int v : m.RingOf(u).vertex) least = std::min(least, collapse_error(u, v));
    }
    return key_of(u, least);
  };
  using Entry = std::pair<double, std::pair<int, int>>;  // key, (vertex, stamp)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  std::vector<int> stamp(n, 0), parent(n, -1);
  for (size_t v = 0; v < n; ++v) {
    if (!m.at[v].empty() && !locked[v]) queue.push({estimate(int(v)), {int(v), 0}});
  }
  while (count > options.target_vertices && !queue.empty()) {
    const auto [key, item] = queue.top();
    queue.pop();
    const int u = item.first;
    if (item.second != stamp[size_t(u)] || m.at[size_t(u)].empty()) continue;
    const DcMesh::Ring ru = m.RingOf(u);
    int best = -1;
    double best_angle = -1, best_error = INFINITY;
    std::vector<std::pair<int, Candidate>> admissible;
    for (int v : ru.vertex) {
      const Candidate c = Evaluate(m, u, v, ru, cos_turn, cap);
      if (!c.ok) {
        ++out.refused;
        continue;
      }
      admissible.push_back({v, c});
      if (by_error) best_error = std::min(best_error, collapse_error(u, v));
    }
    // Error-driven: of the collapses of the least error (up to the tie
    // break), the one of the roundest triangles; otherwise the roundest.
    for (const auto& [v, c] : admissible) {
      if (by_error && collapse_error(u, v) > best_error + kTieBreak * scale4) continue;
      if (c.min_angle > best_angle) {
        best_angle = c.min_angle;
        best = v;
      }
    }
    if (best < 0) continue;  // waits until its one ring changes (a new stamp)
    if (by_error) {
      const double exact = key_of(u, best_error);
      if (exact > key * (1 + 1e-12)) {
        queue.push({exact, item});  // its cheapest collapse was refused: back in line
        continue;
      }
    }
    Collapse(m, u, best);
    quadric[size_t(best)] += quadric[size_t(u)];
    m.error_level = std::max(m.error_level, RmsDistance(quadric[size_t(best)], points[size_t(best)]));
    parent[size_t(u)] = best;
    --count;
    // Flips on the edges at best and around its ring; every vertex they
    // touch gets a new key and is queued again (its collapses may have
    // become admissible).
    std::vector<int> touched = m.RingOf(best).vertex;
    touched.push_back(best);
    for (int w : std::vector<int>(touched)) {
      for (int x : m.RingOf(w).vertex) {
        if (TryFlip(m, w, x, cos_turn, cap)) ++out.flips;
      }
    }
    std::vector<int> requeue;
    for (int w : touched) {
      requeue.push_back(w);
      for (int x : m.RingOf(w).vertex) requeue.push_back(x);
    }
    std::sort(requeue.begin(), requeue.end());
    requeue.erase(std::unique(requeue.begin(), requeue.end()), requeue.end());
    for (int w : requeue) {
      if (locked[size_t(w)] || m.at[size_t(w)].empty()) continue;
      ++stamp[size_t(w)];
      queue.push({estimate(w), {w, stamp[size_t(w)]}});
    }
  }
  out.reached = count == options.target_vertices;
  if (out.reached) ImproveShapes(m, options, locked, input_boundary, cap, cos_turn, parent, out);

  std::vector<int> index(n, -1);
  for (size_t v = 0; v < n; ++v) {
    if (!m.at[v].empty()) {
      index[v] = int(out.nodes.size());
      out.nodes.push_back(int(v));
    }
  }
  for (size_t f = 0; f < m.tri.size(); ++f) {
    if (!m.tri_alive[f]) continue;
    const auto& t = m.tri[f];
    out.triangles.push_back({index[size_t(t[0])], index[size_t(t[1])], index[size_t(t[2])]});
  }
  out.representative.assign(n, -1);
  for (size_t v = 0; v < n; ++v) {
    int r = int(v);
    while (parent[size_t(r)] >= 0) r = parent[size_t(r)];
    out.representative[v] = index[size_t(r)];
  }
  return out;
}

FeatureProximity MeasureFeatureProximity(const std::vector<Eigen::Vector3d>& points,
                                         const std::vector<std::array<int, 3>>& triangles,
                                         const DecimateResult& result) {
  FeatureProximity out;
  const size_t n = points.size();
  const size_t nodes = result.nodes.size();
  out.nodes = int(nodes);
  // The decimated mesh: neighbours, boundary, mean edge length.
  std::vector<V3> coarse_points;
  for (int v : result.nodes) coarse_points.push_back(points[size_t(v)]);
  const DcMesh coarse(coarse_points, result.triangles);
  std::vector<std::vector<int>> ring(nodes);
  std::vector<char> boundary(nodes, 0);
  double length = 0;
  int edges = 0;
  for (size_t v = 0; v < nodes; ++v) {
    const DcMesh::Ring r = coarse.RingOf(int(v));
    ring[v] = r.vertex;
    boundary[v] = DcMesh::OnBoundary(r);
    for (int w : r.vertex) {
      if (w > int(v)) {
        length += (coarse_points[size_t(w)] - coarse_points[v]).norm();
        ++edges;
      }
    }
  }
  const double radius = edges > 0 ? length / edges : 0;
  // The input's edge graph.
  std::vector<std::vector<std::pair<int, double>>> graph(n);
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[size_t(k)], b = t[size_t((k + 1) % 3)];
      const double l = (points[size_t(a)] - points[size_t(b)]).norm();
      graph[size_t(a)].push_back({b, l});
      graph[size_t(b)].push_back({a, l});
    }
  }
  // Visits the vertices within `r` of s along the edges, nearest first
  // (Dijkstra, cut at r), until `visit` returns false.
  std::vector<double> dist(n, INFINITY);
  std::vector<int> touched;
  auto ball = [&](int s, double r, const auto& visit) {
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
    dist[size_t(s)] = 0;
    touched.assign(1, s);
    q.push({0, s});
    while (!q.empty()) {
      const auto [d, v] = q.top();
      q.pop();
      if (d > dist[size_t(v)]) continue;
      if (!visit(v)) break;
      for (const auto& [w, l] : graph[size_t(v)]) {
        if (d + l <= r && d + l < dist[size_t(w)]) {
          if (dist[size_t(w)] == INFINITY) touched.push_back(w);
          dist[size_t(w)] = d + l;
          q.push({d + l, w});
        }
      }
    }
    for (int v : touched) dist[size_t(v)] = INFINITY;
  };
  std::vector<double> smooth(n, -1);
  std::vector<int> reached;
  for (size_t v = 0; v < n; ++v) {
    if (graph[v].empty()) continue;
    reached.clear();
    ball(int(v), radius / 2, [&](int w) {
      reached.push_back(w);
      return true;
    });
    std::sort(reached.begin(), reached.end());  // the sum in index order
    double s = 0;
    for (int w : reached) s += result.importance[size_t(w)];
    smooth[v] = s;
  }
  // A curvature extremum: no vertex within the radius has a larger smoothed
  // importance (ties go to the lower index); the search stops at the first
  // that has.
  std::vector<char> feature_node(nodes, 0);
  for (size_t v = 0; v < n; ++v) {
    if (graph[v].empty() || result.representative[v] < 0) continue;
    if (result.corner[v]) feature_node[size_t(result.representative[v])] = 1;
    bool extremum = true;
    ball(int(v), radius, [&](int w) {
      extremum = !(smooth[size_t(w)] > smooth[v] || (smooth[size_t(w)] == smooth[v] && size_t(w) < v));
      return extremum;
    });
    if (extremum) {
      ++out.extrema;
      feature_node[size_t(result.representative[v])] = 1;
    }
  }
  for (size_t v = 0; v < nodes; ++v) {
    bool near = feature_node[v];
    for (int w : ring[v]) near = near || feature_node[size_t(w)];
    const bool irregular = int(ring[v].size()) != (boundary[v] ? 4 : 6);
    out.near += near;
    out.irregular += irregular;
    out.irregular_near += irregular && near;
  }
  return out;
}

}  // namespace archgeo
