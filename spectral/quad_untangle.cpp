// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "spectral/quad_untangle.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "spectral/quad_relax.h"

namespace archgeo {
namespace {

constexpr double kUntanglePi = 3.14159265358979323846;
constexpr int kUntanglePasses = 50;
constexpr int kUntangleRings = 2;  // quads this many vertex rings round a poor one take part
// Once a quad is bent, the quads whose worst corner is below this (degrees)
// are worked on, so that an unfolded quad does not stop at a corner of 179°.
constexpr double kUntangleMargin = 10;

using QuadList = std::vector<std::array<int, 4>>;

// The interior angle (degrees) of quad q at its corner k in the plane with
// unit normal n, turning about n.
double InteriorAngle(const std::vector<Eigen::Vector3d>& p, const std::array<int, 4>& q, int k,
                     const Eigen::Vector3d& n) {
  const Eigen::Vector3d& a = p[size_t(q[size_t((k + 3) % 4)])];
  const Eigen::Vector3d& b = p[size_t(q[size_t(k)])];
  const Eigen::Vector3d& c = p[size_t(q[size_t((k + 1) % 4)])];
  const Eigen::Vector3d u = (b - a) - (b - a).dot(n) * n, v = (c - b) - (c - b).dot(n) * n;
  return 180 - std::atan2(u.cross(v).dot(n), u.dot(v)) * 180 / kUntanglePi;  // a left turn < 180
}

// min over the corners of quad q of min(θ, 180° − θ), degrees, θ the
// interior angle in the plane with unit normal n.
double WorstInPlane(const std::vector<Eigen::Vector3d>& p, const std::array<int, 4>& q,
                    const Eigen::Vector3d& n) {
  double worst = 180;
  for (int k = 0; k < 4; ++k) {
    const double interior = InteriorAngle(p, q, k, n);
    worst = std::min({worst, interior, 180 - interior});
  }
  return worst;
}

// The worst corner of quad q: WorstInPlane in the plane of its normal (as
// validity measures it) when it faces the side `facing` says, −180° when it
// faces away.
double WorstCorner(const std::vector<Eigen::Vector3d>& p, const std::array<int, 4>& q,
                   const Eigen::Vector3d& facing) {
  const Eigen::Vector3d n = QuadNormal(p, q);
  if (n.norm() == 0 || n.dot(facing) <= 0) return -180;
  return WorstInPlane(p, q, n.normalized());
}

struct UntangleMesh {
  std::vector<std::vector<int>> quads_at;  // per vertex: the quads round it
  std::vector<std::vector<int>> neighbours;
  std::vector<bool> movable;
  std::vector<Eigen::Vector3d> start;      // the points as given
  double mean_edge = 0;                    // the quads' mean edge as given
};

// The side quad q faces: the sum of the design surface's normals at its corners.
Eigen::Vector3d Facing(const std::vector<Eigen::Vector3d>& normals, const std::array<int, 4>& q) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int v : q) sum += normals[size_t(v)];
  return sum;
}

UntangleMesh UntangleSetUp(const QuadList& quads, const std::vector<Eigen::Vector3d>& p,
                           const std::vector<int>& centres, bool move_irregular) {
  UntangleMesh m;
  const size_t n = p.size();
  m.quads_at.resize(n);
  m.neighbours.resize(n);
  for (size_t i = 0; i < quads.size(); ++i) {
    const auto& q = quads[i];
    for (int k = 0; k < 4; ++k) {
      const size_t v = size_t(q[size_t(k)]);
      m.quads_at[v].push_back(int(i));
      m.neighbours[v].push_back(q[size_t((k + 1) % 4)]);
      m.neighbours[v].push_back(q[size_t((k + 3) % 4)]);
    }
  }
  m.start = p;
  for (const auto& q : quads) {
    for (int k = 0; k < 4; ++k) {
      m.mean_edge += (p[size_t(q[size_t(k)])] - p[size_t(q[size_t((k + 1) % 4)])]).norm();
    }
  }
  if (!quads.empty()) m.mean_edge /= 4.0 * double(quads.size());
  m.movable.assign(n, false);
  for (size_t v = 0; v < n; ++v) {
    auto& r = m.neighbours[v];
    const size_t listed = r.size();
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
    // Interior (every neighbour in two of its quads: a closed fan), and of
    // valence 4 unless irregular vertices move too.
    const bool interior = !r.empty() && listed == 2 * r.size();
    m.movable[v] = interior && (move_irregular || r.size() == 4);
  }
  for (int c : centres) {
    if (c < 0 || size_t(c) >= n) continue;
    const size_t listed = m.quads_at[size_t(c)].size() * 2;
    if (listed == 2 * m.neighbours[size_t(c)].size()) m.movable[size_t(c)] = true;  // closed fan
  }
  return m;
}

