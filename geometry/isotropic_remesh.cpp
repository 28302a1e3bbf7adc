// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — incremental isotropic remeshing (Gebreiter 2012, §3.1.2; Botsch &
// Kobbelt 2004, §4): split, collapse, flip, tangential relaxation with
// projection onto the input. See isotropic_remesh.h.
#include "geometry/isotropic_remesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <CGAL/boost/graph/Euler_operations.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "geometry/reference.h"

namespace archgeo {
namespace {

using V3 = Eigen::Vector3d;

V3 Rp(const Mesh& m, VertexIndex v) {
  const Point& p = m.point(v);
  return {p.x(), p.y(), p.z()};
}

void SetRp(Mesh& m, VertexIndex v, const V3& p) { m.point(v) = Point(p.x(), p.y(), p.z()); }

double RmLength(const Mesh& m, HalfedgeIndex h) {
  return (Rp(m, m.target(h)) - Rp(m, m.source(h))).norm();
}

// Area vector of the triangle of `h` with its target moved to `at`.
V3 RmFaceNormal(const Mesh& m, HalfedgeIndex h) {
  const V3 a = Rp(m, m.source(h)), b = Rp(m, m.target(h)), c = Rp(m, m.target(m.next(h)));
  return (b - a).cross(c - a);
}

// Whether a triangle whose area vector was `before` is turned over or
// flattened when it becomes `after` (its longest edge then `longest`):
// reversed, or below 1e-3 of its old length and of its longest edge squared.
bool RmSpoiled(const V3& before, const V3& after, double longest) {
  return after.dot(before) <= 0 || after.norm() < 1e-3 * std::min(before.norm(), longest * longest);
}

// The longest edge of a triangle.
double RmLongest(const V3& a, const V3& b, const V3& c) {
  return std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
}

struct RmState {
  Mesh mesh;
  // boundary: on the border; feature: on a feature edge; corner: kept.
  Mesh::Property_map<VertexIndex, bool> corner, boundary, feature;
  // The feature chain of an edge, and of a feature vertex that is not a
  // corner: −1 for none. A chain is a run of the input's feature edges
  // between corners (or a closed loop of them).
  Mesh::Property_map<EdgeIndex, int> edge_chain;
  Mesh::Property_map<VertexIndex, int> chain;
  Mesh::Property_map<VertexIndex, double> size;  // target edge length at the vertex
  // The input's (interpolated) normal where the vertex lies: from the
  // closest point that placed it; a boundary or feature vertex keeps the
  // one it had (or its edge's ends' mean, when split off).
  Mesh::Property_map<VertexIndex, V3> normal;
  // The input triangle a vertex lies on, from the closest-point query that
  // put it there (the next query's start); −1 where not known: a boundary
  // or feature vertex moved along its curve, a vertex off the input (a
  // chord midpoint).
  Mesh::Property_map<VertexIndex, int> face;
  const ReferenceSurface* surface = nullptr;
  std::vector<std::vector<std::pair<V3, V3>>> chains;  // each chain's input edges
  std::vector<double> input_size;  // per vertex of surface->Triangles(): its target length
  // An edge between a and b is long beyond 4/3 and short below 4/5 of the
  // mean of their targets.
  double Target(VertexIndex a, VertexIndex b) const { return 0.5 * (size[a] + size[b]); }
  bool Curve(VertexIndex v) const { return boundary[v] || feature[v]; }
  bool CurveEdge(EdgeIndex e) const { return mesh.is_border(e) || edge_chain[e] >= 0; }
};

// Whether the triangle abc faces the input's way where its corners lie
// (its normal less than 90° from the sum of their input normals na, nb,
// nc). Each operation's own check (RmSpoiled) lets a face turn by less than
// 90°; this one keeps a face from turning over by steps, on an input whose
// faces lie close together (a thin plate's top and bottom one edge apart,
// tessellated CAD parts).
bool RmFacesInput(const V3& a, const V3& b, const V3& c, const V3& na, const V3& nb, const V3& nc) {
  return (b - a).cross(c - a).dot(na + nb + nc) > 0;
}

// RmFacesInput for the triangle of h as it is.
bool RmFacesInput(const RmState& s, HalfedgeIndex h) {
  const Mesh& m = s.mesh;
  const VertexIndex a = m.source(h), b = m.target(h), c = m.target(m.next(h));
  return RmFacesInput(Rp(m, a), Rp(m, b), Rp(m, c), s.normal[a], s.normal[b], s.normal[c]);
}

// Distance from q to the segment ab.
double RmSegmentDistance(const V3& q, const V3& a, const V3& b) {
  const V3 d = b - a;
  const double t = std::clamp((q - a).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
  return (q - (a + t * d)).norm();
}

// The first of `curves` whose segments pass within `tolerance` of the ends
// and the midpoint of edge ab; −1 if none.
int RmCurveAlong(const std::vector<std::vector<Vec3>>& curves, double tolerance, const V3& a,
                 const V3& b) {
  for (size_t c = 0; c < curves.size(); ++c) {
    bool all = true;
    for (const V3& q : {a, b, V3(0.5 * (a + b))}) {
      double d = std::numeric_limits<double>::infinity();
      for (size_t i = 1; i < curves[c].size() && d > tolerance; ++i) {
        const Vec3 &p0 = curves[c][i - 1], &p1 = curves[c][i];
        d = std::min(d, RmSegmentDistance(q, V3(p0[0], p0[1], p0[2]), V3(p1[0], p1[1], p1[2])));
      }
      all = all && d <= tolerance;
    }
    if (all) return int(c);
  }
  return -1;
}

// The chains of the feature edges marked (edge_chain 0): from each edge not
// yet in a chain, through the feature vertices that are not corners (each
// has two feature edges), in both directions; the vertices passed take the
// chain.
void RmMarkChains(RmState& s) {
  Mesh& m = s.mesh;
  for (EdgeIndex e : m.edges()) {
    if (s.edge_chain[e] == 0) s.edge_chain[e] = -2;  // a feature edge without its chain yet
  }
  for (EdgeIndex start : m.edges()) {
    if (s.edge_chain[start] != -2) continue;
    const int c = int(s.chains.size());
    s.chains.emplace_back();
    std::vector<EdgeIndex> stack{start};
    s.edge_chain[start] = c;
    while (!stack.empty()) {
      const EdgeIndex e = stack.back();
      stack.pop_back();
      const HalfedgeIndex h = m.halfedge(e);
      s.chains.back().emplace_back(Rp(m, m.source(h)), Rp(m, m.target(h)));
      for (VertexIndex v : {m.source(h), m.target(h)}) {
        if (s.corner[v]) continue;
        s.chain[v] = c;
        for (HalfedgeIndex g : CGAL::halfedges_around_target(m.halfedge(v), m)) {
          if (s.edge_chain[m.edge(g)] != -2) continue;
          s.edge_chain[m.edge(g)] = c;
          stack.push_back(m.edge(g));
        }
      }
    }
  }
}

// Feature edges: interior edges of the input whose faces' normals differ by
// more than the angle, or that lie along a feature curve (counted per curve
// in `curve_edges`). Feature vertices with other than two feature edges
// (ends, junctions) or on the boundary are corners.
int RmMarkFeatures(RmState& s, const RemeshOptions& options, std::vector<int>& curve_edges) {
  Mesh& m = s.mesh;
  curve_edges.assign(options.feature_curves.size(), 0);
  const double angle = options.feature_angle_degrees;
  if (angle <= 0 && options.feature_curves.empty()) return 0;
  const double limit = angle > 0 ? std::cos(angle * M_PI / 180) : -2;
  std::vector<int> count(m.number_of_vertices(), 0);
  for (EdgeIndex e : m.edges()) {
    if (m.is_border(e)) continue;
    const HalfedgeIndex h = m.halfedge(e);
    const V3 n1 = RmFaceNormal(m, h).normalized(), n2 = RmFaceNormal(m, m.opposite(h)).normalized();
    const int curve = RmCurveAlong(options.feature_curves, options.curve_tolerance,
                                   Rp(m, m.source(h)), Rp(m, m.target(h)));
    if (curve >= 0) ++curve_edges[size_t(curve)];
    if (n1.dot(n2) >= limit && curve < 0) continue;
    s.edge_chain[e] = 0;  // a feature edge; its chain below
    for (VertexIndex v : {m.source(h), m.target(h)}) {
      s.feature[v] = true;
      ++count[v.idx()];
    }
  }
  int corners = 0;
  for (VertexIndex v : m.vertices()) {
    if (s.feature[v] && !s.corner[v] && (count[v.idx()] != 2 || s.boundary[v])) {
      s.corner[v] = true;
      ++corners;
    }
  }
  RmMarkChains(s);
  return corners;
}

// The closest point to q of the input edges of feature chain `chain`.
V3 RmOnFeature(const RmState& s, int chain, const V3& q) {
  V3 best = q;
  double best_d = INFINITY;
  for (const auto& [a, b] : s.chains[size_t(chain)]) {
    const V3 ab = b - a;
    const double t = std::clamp(ab.dot(q - a) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    const V3 p = a + t * ab;
    const double d = (p - q).squaredNorm();
    if (d < best_d) {
      best_d = d;
      best = p;
    }
  }
  return best;
}

// A vertex's place: its position, the input's normal there and the input
// triangle it lies on (−1: not known).
struct RmPlace {
  V3 p, n;
  int face = -1;
};

RmPlace RmPlaceOf(const RmState& s, VertexIndex v) {
  return {Rp(s.mesh, v), s.normal[v], s.face[v]};
}

// q put on the input where vertex v belongs: a corner's q as it is, a
// boundary vertex's on the input's boundary, a feature vertex's on its
// chain (these keep the normal n), any other's on the input surface
// (closest points, with the input's normal there; the search starts from
// `near` when it lies on a known input triangle).
RmPlace RmOnInput(const RmState& s, VertexIndex v, const V3& q, const V3& n, const RmPlace& near) {
  if (s.corner[v]) return {q, n};
  if (s.boundary[v]) {
    const auto on = s.surface->ClosestOnBoundary({q.x(), q.y(), q.z()});
    return {on ? V3(on->point[0], on->point[1], on->point[2]) : q, n};
  }
  if (s.chain[v] >= 0) return {RmOnFeature(s, s.chain[v], q), n};
  const Vec3 query = {q.x(), q.y(), q.z()};
  const Vec3 start = {near.p.x(), near.p.y(), near.p.z()};
  const ReferenceSurface::SurfacePoint on = near.face >= 0
                                                ? s.surface->Closest(query, {start, {}, near.face})
                                                : s.surface->Closest(query);
  const V3 normal(on.normal[0], on.normal[1], on.normal[2]);
  return {{on.point[0], on.point[1], on.point[2]}, normal, on.face};
}

// Where a closest-point search near the edge ab starts: an end on a known
// input triangle.
RmPlace RmNear(const RmState& s, VertexIndex a, VertexIndex b) {
  return RmPlaceOf(s, s.face[a] >= 0 ? a : b);
}

void SetPlace(RmState& s, VertexIndex v, const RmPlace& place) {
  SetRp(s.mesh, v, place.p);
  s.normal[v] = place.n;
  s.face[v] = place.face;
}

// Corners: boundary vertices where the boundary turns by more than the angle.
int RmMarkCorners(RmState& s, double corner_angle_degrees) {
  Mesh& m = s.mesh;
  const double limit = std::cos(corner_angle_degrees * M_PI / 180);
  int corners = 0;
  for (HalfedgeIndex h : m.halfedges()) {
    if (!m.is_border(h)) continue;
    const VertexIndex v = m.target(h);
    s.boundary[v] = true;
    const V3 in = (Rp(m, v) - Rp(m, m.source(h))).normalized();
    const V3 out = (Rp(m, m.target(m.next(h))) - Rp(m, v)).normalized();
    if (in.dot(out) < limit) {
      s.corner[v] = true;
      ++corners;
    }
  }
  return corners;
}

int RmSplitLong(RmState& s) {
  Mesh& m = s.mesh;
  std::vector<EdgeIndex> edges(m.edges().begin(), m.edges().end());
  int splits = 0;
  for (size_t i = 0; i < edges.size(); ++i) {
    HalfedgeIndex h = m.halfedge(edges[i]);
    if (RmLength(m, h) <= 4.0 / 3.0 * s.Target(m.source(h), m.target(h))) continue;
    const bool on_boundary = m.is_border(m.edge(h));
    const int chain = s.edge_chain[m.edge(h)];
    const bool on_feature = chain >= 0;
    const RmPlace near = RmNear(s, m.source(h), m.target(h));
    const RmPlace mid = {0.5 * (Rp(m, m.source(h)) + Rp(m, m.target(h))),
                         (s.normal[m.source(h)] + s.normal[m.target(h)]).normalized()};
    const HalfedgeIndex hnew = CGAL::Euler::split_edge(h, m);  // target(hnew): the new vertex
    const VertexIndex v = m.target(hnew);
    const double size = s.Target(m.source(hnew), m.target(h));
    s.size[v] = size;
    s.corner[v] = false;
    s.boundary[v] = on_boundary;
    s.feature[v] = on_feature;
    s.chain[v] = chain;
    s.edge_chain[m.edge(hnew)] = chain;
    SetPlace(s, v, mid);
    if (!m.is_border(h)) CGAL::Euler::split_face(hnew, m.next(h), m);
    const HalfedgeIndex o = m.opposite(h);
    if (!m.is_border(o)) CGAL::Euler::split_face(o, m.next(m.opposite(hnew)), m);
    // On the input where v belongs, unless that turns over or flattens one
    // of its (up to four) triangles: then the chord's midpoint.
    std::vector<std::pair<HalfedgeIndex, V3>> around;
    for (HalfedgeIndex g : CGAL::halfedges_around_target(m.halfedge(v), m)) {
      if (!m.is_border(g)) around.emplace_back(g, RmFaceNormal(m, g));
    }
    SetPlace(s, v, RmOnInput(s, v, mid.p, mid.n, near));
    for (const auto& [g, before] : around) {
      const V3 a = Rp(m, m.source(g)), b = Rp(m, m.target(g)), c = Rp(m, m.target(m.next(g)));
      if (RmSpoiled(before, RmFaceNormal(m, g), RmLongest(a, b, c)) || !RmFacesInput(s, g)) {
        SetPlace(s, v, mid);
      }
    }
    ++splits;
    // The two halves may still be long.
    edges.push_back(m.edge(hnew));
    edges.push_back(m.edge(h));
  }
  return splits;
}

// Whether moving the vertices of h's edge to `at` keeps every remaining
// triangle around them turned by less than 90° and no edge long (4/3 of its
// target, the kept vertex's target for the moved end).
bool RmCollapseKeepsShape(const RmState& s, HalfedgeIndex h, const V3& at) {
  const Mesh& m = s.mesh;
  const VertexIndex a = m.source(h), b = m.target(h);
  for (VertexIndex v : {a, b}) {
    for (HalfedgeIndex g : CGAL::halfedges_around_target(m.halfedge(v), m)) {
      const VertexIndex w = m.source(g);
      if (w != a && w != b && (Rp(m, w) - at).norm() > 4.0 / 3.0 * 0.5 * (s.size[b] + s.size[w])) return false;
      if (m.is_border(g)) continue;
      // The face of g: skip the two faces that vanish with the edge.
      const FaceIndex f = m.face(g);
      if (f == m.face(h) || f == m.face(m.opposite(h))) continue;
      const V3 before = RmFaceNormal(m, g);
      const V3 p = Rp(m, m.source(g)), q = at, r = Rp(m, m.target(m.next(g)));
      const V3 p2 = (m.source(g) == a || m.source(g) == b) ? at : p;
      const V3 r2 = (m.target(m.next(g)) == a || m.target(m.next(g)) == b) ? at : r;
      const V3 after = (q - p2).cross(r2 - p2);
      if (RmSpoiled(before, after, RmLongest(p2, q, r2))) return false;
    }
  }
  return true;
}

int RmCollapseShort(RmState& s) {
  Mesh& m = s.mesh;
  std::vector<EdgeIndex> edges(m.edges().begin(), m.edges().end());
  int collapses = 0;
  for (EdgeIndex e : edges) {
    if (m.is_removed(e)) continue;
    HalfedgeIndex h = m.halfedge(e);
    if (RmLength(m, h) >= 4.0 / 5.0 * s.Target(m.source(h), m.target(h))) continue;
    VertexIndex a = m.source(h), b = m.target(h);  // b is kept
    const bool curve_edge = s.CurveEdge(e);
    if (s.corner[a] && s.corner[b]) continue;
    if (s.Curve(a) && s.Curve(b) && !curve_edge) continue;  // would pinch the surface or a feature
    if (s.boundary[a] != s.boundary[b] && curve_edge) continue;  // a feature edge onto the boundary
    if (s.corner[a] || (s.Curve(a) && !s.Curve(b))) {
      h = m.opposite(h);
      std::swap(a, b);
    }
    // Where the kept vertex goes: a corner or a boundary or feature vertex
    // (of an edge off its curve) stays; else the midpoint, on the input
    // where b belongs.
    const RmPlace at = (s.corner[b] || (s.Curve(b) && !curve_edge))
                           ? RmPlaceOf(s, b)
                           : RmOnInput(s, b, 0.5 * (Rp(m, a) + Rp(m, b)),
                                       (s.normal[a] + s.normal[b]).normalized(), RmNear(s, a, b));
    if (!CGAL::Euler::does_satisfy_link_condition(e, m)) continue;
    // No triangle flattened into its neighbour: the far vertices of the two
    // vanishing faces keep at least 4 edges.
    bool thin = false;
    for (HalfedgeIndex g : {h, m.opposite(h)}) {
      if (!m.is_border(g) && m.degree(m.target(m.next(g))) <= 3) thin = true;
    }
    if (thin || !RmCollapseKeepsShape(s, h, at.p)) continue;
    const bool corner = s.corner[b], boundary = s.boundary[b], feature = s.feature[b];
    const int chain = s.chain[b];
    const double size = std::min(s.size[a], s.size[b]);
    const VertexIndex kept = CGAL::Euler::collapse_edge(e, m);
    SetPlace(s, kept, at);
    s.corner[kept] = corner;
    s.boundary[kept] = boundary;
    s.feature[kept] = feature;
    s.chain[kept] = chain;
    s.size[kept] = size;
    ++collapses;
  }
  return collapses;
}

int RmTargetValence(const RmState& s, VertexIndex v) { return s.boundary[v] ? 4 : 6; }

int RmFlipForValence(RmState& s) {
  Mesh& m = s.mesh;
  std::vector<EdgeIndex> edges(m.edges().begin(), m.edges().end());
  int flips = 0;
  for (EdgeIndex e : edges) {
    if (m.is_removed(e) || s.CurveEdge(e)) continue;
    const HalfedgeIndex h = m.halfedge(e), o = m.opposite(h);
    const VertexIndex a = m.source(h), b = m.target(h);
    const VertexIndex c = m.target(m.next(h)), d = m.target(m.next(o));
    if (c == d || m.halfedge(c, d) != Mesh::null_halfedge()) continue;
    if (m.degree(a) <= 3 || m.degree(b) <= 3) continue;
    auto dev = [&](VertexIndex v, int change) {
      return std::abs(int(m.degree(v)) + change - RmTargetValence(s, v));
    };
    const int before = dev(a, 0) + dev(b, 0) + dev(c, 0) + dev(d, 0);
    const int after = dev(a, -1) + dev(b, -1) + dev(c, 1) + dev(d, 1);
    if (after >= before) continue;
    // The two new triangles (c, d, b) and (d, c, a) must face the old ones'
    // way, and neither may be flat.
    const V3 pa = Rp(m, a), pb = Rp(m, b), pc = Rp(m, c), pd = Rp(m, d);
    const V3 n = RmFaceNormal(m, h) + RmFaceNormal(m, o);
    const V3 n1 = (pd - pc).cross(pb - pc), n2 = (pc - pd).cross(pa - pd);
    if (RmSpoiled(n, n1, RmLongest(pc, pd, pb)) || RmSpoiled(n, n2, RmLongest(pd, pc, pa)) ||
        n1.dot(n2) <= 0 || !RmFacesInput(pc, pd, pb, s.normal[c], s.normal[d], s.normal[b]) ||
        !RmFacesInput(pd, pc, pa, s.normal[d], s.normal[c], s.normal[a])) {
      continue;
    }
    CGAL::Euler::flip_edge(h, m);
    ++flips;
  }
  return flips;
}

V3 RmVertexNormal(const Mesh& m, VertexIndex v) {
  V3 n = V3::Zero();
  for (HalfedgeIndex g : CGAL::halfedges_around_target(m.halfedge(v), m)) {
    if (!m.is_border(g)) n += RmFaceNormal(m, g);
  }
  return n.normalized();
}

// Moves every vertex of `moves` to its position, then puts back, until
// none is left, the moved vertices of every triangle the moves turned over
// or flattened (its area vector reversed, or below 1e-3 of its old length
// and of its longest edge squared) or turned against the input
// (RmFacesInput): the tangent plane and the closest point can send two
// neighbours to one point of a bent surface.
void RmMoveKeepingFaces(RmState& s, const std::vector<std::pair<VertexIndex, RmPlace>>& moves) {
  Mesh& m = s.mesh;
  std::vector<RmPlace> old(m.number_of_vertices() + m.number_of_removed_vertices());
  std::vector<char> moved(old.size(), 0);
  std::vector<std::pair<FaceIndex, V3>> faces;  // around a moved vertex, with the old area vector
  for (const auto& [v, place] : moves) {
    old[v.idx()] = RmPlaceOf(s, v);
    moved[v.idx()] = 1;
  }
  for (const auto& [v, place] : moves) {
    for (HalfedgeIndex g : CGAL::halfedges_around_target(m.halfedge(v), m)) {
      if (!m.is_border(g)) faces.emplace_back(m.face(g), RmFaceNormal(m, g));
    }
  }
  for (const auto& [v, place] : moves) SetPlace(s, v, place);
  for (bool again = true; again;) {
    again = false;
    for (const auto& [f, before] : faces) {
      const HalfedgeIndex h = m.halfedge(f);
      const V3 after = RmFaceNormal(m, h);
      const V3 a = Rp(m, m.source(h)), b = Rp(m, m.target(h)), c = Rp(m, m.target(m.next(h)));
      if (!RmSpoiled(before, after, RmLongest(a, b, c)) && RmFacesInput(s, h)) continue;
      for (VertexIndex w : CGAL::vertices_around_face(h, m)) {
        if (!moved[w.idx()]) continue;
        SetPlace(s, w, old[w.idx()]);
        moved[w.idx()] = 0;
        again = true;
      }
    }
  }
}

void RmRelax(RmState& s) {
  Mesh& m = s.mesh;
  std::vector<std::pair<VertexIndex, RmPlace>> moves;
  for (VertexIndex v : m.vertices()) {
    if (s.corner[v]) continue;
    const V3 p = Rp(m, v);
    V3 q;  // where v would go, before it is put on the input (RmOnInput)
    if (s.Curve(v)) {
      // The midpoint of its two neighbours along its curve: the boundary,
      // or its own feature chain (on no other feature: chains meet at
      // corners only).
      V3 sum = V3::Zero();
      int count = 0;
      for (HalfedgeIndex g : CGAL::halfedges_around_target(m.halfedge(v), m)) {
        const EdgeIndex e = m.edge(g);
        if (s.boundary[v] ? m.is_border(e) : s.edge_chain[e] == s.chain[v]) {
          sum += Rp(m, m.source(g));
          ++count;
        }
      }
      if (count != 2 && s.boundary[v]) continue;
      q = count == 2 ? V3(0.5 * sum) : p;
    } else {
      // Its tangent plane's step to the area-weighted centroid of its ring.
      V3 centroid = V3::Zero();
      double area = 0;
      for (HalfedgeIndex g : CGAL::halfedges_around_target(m.halfedge(v), m)) {
        if (m.is_border(g)) continue;
        const V3 a = Rp(m, m.source(g)), b = Rp(m, m.target(g)), c = Rp(m, m.target(m.next(g)));
        const double w = (b - a).cross(c - a).norm();
        centroid += w * (a + b + c) / 3;
        area += w;
      }
      if (area <= 0) continue;
      centroid /= area;
      const V3 n = RmVertexNormal(m, v);
      q = p + (centroid - p) - n * n.dot(centroid - p);
    }
    moves.emplace_back(v, RmOnInput(s, v, q, s.normal[v], RmPlaceOf(s, v)));
  }
  RmMoveKeepingFaces(s, moves);
}

// Curvature-adaptive targets (Dunyach et al. 2013, "Adaptive remeshing for
// real-time mesh deformation", §3): an edge of length ℓ on a circle of
// curvature κ deviates from it by ε when ℓ = √(6ε/κ − 3ε²); κ at an input
// vertex is the largest normal curvature its edges estimate,
// 2|n·(q − p)|/|q − p|². Targets stay within [L/16, L]. Without a tolerance
// every target is L (the vertices' own, s.size) and there are none per
// input vertex.
void RmInputSizes(RmState& s, const RemeshOptions& o) {
  const Mesh& tri = s.surface->Triangles();
  const double L = o.target_edge_length, eps = o.tolerance;
  s.input_size.clear();
  if (!(eps > 0)) return;
  s.input_size.assign(tri.number_of_vertices() + tri.number_of_removed_vertices(), L);
  for (VertexIndex v : tri.vertices()) {
    if (tri.is_isolated(v)) continue;
    const V3 n = RmVertexNormal(tri, v), p = Rp(tri, v);
    double kappa = 0;
    for (HalfedgeIndex g : CGAL::halfedges_around_target(tri.halfedge(v), tri)) {
      const V3 d = Rp(tri, tri.source(g)) - p;
      kappa = std::max(kappa, 2 * std::abs(n.dot(d)) / std::max(d.squaredNorm(), 1e-300));
    }
    const double l = kappa > 0 ? std::sqrt(std::max(0.0, 6 * eps / kappa - 3 * eps * eps)) : L;
    s.input_size[v.idx()] = std::clamp(l, L / 16, L);
  }
}

// Each vertex's target: the smallest of the input triangle nearest to it.
void RmUpdateSizes(RmState& s) {
  if (s.input_size.empty()) return;
  const Mesh& tri = s.surface->Triangles();
  for (VertexIndex v : s.mesh.vertices()) {
    const V3 p = Rp(s.mesh, v);
    const int face = s.surface->Closest({p.x(), p.y(), p.z()}).face;
    double size = INFINITY;
    for (VertexIndex w : CGAL::vertices_around_face(tri.halfedge(FaceIndex(face)), tri)) {
      size = std::min(size, s.input_size[w.idx()]);
    }
    s.size[v] = size;
  }
}

}  // namespace

RemeshResult IsotropicRemesh(const Mesh& input, const RemeshOptions& options) {
  if (!(options.target_edge_length > 0) || !std::isfinite(options.target_edge_length)) {
    throw std::invalid_argument("remeshing needs a positive, finite target edge length");
  }
  if (options.iterations < 1) throw std::invalid_argument("remeshing needs at least one iteration");
  if (!(options.tolerance >= 0)) throw std::invalid_argument("remeshing needs a tolerance ≥ 0");
  const ReferenceSurface surface(input);
  RmState s;
  s.mesh = surface.Triangles();
  s.mesh.collect_garbage();
  s.surface = &surface;
  s.corner = s.mesh.add_property_map<VertexIndex, bool>("v:rm_corner", false).first;
  s.boundary = s.mesh.add_property_map<VertexIndex, bool>("v:rm_boundary", false).first;
  s.feature = s.mesh.add_property_map<VertexIndex, bool>("v:rm_feature", false).first;
  s.edge_chain = s.mesh.add_property_map<EdgeIndex, int>("e:rm_chain", -1).first;
  s.chain = s.mesh.add_property_map<VertexIndex, int>("v:rm_chain", -1).first;
  s.size = s.mesh.add_property_map<VertexIndex, double>("v:rm_size", options.target_edge_length).first;
  s.normal = s.mesh.add_property_map<VertexIndex, V3>("v:rm_normal", V3::Zero()).first;
  s.face = s.mesh.add_property_map<VertexIndex, int>("v:rm_face", -1).first;
  for (VertexIndex v : s.mesh.vertices()) {
    const ReferenceSurface::SurfacePoint on = surface.Closest(ToVec3(s.mesh.point(v)));
    s.normal[v] = {on.normal[0], on.normal[1], on.normal[2]};
    s.face[v] = on.face;
  }
  RmInputSizes(s, options);
  RmUpdateSizes(s);
  RemeshResult result;
  result.corners = RmMarkCorners(s, options.corner_angle_degrees);
  result.corners += RmMarkFeatures(s, options, result.curve_edges);
  for (const auto& chain : s.chains) result.feature_edges += int(chain.size());
  for (int it = 0; it < options.iterations; ++it) {
    result.splits += RmSplitLong(s);
    result.collapses += RmCollapseShort(s);
    s.mesh.collect_garbage();
    result.flips += RmFlipForValence(s);
    RmRelax(s);
    RmUpdateSizes(s);
  }
  s.mesh.remove_property_map(s.corner);
  s.mesh.remove_property_map(s.boundary);
  s.mesh.remove_property_map(s.feature);
  s.mesh.remove_property_map(s.edge_chain);
  s.mesh.remove_property_map(s.chain);
  s.mesh.remove_property_map(s.size);
  s.mesh.remove_property_map(s.normal);
  s.mesh.remove_property_map(s.face);
  s.mesh.collect_garbage();
  result.mesh = std::move(s.mesh);
  return result;
}

TriangleQuality MeasureTriangles(const Mesh& m) {
  TriangleQuality q;
  q.min_angle_degrees = 180;
  long good = 0, faces = 0;
  for (FaceIndex f : m.faces()) {
    const HalfedgeIndex h = m.halfedge(f);
    const V3 p[3] = {Rp(m, m.source(h)), Rp(m, m.target(h)), Rp(m, m.target(m.next(h)))};
    double smallest = 180;
    for (int k = 0; k < 3; ++k) {
      const V3 u = p[(k + 1) % 3] - p[k], w = p[(k + 2) % 3] - p[k];
      smallest = std::min(smallest, std::atan2(u.cross(w).norm(), u.dot(w)) * 180 / M_PI);
    }
    q.min_angle_degrees = std::min(q.min_angle_degrees, smallest);
    good += smallest >= 30;
    ++faces;
  }
  q.min_angle_30_fraction = faces ? double(good) / double(faces) : 0;
  double sum = 0, sum2 = 0;
  long n = 0;
  for (EdgeIndex e : m.edges()) {
    const double l = RmLength(m, m.halfedge(e));
    sum += l;
    sum2 += l * l;
    ++n;
  }
  if (n) {
    q.edge_mean = sum / double(n);
    q.edge_cv = std::sqrt(std::max(0.0, sum2 / double(n) - q.edge_mean * q.edge_mean)) / q.edge_mean;
  }
  return q;
}

}  // namespace archgeo
