// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The quad mesh of a parameterised base complex (spectral/base_complex_charts.h,
// step 3).
#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "spectral/base_complex_charts.h"

namespace archgeo {
namespace {

// Point location in a chart's parameter triangles (a uniform grid of buckets).
class ChartLocator {
 public:
  ChartLocator(const std::vector<Eigen::Vector3d>& points,
               const std::vector<std::array<int, 3>>& triangles, const Chart& chart,
               const ChartMap& map)
      : points_(points), triangles_(triangles), chart_(chart), map_(map) {
    local_.reserve(chart.vertices.size());
    for (size_t i = 0; i < chart.vertices.size(); ++i) local_[chart.vertices[i]] = int(i);
    cells_ = std::max(1, int(std::sqrt(double(chart.triangles.size()) / 2)));
    buckets_.assign(size_t(cells_) * cells_, {});
    for (size_t k = 0; k < chart.triangles.size(); ++k) {
      Eigen::Vector2d lo = Uv(k, 0), hi = lo;
      for (int c = 1; c < 3; ++c) {
        lo = lo.cwiseMin(Uv(k, c));
        hi = hi.cwiseMax(Uv(k, c));
      }
      const int x0 = Cell(lo.x()), x1 = Cell(hi.x()), y0 = Cell(lo.y()), y1 = Cell(hi.y());
      for (int x = x0; x <= x1; ++x) {
        for (int y = y0; y <= y1; ++y) buckets_[size_t(x) * cells_ + y].push_back(int(k));
      }
    }
  }

  // The surface point at parameter q; `*missed` when q is in no triangle (the
  // nearest by barycentric coordinates is used, clamped).
  Eigen::Vector3d Map(const Eigen::Vector2d& q, bool* missed) const {
    int best = -1;
    Eigen::Vector3d lambda, best_lambda;
    double score = -std::numeric_limits<double>::infinity();
    for (int k : buckets_[size_t(Cell(q.x())) * cells_ + Cell(q.y())]) {
      if (Bary(k, q, lambda) && lambda.minCoeff() > score) {
        score = lambda.minCoeff();
        best = k;
        best_lambda = lambda;
      }
    }
    *missed = false;
    if (score < -kInside) {
      for (size_t k = 0; k < chart_.triangles.size(); ++k) {
        if (Bary(int(k), q, lambda) && lambda.minCoeff() > score) {
          score = lambda.minCoeff();
          best = int(k);
          best_lambda = lambda;
        }
      }
      *missed = score < -kInside;
    }
    if (best < 0) {
      *missed = true;
      return points_[chart_.vertices[0]];
    }
    if (*missed) best_lambda = best_lambda.cwiseMax(0.0) / best_lambda.cwiseMax(0.0).sum();
    const std::array<int, 3>& t = triangles_[chart_.triangles[size_t(best)]];
    return best_lambda[0] * points_[t[0]] + best_lambda[1] * points_[t[1]] +
           best_lambda[2] * points_[t[2]];
  }

 private:
  static constexpr double kInside = 1e-9;

  const Eigen::Vector2d& Uv(size_t k, int corner) const {
    return map_.uv[local_.at(triangles_[chart_.triangles[k]][corner])];
  }
  int Cell(double x) const { return std::clamp(int(x * cells_), 0, cells_ - 1); }
  bool Bary(int k, const Eigen::Vector2d& q, Eigen::Vector3d& lambda) const {
    const Eigen::Vector2d &a = Uv(size_t(k), 0), &b = Uv(size_t(k), 1), &c = Uv(size_t(k), 2);
    const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    if (!(std::abs(area) > 0)) return false;
    lambda[1] = ((q - a).x() * (c - a).y() - (q - a).y() * (c - a).x()) / area;
    lambda[2] = ((b - a).x() * (q - a).y() - (b - a).y() * (q - a).x()) / area;
    lambda[0] = 1 - lambda[1] - lambda[2];
    return true;
  }

  const std::vector<Eigen::Vector3d>& points_;
  const std::vector<std::array<int, 3>>& triangles_;
  const Chart& chart_;
  const ChartMap& map_;
  std::unordered_map<int, int> local_;
  int cells_ = 1;
  std::vector<std::vector<int>> buckets_;
};

// The point at arc-length fraction s along a path.
Eigen::Vector3d PathPoint(const std::vector<Eigen::Vector3d>& points, const BaseEdgePath& e,
                          double s) {
  const double target = s * e.length;
  double at = 0;
  for (size_t i = 1; i < e.path.size(); ++i) {
    const Eigen::Vector3d &p = points[e.path[i - 1]], &q = points[e.path[i]];
    const double l = (q - p).norm();
    if (at + l >= target && l > 0) return p + (target - at) / l * (q - p);
    at += l;
  }
  return points[e.path.back()];
}

struct ExtractState {
  QuadExtraction* out;
  std::vector<std::vector<int>> edge_vertex;  // per base edge: its n + 1 samples, a → b
  int n = 0;

