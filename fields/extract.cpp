// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fields/extract.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Union_find.h>
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <glog/logging.h>

#include "fields/cut_jumps.h"
#include "fields/layout_cleanup.h"

namespace archgeo {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using V3 = Eigen::Vector3d;
using UnionFind = CGAL::Union_find<size_t>;

enum KeyType : int { kVertex = 0, kEdgePoint = 1, kFacePoint = 2 };
using CutKey = std::array<int, 4>;  // type, a, b, c

// A point of a (sub-)polygon of one triangle, in that triangle's coordinates.
struct PV {
  CutKey key;
  V3 pos;
  double u = 0, v = 0;        // spacing units, own (face) coordinates
  bool on_u = false, on_v = false;
  int mask = 0;               // bits k of the triangle edges h_k the point lies on
};

// A level crossing on a mesh edge, in the canonical face's coordinates.
struct EdgeCrossing {
  double t = 0;  // from source to target of the canonical halfedge
  double u = 0, v = 0;
  bool on_u = false, on_v = false;
};

constexpr double kSameCrossing = 1e-10;  // edge parameter

// Singleton sets 0 … n − 1 in `uf`; element i is handles[i].
std::vector<UnionFind::handle> MakeSets(size_t n, UnionFind* uf) {
  std::vector<UnionFind::handle> handles;
  handles.reserve(n);
  for (size_t i = 0; i < n; ++i) handles.push_back(uf->make_set(i));
  return handles;
}

V3 Pos(const Mesh& mesh, VertexIndex v) {
  const Point& p = mesh.point(v);
  return V3(p.x(), p.y(), p.z());
}

bool IsInteger(double x) { return x == std::round(x); }

// Splits the convex polygon q by the level `level` of coordinate `c` (0: u,
// 1: v). New points (only where a v-level crosses a u-chord) come from / go
// into `cache`.
struct Splitter {
  int face;
  std::map<CutKey, PV>* cache;
  int* anomalies;

  static double Coord(const PV& p, int c) { return c == 0 ? p.u : p.v; }
  static bool On(const PV& p, int c) { return c == 0 ? p.on_u : p.on_v; }

  std::vector<std::vector<PV>> operator()(const std::vector<PV>& q, int c, double level) const {
    const size_t n = q.size();
    std::vector<int> s(n);
    bool neg = false, pos = false;
    for (size_t i = 0; i < n; ++i) {
      const double x = Coord(q[i], c);
      s[i] = x == level ? 0 : (x < level ? -1 : 1);
      neg = neg || s[i] < 0;
      pos = pos || s[i] > 0;
    }
    if (!neg || !pos) return {q};
    int changes = 0, last = 0;
    for (size_t i = 0; i <= n; ++i) {
      const int si = s[i % n];
      if (si == 0) continue;
      if (last != 0 && si != last) ++changes;
      last = si;
    }
    if (changes > 2) {  // not a linear function on a convex polygon: rounding
      ++*anomalies;
      return {q};
    }
    std::vector<PV> lower, upper;
    for (size_t i = 0; i < n; ++i) {
      const PV& a = q[i];
      const PV& b = q[(i + 1) % n];
      if (s[i] <= 0) lower.push_back(a);
      if (s[i] >= 0) upper.push_back(a);
      if (s[i] * s[(i + 1) % n] < 0) {
        const PV x = Cross(a, b, c, level);
        lower.push_back(x);
        upper.push_back(x);
      }
    }
    return {lower, upper};
  }

  PV Cross(const PV& a, const PV& b, int c, double level) const {
    // The segment a–b lies on a level of the other coordinate (a chord);
    // otherwise the slicing is inconsistent.
    const int o = 1 - c;
    const bool chord = On(a, o) && On(b, o) && Coord(a, o) == Coord(b, o);
    CutKey key;
    if (chord) {
      const int level_u = static_cast<int>(c == 0 ? level : Coord(a, o));
      const int level_v = static_cast<int>(c == 1 ? level : Coord(a, o));
      key = {kFacePoint, face, level_u, level_v};
    } else {
      ++*anomalies;
      key = {kFacePoint, face, 1 << 30, static_cast<int>(cache->size())};
    }
    auto it = cache->find(key);
    if (it != cache->end()) return it->second;
    const double t = (level - Coord(a, c)) / (Coord(b, c) - Coord(a, c));
    PV x;
    x.key = key;
    x.pos = a.pos + t * (b.pos - a.pos);
    x.mask = a.mask & b.mask;
    if (c == 0) {
      x.u = level;
      x.on_u = true;
      x.v = chord ? a.v : a.v + t * (b.v - a.v);
      x.on_v = chord;
    } else {
      x.v = level;
      x.on_v = true;
      x.u = chord ? a.u : a.u + t * (b.u - a.u);
      x.on_u = chord;
    }
    (*cache)[key] = x;
    return x;
  }
};

// The triangle mesh and its level-set functions, as the steps read them.
struct Input {
  const Mesh& mesh;
  const LevelSetFunctions& fn;

