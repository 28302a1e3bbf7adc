// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — boundary-aligned rows [Zadravec 2010, §5; Gebreiter 2012, §8.3.2].
#include "fields/boundary_rows.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>

#include <glog/logging.h>

namespace archgeo {
namespace boundary_rows_impl {  // named: the fields unity build has other Pos, Run, Loop

using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

V3 Pos(const Mesh& mesh, VertexIndex v) {
  const Point& p = mesh.point(v);
  return V3(p.x(), p.y(), p.z());
}

// The boundary's turn (degrees) at target(in), `in` a border halfedge: the
// rule of fields/extract.cpp MarkBoundaryCorners.
double TurnDeg(const Mesh& mesh, HalfedgeIndex in) {
  const VertexIndex v = mesh.target(in);
  const V3 a = Pos(mesh, v) - Pos(mesh, mesh.source(in));
  const V3 b = Pos(mesh, mesh.target(mesh.next(in))) - Pos(mesh, v);
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI;
}

// ℓ |sin∠(t, d)| of border halfedge b against the direction d of the face
// across it; −1 where d is undefined.
double Misalignment(const Mesh& mesh, const FaceFrames& frames, HalfedgeIndex b,
                    const std::vector<V2>& dir) {
  const FaceIndex f = mesh.face(mesh.opposite(b));
  const V2& d = dir[f.idx()];
  if (d.isZero() || !d.allFinite()) return -1.0;
  const V2 t = ToFrame(frames, f, Pos(mesh, mesh.target(b)) - Pos(mesh, mesh.source(b)));
  const double n = t.norm() * d.norm();
  return n > 0 ? std::abs(t.x() * d.y() - t.y() * d.x()) / d.norm() : -1.0;
}

// The border loops, each starting at a corner if it has one; corner flags
// per halfedge (at its source).
struct Loop {
  std::vector<HalfedgeIndex> border;
  std::vector<bool> corner_at_source;
};

std::vector<Loop> BorderLoops(const Mesh& mesh, double corner_angle_deg) {
  std::vector<Loop> loops;
  std::vector<bool> seen(mesh.number_of_halfedges(), false);
  for (HalfedgeIndex h : mesh.halfedges()) {
    if (!mesh.is_border(h) || seen[h.idx()]) continue;
    Loop loop;
    HalfedgeIndex b = h;
    do {
      seen[b.idx()] = true;
      loop.border.push_back(b);
      b = mesh.next(b);
    } while (b != h);
    const size_t n = loop.border.size();
    loop.corner_at_source.resize(n);
    size_t first = 0;
    for (size_t i = 0; i < n; ++i) {
      loop.corner_at_source[i] = TurnDeg(mesh, loop.border[(i + n - 1) % n]) > corner_angle_deg;
      if (loop.corner_at_source[i] && !loop.corner_at_source[first]) first = i;
    }
    std::rotate(loop.border.begin(), loop.border.begin() + long(first), loop.border.end());
    std::vector<bool> c = loop.corner_at_source;
    std::rotate(c.begin(), c.begin() + long(first), c.end());
    loop.corner_at_source = std::move(c);
    loops.push_back(std::move(loop));
  }
  return loops;
}

// A run: consecutive border halfedges held on one level of `function`.
struct Run {
  std::vector<HalfedgeIndex> border;
  int function = 0;
  bool closed = false;
};

// The family whose direction runs along each edge of a loop (the smaller
// |sin∠(t, ·)|; an edge without a field takes its predecessor's), runs of
// fewer than kMinRunEdges edges given to the run before them (near an
// asymptotic tangent both directions run along the boundary and the choice
// flickers), then the loop cut into runs where the family changes.
constexpr int kMinRunEdges = 3;

std::vector<Run> Runs(const Mesh& mesh, const FaceFrames& frames, const Loop& loop,
                      const std::vector<V2>& v, const std::vector<V2>& w) {
  const size_t n = loop.border.size();
  std::vector<int> family(n, -1);
  for (size_t i = 0; i < n; ++i) {
    const double a = Misalignment(mesh, frames, loop.border[i], v);
    const double b = Misalignment(mesh, frames, loop.border[i], w);
    if (a >= 0 && b >= 0) family[i] = a <= b ? 0 : 1;
  }
  std::vector<bool> undefined(n);
  for (size_t i = 0; i < n; ++i) undefined[i] = family[i] < 0;
  const auto defined = std::find_if(family.begin(), family.end(), [](int f) { return f >= 0; });
  if (defined == family.end()) return {};
  const size_t first = size_t(defined - family.begin());
  for (size_t k = 1; k < n; ++k) {
    int& f = family[(first + k) % n];
    if (f < 0) f = family[(first + k - 1) % n];
  }
  // Run starts: edges whose family differs from the one before; short runs
  // flipped until none is left (each flip removes a run).
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<size_t> starts;
    for (size_t i = 0; i < n; ++i) {
      if (family[i] != family[(i + n - 1) % n]) starts.push_back(i);
    }
    for (size_t k = 0; k < starts.size() && starts.size() > 1; ++k) {
      const size_t length = (starts[(k + 1) % starts.size()] + n - starts[k]) % n;
      if (length >= size_t(kMinRunEdges)) continue;
      for (size_t j = 0; j < length; ++j) family[(starts[k] + j) % n] = 1 - family[starts[k]];
      changed = true;
      break;
    }
  }
  size_t begin = 0;
  for (size_t i = 0; i < n; ++i) {
    if (family[i] != family[(i + n - 1) % n]) {
      begin = i;
      break;
    }
  }
  // Runs of defined edges: an edge without a field (a flat or degenerate
  // face) ends its run, the level sets there follow no direction.
  std::vector<Run> runs;
  bool open = false;
  for (size_t k = 0; k < n; ++k) {
    const size_t i = (begin + k) % n;
    if (undefined[i]) {
      open = false;
      continue;
    }
    if (!open || family[i] != runs.back().function) {
      runs.emplace_back();
      runs.back().function = family[i];
      open = true;
    }
    runs.back().border.push_back(loop.border[i]);
  }
  if (runs.size() == 1 && runs.front().border.size() == n) runs.front().closed = true;
  return runs;
}

// A wedge value as a + b·x in the run's unknown level x (b = ±1).
struct Affine {
  double a = 0.0;
  int b = 1;
};

// The wedges of one run as affine functions of its level, and the
// conditions on x met while propagating (fixed x, or impossible).
class RunPropagation {
 public:
  RunPropagation(const CutGraph& cut, const std::vector<std::vector<int>>& relations_at,
                 const std::vector<double>& alpha, const std::vector<int>& sign, double tol)
      : cut_(cut), relations_at_(relations_at), alpha_(alpha), sign_(sign), tol_(tol) {}

