// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "surfaces/force_directed.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <glog/logging.h>

#include "surfaces/grid_cover.h"

namespace archgeo {
namespace {

using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;

// The fixed structure of the grid the iterations use.
struct Stencils {
  std::vector<GridNeighbours> neighbours;
  std::vector<VertexRole> role;
  std::vector<BoundaryStencil> boundary;  // valid where role == kBoundary
  std::vector<std::array<int, 2>> edges;
};

Stencils StencilsOf(const Grid& grid) {
  Stencils s;
  const int n = grid.NumVertices();
  s.neighbours.resize(n);
  s.role.resize(n);
  s.boundary.resize(n, {-1, -1, -1, -1});
  for (int v = 0; v < n; ++v) {
    s.neighbours[v] = Neighbours(grid, v);
    s.role[v] = Role(grid, v);
    if (s.role[v] == VertexRole::kBoundary) s.boundary[v] = BoundaryStencilAt(grid, v);
  }
  s.edges = GridEdges(grid);
  return s;
}

// The parameter step that moves x(u, v) to the normal projection of `target`
// onto the tangent plane at (u, v) (eq. 3): the coordinates of the tangential
// part of target − x in the basis {x_u, x_v}. Zero where the basis degenerates.
Vec2 ParameterStep(const Vec3& x, const Vec3& xu, const Vec3& xv, const Vec3& target) {
  const Vec3 d = target - x;
  Eigen::Matrix2d g;
  g << xu.dot(xu), xu.dot(xv), xu.dot(xv), xv.dot(xv);
  const double det = g.determinant();
  if (!(det > 1e-14 * g(0, 0) * g(1, 1))) return Vec2::Zero();
  return g.inverse() * Vec2(xu.dot(d), xv.dot(d));
}

// The parameter step along a curve with tangent t at x that moves x to the
// normal projection of `target` onto the tangent line (zero where t = 0).
double SideStep(const Vec3& x, const Vec3& t, const Vec3& target) {
  const double tt = t.squaredNorm();
  return tt > 0 ? t.dot(target - x) / tt : 0.0;
}

// Every Table 1 measure of `now` within `tolerance` of `then` (NaN = NaN).
bool Unchanged(const QualityMeasures& now, const QualityMeasures& then, double tolerance) {
  const auto same = [&](double a, double b) {
    return (std::isnan(a) && std::isnan(b)) || std::abs(a - b) <= tolerance;
  };
  return same(now.mdo, then.mdo) && same(now.ado, then.ado) && same(now.mde, then.mde) &&
         same(now.ade, then.ade);
}

bool ThresholdsMet(const QualityMeasures& q, const ForceDirectedOptions& o) {
  const bool any = o.stop_mdo > 0 || o.stop_ado > 0 || o.stop_mde > 0 || o.stop_ade > 0;
  if (!any) return false;
  // A NaN measure (no crossings / quads) does not hold a threshold.
  const auto holds = [](double threshold, double value) {
    return threshold <= 0 || value <= threshold;
  };
  return holds(o.stop_mdo, q.mdo) && holds(o.stop_ado, q.ado) && holds(o.stop_mde, q.mde) &&
         holds(o.stop_ade, q.ade);
}

// A boundary vertex back on its side: the held coordinate at the side, the
// other within the side's extent (a vertex slides along its side, not past
// the corner).
Vec2 HeldOnSide(Vec2 uv, const BoundaryHold& hold, const ParameterDomain& covered,
                const Grid& grid) {
  if (hold.u) {
    uv[0] = hold.u_value;
    if (!grid.closed_v) uv[1] = std::clamp(uv[1], covered.v0, covered.v1);
  }
  if (hold.v) {
    uv[1] = hold.v_value;
    if (!grid.closed_u) uv[0] = std::clamp(uv[0], covered.u0, covered.u1);
  }
  return uv;
}

}  // namespace

const char* ForceStopName(ForceStop stop) {
  switch (stop) {
    case ForceStop::kThresholds: return "thresholds";
    case ForceStop::kStalled: return "stalled";
    case ForceStop::kPlateau: return "plateau";
    case ForceStop::kMaxIterations: return "max_iterations";
  }
  return "";
}

ForceDirectedResult RunForceDirected(const Surface& surface, const Grid& initial,
                                     const ForceDirectedOptions& o) {
  CHECK(o.d_o >= 0 && o.d_b >= 0 && o.d_l >= 0) << "RunForceDirected: negative factor";
  CHECK(std::isfinite(o.d_o) && std::isfinite(o.d_b) && std::isfinite(o.d_l));
  CHECK(std::isfinite(o.ideal_length) && o.ideal_length >= 0);
  CHECK(o.projection_repetitions >= 0 && o.max_iterations >= 0 && o.history_stride >= 1);
  CHECK(std::isfinite(o.plateau_tolerance) && o.plateau_tolerance >= 0);
  CHECK_EQ(static_cast<int>(initial.uv.size()), initial.NumVertices());
  const ParameterDomain domain = surface.Domain();
  CHECK(!initial.closed_u || domain.periodic_u) << "RunForceDirected: u is not periodic";
  CHECK(!initial.closed_v || domain.periodic_v) << "RunForceDirected: v is not periodic";
  for (const Vec2& uv : initial.uv) CHECK(uv.allFinite()) << "RunForceDirected: non-finite (u, v)";

  ForceDirectedResult result;
  result.grid = initial;
  Grid& grid = result.grid;
  const int n = grid.NumVertices();
  const Stencils st = StencilsOf(grid);
  std::vector<BoundaryHold> hold(static_cast<size_t>(n));
  if (o.hold_boundary) {
    for (int v = 0; v < n; ++v) hold[size_t(v)] = HoldOf(grid, v, o.covered);
  }
  const GridNetwork network = NetworkOfGrid(grid);
  const double L = o.ideal_length > 0 ? o.ideal_length : MeanEdgeLength(grid, surface);
  CHECK(L > 0) << "RunForceDirected: the grid has no length";
  result.ideal_length = L;

  std::vector<Vec3> x = GridPoints(grid, surface);
  std::vector<Vec3> xu(n), xv(n), disp(n);
  std::vector<Vec2> step(n, Vec2::Zero()), previous_step(n, Vec2::Zero());
  result.before = MeasureGridNetwork(network, x);
  result.history.push_back({0, result.before, 0.0});

  int k = 0;
  ForceStop stop = ForceStop::kMaxIterations;
  double max_move = 0.0;
  while (k < o.max_iterations) {
    for (int v = 0; v < n; ++v) surface.Tangents(grid.uv[v][0], grid.uv[v][1], &xu[v], &xv[v]);
    std::fill(disp.begin(), disp.end(), Vec3::Zero());

    // Step 1: orthogonality (eq. 1) at interior points, anti-folding (eq. 2)
    // at boundary points, nothing at corners.
    for (int v = 0; v < n; ++v) {
      if (st.role[v] == VertexRole::kInterior) {
        const Vec3 normal = xu[v].cross(xv[v]).normalized();
        Vec3 sum = Vec3::Zero();
        const GridNeighbours& nb = st.neighbours[v];
        for (int w : {nb.l0, nb.l1, nb.t0, nb.t1}) {
          Vec3 e = x[w] - x[v];
          e -= e.dot(normal) * normal;  // projected on the tangential plane
          const double length = e.norm();
          if (length > 0) sum += e / length;
        }
        disp[v] += o.d_o * L * sum;
      } else if (st.role[v] == VertexRole::kBoundary) {
        const BoundaryStencil& b = st.boundary[v];
        const Vec3 along = x[b.p2] - x[b.p1];
        const double length = along.norm();
        if (length > 0) {
          const Vec3 unit = along / length;
          disp[v] += o.d_b * (x[b.p3] - x[b.p0]).dot(unit) * unit;
        }
      }
    }
    // Step 2: edge lengths towards L.
    for (const auto& e : st.edges) {
      const Vec3 d = x[e[1]] - x[e[0]];
      const double length = d.norm();
      if (!(length > 0)) continue;
      const Vec3 f = o.d_l * (L - length) / length * d;
      disp[e[0]] -= f;
      disp[e[1]] += f;
    }
    // Step 3: displacement and back-projection through (u, v) (eq. 3).
    max_move = 0.0;
    double max_change = 0.0;
    previous_step.swap(step);
    for (int v = 0; v < n; ++v) {
      const Vec3 target = x[v] + disp[v];
      const BoundaryHold& held = hold[size_t(v)];
      // A held vertex: the target projected onto its side's tangent (x_v on
      // a side u = const, x_u on v = const), not the coordinate of the
      // tangent-plane step in the skew basis {x_u, x_v}, which would turn a
      // push across the side into a slide along it.
      const auto step_of = [&](const Vec3& at, const Vec3& pu, const Vec3& pv) {
        if (held.u && held.v) return Vec2(Vec2::Zero());
        if (held.u) return Vec2(0, SideStep(at, pv, target));
        if (held.v) return Vec2(SideStep(at, pu, target), 0);
        return ParameterStep(at, pu, pv, target);
      };
      Vec2 uv = grid.uv[v] + step_of(x[v], xu[v], xv[v]);
      for (int r = 0; r < o.projection_repetitions; ++r) {
        Vec3 pu, pv;
        surface.Tangents(uv[0], uv[1], &pu, &pv);
        uv += step_of(surface.Point(uv), pu, pv);
      }
      if (o.clamp_to_domain) {
        if (!domain.periodic_u) uv[0] = std::clamp(uv[0], domain.u0, domain.u1);
        if (!domain.periodic_v) uv[1] = std::clamp(uv[1], domain.v0, domain.v1);
      }
      if (hold[size_t(v)].Any()) uv = HeldOnSide(uv, hold[size_t(v)], o.covered, grid);
      step[v] = uv - grid.uv[v];
      const Vec2 change = step[v] - previous_step[v];
      max_change = std::max(max_change, (xu[v] * change[0] + xv[v] * change[1]).norm());
      grid.uv[v] = surface.Wrapped(uv);
      const Vec3 moved = surface.Point(grid.uv[v]);
      max_move = std::max(max_move, (moved - x[v]).norm());
      x[v] = moved;
    }
    ++k;

    if (k > 1 && o.stall_tolerance > 0 && max_change <= o.stall_tolerance * L) {
      stop = ForceStop::kStalled;
      break;
    }
    if (k % o.history_stride == 0) {
      const GridQuality q = MeasureGridNetwork(network, x);
      result.history.push_back({k, q, max_move / L});
      if (ThresholdsMet(q.Table1(), o)) {
        stop = ForceStop::kThresholds;
        break;
      }
      if (o.plateau_window > 0) {
        // The latest entry at least plateau_window iterations back.
        const ForceHistoryEntry* then = nullptr;
        for (const ForceHistoryEntry& h : result.history) {
          if (h.iteration <= k - o.plateau_window) then = &h;
        }
        if (then != nullptr && Unchanged(q.Table1(), then->quality.Table1(), o.plateau_tolerance)) {
          stop = ForceStop::kPlateau;
          break;
        }
      }
    }
  }
  result.iterations = k;
  result.stop = stop;
  result.after = MeasureGridNetwork(network, x);
  if (result.history.back().iteration != k) result.history.push_back({k, result.after, max_move / L});
  if (stop == ForceStop::kMaxIterations && ThresholdsMet(result.after.Table1(), o)) {
    result.stop = ForceStop::kThresholds;
  }
  return result;
}

}  // namespace archgeo