  // Index of a corner's value in fn.g, fn.h: its wedge (its vertex without cut).
  int Wedge(HalfedgeIndex corner) const {
    return fn.cut != nullptr ? fn.cut->corner_wedge[corner.idx()]
                             : static_cast<int>(mesh.target(corner).idx());
  }
};

// The functions in spacing units (step 1).
struct UnitValues {
  std::vector<double> u, v;    // per wedge (per vertex without cut)
  std::vector<double> ku, kv;  // per cut chain: the integer jumps α/Δw
};

// The level crossings on the mesh edges (step 2).
struct EdgeCrossings {
  // Per edge: the halfedge (not a border one) whose face's coordinates the
  // crossings carry.
  std::vector<HalfedgeIndex> canonical;
  std::vector<std::vector<EdgeCrossing>> on_edge;  // per edge, ordered by t
  std::vector<FaceIndex> left_face;                // per cut edge: its left face
};

// The pieces of all triangles (step 3), each a convex polygon.
struct Pieces {
  std::vector<std::vector<PV>> polys;
  std::vector<FaceIndex> face;                               // per piece: its triangle
  std::vector<std::array<HalfedgeIndex, 3>> face_halfedges;  // per triangle: h_0, h_1, h_2 (bits of PV::mask)
};

// How the pieces are glued into regions (step 4).
struct Gluing {
  // Per piece side: the glued (piece, side), or (−1, −1).
  std::vector<std::vector<std::pair<int, int>>> twin;
  std::vector<std::vector<char>> on_boundary;  // per piece side: it lies on a mesh boundary edge
  std::vector<size_t> region;                  // per piece: the key of its region
};

// Which polygon points become output vertices (step 4 of the header).
struct OutputVertices {
  std::vector<bool> boundary_vertex, corner;  // per mesh vertex
  // Per mesh vertex: its distinct neighbours along u- and v-levels.
  std::map<int, std::set<CutKey>> iso_u, iso_v;
  std::set<int> leaves_boundary;  // mesh vertices where a level leaves the boundary
};

// The output as a polygon soup: points with their flags, faces as cycles of
// point indices.
struct Soup {
  std::vector<V3> points;
  std::vector<bool> on_boundary, is_corner;  // per point
  std::vector<std::vector<int>> faces;
};

// Boundary loops of the regions (cycles of point indices), by region key.
using RegionLoops = std::map<size_t, std::vector<std::vector<int>>>;

// Preconditions of ExtractQuadMesh (see extract.h).
void CheckInput(const Mesh& mesh, const LevelSetFunctions& fn) {
  CHECK(!mesh.has_garbage());
  CHECK(fn.spacing_g > 0.0 && fn.spacing_h > 0.0) << "ExtractQuadMesh: spacings must be > 0";
  const CutGraph* cut = fn.cut;
  const size_t num_values = cut != nullptr ? cut->num_wedges : mesh.number_of_vertices();
  CHECK_EQ(fn.g.size(), num_values);
  CHECK_EQ(fn.h.size(), num_values);
  const size_t num_chains = cut != nullptr ? cut->chains.size() : 0;
  CHECK_EQ(fn.alpha_g.size(), num_chains);
  CHECK_EQ(fn.alpha_h.size(), num_chains);
  CHECK_EQ(fn.sign_g.size(), num_chains);
  CHECK_EQ(fn.sign_h.size(), num_chains);
  for (size_t c = 0; c < num_chains; ++c)
    CHECK(std::abs(fn.sign_g[c]) == 1 && std::abs(fn.sign_h[c]) == 1) << "signs must be ±1";
  for (FaceIndex f : mesh.faces()) CHECK_EQ(mesh.degree(f), 3u) << "ExtractQuadMesh: triangles only";
}

// 1. Spacing units, integer jumps, projection, snapping. False (with
// out->error) when a jump is not an integer number of spacings or the values
// violate the jump conditions by more than the tolerance.
bool ToSpacingUnits(const LevelSetFunctions& fn, const ExtractOptions& options, UnitValues* values,
                    Extraction* out) {
  const size_t num_values = fn.g.size(), num_chains = fn.alpha_g.size();
  std::vector<double>& u = values->u;
  std::vector<double>& v = values->v;
  std::vector<double>& ku = values->ku;
  std::vector<double>& kv = values->kv;
  u.resize(num_values);
  v.resize(num_values);
  for (size_t i = 0; i < num_values; ++i) {
    u[i] = fn.g[i] / fn.spacing_g;
    v[i] = fn.h[i] / fn.spacing_h;
  }
  ku.resize(num_chains);
  kv.resize(num_chains);
  for (size_t c = 0; c < num_chains; ++c) {
    ku[c] = std::round(fn.alpha_g[c] / fn.spacing_g);
    kv[c] = std::round(fn.alpha_h[c] / fn.spacing_h);
    if (std::abs(ku[c] - fn.alpha_g[c] / fn.spacing_g) > 1e-6 ||
        std::abs(kv[c] - fn.alpha_h[c] / fn.spacing_h) > 1e-6) {
      std::ostringstream m;
      m << "the jump constant of cut chain " << c << " is not an integer multiple of the spacing ("
        << fn.alpha_g[c] / fn.spacing_g << ", " << fn.alpha_h[c] / fn.spacing_h
        << " spacings): round it first";
      out->error = m.str();
      return false;
    }
  }
  if (fn.cut != nullptr) {
    double change_u = 0, change_v = 0;
    if (!ProjectOntoJumps(*fn.cut, ku, fn.sign_g, &u, &change_u, &out->error) ||
        !ProjectOntoJumps(*fn.cut, kv, fn.sign_h, &v, &change_v, &out->error)) {
      return false;
    }
    out->max_jump_correction = std::max(change_u, change_v);
    if (out->max_jump_correction > options.jump_tolerance) {
      std::ostringstream m;
      m << "the values violate the jump conditions by up to " << out->max_jump_correction
        << " spacings (tolerance " << options.jump_tolerance << ")";
      out->error = m.str();
      return false;
    }
  }
  for (size_t i = 0; i < num_values; ++i) {
    if (std::abs(u[i] - std::round(u[i])) < options.snap_tolerance) u[i] = std::round(u[i]);
    if (std::abs(v[i] - std::round(v[i])) < options.snap_tolerance) v[i] = std::round(v[i]);
  }
  return true;
}

// The crossings of one edge whose end values are (ua, va) at the source and
// (ub, vb) at the target, ordered by the edge parameter; a u- and a
// v-crossing closer than kSameCrossing are one point.
std::vector<EdgeCrossing> CrossingsOnEdge(double ua, double ub, double va, double vb) {
  std::vector<EdgeCrossing> list;
  for (double i = std::floor(std::min(ua, ub)) + 1; i < std::max(ua, ub); i += 1.0) {
    EdgeCrossing x;
    x.t = (i - ua) / (ub - ua);
    x.u = i;
    x.on_u = true;
    x.v = va + x.t * (vb - va);
    x.on_v = IsInteger(x.v);  // e.g. the whole edge lies on a v-level
    list.push_back(x);
  }
  for (double j = std::floor(std::min(va, vb)) + 1; j < std::max(va, vb); j += 1.0) {
    EdgeCrossing x;
    x.t = (j - va) / (vb - va);
    x.v = j;
    x.on_v = true;
    x.u = ua + x.t * (ub - ua);
    x.on_u = IsInteger(x.u);
    list.push_back(x);
  }
  std::sort(list.begin(), list.end(),
            [](const EdgeCrossing& a, const EdgeCrossing& b) { return a.t < b.t; });
  std::vector<EdgeCrossing> merged;
  for (const EdgeCrossing& x : list) {
    if (!merged.empty() && x.t - merged.back().t < kSameCrossing) {
      EdgeCrossing& m = merged.back();
      if (x.on_u) m.u = x.u, m.on_u = true;
      if (x.on_v) m.v = x.v, m.on_v = true;
      continue;
    }
    merged.push_back(x);
  }
  return merged;
}

// 2. Crossings on edges, from the canonical halfedge's face; and the
// transitions of cut edges: the left face of each cut edge.
EdgeCrossings FindEdgeCrossings(const Input& in, const UnitValues& values) {
  const Mesh& mesh = in.mesh;
  EdgeCrossings out;
  out.left_face.resize(mesh.number_of_edges());
  if (in.fn.cut != nullptr) {
    for (const CutChain& c : in.fn.cut->chains)
      for (HalfedgeIndex h : c.halfedges) out.left_face[mesh.edge(h).idx()] = mesh.face(h);
  }
  out.canonical.resize(mesh.number_of_edges());
  out.on_edge.resize(mesh.number_of_edges());
  for (EdgeIndex e : mesh.edges()) {
    const HalfedgeIndex hc = mesh.is_border(mesh.halfedge(e, 0)) ? mesh.halfedge(e, 1) : mesh.halfedge(e, 0);
    out.canonical[e.idx()] = hc;
    const int wa = in.Wedge(mesh.prev(hc)), wb = in.Wedge(hc);
    out.on_edge[e.idx()] = CrossingsOnEdge(values.u[wa], values.u[wb], values.v[wa], values.v[wb]);
  }
  return out;
}

// Values (cu, cv) of a crossing of edge e in the coordinates of face f.
void CrossingInFace(const Input& in, const UnitValues& values, const EdgeCrossings& crossings,
                    EdgeIndex e, FaceIndex f, double cu, double cv, double* u, double* v) {
  const CutGraph* cut = in.fn.cut;
  *u = cu;
  *v = cv;
  if (cut == nullptr || !cut->is_cut_edge[e.idx()] || in.mesh.face(crossings.canonical[e.idx()]) == f) return;
  const int c = cut->edge_chain[e.idx()];
  const double su = in.fn.sign_g[c], sv = in.fn.sign_h[c];
  if (crossings.left_face[e.idx()] == f) {  // canonical is the right side: u_L = k + s u_R
    *u = values.ku[c] + su * cu;
    *v = values.kv[c] + sv * cv;
  } else {  // canonical is the left side: u_R = s (u_L − k)
    *u = su * (cu - values.ku[c]);
    *v = sv * (cv - values.kv[c]);
  }
}

// Triangle f (halfedges hs) as the polygon of its corners and edge crossings,
// in f's coordinates.
std::vector<PV> TrianglePolygon(const Input& in, const UnitValues& values,
                                const EdgeCrossings& crossings, FaceIndex f,
                                const std::array<HalfedgeIndex, 3>& hs) {
  const Mesh& mesh = in.mesh;
  std::vector<PV> poly;
  for (int k = 0; k < 3; ++k) {
    const HalfedgeIndex hk = hs[k];
    const VertexIndex x = mesh.source(hk);
    const int w = in.Wedge(mesh.prev(hk));
    PV corner;
    corner.key = {kVertex, static_cast<int>(x.idx()), 0, 0};
    corner.pos = Pos(mesh, x);
    corner.u = values.u[w];
    corner.v = values.v[w];
    corner.on_u = IsInteger(corner.u);
    corner.on_v = IsInteger(corner.v);
    corner.mask = (1 << k) | (1 << ((k + 2) % 3));
    poly.push_back(corner);
    const EdgeIndex e = mesh.edge(hk);
    const HalfedgeIndex hc = crossings.canonical[e.idx()];
    const std::vector<EdgeCrossing>& list = crossings.on_edge[e.idx()];
    const bool forward = hc == hk;
    const V3 a = Pos(mesh, mesh.source(hc)), b = Pos(mesh, mesh.target(hc));
    for (size_t m = 0; m < list.size(); ++m) {
      const size_t idx = forward ? m : list.size() - 1 - m;
      const EdgeCrossing& c = list[idx];
      PV p;
      p.key = {kEdgePoint, static_cast<int>(e.idx()), static_cast<int>(idx), 0};
      p.pos = a + c.t * (b - a);
      CrossingInFace(in, values, crossings, e, f, c.u, c.v, &p.u, &p.v);
      p.on_u = c.on_u;
      p.on_v = c.on_v;
      p.mask = 1 << k;
      poly.push_back(p);
    }
  }
  return poly;
}

// Splits the polygon `poly` of triangle `face` by the lines u = i, then v = j.
std::vector<std::vector<PV>> SliceByLevels(const std::vector<PV>& poly, int face, int* anomalies) {
  std::map<CutKey, PV> cache;
  const Splitter split{face, &cache, anomalies};
  std::vector<std::vector<PV>> pieces = {poly};
  for (int c = 0; c < 2; ++c) {
    double lo = INFINITY, hi = -INFINITY;
    for (const PV& p : poly) {
      lo = std::min(lo, c == 0 ? p.u : p.v);
      hi = std::max(hi, c == 0 ? p.u : p.v);
    }
    for (double level = std::ceil(lo); level <= hi; level += 1.0) {
      std::vector<std::vector<PV>> next;
      for (const auto& q : pieces)
        for (auto& r : split(q, c, level)) next.push_back(std::move(r));
      pieces.swap(next);
    }
  }
  return pieces;
}

// 3. Slicing, triangle by triangle.
Pieces SliceTriangles(const Input& in, const UnitValues& values, const EdgeCrossings& crossings,
                      int* anomalies) {
  const Mesh& mesh = in.mesh;
  Pieces out;
  out.face_halfedges.resize(mesh.number_of_faces());
  for (FaceIndex f : mesh.faces()) {
    const HalfedgeIndex h0 = mesh.halfedge(f);
    const std::array<HalfedgeIndex, 3> hs = {h0, mesh.next(h0), mesh.next(mesh.next(h0))};
    out.face_halfedges[f.idx()] = hs;
    const std::vector<PV> poly = TrianglePolygon(in, values, crossings, f, hs);
    for (auto& q : SliceByLevels(poly, static_cast<int>(f.idx()), anomalies)) {
      out.polys.push_back(std::move(q));
      out.face.push_back(f);
    }
  }
  return out;
}

// Piece sides on a triangle edge that does not lie on a level, by the keys of
// their end points (each such side appears once from each side of the edge);
// marks the sides on a mesh boundary edge.
std::map<std::pair<CutKey, CutKey>, std::vector<std::pair<int, int>>> SidesAcrossEdges(
    const Mesh& mesh, const Pieces& pieces, Gluing* gluing) {
  std::map<std::pair<CutKey, CutKey>, std::vector<std::pair<int, int>>> shared;
  auto iso = [](const PV& a, const PV& b) {
    return (a.on_u && b.on_u && a.u == b.u) || (a.on_v && b.on_v && a.v == b.v);
  };
  for (size_t p = 0; p < pieces.polys.size(); ++p) {
    const auto& q = pieces.polys[p];
    gluing->twin[p].assign(q.size(), {-1, -1});
    gluing->on_boundary[p].assign(q.size(), 0);
    for (size_t i = 0; i < q.size(); ++i) {
      const PV& a = q[i];
      const PV& b = q[(i + 1) % q.size()];
      const int common = a.mask & b.mask;
      if (common == 0) continue;
      const int k = common & 1 ? 0 : (common & 2 ? 1 : 2);
      const EdgeIndex e = mesh.edge(pieces.face_halfedges[pieces.face[p].idx()][k]);
      if (mesh.is_border(e)) {
        gluing->on_boundary[p][i] = 1;
        continue;
      }
      if (iso(a, b)) continue;
      shared[{std::min(a.key, b.key), std::max(a.key, b.key)}].push_back(
          {static_cast<int>(p), static_cast<int>(i)});
    }
  }
  return shared;
}

// 4. Glue pieces across triangle edges that do not lie on a level. Each
// region (a connected group of glued pieces) gets a key that depends only on
// the order of the gluings: gluing piece a to piece b gives the joined region
// the key of b's region; faces are emitted in key order.
Gluing GluePieces(const Mesh& mesh, const Pieces& pieces, int* anomalies) {
  const size_t np = pieces.polys.size();
  Gluing out;
  out.twin.resize(np);
  out.on_boundary.resize(np);
  const auto shared = SidesAcrossEdges(mesh, pieces, &out);
  UnionFind regions;
  const std::vector<UnionFind::handle> piece = MakeSets(np, &regions);
  std::vector<size_t> key(np);  // by the piece at the root of a set
  for (size_t p = 0; p < np; ++p) key[p] = p;
  for (const auto& [pair, list] : shared) {
    if (list.size() != 2) {
      ++*anomalies;
      continue;
    }
    out.twin[list[0].first][list[0].second] = list[1];
    out.twin[list[1].first][list[1].second] = list[0];
    const size_t joined_key = key[*regions.find(piece[list[1].first])];
    regions.unify_sets(piece[list[0].first], piece[list[1].first]);
    key[*regions.find(piece[list[0].first])] = joined_key;
  }
  out.region.resize(np);
  for (size_t p = 0; p < np; ++p) out.region[p] = key[*regions.find(piece[p])];
  return out;
}

// Boundary vertices of the mesh, and among them the corners: where the
// boundary turns by more than corner_angle_deg.
void MarkBoundaryCorners(const Mesh& mesh, double corner_angle_deg, OutputVertices* out) {
  out->boundary_vertex.assign(mesh.number_of_vertices(), false);
  out->corner.assign(mesh.number_of_vertices(), false);
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_isolated(v) || !mesh.is_border(v, true)) continue;
    out->boundary_vertex[v.idx()] = true;
    for (HalfedgeIndex h : mesh.halfedges_around_target(mesh.halfedge(v))) {
      if (!mesh.is_border(h)) continue;
      const V3 a = Pos(mesh, v) - Pos(mesh, mesh.source(h));
      const V3 b = Pos(mesh, mesh.target(mesh.next(h))) - Pos(mesh, v);
      const double turn = std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI;
      if (turn > corner_angle_deg) out->corner[v.idx()] = true;
    }
  }
}