  void Assign(int wedge, Affine x) {
    CHECK_GE(wedge, 0);
    const auto [it, inserted] = value_.emplace(wedge, x);
    if (inserted) return;
    const Affine& y = it->second;
    if (y.b == x.b) {
      if (std::abs(y.a - x.a) > tol_) impossible_ = true;
    } else {
      forced_.push_back((x.a - y.a) / double(y.b - x.b));
    }
  }

  // Every wedge at vertex `x` through the jump relations there.
  void Spread(VertexIndex x, int from) {
    std::queue<int> todo;
    todo.push(from);
    std::map<int, bool> done;
    while (!todo.empty()) {
      const int wedge = todo.front();
      todo.pop();
      if (done[wedge]) continue;
      done[wedge] = true;
      const Affine y = value_.at(wedge);
      for (int r : relations_at_[x.idx()]) {
        const JumpRelation& rel = cut_.relations[size_t(r)];
        const double al = alpha_[size_t(rel.chain)];
        const int s = sign_[size_t(rel.chain)];
        if (rel.left_wedge == wedge && rel.right_wedge != wedge) {  // right = s(left − α)
          Assign(rel.right_wedge, {s * (y.a - al), s * y.b});
          todo.push(rel.right_wedge);
        } else if (rel.right_wedge == wedge && rel.left_wedge != wedge) {  // left = α + s right
          Assign(rel.left_wedge, {al + s * y.a, s * y.b});
          todo.push(rel.left_wedge);
        }
      }
    }
  }

  const std::map<int, Affine>& values() const { return value_; }
  const std::vector<double>& forced() const { return forced_; }
  bool impossible() const { return impossible_; }

 private:
  const CutGraph& cut_;
  const std::vector<std::vector<int>>& relations_at_;
  const std::vector<double>& alpha_;
  const std::vector<int>& sign_;
  double tol_;
  std::map<int, Affine> value_;
  std::vector<double> forced_;
  bool impossible_ = false;
};

// Holds one run on a level; false when the run cannot be one level or a
// held value would move by more than max_shift spacings.
bool HoldRun(const Mesh& mesh, const CutGraph& cut,
             const std::vector<std::vector<int>>& relations_at, const WedgeFunctions& fn,
             const Run& run, double max_shift, BoundaryRows* out) {
  const int f = run.function;
  const double spacing = fn.spacing[f];
  const double tol = 1e-6 * spacing;
  RunPropagation p(cut, relations_at, *fn.alpha[f], *fn.sign[f], tol);
  const int first = cut.corner_wedge[mesh.opposite(run.border.front()).idx()];
  p.Assign(first, {0.0, 1});
  if (!run.closed) p.Spread(mesh.source(run.border.front()), first);
  for (HalfedgeIndex b : run.border) {
    const HalfedgeIndex inside = mesh.opposite(b);  // corner at source(b)
    const int at_source = cut.corner_wedge[inside.idx()];
    const int at_target = cut.corner_wedge[mesh.prev(inside).idx()];
    p.Assign(at_target, p.values().at(at_source));
    p.Spread(mesh.target(b), at_target);
  }
  if (p.impossible()) return false;
  const std::vector<double>& values = *fn.values[f];
  double x = 0;
  if (!p.forced().empty()) {
    x = p.forced().front();
    for (double y : p.forced()) {
      if (std::abs(y - x) > tol) return false;
    }
    if (std::abs(x / spacing - std::round(x / spacing)) > 1e-6) return false;
    x = std::round(x / spacing) * spacing;
  } else {
    for (const auto& [wedge, a] : p.values()) x += a.b * (values[size_t(wedge)] - a.a);
    x = std::round(x / double(p.values().size()) / spacing) * spacing;
  }
  double shift = 0;
  for (const auto& [wedge, a] : p.values()) {
    shift = std::max(shift, std::abs(a.a + a.b * x - values[size_t(wedge)]) / spacing);
  }
  if (shift > max_shift) return false;
  out->max_shift = std::max(out->max_shift, shift);
  for (const auto& [wedge, a] : p.values()) out->fixed.push_back({f, wedge, a.a + a.b * x});
  return true;
}

}  // namespace boundary_rows_impl

