// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fields/pair_cancellation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <string>

#include <glog/logging.h>

#include "fields/singularities.h"
#include "fields/spin2_extension.h"

namespace archgeo {
namespace {

using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

constexpr double kPairCircleMargin = 1e-3;  // ‖z_N − e1‖ ≤ 1 − margin in U
// The tries: U's radius as these multiples of r = region × distance.
constexpr double kPairTries[] = {1.0 / 3, 2.0 / 3, 1, 2};

V3 PairVertexPoint(const Mesh& mesh, int v) {
  const Point& p = mesh.point(VertexIndex(v));
  return V3(p.x(), p.y(), p.z());
}

double PairSegmentDistance(const V3& x, const V3& a, const V3& b) {
  const V3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((x - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (x - (a + t * ab)).norm();
}

// The faces of U for radius r (see the header), as a per-face flag.
// Beyond the two stars, faces with K ≤ 0 (z_M outside the auxiliary circle,
// or at infinity) are left out: no singularity can be there [Zadravec 2010,
// Prop. 4], and z_N = z_M + d would leave the circle.
std::vector<bool> PairRegion(const Mesh& mesh, const FieldGeometry& geo, int p, int q, double r) {
  const FaceFrames& frames = geo.frames;
  std::vector<bool> in(mesh.number_of_faces(), false);
  std::queue<FaceIndex> todo;
  for (int v : {p, q}) {
    for (FaceIndex f : CGAL::faces_around_target(mesh.halfedge(VertexIndex(v)), mesh)) {
      if (f == Mesh::null_face() || in[f.idx()]) continue;
      in[f.idx()] = true;
      todo.push(f);
    }
  }
  const V3 a = PairVertexPoint(mesh, p), b = PairVertexPoint(mesh, q);
  while (!todo.empty()) {
    const FaceIndex f = todo.front();
    todo.pop();
    for (HalfedgeIndex h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const FaceIndex g = mesh.face(mesh.opposite(h));
      if (g == Mesh::null_face() || in[g.idx()]) continue;
      if (PairSegmentDistance(frames.centroid[g.idx()], a, b) > r) continue;
      const FaceCurvature& k = geo.curvature[g.idx()];
      if (!k.z_m_finite || (k.z_m - V2(1, 0)).norm() >= 1) continue;  // K ≤ 0: no singularity
      in[g.idx()] = true;
      todo.push(g);
    }
  }
  return in;
}

// d = z_N − z_M on U: the connection-harmonic extension of d from the faces
// next to U. Returns false when U has no such face or the solve fails.
bool PairHarmonicDifference(const Mesh& mesh, const FieldGeometry& g, const std::vector<bool>& in,
                        const std::vector<V2>& z_n, std::vector<V2>* d_out) {
  const Spin2Extension extension(g.transports, in);
  if (!extension.anchored()) return false;
  std::vector<V2> d(mesh.number_of_faces());
  for (size_t f = 0; f < d.size(); ++f) d[f] = z_n[f] - g.curvature[f].z_m;
  if (!extension.Extend(&d)) return false;
  d_out->assign(d.size(), V2::Zero());
  for (size_t f = 0; f < d.size(); ++f) {
    if (in[f]) (*d_out)[f] = d[f];
  }
  return true;
}

// Whether `after` has exactly the singular vertices of `before` but `gone`.
bool PairOnlyRemoved(const std::vector<double>& before, const std::vector<double>& after,
                 const std::vector<int>& gone) {
  for (size_t v = 0; v < before.size(); ++v) {
    const bool removed = std::find(gone.begin(), gone.end(), int(v)) != gone.end();
    if (after[v] != (removed ? 0.0 : before[v])) return false;
  }
  return true;
}

// One try of the surgery on U; true (and z_n, index changed) when accepted.
// The singular vertices on U's faces must be the pair's, or the members of
// other pending pairs (`partner`: vertex → its partner, −1 if none) with
// their partners: a cluster of close pairs is cancelled together (`gone`).
// Returns "" when accepted, else why not.
std::string PairCancelInRegion(const Mesh& mesh, const FieldGeometry& g, const std::vector<bool>& in,
                           const std::vector<int>& partner, std::vector<V2>* z_n,
                           std::vector<double>* index, std::vector<int>* gone) {
  std::vector<int> singular;
  for (FaceIndex f : mesh.faces()) {
    if (!in[f.idx()]) continue;
    if (!g.curvature[f.idx()].z_m_finite) return "mean curvature 0 at the pair (z_M at infinity)";
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      if ((*index)[v.idx()] == 0) continue;
      if (std::find(singular.begin(), singular.end(), int(v.idx())) == singular.end()) {
        singular.push_back(int(v.idx()));
      }
    }
  }
  for (int v : singular) {
    const int w = partner[size_t(v)];
    if (w < 0 || std::find(singular.begin(), singular.end(), w) == singular.end()) {
      return "another singularity in the region without its partner";
    }
  }
  std::vector<V2> d;
  if (!PairHarmonicDifference(mesh, g, in, *z_n, &d)) return "the harmonic extension has no solution";
  std::vector<V2> trial = *z_n;
  for (FaceIndex f : mesh.faces()) {
    if (!in[f.idx()]) continue;
    trial[f.idx()] = g.curvature[f.idx()].z_m + d[f.idx()];
    if ((trial[f.idx()] - V2(1, 0)).norm() > 1 - kPairCircleMargin) {
      return "z_N would leave the auxiliary circle (no transverse pair)";
    }
  }
  std::vector<double> after = FieldVertexIndices(mesh, g, trial);
  if (!PairOnlyRemoved(*index, after, singular)) return "the singularities would not just disappear";
  *z_n = std::move(trial);
  *index = std::move(after);
  *gone = std::move(singular);
  return "";
}

// The boundary vertex nearest to vertex v (straight distance), −1 if none.
int PairNearestBoundaryVertex(const Mesh& mesh, const std::vector<bool>& boundary, int v,
                          double* distance) {
  const V3 x = PairVertexPoint(mesh, v);
  int best = -1;
  *distance = std::numeric_limits<double>::infinity();
  for (VertexIndex b : mesh.vertices()) {
    if (!boundary[b.idx()]) continue;
    const double d = (PairVertexPoint(mesh, int(b.idx())) - x).norm();
    if (d < *distance) {
      *distance = d;
      best = int(b.idx());
    }
  }
  return best;
}

// Singularities near the boundary pushed out (options.boundary_distance).
void PairPushOut(const Mesh& mesh, const FieldGeometry& geometry,
             const PairCancellationOptions& options, std::vector<double>* index,
             std::vector<bool>* changed, PairCancellation* out) {
  std::vector<bool> boundary(mesh.number_of_vertices(), false);
  for (HalfedgeIndex h : mesh.halfedges()) {
    if (mesh.is_border(h)) boundary[mesh.target(h).idx()] = true;
  }
  std::vector<int> partner(mesh.number_of_vertices(), -1);
  for (VertexIndex v : mesh.vertices()) {
    if ((*index)[v.idx()] == 0) continue;
    double distance = 0;
    const int b = PairNearestBoundaryVertex(mesh, boundary, int(v.idx()), &distance);
    if (b < 0 || distance >= options.boundary_distance) continue;
    ++out->near_boundary;
    partner[v.idx()] = int(v.idx());  // it goes alone
    for (double k : kPairTries) {
      const std::vector<bool> in =
          PairRegion(mesh, geometry, int(v.idx()), b, k * options.region * distance);
      std::vector<int> gone;
      if (!PairCancelInRegion(mesh, geometry, in, partner, &out->z_n, index, &gone).empty()) continue;
      ++out->pushed_out;
      for (size_t f = 0; f < in.size(); ++f) (*changed)[f] = (*changed)[f] || in[f];
      break;
    }
    partner[v.idx()] = -1;
  }
}

}  // namespace

std::vector<double> FieldVertexIndices(const Mesh& mesh, const FieldGeometry& geometry,
                                       const std::vector<Eigen::Vector2d>& z_n) {
  return VertexIndices(mesh, geometry.transports, geometry.edge_to_transport,
                       BisectorAngles(TcdPairs(geometry.curvature, z_n)));
}

std::vector<CancelledPair> CloseOppositePairs(const std::vector<Singularity>& s,
                                              double max_distance) {
  std::vector<CancelledPair> candidates;
  int vertices = 0;
  for (const Singularity& x : s) vertices = std::max(vertices, int(x.vertex.idx()) + 1);
  for (size_t i = 0; i < s.size(); ++i) {
    for (size_t j = 0; j < s.size(); ++j) {
      if (!(s[i].index > 0) || s[i].index + s[j].index != 0) continue;
      CancelledPair c;
      c.plus_vertex = int(s[i].vertex.idx());
      c.minus_vertex = int(s[j].vertex.idx());
      c.index = s[i].index;
      c.distance = (s[i].position - s[j].position).norm();
      if (c.distance < max_distance) candidates.push_back(c);
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const CancelledPair& a, const CancelledPair& b) {
                     return a.distance < b.distance;
                   });
  std::vector<bool> used(size_t(vertices), false);
  std::vector<CancelledPair> out;
  for (const CancelledPair& c : candidates) {
    if (used[size_t(c.plus_vertex)] || used[size_t(c.minus_vertex)]) continue;
    used[size_t(c.plus_vertex)] = used[size_t(c.minus_vertex)] = true;
    out.push_back(c);
  }
  return out;
}

PairCancellation CancelSingularityPairs(const Mesh& mesh, const FieldGeometry& geometry,
                                        const TcdField& field,
                                        const PairCancellationOptions& options) {
  PairCancellation out;
  out.z_n = field.z_n;
  if (field.smooth_fallback) return out;
  out.pairs = CloseOppositePairs(field.singularities, options.max_distance);
  out.found = int(out.pairs.size());

  std::vector<double> index = field.vertex_index;
  std::vector<int> partner(mesh.number_of_vertices(), -1);
  for (const CancelledPair& c : out.pairs) {
    partner[size_t(c.plus_vertex)] = c.minus_vertex;
    partner[size_t(c.minus_vertex)] = c.plus_vertex;
  }
  std::vector<bool> changed(mesh.number_of_faces(), false);
  for (CancelledPair& c : out.pairs) {
    if (c.cancelled) continue;  // with a cluster before
    for (double k : kPairTries) {
      if (c.cancelled) break;
      const double r = k * options.region * c.distance;
      const std::vector<bool> in =
          PairRegion(mesh, geometry, c.plus_vertex, c.minus_vertex, r);
      std::vector<int> gone;
      c.kept_because = PairCancelInRegion(mesh, geometry, in, partner, &out.z_n, &index, &gone);
      if (!c.kept_because.empty()) continue;
      int faces = 0;
      for (size_t f = 0; f < in.size(); ++f) {
        if (!in[f]) continue;
        ++faces;
        changed[f] = true;
      }
      for (CancelledPair& other : out.pairs) {
        if (std::find(gone.begin(), gone.end(), other.plus_vertex) == gone.end()) continue;
        other.cancelled = true;
        other.kept_because.clear();
        other.radius = r;
        other.faces_changed = faces;
      }
      for (int v : gone) partner[size_t(v)] = -1;
    }
  }
  for (const CancelledPair& c : out.pairs) out.cancelled += c.cancelled ? 1 : 0;
  if (options.boundary_distance > 0) PairPushOut(mesh, geometry, options, &index, &changed, &out);
  for (bool x : changed) out.faces_changed += x ? 1 : 0;
  return out;
}

}  // namespace archgeo