// Level-set pieces at mesh vertices: distinct neighbours along u- and
// v-levels, and whether one of them leaves the boundary.
void FindLevelsAtVertices(const Pieces& pieces, const Gluing& gluing, OutputVertices* out) {
  for (size_t p = 0; p < pieces.polys.size(); ++p) {
    const auto& q = pieces.polys[p];
    for (size_t i = 0; i < q.size(); ++i) {
      const PV& a = q[i];
      const PV& b = q[(i + 1) % q.size()];
      const bool on_u = a.on_u && b.on_u && a.u == b.u, on_v = a.on_v && b.on_v && a.v == b.v;
      if (!on_u && !on_v) continue;
      for (const auto& [x, y] : {std::make_pair(a, b), std::make_pair(b, a)}) {
        if (x.key[0] != kVertex) continue;
        if (on_u) out->iso_u[x.key[1]].insert(y.key);
        if (on_v) out->iso_v[x.key[1]].insert(y.key);
        if (!gluing.on_boundary[p][i]) out->leaves_boundary.insert(x.key[1]);
      }
    }
  }
}

// Number of distinct neighbours of mesh vertex v along one family of levels.
size_t LevelDegree(const std::map<int, std::set<CutKey>>& iso, int v) {
  const auto it = iso.find(v);
  return it == iso.end() ? 0 : it->second.size();
}