BoundaryRows BoundaryRowLevels(const Mesh& mesh, const CutGraph& cut, const FaceFrames& frames,
                               const std::vector<Eigen::Vector2d>& v,
                               const std::vector<Eigen::Vector2d>& w,
                               const WedgeFunctions& functions, double corner_angle_deg,
                               double max_shift) {
  using namespace boundary_rows_impl;
  CHECK_EQ(v.size(), mesh.number_of_faces());
  CHECK_EQ(w.size(), mesh.number_of_faces());
  CHECK_EQ(cut.corner_wedge.size(), mesh.number_of_halfedges());
  for (int f = 0; f < 2; ++f) {
    CHECK(functions.values[f] && functions.alpha[f] && functions.sign[f]);
    CHECK_EQ(functions.values[f]->size(), size_t(cut.num_wedges));
    CHECK_GE(functions.alpha[f]->size(), cut.chains.size());
    CHECK_GE(functions.sign[f]->size(), cut.chains.size());
    CHECK_GT(functions.spacing[f], 0.0);
  }
  std::vector<std::vector<int>> relations_at(mesh.number_of_vertices());
  for (size_t r = 0; r < cut.relations.size(); ++r) {
    relations_at[cut.relations[r].vertex.idx()].push_back(int(r));
  }
  BoundaryRows out;
  for (const Loop& loop : BorderLoops(mesh, corner_angle_deg)) {
    ++out.loops;
    for (bool c : loop.corner_at_source) out.corners += c ? 1 : 0;
    for (const Run& run : Runs(mesh, frames, loop, v, w)) {
      if (!HoldRun(mesh, cut, relations_at, functions, run, max_shift, &out)) {
        ++out.skipped_runs;
        continue;
      }
      ++(run.function == 0 ? out.runs_g : out.runs_h);
      for (HalfedgeIndex b : run.border) {
        const double length =
            (boundary_rows_impl::Pos(mesh, mesh.target(b)) - boundary_rows_impl::Pos(mesh, mesh.source(b))).norm();
        const double m = Misalignment(mesh, frames, b, run.function == 0 ? v : w);
        if (m < 0 || length <= 0) continue;
        const double angle = std::asin(std::min(1.0, m / length)) * 180.0 / M_PI;
        out.angle_mean_deg += angle;
        out.angle_max_deg = std::max(out.angle_max_deg, angle);
        ++out.edges;
      }
    }
  }
  if (out.edges > 0) out.angle_mean_deg /= out.edges;
  return out;
}

std::vector<BoundaryRowEdge> BoundaryRowEdges(const Mesh& mesh, const FaceFrames& frames,
                                              const std::vector<Eigen::Vector2d>& v,
                                              const std::vector<Eigen::Vector2d>& w) {
  using namespace boundary_rows_impl;
  CHECK_EQ(v.size(), mesh.number_of_faces());
  CHECK_EQ(w.size(), mesh.number_of_faces());
  std::vector<BoundaryRowEdge> edges;
  for (const Loop& loop : BorderLoops(mesh, 180.0)) {
    for (const Run& run : Runs(mesh, frames, loop, v, w)) {
      for (HalfedgeIndex b : run.border) edges.push_back({b, run.function});
    }
  }
  return edges;
}

BoundaryFaceCounts CountBoundaryFaces(const Mesh& layout) {
  BoundaryFaceCounts counts;
  for (FaceIndex f : layout.faces()) {
    bool touches = false, edge_on_boundary = false;
    for (HalfedgeIndex h : CGAL::halfedges_around_face(layout.halfedge(f), layout)) {
      if (layout.is_border(layout.target(h), true)) touches = true;
      if (layout.is_border(layout.opposite(h))) edge_on_boundary = true;
    }
    if (!touches) continue;
    ++counts.boundary_faces;
    if (edge_on_boundary && layout.degree(f) == 4) ++counts.quads_on_boundary;
  }
  return counts;
}

}  // namespace archgeo
