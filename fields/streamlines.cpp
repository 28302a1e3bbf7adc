// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Streamlines and separatrices of a TCD field [Gebreiter 2012, §8.2, §8.1.3;
// Jobard & Lefer 1997]; see fields/streamlines.h.
#include "fields/streamlines.h"

#include <glog/logging.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <unordered_map>
#include <utility>

#include "core/segments.h"

namespace archgeo {
namespace {

using V3 = Eigen::Vector3d;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Distance between the segments [p1, q1] and [p2, q2].
double SegmentDistance(const V3& p1, const V3& q1, const V3& p2, const V3& q2) {
  const auto [s, t] = ClosestSegmentParameters(p1, q1, p2, q2);
  return ((p1 + s * (q1 - p1)) - (p2 + t * (q2 - p2))).norm();
}

struct Segment {
  V3 a, b;
  int line = 0;
  double s0 = 0, s1 = 0;  // signed arc positions of a and b along the line
};

// Segments hashed into cubic cells (each segment in every cell its box meets).
class SegmentGrid {
 public:
  explicit SegmentGrid(double cell) : cell_(cell) {}

  void Add(const Segment& s) {
    const int id = int(segments_.size());
    segments_.push_back(s);
    stamp_.push_back(0);
    ForCells(s.a.cwiseMin(s.b), s.a.cwiseMax(s.b), [&](std::uint64_t k) { cells_[k].push_back(id); });
  }

  // Calls f(segment) once for every segment whose box comes within r of the box of [a, b].
  template <class F>
  void Near(const V3& a, const V3& b, double r, F f) {
    ++visit_;
    const V3 pad = V3::Constant(r);
    ForCells(a.cwiseMin(b) - pad, a.cwiseMax(b) + pad, [&](std::uint64_t k) {
      const auto it = cells_.find(k);
      if (it == cells_.end()) return;
      for (int id : it->second) {
        if (stamp_[size_t(id)] == visit_) continue;
        stamp_[size_t(id)] = visit_;
        f(segments_[size_t(id)]);
      }
    });
  }

  const std::vector<Segment>& segments() const { return segments_; }

 private:
  template <class F>
  void ForCells(const V3& lo, const V3& hi, F f) const {
    const Eigen::Array3i a = (lo / cell_).array().floor().cast<int>();
    const Eigen::Array3i b = (hi / cell_).array().floor().cast<int>();
    for (int x = a[0]; x <= b[0]; ++x) {
      for (int y = a[1]; y <= b[1]; ++y) {
        for (int z = a[2]; z <= b[2]; ++z) f(Key(x, y, z));
      }
    }
  }
  static std::uint64_t Key(int x, int y, int z) {
    auto u = [](int v) { return std::uint64_t(std::uint32_t(v + (1 << 20)) & 0x1fffff); };
    return (u(x) << 42) | (u(y) << 21) | u(z);
  }