// Whether x is an output vertex (step 4 of the header).
bool IsOutput(const Mesh& mesh, const OutputVertices& ov, const PV& x) {
  if (x.key[0] == kFacePoint) return x.on_u && x.on_v;
  if (x.key[0] == kEdgePoint) {
    return (x.on_u && x.on_v) || (mesh.is_border(EdgeIndex(x.key[1])) && (x.on_u || x.on_v));
  }
  const int v = x.key[1];
  if (x.on_u && x.on_v) return true;
  if (ov.boundary_vertex[v]) return ov.corner[v] || ((x.on_u || x.on_v) && ov.leaves_boundary.count(v) > 0);
  auto odd = [](size_t d) { return d != 0 && d != 2; };
  return (x.on_u && odd(LevelDegree(ov.iso_u, v))) || (x.on_v && odd(LevelDegree(ov.iso_v, v)));
}

bool OnMeshBoundary(const Mesh& mesh, const OutputVertices& ov, const PV& x) {
  if (x.key[0] == kVertex) return static_cast<bool>(ov.boundary_vertex[x.key[1]]);
  if (x.key[0] == kEdgePoint) return mesh.is_border(EdgeIndex(x.key[1]));
  return false;
}

// The index of output vertex x in the soup, added on first use.
int PointIndex(const Mesh& mesh, const OutputVertices& ov, const PV& x, std::map<CutKey, int>* index,
               Soup* soup) {
  auto it = index->find(x.key);
  if (it != index->end()) return it->second;
  const int id = static_cast<int>(soup->points.size());
  (*index)[x.key] = id;
  soup->points.push_back(x.pos);
  soup->on_boundary.push_back(OnMeshBoundary(mesh, ov, x));
  soup->is_corner.push_back(x.key[0] == kVertex && ov.corner[x.key[1]]);
  return id;
}

