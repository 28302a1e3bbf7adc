// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "surfaces/grid_cover.h"

#include <array>
#include <cmath>

#include <Eigen/Geometry>
#include <glog/logging.h>

namespace archgeo {
namespace {

constexpr int kCells = 64;  // per direction
// Gauss–Legendre, 3 points on [−1, 1].
constexpr double kNodes[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
constexpr double kWeights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

double TriangleArea(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return 0.5 * (b - a).cross(c - a).norm();
}

// Twice the signed area of the polygon p (shoelace).
double SignedArea2(const std::array<Eigen::Vector2d, 4>& p) {
  double s = 0.0;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d& a = p[size_t(k)];
    const Eigen::Vector2d& b = p[size_t((k + 1) % 4)];
    s += a[0] * b[1] - a[1] * b[0];
  }
  return s;
}

// The quad's (u, v) corners in the chart of its first corner.
std::array<Eigen::Vector2d, 4> QuadChart(const Grid& grid, const std::array<int, 4>& q,
                                         const Surface& surface) {
  std::array<Eigen::Vector2d, 4> p;
  p[0] = grid.uv[size_t(q[0])];
  for (size_t k = 1; k < 4; ++k) p[k] = surface.NearestChart(grid.uv[size_t(q[k])], p[0]);
  return p;
}

}  // namespace

ParameterDomain CoveredDomain(const ParameterDomain& domain, const Grid& grid, double fraction) {
  CHECK(fraction > 0.0 && fraction <= 1.0) << "CoveredDomain: fraction " << fraction;
  const int open = int(!grid.closed_u) + int(!grid.closed_v);
  const double scale = open == 2 ? std::sqrt(fraction) : fraction;
  ParameterDomain covered = domain;
  if (!grid.closed_u) {
    const double centre = 0.5 * (domain.u0 + domain.u1), half = 0.5 * scale * domain.PeriodU();
    covered.u0 = scale == 1.0 ? domain.u0 : centre - half;
    covered.u1 = scale == 1.0 ? domain.u1 : centre + half;
  }
  if (!grid.closed_v) {
    const double centre = 0.5 * (domain.v0 + domain.v1), half = 0.5 * scale * domain.PeriodV();
    covered.v0 = scale == 1.0 ? domain.v0 : centre - half;
    covered.v1 = scale == 1.0 ? domain.v1 : centre + half;
  }
  return covered;
}

void MapOpenDirections(Grid* grid, const ParameterDomain& from, const ParameterDomain& to) {
  const int nu = grid->nu, nv = grid->nv;
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      Eigen::Vector2d& p = grid->uv[size_t(grid->Index(i, j))];
      // The bounds exactly (the boundary rows sit on the sides).
      if (!grid->closed_u) {
        p[0] = i == 0 ? to.u0 : i == nu - 1 ? to.u1
                              : to.u0 + (p[0] - from.u0) / from.PeriodU() * to.PeriodU();
      }
      if (!grid->closed_v) {
        p[1] = j == 0 ? to.v0 : j == nv - 1 ? to.v1
                              : to.v0 + (p[1] - from.v0) / from.PeriodV() * to.PeriodV();
      }
    }
  }
}

BoundaryHold HoldOf(const Grid& grid, int vertex, const ParameterDomain& covered) {
  const int i = vertex % grid.nu, j = vertex / grid.nu;
  BoundaryHold h;
  if (!grid.closed_u && (i == 0 || i == grid.nu - 1)) {
    h.u = true;
    h.u_value = i == 0 ? covered.u0 : covered.u1;
  }
  if (!grid.closed_v && (j == 0 || j == grid.nv - 1)) {
    h.v = true;
    h.v_value = j == 0 ? covered.v0 : covered.v1;
  }
  return h;
}

double PatchArea(const Surface& surface, const ParameterDomain& d) {
  const double hu = d.PeriodU() / kCells, hv = d.PeriodV() / kCells;
  double area = 0.0;
  for (int a = 0; a < kCells; ++a) {
    for (int b = 0; b < kCells; ++b) {
      for (int p = 0; p < 3; ++p) {
        for (int q = 0; q < 3; ++q) {
          const double u = d.u0 + hu * (a + 0.5 * (1.0 + kNodes[p]));
          const double v = d.v0 + hv * (b + 0.5 * (1.0 + kNodes[q]));
          Eigen::Vector3d xu, xv;
          surface.Tangents(u, v, &xu, &xv);
          area += kWeights[p] * kWeights[q] * xu.cross(xv).norm();
        }
      }
    }
  }
  return area * 0.25 * hu * hv;
}

GridCoverage MeasureCoverage(const Grid& grid, const Grid& reference, const Surface& surface,
                             double patch_area) {
  CHECK_EQ(grid.uv.size(), reference.uv.size()) << "MeasureCoverage: another grid";
  const ParameterDomain d = surface.Domain();
  GridCoverage c;
  c.patch_area = patch_area;
  c.domain_area = d.PeriodU() * d.PeriodV();
  const std::vector<Eigen::Vector3d> x = GridPoints(grid, surface);
  double oriented2 = 0.0;
  for (const std::array<int, 4>& q : GridQuads(grid)) {
    const Eigen::Vector3d& a = x[size_t(q[0])];
    const Eigen::Vector3d& b = x[size_t(q[1])];
    const Eigen::Vector3d& e = x[size_t(q[2])];
    const Eigen::Vector3d& f = x[size_t(q[3])];
    c.grid_area += 0.5 * (TriangleArea(a, b, e) + TriangleArea(a, e, f) + TriangleArea(a, b, f) +
                          TriangleArea(b, e, f));
    const double sign = SignedArea2(QuadChart(reference, q, surface)) < 0 ? -1.0 : 1.0;
    oriented2 += sign * SignedArea2(QuadChart(grid, q, surface));
  }
  c.parameter_area = 0.5 * oriented2;
  c.area_fraction = patch_area > 0 ? c.grid_area / patch_area : 0.0;
  c.parameter_fraction = c.domain_area > 0 ? c.parameter_area / c.domain_area : 0.0;
  return c;
}

}  // namespace archgeo
