// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "spectral/quad_relax.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace archgeo {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kCosMaxTurn = 0.70710678118654752;  // 45°: a quad's largest turn

// The shortest side of quad q.
double ShortestSide(const std::vector<Eigen::Vector3d>& p, const std::array<int, 4>& q) {
  double shortest = (p[size_t(q[1])] - p[size_t(q[0])]).norm();
  for (int k = 1; k < 4; ++k) {
    shortest = std::min(shortest, (p[size_t(q[size_t((k + 1) % 4)])] - p[size_t(q[size_t(k)])]).norm());
  }
  return shortest;
}

// Bit k set: corner k of quad q turns left about `normal` (convex there).
unsigned ConvexCorners(const std::vector<Eigen::Vector3d>& p, const std::array<int, 4>& q,
                       const Eigen::Vector3d& normal) {
  unsigned bits = 0;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d& a = p[size_t(q[size_t((k + 3) % 4)])];
    const Eigen::Vector3d& b = p[size_t(q[size_t(k)])];
    const Eigen::Vector3d& c = p[size_t(q[size_t((k + 1) % 4)])];
    if ((b - a).cross(c - b).dot(normal) > 0) bits |= 1u << k;
  }
  return bits;
}

// Per vertex of valence 4: its neighbours as two opposite pairs; an empty
// list for the other vertices. Two neighbours are adjacent when a quad holds
// both beside the vertex; the opposite of a neighbour is the one never so.
std::vector<std::array<int, 4>> OppositePairs(int vertices,
                                              const std::vector<std::array<int, 4>>& quads,
                                              std::vector<bool>* regular) {
  const size_t n = static_cast<size_t>(vertices);
  std::vector<std::vector<int>> ring(n);
  std::vector<std::vector<std::array<int, 2>>> beside(n);
  for (const auto& q : quads) {
    for (int k = 0; k < 4; ++k) {
      const int v = q[size_t(k)], next = q[size_t((k + 1) % 4)], prev = q[size_t((k + 3) % 4)];
      ring[size_t(v)].push_back(next);
      ring[size_t(v)].push_back(prev);
      beside[size_t(v)].push_back({prev, next});
    }
  }
  std::vector<std::array<int, 4>> pairs(n, {-1, -1, -1, -1});
  regular->assign(n, false);
  for (int v = 0; v < vertices; ++v) {
    std::vector<int>& r = ring[size_t(v)];
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
    if (r.size() != 4 || beside[size_t(v)].size() != 4) continue;
    const auto adjacent = [&](int a, int b) {
      for (const auto& p : beside[size_t(v)]) {
        if ((p[0] == a && p[1] == b) || (p[0] == b && p[1] == a)) return true;
      }
      return false;
    };
    int opposite = -1;
    for (int k = 1; k < 4; ++k) {
      if (!adjacent(r[0], r[size_t(k)])) opposite = k;
    }
    if (opposite < 0) continue;
    std::array<int, 4> p{r[0], r[size_t(opposite)], -1, -1};
    int at = 2;
    for (int k = 1; k < 4; ++k) {
      if (k != opposite) p[size_t(at++)] = r[size_t(k)];
    }
    pairs[size_t(v)] = p;
    (*regular)[size_t(v)] = true;
  }
  return pairs;
}