// The boundary loop of a region that starts at the unglued side i0 of piece
// p0, as its output vertices; marks the sides it passes in `visited`.
std::vector<int> WalkLoop(const Mesh& mesh, const Pieces& pieces, const Gluing& gluing,
                          const OutputVertices& ov, size_t p0, size_t i0,
                          std::vector<std::vector<char>>* visited, std::map<CutKey, int>* index,
                          Soup* soup, int* anomalies) {
  const size_t guard = 8 * pieces.polys.size() + 64;
  std::vector<int> loop;
  size_t p = p0, i = i0;
  for (size_t step = 0; step < guard; ++step) {
    (*visited)[p][i] = 1;
    const PV& start = pieces.polys[p][i];
    if (IsOutput(mesh, ov, start)) loop.push_back(PointIndex(mesh, ov, start, index, soup));
    // Next boundary edge: turn around the end vertex through glued pieces.
    size_t j = (i + 1) % pieces.polys[p].size();
    size_t turns = 0;
    while (gluing.twin[p][j].first >= 0 && turns++ < guard) {
      const auto [q, t] = gluing.twin[p][j];
      p = q;
      j = (t + 1) % pieces.polys[p].size();
    }
    i = j;
    if (p == p0 && i == i0) break;
    if ((*visited)[p][i]) {
      ++*anomalies;
      break;
    }
  }
  return loop;
}