// True when the quads round vertex v that face the right way wrap round it
// more than once: their corners at v add up to more than 540° (one turn is
// 360° on a flat surface, less on a curved one). A quad facing away counts
// against a move already (WorstCorner).
bool Wraps(const UntangleMesh& m, const QuadList& quads, const std::vector<Eigen::Vector3d>& p,
           const std::vector<Eigen::Vector3d>& normals, size_t v) {
  double sum = 0;
  for (int q : m.quads_at[v]) {
    const auto& quad = quads[size_t(q)];
    const Eigen::Vector3d n = QuadNormal(p, quad);
    if (n.norm() == 0 || n.dot(Facing(normals, quad)) <= 0) continue;
    for (int k = 0; k < 4; ++k) {
      if (size_t(quad[size_t(k)]) == v) sum += InteriorAngle(p, quad, k, n.normalized());
    }
  }
  return sum > 540;
}

// The worst corner of the quads round v, or −inf when an edge at v is
// shorter than half its length as given or a quarter of the mean edge
// (but no longer than as given) or the quads round v or a
// neighbour wrap round it twice.
double WorstAround(const UntangleMesh& m, const QuadList& quads, const std::vector<Eigen::Vector3d>& p,
                   const std::vector<Eigen::Vector3d>& normals, size_t v) {
  for (int u : m.neighbours[v]) {
    const size_t w = size_t(u);
    const double given = (m.start[w] - m.start[v]).norm();
    if ((p[w] - p[v]).norm() < std::min(given, std::max(0.5 * given, 0.25 * m.mean_edge))) {
      return -std::numeric_limits<double>::infinity();
    }
  }
  if (Wraps(m, quads, p, normals, v)) return -std::numeric_limits<double>::infinity();
  for (int u : m.neighbours[v]) {
    if (Wraps(m, quads, p, normals, size_t(u))) return -std::numeric_limits<double>::infinity();
  }
  double worst = 180;
  for (int q : m.quads_at[v]) {
    worst = std::min(worst, WorstCorner(p, quads[size_t(q)], Facing(normals, quads[size_t(q)])));
  }
  return worst;
}