// The interior vertices of valence 3 (irregular nodes of the base complex,
// not triangle centres) with their edge neighbours in cyclic order; a
// vertex on the boundary (its quads do not close round it) is left out.
struct Spokes {
  int vertex;
  std::vector<int> around;
};
std::vector<Spokes> ValenceThreeSpokes(int vertices, const std::vector<std::array<int, 4>>& quads,
                                    const std::vector<bool>& regular, const std::vector<int>& centres) {
  std::vector<std::vector<std::array<int, 2>>> beside(static_cast<size_t>(vertices));
  for (const auto& q : quads) {
    for (int k = 0; k < 4; ++k) {
      beside[size_t(q[size_t(k)])].push_back({q[size_t((k + 3) % 4)], q[size_t((k + 1) % 4)]});
    }
  }
  std::vector<Spokes> out;
  for (int v = 0; v < vertices; ++v) {
    const auto& b = beside[size_t(v)];
    if (regular[size_t(v)] || b.size() != 3 ||
        std::find(centres.begin(), centres.end(), v) != centres.end()) {
      continue;
    }
    // Chain the quads round v: each quad's next neighbour is the following quad's previous one.
    Spokes s{v, {b[0][0]}};
    int at = b[0][1];
    bool closed = true;
    for (size_t step = 1; step < b.size() && closed; ++step) {
      s.around.push_back(at);
      closed = false;
      for (const auto& pair : b) {
        if (pair[0] == at) {
          at = pair[1];
          closed = true;
          break;
        }
      }
    }
    if (closed && at == s.around.front() && s.around.size() == b.size()) out.push_back(std::move(s));
  }
  return out;
}

// Turns each spoke of such a vertex (an edge neighbour of valence 4; the
// boundary and other nodes stay) about the vertex's normal, a quarter of
// the way per sweep, towards the spokes dividing the tangent plane evenly
// (360°/valence apart, the fan turned as a whole to fit the spokes as they
// are), keeping its length.
void BalanceSpokes(const Spokes& s, const std::vector<Eigen::Vector3d>& points, const std::vector<bool>& regular,
                   std::vector<Eigen::Vector3d>* next) {
  const Eigen::Vector3d& v = points[size_t(s.vertex)];
  const size_t k = s.around.size();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (size_t j = 0; j < k; ++j) {
    normal += (points[size_t(s.around[j])] - v).cross(points[size_t(s.around[(j + 1) % k])] - v);
  }
  if (normal.norm() == 0) return;
  normal.normalize();
  const Eigen::Vector3d x0 = points[size_t(s.around[0])] - v;
  const Eigen::Vector3d e1 = (x0 - x0.dot(normal) * normal).normalized();
  const Eigen::Vector3d e2 = normal.cross(e1);
  std::vector<double> angle(k);
  double offset = 0, previous = 0;
  for (size_t j = 0; j < k; ++j) {
    const Eigen::Vector3d d = points[size_t(s.around[j])] - v;
    double a = std::atan2(d.dot(e2), d.dot(e1));
    while (a < previous) a += 2 * kPi;  // counter-clockwise order, unwrapped
    angle[j] = previous = a;
    offset += a - 2 * kPi * double(j) / double(k);
  }
  offset /= double(k);
  for (size_t j = 0; j < k; ++j) {
    if (!regular[size_t(s.around[j])]) continue;  // the boundary and other nodes stay
    const double turn = 0.25 * (offset + 2 * kPi * double(j) / double(k) - angle[j]);
    const Eigen::Vector3d d = (*next)[size_t(s.around[j])] - v;
    (*next)[size_t(s.around[j])] = v + Eigen::AngleAxisd(turn, normal) * d;
  }
}

}  // namespace

Eigen::Vector3d QuadNormal(const std::vector<Eigen::Vector3d>& p, const std::array<int, 4>& q) {
  return (p[size_t(q[2])] - p[size_t(q[0])]).cross(p[size_t(q[3])] - p[size_t(q[1])]);
}