// Walk the boundary loops of every region.
RegionLoops WalkRegionBoundaries(const Mesh& mesh, const Pieces& pieces, const Gluing& gluing,
                                 const OutputVertices& ov, Soup* soup, int* anomalies) {
  const size_t np = pieces.polys.size();
  std::map<CutKey, int> index;
  std::vector<std::vector<char>> visited(np);
  for (size_t p = 0; p < np; ++p) visited[p].assign(pieces.polys[p].size(), 0);
  RegionLoops region_loops;
  for (size_t p0 = 0; p0 < np; ++p0) {
    for (size_t i0 = 0; i0 < pieces.polys[p0].size(); ++i0) {
      if (gluing.twin[p0][i0].first >= 0 || visited[p0][i0]) continue;
      region_loops[gluing.region[p0]].push_back(
          WalkLoop(mesh, pieces, gluing, ov, p0, i0, &visited, &index, soup, anomalies));
    }
  }
  return region_loops;
}

// Faces: one loop with ≥ 3 vertices per region.
void FacesFromLoops(RegionLoops* region_loops, std::vector<std::vector<int>>* faces, Extraction* out) {
  for (auto& [region, loops] : *region_loops) {
    std::vector<std::vector<int>> good;
    for (auto& loop : loops) {
      CleanCycle(&loop);
      if (loop.size() >= 3) good.push_back(loop);
    }
    if (good.size() == 1) {
      SimpleCycles(good[0], faces, &out->dropped_small_faces);
    } else if (good.empty()) {
      ++out->dropped_small_faces;
    } else {
      ++out->dropped_non_disk_regions;
    }
  }
}

// The median edge length of the soup's faces; none without faces.
std::optional<double> MedianEdgeLength(const Soup& soup) {
  std::vector<double> lengths;
  for (const auto& f : soup.faces)
    for (size_t i = 0; i < f.size(); ++i)
      lengths.push_back((soup.points[f[i]] - soup.points[f[(i + 1) % f.size()]]).norm());
  if (lengths.empty()) return std::nullopt;
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return lengths[lengths.size() / 2];
}

// The groups of points to merge: joined by an edge shorter than `threshold`,
// or an interior point and the boundary point it snaps to. Each interior
// vertex joined by an edge shorter than the snap threshold to a boundary
// vertex goes to the nearest such boundary vertex (counted in
// out->snapped_vertices). Groups are ordered by their smallest point, members
// ascending.
std::vector<std::vector<int>> MergeGroups(const Soup& soup, double threshold, double snap_threshold,
                                          Extraction* out) {
  const size_t n = soup.points.size();
  UnionFind uf;
  const std::vector<UnionFind::handle> point = MakeSets(n, &uf);
  std::vector<int> snap_to(n, -1);
  std::vector<double> snap_length(n, snap_threshold);
  for (const auto& f : soup.faces)
    for (size_t i = 0; i < f.size(); ++i) {
      const int a = f[i], b = f[(i + 1) % f.size()];
      const double length = (soup.points[a] - soup.points[b]).norm();
      if (length < threshold) uf.unify_sets(point[a], point[b]);
      if (soup.on_boundary[a] == soup.on_boundary[b]) continue;
      const int inner = soup.on_boundary[a] ? b : a, outer = soup.on_boundary[a] ? a : b;
      if (length < snap_length[inner]) {
        snap_length[inner] = length;
        snap_to[inner] = outer;
      }
    }
  for (size_t i = 0; i < n; ++i) {
    if (snap_to[i] < 0 || uf.same_set(point[i], point[snap_to[i]])) continue;
    uf.unify_sets(point[i], point[snap_to[i]]);
    ++out->snapped_vertices;
  }
  std::vector<std::vector<int>> groups;
  std::vector<int> group(n, -1);  // by the point at the root of a set
  for (size_t i = 0; i < n; ++i) {
    int& g = group[*uf.find(point[i])];
    if (g < 0) {
      g = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    groups[g].push_back(static_cast<int>(i));
  }
  return groups;
}

// 6. Merge vertices joined by short edges; snap interior vertices near the
// boundary onto it. A merged group sits at the mean of its corner points, else
// of its boundary points, else of all (a group changes only its own points,
// so the order of the groups does not matter); faces are remapped and cleaned.
void MergeShortEdges(double median, const ExtractOptions& options, Soup* soup, Extraction* out) {
  const double threshold = options.merge_fraction * median;
  const std::vector<std::vector<int>> groups =
      MergeGroups(*soup, threshold, options.boundary_snap_fraction * median, out);
  std::vector<int> rep(soup->points.size());
  for (const std::vector<int>& members : groups) {
    V3 sum = V3::Zero();
    int n = 0;
    bool boundary = false, is_corner = false;
    for (int m : members) boundary = boundary || soup->on_boundary[m];
    for (int m : members) is_corner = is_corner || soup->is_corner[m];
    for (int m : members) {
      if (boundary && !soup->on_boundary[m]) continue;
      if (is_corner && !soup->is_corner[m]) continue;
      sum += soup->points[m];
      ++n;
    }
    const int r = members[0];
    soup->points[r] = sum / n;
    soup->on_boundary[r] = boundary;
    soup->is_corner[r] = is_corner;
    for (int m : members) rep[m] = r;
    out->merged_vertices += static_cast<int>(members.size()) - 1;
  }
  out->merged_vertices -= out->snapped_vertices;
  std::vector<std::vector<int>> kept;
  for (auto& f : soup->faces) {
    for (int& x : f) x = rep[x];
    SimpleCycles(f, &kept, &out->dropped_small_faces);
  }
  soup->faces.swap(kept);
}

// A thin triangle along the boundary (a level meeting the boundary at a
// small angle): its interior vertex, closer to the boundary chord than the
// snap threshold `limit`, goes onto the chord and the triangle disappears.
void SnapThinBoundaryTriangles(double limit, Soup* soup, Extraction* out) {
  std::vector<std::vector<int>> kept;
  for (auto& f : soup->faces) {
    if (f.size() == 3) {
      int inner = -1, count = 0;
      for (int k = 0; k < 3; ++k) {
        if (!soup->on_boundary[f[k]]) inner = k, ++count;
      }
      if (count == 1) {
        const V3& p = soup->points[f[inner]];
        const V3& a = soup->points[f[(inner + 1) % 3]];
        const V3& b = soup->points[f[(inner + 2) % 3]];
        const double t = std::clamp((p - a).dot(b - a) / std::max(1e-300, (b - a).squaredNorm()), 0.0, 1.0);
        const V3 foot = a + t * (b - a);
        if ((p - foot).norm() < limit) {
          soup->points[f[inner]] = foot;
          soup->on_boundary[f[inner]] = true;
          ++out->snapped_vertices;
          ++out->dropped_small_faces;
          continue;
        }
      }
    }
    kept.push_back(f);
  }
  soup->faces.swap(kept);
}

// A boundary edge (used by one face, both ends on the boundary) shorter
// than `limit` (half the snap threshold) — a level that ends just beside a
// corner or beside another level's end — is collapsed: its face loses a
// sliver side (a corner of more than 10° bent inward after the PQ step
// otherwise). A corner of the boundary keeps its position; else the midpoint.
void CollapseShortBoundaryEdges(double limit, Soup* soup, Extraction* out) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& f : soup->faces)
    for (size_t i = 0; i < f.size(); ++i) {
      const int a = f[i], b = f[(i + 1) % f.size()];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<V3>& points = soup->points;
  std::vector<int> rep(points.size());
  for (size_t i = 0; i < points.size(); ++i) rep[i] = static_cast<int>(i);
  std::vector<bool> touched(points.size(), false);
  for (const auto& [edge, count] : uses) {
    const auto [a, b] = edge;
    if (count != 1 || !soup->on_boundary[a] || !soup->on_boundary[b]) continue;
    if (touched[a] || touched[b] || (soup->is_corner[a] && soup->is_corner[b])) continue;
    if ((points[a] - points[b]).norm() >= limit) continue;
    const int keep = soup->is_corner[b] ? b : a, drop = keep == a ? b : a;
    if (!soup->is_corner[keep]) points[keep] = 0.5 * (points[a] + points[b]);
    rep[drop] = keep;
    touched[a] = touched[b] = true;
    ++out->collapsed_boundary_edges;
  }
  std::vector<std::vector<int>> kept;
  for (auto& f : soup->faces) {
    for (int& x : f) x = rep[x];
    SimpleCycles(f, &kept, &out->dropped_small_faces);
  }
  soup->faces.swap(kept);
}