  double cell_;
  std::vector<Segment> segments_;
  std::vector<unsigned> stamp_;
  unsigned visit_ = 0;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
};

enum class Stop { kBoundary, kInvalid, kSingularity, kNeighbour, kSelf, kLoop, kLength, kStuck };

struct Cursor {
  int face = -1;
  V3 p = V3::Zero();
  V3 dir = V3::Zero();  // direction of travel (unit, in the face plane)
  int family = 0;       // the family followed in this face
};

class Tracer {
 public:
  Tracer(const StreamlineInput& in, const StreamlineOptions& o) : in_(in) {
    const int faces = int(in.triangles.size());
    V3 lo = V3::Constant(kInf), hi = -lo;
    for (const V3& p : in.points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    diagonal_ = in.points.empty() ? 1.0 : (hi - lo).norm();
    d_sep_ = o.separation;
    d_test_ = o.test_ratio * o.separation;
    h_ = o.step * o.separation;
    window_ = 3 * d_test_;
    r_sing_ = d_test_;
    max_length_ = o.max_length > 0 ? o.max_length : 10 * diagonal_;
    // Faces, normals, neighbours (an edge of more than two faces: a boundary).
    normal_.resize(size_t(faces));
    neighbour_.assign(size_t(faces), {-1, -1, -1});
    std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edges;
    for (int f = 0; f < faces; ++f) {
      const auto& t = in.triangles[size_t(f)];
      const V3 n = (X(t[1]) - X(t[0])).cross(X(t[2]) - X(t[0]));
      normal_[size_t(f)] = n.norm() > 0 ? V3(n.normalized()) : V3::UnitZ();
      for (int k = 0; k < 3; ++k) {
        const int a = t[size_t(k)], b = t[size_t((k + 1) % 3)];
        edges[{std::min(a, b), std::max(a, b)}].push_back({f, k});
      }
    }
    for (const auto& [key, list] : edges) {
      if (list.size() != 2) continue;
      neighbour_[size_t(list[0].first)][size_t(list[0].second)] = list[1].first;
      neighbour_[size_t(list[1].first)][size_t(list[1].second)] = list[0].first;
    }
    // Vertex lines per family: the dominant eigenvector of Σ A_f d dᵀ.
    std::vector<std::array<Eigen::Matrix3d, 2>> tensor(
        in.points.size(), {Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero()});
    vertex_faces_.resize(in.points.size());
    for (int f = 0; f < faces; ++f) {
      for (int v : in.triangles[size_t(f)]) vertex_faces_[size_t(v)].push_back(f);
      if (!in.valid[size_t(f)]) continue;
      const auto& t = in.triangles[size_t(f)];
      const double area = 0.5 * (X(t[1]) - X(t[0])).cross(X(t[2]) - X(t[0])).norm();
      for (int fam = 0; fam < 2; ++fam) {
        const V3& d = in.directions[size_t(f)][size_t(fam)];
        for (int v : t) tensor[size_t(v)][size_t(fam)] += area * d * d.transpose();
      }
    }
    vertex_line_.resize(in.points.size());
    strong_.assign(in.points.size(), true);
    for (size_t v = 0; v < in.points.size(); ++v) {
      for (int fam = 0; fam < 2; ++fam) {
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
        eig.computeDirect(tensor[v][size_t(fam)]);
        const Eigen::Vector3d l = eig.eigenvalues();
        vertex_line_[v][size_t(fam)] = eig.eigenvectors().col(2);
        // A corner whose faces disagree (near a singularity) is not blended.
        if (!(l[2] > 0) || l[1] > 0.5 * l[2]) strong_[v] = false;
      }
    }
    for (const auto& s : in.singularities) strong_[size_t(s.vertex)] = false;
    // Per face: the singularities within r_sing of it (tested while tracing).
    near_singular_.resize(size_t(faces));
    for (int f = 0; f < faces; ++f) {
      const auto& t = in.triangles[size_t(f)];
      const V3 c = (X(t[0]) + X(t[1]) + X(t[2])) / 3;
      double radius = 0;
      for (int v : t) radius = std::max(radius, (X(v) - c).norm());
      for (size_t j = 0; j < in.singularities.size(); ++j) {
        if ((X(in.singularities[j].vertex) - c).norm() <= radius + r_sing_ + h_) {
          near_singular_[size_t(f)].push_back(int(j));
        }
      }
    }
    grid_.assign(2, SegmentGrid(std::max(d_sep_, 1e-300)));
  }

  StreamlineResult Run(bool separatrices) {
    StreamlineResult out;
    out.d_sep = d_sep_;
    out.d_test = d_test_;
    out.separatrix_directions.assign(in_.singularities.size(), {0, 0});
    if (separatrices) {
      for (size_t j = 0; j < in_.singularities.size(); ++j) {
        for (int fam = 0; fam < 2; ++fam) {
          for (const Cursor& c : SeparatrixStarts(int(j), fam)) {
            ++out.separatrix_directions[j][size_t(fam)];
            TraceSeparatrix(int(j), c);
          }
        }
      }
    }
    // Seeds: the face nearest the middle first, then every face centroid.
    V3 middle = V3::Zero();
    for (const V3& p : in_.points) middle += p / double(in_.points.size());
    std::vector<int> order;
    int first = -1;
    for (int f = 0; f < int(in_.triangles.size()); ++f) {
      if (!in_.valid[size_t(f)]) continue;
      order.push_back(f);
      if (first < 0 || (Centroid(f) - middle).norm() < (Centroid(first) - middle).norm()) first = f;
    }
    if (first >= 0) order.insert(order.begin(), first);
    for (int fam = 0; fam < 2; ++fam) {
      std::deque<int> queue;
      for (size_t l = 0; l < lines_.size(); ++l) {
        if (lines_[l].line.family == fam) queue.push_back(int(l));
      }
      Drain(fam, &queue);
      for (int f : order) {
        if (TrySeed(fam, f, Centroid(f))) {
          queue.push_back(int(lines_.size()) - 1);
          Drain(fam, &queue);
        }
      }
    }
    for (Traced& t : lines_) out.lines.push_back(std::move(t.line));
    return out;
  }

 private:
  struct Traced {
    Streamline line;
    std::vector<int> faces;  // per point
  };

  V3 X(int v) const { return in_.points[size_t(v)]; }
  V3 Corner(int f, int k) const { return X(in_.triangles[size_t(f)][size_t(k)]); }
  V3 Centroid(int f) const { return (Corner(f, 0) + Corner(f, 1) + Corner(f, 2)) / 3; }

  std::array<double, 3> Bary(int f, const V3& p) const {
    const V3& n = normal_[size_t(f)];
    const V3 x0 = Corner(f, 0), x1 = Corner(f, 1), x2 = Corner(f, 2);
    const double d = n.dot((x1 - x0).cross(x2 - x0));
    return {n.dot((x1 - p).cross(x2 - p)) / d, n.dot((x2 - p).cross(x0 - p)) / d,
            n.dot((x0 - p).cross(x1 - p)) / d};
  }

  V3 InPlane(int f, const V3& d) const { return d - d.dot(normal_[size_t(f)]) * normal_[size_t(f)]; }

  // The blended line of `family` at p in face f, oriented along `ref`.
  V3 Direction(int f, int family, const V3& p, const V3& ref) const {
    const V3& own = in_.directions[size_t(f)][size_t(family)];
    const std::array<double, 3> b = Bary(f, p);
    V3 sum = V3::Zero();
    for (int k = 0; k < 3; ++k) {
      const int v = in_.triangles[size_t(f)][size_t(k)];
      V3 c = own;
      if (strong_[size_t(v)]) {
        const V3& a = vertex_line_[size_t(v)][0];
        const V3& w = vertex_line_[size_t(v)][1];
        c = std::abs(a.dot(own)) >= std::abs(w.dot(own)) ? a : w;
      }
      if (c.dot(ref) < 0) c = -c;
      sum += b[size_t(k)] * c;
    }
    sum = InPlane(f, sum);
    if (sum.norm() < 1e-9) sum = own.dot(ref) < 0 ? V3(-own) : own;
    return sum.normalized();
  }

  // The direction d of face f carried across its edge `slot` into face g.
  V3 Carry(int f, int slot, int g, const V3& d) const {
    const V3 a = (Corner(f, (slot + 1) % 3) - Corner(f, slot)).normalized();
    const V3 carried = d.dot(a) * a + d.dot(normal_[size_t(f)].cross(a)) * normal_[size_t(g)].cross(a);
    return carried.normalized();
  }

  // Moves p in face f by the step `delta` (in f's plane) up to f's boundary:
  // returns the fraction t ∈ [0, 1] done and the corner opposite the edge
  // crossed (−1: none).
  std::pair<double, int> Clip(int f, const V3& p, const V3& delta) const {
    const std::array<double, 3> b0 = Bary(f, p), b1 = Bary(f, p + delta);
    double t = 1;
    int corner = -1;
    for (int j = 0; j < 3; ++j) {
      if (b1[size_t(j)] >= 0) continue;
      const double start = std::max(0.0, b0[size_t(j)]);
      const double tj = start / (start - b1[size_t(j)]);
      if (tj < t) {
        t = tj;
        corner = j;
      }
    }
    return {t, corner};
  }

  // A straight walk on the surface from p in face f along d (unfolding at
  // every edge); false at the boundary.
  bool Walk(int f, V3 p, V3 d, double length, int* face, V3* at) const {
    for (int crossings = 0; crossings < 100000; ++crossings) {
      const auto [t, corner] = Clip(f, p, length * d);
      p += t * length * d;
      length *= 1 - t;
      if (corner < 0 || length <= 0) {
        *face = f;
        *at = p;
        return true;
      }
      const int slot = (corner + 1) % 3;
      const int g = neighbour_[size_t(f)][size_t(slot)];
      if (g < 0) return false;
      d = Carry(f, slot, g, d);
      f = g;
    }
    return false;
  }

  // Whether the segment [a, b] at arc s of `line` (family, separatrix of
  // `origin` or −1) may be added: kNeighbour/kSelf/kLoop when it may not.
  std::optional<Stop> Blocked(int family, int line, int origin, const V3& a, const V3& b,
                              double s, bool forward, double length) {
    std::optional<Stop> stop;
    const bool near_origin =
        origin >= 0 && (a - X(in_.singularities[size_t(origin)].vertex)).norm() < 3 * d_test_;
    grid_[size_t(family)].Near(a, b, d_test_, [&](const Segment& seg) {
      if (stop == Stop::kNeighbour) return;
      if (seg.line == line) {
        const double gap = std::min(std::abs(s - seg.s0), std::abs(s - seg.s1));
        if (gap < window_) return;
        if (SegmentDistance(a, b, seg.a, seg.b) >= d_test_) return;
        const bool at_start = std::min(std::abs(seg.s0), std::abs(seg.s1)) < window_;
        stop = forward && at_start && length > 2 * window_ && !lines_[size_t(line)].line.separatrix
                   ? Stop::kLoop
                   : Stop::kSelf;
        return;
      }
      if (near_origin && lines_[size_t(seg.line)].line.singularity == origin) return;
      if (SegmentDistance(a, b, seg.a, seg.b) < d_test_) stop = Stop::kNeighbour;
    });
    return stop;
  }

  // Traces from c in one direction, appending points (and faces) after c.p.
  // `sign` +1: arc positions grow from s = 0, −1: they fall.
  Stop TraceHalf(Cursor c, int line, int line_family, int origin, int sign,
                 std::vector<V3>* points, std::vector<int>* faces) {
    double s = 0, length = 0;
    int idle = 0;
    const long long max_steps = 20 * (long long)(max_length_ / h_) + 100000;
    for (long long step = 0; step < max_steps; ++step) {
      if (!in_.valid[size_t(c.face)]) return Stop::kInvalid;
      const int f = c.face, fam = c.family;
      const V3 k1 = Direction(f, fam, c.p, c.dir);
      const V3 k2 = Direction(f, fam, c.p + 0.5 * h_ * k1, k1);
      const V3 k3 = Direction(f, fam, c.p + 0.5 * h_ * k2, k2);
      const V3 k4 = Direction(f, fam, c.p + h_ * k3, k3);
      // A separatrix leaves its singular vertex along its radial direction.
      V3 d = step == 0 && origin >= 0 ? c.dir : InPlane(f, k1 + 2 * k2 + 2 * k3 + k4);
      if (d.norm() < 1e-12) return Stop::kStuck;
      d.normalize();
      const auto [t, corner] = Clip(f, c.p, h_ * d);
      const V3 q = c.p + t * h_ * d;
      const double ds = (q - c.p).norm();
      if (ds > 0) {
        const double s_next = s + sign * ds;
        if (const std::optional<Stop> stop =
                Blocked(line_family, line, origin, c.p, q, s, sign > 0, length)) {
          if (*stop == Stop::kLoop) {
            // Close: the last point joins the line's first point.
            const V3& start = lines_[size_t(line)].line.points.front();
            grid_[size_t(line_family)].Add({c.p, start, line, s, 0.0});
            points->push_back(start);
            faces->push_back(lines_[size_t(line)].faces.front());
          }
          return *stop;
        }
        grid_[size_t(line_family)].Add({c.p, q, line, s, s_next});
        points->push_back(q);
        faces->push_back(f);
        s = s_next;
        length += ds;
        idle = 0;
      } else if (++idle > 8) {
        return Stop::kStuck;
      }
      if (length > max_length_) return Stop::kLength;
      for (int j : near_singular_[size_t(f)]) {
        const V3 x = X(in_.singularities[size_t(j)].vertex);
        if (j == origin && length < 2 * r_sing_) continue;
        if ((q - x).norm() < r_sing_) {
          if (origin >= 0 && j != origin) {  // a separatrix ends at the singularity
            grid_[size_t(line_family)].Add({q, x, line, s, s + sign * (x - q).norm()});
            points->push_back(x);
            faces->push_back(f);
          }
          return Stop::kSingularity;
        }
      }
      c.p = q;
      if (corner < 0) {
        c.dir = d;
        continue;
      }
      const int slot = (corner + 1) % 3;
      const int g = neighbour_[size_t(f)][size_t(slot)];
      if (g < 0) return Stop::kBoundary;
      if (!in_.valid[size_t(g)]) return Stop::kInvalid;
      const V3 carried = Carry(f, slot, g, d);
      // The family and sign in g closest to the carried direction.
      double best = -1;
      for (int k = 0; k < 2; ++k) {
        const V3& e = in_.directions[size_t(g)][size_t(k)];
        if (std::abs(e.dot(carried)) > best) {
          best = std::abs(e.dot(carried));
          c.family = k;
        }
      }
      c.dir = carried;
      c.face = g;
    }
    return Stop::kLength;
  }

  // A new line from c both ways (a separatrix: forward only from its vertex).
  void Trace(int family, const Cursor& c, bool separatrix, int origin) {
    const int id = int(lines_.size());
    Traced& t = lines_.emplace_back();
    t.line.family = family;
    t.line.separatrix = separatrix;
    t.line.singularity = origin;
    t.line.points = {c.p};
    t.faces = {c.face};
    std::vector<V3> forward, backward;
    std::vector<int> forward_faces, backward_faces;
    const Stop stop = TraceHalf(c, id, family, origin, +1, &forward, &forward_faces);
    if (!separatrix && stop != Stop::kLoop) {
      Cursor back = c;
      back.dir = -c.dir;
      TraceHalf(back, id, family, origin, -1, &backward, &backward_faces);
    }
    Traced& line = lines_[size_t(id)];  // TraceHalf does not add lines
    std::vector<V3> points(backward.rbegin(), backward.rend());
    std::vector<int> faces(backward_faces.rbegin(), backward_faces.rend());
    points.push_back(c.p);
    faces.push_back(c.face);
    points.insert(points.end(), forward.begin(), forward.end());
    faces.insert(faces.end(), forward_faces.begin(), forward_faces.end());
    line.line.closed = stop == Stop::kLoop;
    if (line.line.closed) {
      points.pop_back();  // the first point again
      faces.pop_back();
    }
    line.line.points = std::move(points);
    line.faces = std::move(faces);
    double length = 0;
    for (size_t i = 1; i < line.line.points.size(); ++i) {
      length += (line.line.points[i] - line.line.points[i - 1]).norm();
    }
    if (line.line.closed) length += (line.line.points.front() - line.line.points.back()).norm();
    line.line.length = length;
  }

  void TraceSeparatrix(int j, const Cursor& c) {
    Trace(c.family, c, true, j);
    if (lines_.back().line.points.size() < 2) lines_.pop_back();  // blocked at once
  }

  // Separatrix directions at singularity j for `family` (Tricoche; see the
  // header): along the ring of faces around the vertex, ψ = θ − φ (the line
  // angle relative to the radial direction) decreases inside each face (θ is
  // constant there) and jumps between faces (by the smallest rotation, the
  // two faces unfolded about their shared edge); ψ ≡ 0 (mod π) marks a
  // radial line. The crossings are listed in order around the vertex, an
  // adjacent pair of opposite crossings (the field's wiggle about the radial
  // direction) removed while there is one, the closest pair first; the
  // 2|1 − k| that remain (all of one sense) are the separatrices: ±d_f from
  // the vertex into f for a crossing inside face f, the shared edge for one
  // at a jump.
  std::vector<Cursor> SeparatrixStarts(int j, int family) const {
    const int v = in_.singularities[size_t(j)].vertex;
    const V3 p = X(v);
    // The ring, counter-clockwise: from face f (corners v, a, b) to the face across (v, b).
    std::vector<int> ring;
    const int first = vertex_faces_[size_t(v)].empty() ? -1 : vertex_faces_[size_t(v)][0];
    for (int f = first; f >= 0;) {
      ring.push_back(f);
      const auto& t = in_.triangles[size_t(f)];
      const int k = int(std::find(t.begin(), t.end(), v) - t.begin());
      f = neighbour_[size_t(f)][size_t((k + 2) % 3)];
      if (f == first || ring.size() > vertex_faces_[size_t(v)].size()) break;
    }
    std::vector<Cursor> out;
    if (ring.size() != vertex_faces_[size_t(v)].size() || ring.size() < 3) return out;
    for (int f : ring) {
      if (!in_.valid[size_t(f)]) return out;
    }
    struct Event {
      double at;      // angle around the vertex
      int sense;      // −1: ψ falls through 0 mod π, +1: rises
      Cursor start;
    };
    std::vector<Event> events;
    double psi = 0, around = 0;  // ψ unwrapped; the angle walked around the vertex
    bool started = false;
    for (size_t i = 0; i <= ring.size(); ++i) {
      const int f = ring[i % ring.size()];
      const auto& t = in_.triangles[size_t(f)];
      const int k = int(std::find(t.begin(), t.end(), v) - t.begin());
      const V3 ea = (Corner(f, (k + 1) % 3) - p).normalized();
      const V3 eb = (Corner(f, (k + 2) % 3) - p).normalized();
      const V3& n = normal_[size_t(f)];
      const V3& d = in_.directions[size_t(f)][size_t(family)];
      const double theta = std::atan2(n.dot(ea.cross(d)), ea.dot(d));  // from edge a
      const double alpha = std::atan2(n.dot(ea.cross(eb)), ea.dot(eb));
      if (!started) {
        psi = theta;
        started = true;
      } else {
        // The jump from the last face's end to this face's start (edge a).
        const double before = psi;
        psi += std::remainder(theta - psi, M_PI);
        const double lo = std::floor(before / M_PI), hi = std::floor(psi / M_PI);
        if (lo != hi && i < ring.size() + 1) {
          // Along the shared edge, turned into f by a hair (a step exactly
          // along an edge has no face to be in).
          const double e = 1e-3 * alpha;
          const V3 dir = std::cos(e) * ea + std::sin(e) * n.cross(ea);
          events.push_back({around, psi > before ? +1 : -1, {f, p, dir.normalized(), family}});
        }
        if (i == ring.size()) break;
      }
      // Inside the face ψ falls by alpha.
      const double before = psi;
      psi -= alpha;
      for (double m = std::floor(before / M_PI); m * M_PI > psi; m -= 1) {
        if (m * M_PI >= before) continue;
        const double tk = before - m * M_PI;  // the angle from edge a where ψ = mπ
        const V3 dir = std::cos(tk) * ea + std::sin(tk) * n.cross(ea);
        events.push_back({around + tk, -1, {f, p, dir.normalized(), family}});
      }
      around += alpha;
    }
    // Cancel adjacent opposite pairs, the closest first.
    while (true) {
      int best = -1;
      double gap = kInf;
      const int m = int(events.size());
      for (int a = 0; a < m && m >= 2; ++a) {
        const int b = (a + 1) % m;
        if (events[size_t(a)].sense == events[size_t(b)].sense) continue;
        double g = events[size_t(b)].at - events[size_t(a)].at;
        if (g < 0) g += around;
        if (g < gap) {
          gap = g;
          best = a;
        }
      }
      if (best < 0) break;
      const int b = (best + 1) % m;
      events.erase(events.begin() + std::max(best, b));
      events.erase(events.begin() + std::min(best, b));
    }
    for (const Event& e : events) out.push_back(e.start);
    return out;
  }

  // Whether a seed at p (face f) is far enough from every line of `family`.
  bool FarFromLines(int family, int f, const V3& p) {
    if (!in_.valid[size_t(f)]) return false;
    for (int j : near_singular_[size_t(f)]) {
      if ((p - X(in_.singularities[size_t(j)].vertex)).norm() < 2 * r_sing_) return false;
    }
    bool far = true;
    const double r = 0.9 * d_sep_;
    grid_[size_t(family)].Near(p, p, r, [&](const Segment& seg) {
      if (far && SegmentDistance(p, p, seg.a, seg.b) < r) far = false;
    });
    return far;
  }

  bool TrySeed(int family, int f, const V3& p) {
    if (!FarFromLines(family, f, p)) return false;
    const V3& d = in_.directions[size_t(f)][size_t(family)];
    Trace(family, {f, p, d, family}, false, -1);
    return true;
  }

  // Jobard & Lefer: seeds d_sep to either side of each queued line.
  void Drain(int family, std::deque<int>* queue) {
    while (!queue->empty()) {
      const int l = queue->front();
      queue->pop_front();
      const std::vector<V3> points = lines_[size_t(l)].line.points;
      const std::vector<int> faces = lines_[size_t(l)].faces;
      double next = 0, arc = 0;
      for (size_t i = 0; i + 1 < points.size(); ++i) {
        const double ds = (points[i + 1] - points[i]).norm();
        if (arc >= next && ds > 0) {
          next = arc + 0.25 * d_sep_;
          const int f = faces[i];
          const V3 tangent = InPlane(f, points[i + 1] - points[i]).normalized();
          const V3 side = normal_[size_t(f)].cross(tangent);
          for (double sign : {1.0, -1.0}) {
            int g = -1;
            V3 at;
            if (Walk(f, points[i], sign * side, d_sep_, &g, &at) && TrySeed(family, g, at)) {
              queue->push_back(int(lines_.size()) - 1);
            }
          }
        }
        arc += ds;
      }
    }
  }

  const StreamlineInput& in_;
  double diagonal_ = 1, d_sep_ = 0, d_test_ = 0, h_ = 0, window_ = 0, r_sing_ = 0,
         max_length_ = 0;
  std::vector<V3> normal_;
  std::vector<std::array<int, 3>> neighbour_;
  std::vector<std::vector<int>> vertex_faces_;
  std::vector<std::array<V3, 2>> vertex_line_;
  std::vector<bool> strong_;
  std::vector<std::vector<int>> near_singular_;
  std::vector<SegmentGrid> grid_;
  std::vector<Traced> lines_;
};

// Calls f(line, i) for every segment i (points i, i+1; the closing one of a loop).
template <class F>
void ForSegments(const Streamline& l, F f) {
  const size_t n = l.points.size();
  if (n < 2) return;
  for (size_t i = 0; i + 1 < n; ++i) f(l.points[i], l.points[i + 1]);
  if (l.closed) f(l.points[n - 1], l.points[0]);
}

}  // namespace

StreamlineResult TraceStreamlines(const StreamlineInput& input, const StreamlineOptions& options) {
  CHECK_EQ(input.directions.size(), input.triangles.size());
  CHECK_EQ(input.valid.size(), input.triangles.size());
  CHECK(options.separation > 0 && std::isfinite(options.separation));
  CHECK(options.test_ratio > 0 && options.test_ratio <= 1);
  CHECK(options.step > 0 && options.step <= 1);
  for (const auto& t : input.triangles) {
    for (int v : t) CHECK(v >= 0 && v < int(input.points.size()));
  }
  for (const auto& s : input.singularities) {
    CHECK(s.vertex >= 0 && s.vertex < int(input.points.size()));
  }
  Tracer tracer(input, options);
  return tracer.Run(options.separatrices);
}

double SmallestSeparation(const std::vector<Streamline>& lines, double cell) {
  double best = kInf;
  for (int family = 0; family < 2; ++family) {
    SegmentGrid grid(cell);
    for (size_t l = 0; l < lines.size(); ++l) {
      if (lines[l].family != family) continue;
      ForSegments(lines[l], [&](const V3& a, const V3& b) { grid.Add({a, b, int(l), 0, 0}); });
    }
    for (const Segment& s : grid.segments()) {
      grid.Near(s.a, s.b, cell, [&](const Segment& o) {
        if (o.line == s.line) return;
        if (lines[size_t(o.line)].separatrix && lines[size_t(s.line)].separatrix) return;
        best = std::min(best, SegmentDistance(s.a, s.b, o.a, o.b));
      });
    }
  }
  return best;
}

double SmallestSelfDistance(const std::vector<Streamline>& lines, double window, double cell) {
  double best = kInf;
  for (size_t l = 0; l < lines.size(); ++l) {
    SegmentGrid grid(cell);
    double s = 0;
    ForSegments(lines[l], [&](const V3& a, const V3& b) {
      const double ds = (b - a).norm();
      grid.Add({a, b, int(l), s, s + ds});
      s += ds;
    });
    const double total = s;
    for (const Segment& x : grid.segments()) {
      grid.Near(x.a, x.b, cell, [&](const Segment& y) {
        double gap = std::max(0.0, std::max(x.s0, y.s0) - std::min(x.s1, y.s1));
        if (lines[l].closed) gap = std::min(gap, total - (std::max(x.s1, y.s1) - std::min(x.s0, y.s0)));
        if (gap <= window) return;
        best = std::min(best, SegmentDistance(x.a, x.b, y.a, y.b));
      });
    }
  }
  return best;
}

int ExpectedSeparatrices(double index) {
  if (std::abs(index - 1) < 1e-9) return -1;
  return int(std::lround(2 * std::abs(1 - index)));
}

}  // namespace archgeo