GridLineKinks MeasureGridLineKinks(const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<std::array<int, 4>>& quads) {
  std::vector<bool> regular;
  const auto pairs = OppositePairs(int(points.size()), quads, &regular);
  GridLineKinks out;
  int count = 0;
  for (size_t v = 0; v < points.size(); ++v) {
    if (!regular[v]) continue;
    // The surface normal at v from the two lines' central differences; the
    // turn is measured in the tangent plane (a line on a curved surface
    // bends out of it; only its turn within the surface is a kink).
    const auto& p = pairs[v];
    const Eigen::Vector3d normal = (points[size_t(p[1])] - points[size_t(p[0])])
                                       .cross(points[size_t(p[3])] - points[size_t(p[2])])
                                       .normalized();
    const auto tangential = [&normal](const Eigen::Vector3d& e) {
      return Eigen::Vector3d(e - e.dot(normal) * normal);
    };
    for (int k = 0; k < 4; k += 2) {
      const Eigen::Vector3d in = tangential(points[v] - points[size_t(p[size_t(k)])]);
      const Eigen::Vector3d out_edge = tangential(points[size_t(p[size_t(k + 1)])] - points[v]);
      const double c = in.dot(out_edge) / std::max(in.norm() * out_edge.norm(), 1e-300);
      const double degrees = std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / kPi;
      out.max_degrees = std::max(out.max_degrees, degrees);
      out.mean_degrees += degrees;
      ++count;
    }
  }
  if (count > 0) out.mean_degrees /= count;
  return out;
}

void RelaxQuads(const std::vector<std::array<int, 4>>& quads, int sweeps,
                const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& onto,
                std::vector<Eigen::Vector3d>* points, const std::vector<int>& centres) {
  std::vector<bool> regular;
  const auto pairs = OppositePairs(int(points->size()), quads, &regular);
  std::vector<std::vector<int>> centre_ring;  // per entry of `centres`: its edge neighbours
  for (int c : centres) {
    std::vector<int> ring;
    for (const auto& q : quads) {
      for (int k = 0; k < 4; ++k) {
        if (c >= 0 && q[size_t(k)] == c) ring.push_back(q[size_t((k + 1) % 4)]);
      }
    }
    centre_ring.push_back(ring);
  }
  std::vector<Eigen::Vector3d> mapped(quads.size());
  std::vector<unsigned> convex(quads.size());
  std::vector<double> shortest(quads.size());
  for (size_t q = 0; q < quads.size(); ++q) {
    mapped[q] = QuadNormal(*points, quads[q]);
    convex[q] = ConvexCorners(*points, quads[q], mapped[q]);
    shortest[q] = ShortestSide(*points, quads[q]);
  }
  const std::vector<Spokes> spokes = ValenceThreeSpokes(int(points->size()), quads, regular, centres);
  std::vector<Eigen::Vector3d> next = *points;
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    for (size_t v = 0; v < points->size(); ++v) {
      if (!regular[v]) continue;
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (int u : pairs[v]) sum += (*points)[size_t(u)];
      next[v] = 0.5 * (*points)[v] + 0.125 * sum;
    }
    for (const Spokes& s : spokes) BalanceSpokes(s, *points, regular, &next);
    for (size_t v = 0; v < points->size(); ++v) {
      if (regular[v]) next[v] = onto(next[v]);
    }
    for (size_t i = 0; i < centres.size(); ++i) {
      if (centre_ring[i].empty()) continue;
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (int u : centre_ring[i]) sum += (*points)[size_t(u)];
      const size_t c = size_t(centres[i]);
      next[c] = onto(0.5 * (*points)[c] + 0.5 / double(centre_ring[i].size()) * sum);
    }
    // A quad that would turn by more than 45° from its normal as mapped,
    // bend inward at a corner that was convex as mapped, or shrink its
    // shortest side below half its length as mapped, keeps its corners
    // of the last sweep (which may spoil a neighbour: repeated until none).
    for (bool reverted = true; reverted;) {
      reverted = false;
      for (size_t q = 0; q < quads.size(); ++q) {
        const Eigen::Vector3d n = QuadNormal(next, quads[q]);
        const bool kept_convex =
            (ConvexCorners(next, quads[q], mapped[q]) & convex[q]) == convex[q];
        if (kept_convex && n.dot(mapped[q]) >= kCosMaxTurn * n.norm() * mapped[q].norm() &&
            ShortestSide(next, quads[q]) >= 0.5 * shortest[q]) {
          continue;
        }
        for (int v : quads[q]) {
          if (next[size_t(v)] != (*points)[size_t(v)]) reverted = true;
          next[size_t(v)] = (*points)[size_t(v)];
        }
      }
    }
    *points = next;
  }
}

}  // namespace archgeo