  int Add(const Eigen::Vector3d& p) {
    out->points.push_back(p);
    return int(out->points.size()) - 1;
  }
};

// Sample i (from corner k) of side k of chart f.
int ChartSideVertex(const ChartLayout& layout, const ExtractState& st, int f, int k, int i) {
  const int sides = int(layout.sides[f].size());
  const auto [e, reversed] = layout.sides[f][((k % sides) + sides) % sides];
  return st.edge_vertex[e][reversed ? st.n - i : i];
}

// Each side's samples mapped by this chart, against the welded samples (at
// equal arc length along the base edge's path).
void CompareSides(const ChartLocator& locate, const ChartLayout& layout,
                  const std::vector<Eigen::Vector2d>& corners, int f, ExtractState& st) {
  const int sides = int(corners.size());
  for (int k = 0; k < sides; ++k) {
    for (int i = 0; i <= st.n; ++i) {
      const double s = double(i) / st.n;
      bool missed = false;
      const Eigen::Vector3d p = locate.Map((1 - s) * corners[k] + s * corners[(k + 1) % sides], &missed);
      st.out->unlocated += missed;
      const Eigen::Vector3d& welded = st.out->points[size_t(ChartSideVertex(layout, st, f, k, i))];
      st.out->shared_edge_mismatch = std::max(st.out->shared_edge_mismatch, (p - welded).norm());
    }
  }
}

void ExtractQuadChart(const ChartLayout& layout, const ChartLocator& locate, int f,
                      ExtractState& st) {
  const int n = st.n;
  std::vector<int> inner(size_t(std::max(0, n - 1)) * std::max(0, n - 1));
  for (int i = 1; i < n; ++i) {
    for (int j = 1; j < n; ++j) {
      bool missed = false;
      inner[size_t(i - 1) * (n - 1) + (j - 1)] =
          st.Add(locate.Map(Eigen::Vector2d(double(i) / n, double(j) / n), &missed));
      st.out->unlocated += missed;
    }
  }
  auto at = [&](int i, int j) {
    if (j == 0) return ChartSideVertex(layout, st, f, 0, i);
    if (i == n) return ChartSideVertex(layout, st, f, 1, j);
    if (j == n) return ChartSideVertex(layout, st, f, 2, n - i);
    if (i == 0) return ChartSideVertex(layout, st, f, 3, n - j);
    return inner[size_t(i - 1) * (n - 1) + (j - 1)];
  };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) st.out->quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  }
}

// A triangle chart as three quads (corner k, midpoint of side k, centre,
// midpoint of side k − 1), each an (n/2) × (n/2) grid.
void ExtractTriangleChart(const ChartLayout& layout, const ChartLocator& locate,
                          const std::vector<Eigen::Vector2d>& c, int f, ExtractState& st) {
  const int n = st.n, m = n / 2;
  const Eigen::Vector2d centre = (c[0] + c[1] + c[2]) / 3;
  std::array<Eigen::Vector2d, 3> mid;
  for (int k = 0; k < 3; ++k) mid[k] = 0.5 * (c[k] + c[(k + 1) % 3]);
  bool missed = false;
  const int g = st.Add(locate.Map(centre, &missed));
  st.out->unlocated += missed;
  st.out->centre_vertex[f] = g;
  std::array<std::vector<int>, 3> spoke;  // midpoint k → centre, samples 1 … m − 1
  for (int k = 0; k < 3; ++k) {
    for (int t = 1; t < m; ++t) {
      const double s = double(t) / m;
      spoke[k].push_back(st.Add(locate.Map((1 - s) * mid[k] + s * centre, &missed)));
      st.out->unlocated += missed;
    }
  }
  auto spoke_at = [&](int k, int t) {
    k = (k + 3) % 3;
    if (t == 0) return ChartSideVertex(layout, st, f, k, m);
    if (t == m) return g;
    return spoke[k][size_t(t - 1)];
  };
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector2d &a = c[k], &b = mid[k], &d = mid[(k + 2) % 3];
    std::vector<int> inner(size_t(std::max(0, m - 1)) * std::max(0, m - 1));
    for (int i = 1; i < m; ++i) {
      for (int j = 1; j < m; ++j) {
        const double s = double(i) / m, t = double(j) / m;
        const Eigen::Vector2d q = (1 - s) * (1 - t) * a + s * (1 - t) * b + s * t * centre + (1 - s) * t * d;
        inner[size_t(i - 1) * (m - 1) + (j - 1)] = st.Add(locate.Map(q, &missed));
        st.out->unlocated += missed;
      }
    }
    auto at = [&](int i, int j) {
      if (j == 0) return ChartSideVertex(layout, st, f, k, i);
      if (i == 0) return ChartSideVertex(layout, st, f, k - 1, n - j);
      if (i == m) return spoke_at(k, j);
      if (j == m) return spoke_at(k - 1, i);
      return inner[size_t(i - 1) * (m - 1) + (j - 1)];
    };
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m; ++j) {
        st.out->quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }
}