// A boundary vertex that only one face uses and that is not a corner of
// the boundary (a level that ended there before a snap) is dissolved from
// a face with more than four vertices.
void DissolveSingleFaceBoundaryVertices(Soup* soup, Extraction* out) {
  std::vector<int> uses(soup->points.size(), 0);
  for (const auto& f : soup->faces)
    for (int x : f) ++uses[x];
  std::vector<std::vector<int>> kept;
  for (auto& f : soup->faces) {
    std::vector<int> g;
    size_t size = f.size();
    for (int x : f) {
      if (size > 4 && uses[x] == 1 && soup->on_boundary[x] && !soup->is_corner[x]) {
        ++out->dissolved_vertices;
        --size;
        continue;
      }
      g.push_back(x);
    }
    kept.push_back(g);
  }
  soup->faces.swap(kept);
}

// The clean-ups of the face shapes (fields/layout_cleanup.h), each when its
// option is on.
void CleanUpFaceShapes(const ExtractOptions& options, Soup* soup, Extraction* out) {
  // An interior vertex on two faces only (valence 2: a +1/2 singularity on a
  // level of both functions, or two level crossings merged beside one) is
  // removed by merging its two faces: F1 = (v, b, X…, a), F2 = (v, a, Y…, b)
  // become (b, X…, a, Y…) — two quads a quad whose corners a and b have
  // valence 3, the configuration of a +1/2 singularity with both levels odd.
  // A valence-2 vertex gives two corners of about 180° that the PQ step
  // cannot keep apart (a face folded onto its neighbour).
  if (options.merge_valence_two) {
    MergeValenceTwo(&soup->faces, &out->merged_valence_two, &out->dropped_small_faces);
  }
  // A triangle whose three vertices lie nearly on a line (a corner above
  // cap_angle_deg: a level line passing a crossing at a fraction of an edge,
  // typically between two singularities closer than the spacing) is merged
  // into the face across its longest side: that face gets the middle vertex
  // as a corner of about 180°, instead of a sliver the PQ step turns over.
  if (options.cap_angle_deg > 0) {
    MergeCaps(soup->points, options.cap_angle_deg, &soup->faces, &out->merged_caps,
              &out->dropped_small_faces);
  }
  // A face bent inward at an interior vertex (a corner above 180° +
  // reflex_margin_deg in the plane of its Newell normal: a polygon wrapped
  // around a singularity near another or near the boundary, or the merge of
  // a valence-2 vertex) is split along a diagonal from that corner into two
  // faces, so that panels are convex there: the PQ step keeps corners from
  // folding further and cannot make such a face planar otherwise.
  // A corner whose two sides leave within slit_angle_deg of each other (two
  // level lines of one family running side by side from a singular vertex)
  // is a near-slit: the nearer vertex is moved onto the longer side, which
  // the face across then shares (a T-junction resolved), and the corner
  // leaves the face. Otherwise the face is a hairline the reflex split or
  // the PQ step folds onto its neighbour.
  if (options.slit_angle_deg > 0) {
    RemoveNearSlits(soup->points, options.slit_angle_deg, &soup->faces, &out->removed_slits,
                    &out->dropped_small_faces);
  }
  if (options.reflex_margin_deg >= 0) {
    SplitReflexCorners(soup->points, soup->on_boundary, options.reflex_margin_deg, &soup->faces,
                       &out->split_reflex_corners);
  }
}