// Compass search for vertex v in its tangent plane; true when it moved.
bool UntangleVertex(const UntangleMesh& m, const QuadList& quads,
                    const std::function<SurfaceSample(const Eigen::Vector3d&)>& onto,
                    std::vector<Eigen::Vector3d>* points, std::vector<Eigen::Vector3d>* normals,
                    size_t v) {
  std::vector<Eigen::Vector3d>& p = *points;
  const Eigen::Vector3d normal = (*normals)[v];
  double mean_edge = 0;
  for (int u : m.neighbours[v]) mean_edge += (p[size_t(u)] - p[v]).norm();
  if (mean_edge == 0) return false;
  mean_edge /= double(m.neighbours[v].size());
  const Eigen::Vector3d any = std::abs(normal.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = normal.cross(any).normalized(), e2 = normal.cross(e1);
  double best = WorstAround(m, quads, p, *normals, v);
  bool moved = false;
  for (double h = 0.5 * mean_edge; h > mean_edge / 256;) {
    const Eigen::Vector3d start = p[v], start_normal = (*normals)[v];
    bool improved = false;
    for (int d = 0; d < 16 && !improved; ++d) {
      const double a = kUntanglePi * d / 8;
      const SurfaceSample sample = onto(start + h * (std::cos(a) * e1 + std::sin(a) * e2));
      p[v] = sample.point;
      (*normals)[v] = sample.normal;
      const double worst = WorstAround(m, quads, p, *normals, v);
      if (worst > best + 1e-9) {
        best = worst;
        improved = moved = true;
      } else {
        p[v] = start;
        (*normals)[v] = start_normal;
      }
    }
    if (!improved) h *= 0.5;
  }
  return moved;
}

// Flags the quads whose worst corner is below `margin` (degrees); their count.
int CountBelow(const QuadList& quads, const std::vector<Eigen::Vector3d>& p,
               const std::vector<Eigen::Vector3d>& normals, double margin, std::vector<bool>* below) {
  below->assign(quads.size(), false);
  int count = 0;
  for (size_t q = 0; q < quads.size(); ++q) {
    if (WorstCorner(p, quads[q], Facing(normals, quads[q])) < margin) {
      (*below)[q] = true;
      ++count;
    }
  }
  return count;
}

// The movable vertices of the quads within kUntangleRings vertex rings of a flagged quad.
std::vector<size_t> UntangleWork(const UntangleMesh& m, const QuadList& quads,
                                 const std::vector<bool>& bent) {
  std::vector<bool> near(m.movable.size(), false);
  for (size_t q = 0; q < quads.size(); ++q) {
    if (!bent[q]) continue;
    for (int v : quads[q]) near[size_t(v)] = true;
  }
  for (int ring = 0; ring < kUntangleRings; ++ring) {
    std::vector<bool> grown = near;
    for (size_t v = 0; v < near.size(); ++v) {
      if (!near[v]) continue;
      for (int q : m.quads_at[v]) {
        for (int u : quads[size_t(q)]) grown[size_t(u)] = true;
      }
    }
    near = grown;
  }
  std::vector<size_t> work;
  for (size_t v = 0; v < near.size(); ++v) {
    if (near[v] && m.movable[v]) work.push_back(v);
  }
  return work;
}

}  // namespace

UntangleResult UntangleQuads(const QuadList& quads,
                             const std::function<SurfaceSample(const Eigen::Vector3d&)>& onto,
                             std::vector<Eigen::Vector3d>* points, const std::vector<int>& centres,
                             bool move_irregular) {
  const UntangleMesh m = UntangleSetUp(quads, *points, centres, move_irregular);
  std::vector<Eigen::Vector3d> normals;
  for (const Eigen::Vector3d& x : *points) normals.push_back(onto(x).normal);
  UntangleResult out;
  std::vector<bool> bent, poor;
  out.bent_before = out.bent_after = CountBelow(quads, *points, normals, 0, &bent);
  if (out.bent_before == 0) return out;
  // First unfold (every quad's worst corner ≥ 0), then open the corners
  // below the margin; a step that leaves more quads bent is undone.
  for (const double margin : {0.0, kUntangleMargin}) {
    const std::vector<Eigen::Vector3d> kept = *points, kept_normals = normals;
    const int kept_moves = out.moves;
    for (int pass = 0; pass < kUntanglePasses && CountBelow(quads, *points, normals, margin, &poor) > 0;
         ++pass) {
      int moves = 0;
      for (size_t v : UntangleWork(m, quads, poor)) moves += UntangleVertex(m, quads, onto, points, &normals, v);
      out.moves += moves;
      if (moves == 0) break;
    }
    const int bent_now = CountBelow(quads, *points, normals, 0, &bent);
    if (bent_now > out.bent_after) {
      *points = kept;
      normals = kept_normals;
      out.moves = kept_moves;
    } else {
      out.bent_after = bent_now;
    }
  }
  return out;
}

}  // namespace archgeo