// A triangle chart on the lattice A + (i/n)(B − A) + (j/n)(C − A) over
// A = corner b + 2, B = corner b + 2 + 1, C = corner b + 2 + 2. A strip
// (side b on the open boundary, §4.1.4): its lines run parallel to the two
// inner sides and meet them at their n samples, as the neighbouring charts'
// grid lines do; cells are quads but the n the boundary side cuts, which
// are triangles. Otherwise (`strip` false) every cell is two triangles.
void ExtractLatticeChart(const ChartLayout& layout, const ChartLocator& locate,
                         const std::vector<Eigen::Vector2d>& c, int f, int b, bool strip,
                         ExtractState& st) {
  const int n = st.n, a = (b + 2) % 3;
  const Eigen::Vector2d &A = c[size_t(a)], &B = c[size_t((a + 1) % 3)], &C = c[size_t((a + 2) % 3)];
  std::vector<int> inner(size_t(n + 1) * (n + 1), -1);
  for (int i = 1; i < n; ++i) {
    for (int j = 1; i + j < n; ++j) {
      bool missed = false;
      const Eigen::Vector2d q = A + double(i) / n * (B - A) + double(j) / n * (C - A);
      inner[size_t(i) * (n + 1) + j] = st.Add(locate.Map(q, &missed));
      st.out->unlocated += missed;
    }
  }
  auto at = [&](int i, int j) {
    if (j == 0) return ChartSideVertex(layout, st, f, a, i);          // A → B
    if (i == 0) return ChartSideVertex(layout, st, f, a + 2, n - j);  // C → A
    if (i + j == n) return ChartSideVertex(layout, st, f, a + 1, j);  // B → C
    return inner[size_t(i) * (n + 1) + j];
  };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; i + j < n; ++j) {
      if (i + j + 1 == n || !strip) st.out->triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
      if (i + j + 1 == n) continue;
      if (strip) {
        st.out->quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      } else {
        st.out->triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }
  if (!strip) return;
  for (int j = 1; j < n; ++j) st.out->strip_boundary_vertex.push_back(at(n - j, j));
}

// The side of triangle chart f on the surface boundary, or −1 unless exactly one is.
int StripSide(const ChartLayout& layout, int f) {
  int side = -1, count = 0;
  for (int k = 0; k < 3; ++k) {
    if (layout.edges[size_t(layout.sides[f][k].first)].boundary) side = k, ++count;
  }
  return count == 1 ? side : -1;
}

}  // namespace

bool StripChart(const ChartLayout& layout, int f, ChartFill fill) {
  return fill == ChartFill::kStrip && layout.sides[size_t(f)].size() == 3 && StripSide(layout, f) >= 0;
}

QuadExtraction ExtractQuads(const std::vector<Eigen::Vector3d>& points,
                            const std::vector<std::array<int, 3>>& triangles,
                            const BaseComplex& base, const ChartLayout& layout,
                            const std::vector<ChartMap>& maps, int n, ChartFill fill) {
  QuadExtraction out;
  ExtractState st;
  st.out = &out;
  st.n = n;
  for (size_t v = 0; v < base.nodes.size(); ++v) {
    out.node_vertex.push_back(st.Add(points[base.nodes[v]]));
  }
  for (const BaseEdgePath& e : layout.edges) {
    std::vector<int> samples{out.node_vertex[e.a]};
    for (int i = 1; i < n; ++i) samples.push_back(st.Add(PathPoint(points, e, double(i) / n)));
    samples.push_back(out.node_vertex[e.b]);
    st.edge_vertex.push_back(samples);
  }
  out.centre_vertex.assign(layout.charts.size(), -1);
  for (size_t f = 0; f < layout.charts.size(); ++f) {
    const std::vector<Eigen::Vector2d> corners = ChartDomain(int(layout.sides[f].size()));
    const ChartLocator locate(points, triangles, layout.charts[f], maps[f]);
    CompareSides(locate, layout, corners, int(f), st);
    if (fill == ChartFill::kTriangles) {
      if (corners.size() != 3) {
        throw BaseComplexError("base face " + std::to_string(f),
                               "a quad: triangle output (charts.output: triangles) needs a "
                               "triangle base complex");
      }
      ExtractLatticeChart(layout, locate, corners, int(f), 1, false, st);
    } else if (StripChart(layout, int(f), fill)) {
      ExtractLatticeChart(layout, locate, corners, int(f), StripSide(layout, int(f)), true, st);
    } else if (corners.size() == 3) {
      ExtractTriangleChart(layout, locate, corners, int(f), st);
    } else {
      ExtractQuadChart(layout, locate, int(f), st);
    }
  }
  return out;
}

}  // namespace archgeo