// Step 6 of the header: the clean-ups, in order.
void CleanUp(const ExtractOptions& options, Soup* soup, Extraction* out) {
  const std::optional<double> median = MedianEdgeLength(*soup);
  if (median) MergeShortEdges(*median, options, soup, out);
  if (median && options.boundary_snap_fraction > 0) {
    SnapThinBoundaryTriangles(options.boundary_snap_fraction * *median, soup, out);
    CollapseShortBoundaryEdges(0.5 * options.boundary_snap_fraction * *median, soup, out);
  }
  DissolveSingleFaceBoundaryVertices(soup, out);
  CleanUpFaceShapes(options, soup, out);
}

// Compact the points and build the mesh.
void BuildMesh(Soup* soup, Extraction* out) {
  std::vector<int> used(soup->points.size(), -1);
  std::vector<Point> soup_points;
  for (auto& f : soup->faces)
    for (int& x : f) {
      if (used[x] < 0) {
        used[x] = static_cast<int>(soup_points.size());
        const V3& p = soup->points[x];
        soup_points.push_back(Point(p.x(), p.y(), p.z()));
      }
      x = used[x];
    }
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& f : soup->faces) polygons.emplace_back(f.begin(), f.end());
  const size_t points_before = soup_points.size();
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    // Splits non-manifold vertices; a consistently oriented soup keeps its
    // orientation.
    PMP::orient_polygon_soup(soup_points, polygons);
    out->duplicated_vertices = static_cast<int>(soup_points.size() - points_before);
  }
  PMP::polygon_soup_to_polygon_mesh(soup_points, polygons, out->mesh);
}

// Statistics.
void CountDegrees(Extraction* out) {
  const Mesh& mesh = out->mesh;
  for (FaceIndex f : mesh.faces()) {
    const int d = static_cast<int>(mesh.degree(f));
    ++out->face_degrees[d];
    if (d == 4) ++out->quads;
    else if (d == 3) ++out->triangles;
    else if (d == 5) ++out->pentagons;
    else ++out->other_faces;
    bool touches_boundary = false;
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f)))
      touches_boundary = touches_boundary || mesh.is_border(v, true);
    if (d != 4 && !touches_boundary) out->irregular_interior_faces.push_back(f);
  }
  for (VertexIndex v : mesh.vertices()) {
    const int d = static_cast<int>(mesh.degree(v));
    ++out->valence[d];
    if (!mesh.is_border(v, true)) {
      ++out->interior_valence[d];
      if (d != 4) out->irregular_interior_vertices.push_back(v);
    }
  }
}

}  // namespace

Extraction ExtractQuadMesh(const Mesh& mesh, const LevelSetFunctions& fn,
                           const ExtractOptions& options) {
  CheckInput(mesh, fn);
  Extraction out;
  const Input in{mesh, fn};
  UnitValues values;
  if (!ToSpacingUnits(fn, options, &values, &out)) return out;
  const EdgeCrossings crossings = FindEdgeCrossings(in, values);
  const Pieces pieces = SliceTriangles(in, values, crossings, &out.anomalies);
  const Gluing gluing = GluePieces(mesh, pieces, &out.anomalies);
  OutputVertices output_vertices;
  MarkBoundaryCorners(mesh, options.corner_angle_deg, &output_vertices);
  FindLevelsAtVertices(pieces, gluing, &output_vertices);
  Soup soup;
  RegionLoops loops = WalkRegionBoundaries(mesh, pieces, gluing, output_vertices, &soup, &out.anomalies);
  FacesFromLoops(&loops, &soup.faces, &out);
  CleanUp(options, &soup, &out);
  BuildMesh(&soup, &out);
  CountDegrees(&out);
  if (out.mesh.number_of_faces() == 0) {  // e.g. a closed surface of four triangles
    out.error = "the level sets cut out no face (the surface has " +
                std::to_string(mesh.number_of_faces()) + " triangles; more are needed)";
    return out;
  }
  out.ok = true;
  return out;
}

Extraction LayoutFromSoup(std::vector<Eigen::Vector3d> points, std::vector<bool> on_boundary,
                          std::vector<bool> is_corner, std::vector<std::vector<int>> faces,
                          const ExtractOptions& options) {
  CHECK_EQ(points.size(), on_boundary.size());
  CHECK_EQ(points.size(), is_corner.size());
  for (const auto& f : faces)
    for (int v : f) CHECK(v >= 0 && v < int(points.size()));
  Extraction out;
  Soup soup{std::move(points), std::move(on_boundary), std::move(is_corner), std::move(faces)};
  CleanUp(options, &soup, &out);
  BuildMesh(&soup, &out);
  CountDegrees(&out);
  if (out.mesh.number_of_faces() == 0) {
    out.error = "no face was left";
    return out;
  }
  out.ok = true;
  return out;
}

}  // namespace archgeo
