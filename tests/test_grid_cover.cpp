// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// surfaces/grid_cover.h against analytic values: patch areas of a plane, a
// cylinder and a torus; the coverage of uniform grids (a plane grid covers
// its patch exactly, a cylinder's closed rows are chords: sin(π/n)/(π/n));
// a grid shrunk about its centre covers the square of the factor; a folded
// quad subtracts its parameter area; the covered part of a domain has the
// fraction asked for; and the boundary holds of each vertex role.
#include <gtest/gtest.h>

#include <cmath>

#include "surfaces/grid.h"
#include "surfaces/grid_cover.h"
#include "surfaces/surface_factory.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

// Quadrature of a smooth integrand on 64 × 64 cells, 3 × 3 Gauss points.
constexpr double kQuadrature = 1e-10;  // relative
constexpr double kExact = 1e-12;

TEST(GridCover, PatchAreasOfAnalyticSurfaces) {
  const Surface plane = MakeSurface("plane", {{"a", 20}, {"b", 10}});
  EXPECT_NEAR(PatchArea(plane, plane.Domain()), 200.0, 200.0 * kExact);
  const Surface cylinder = MakeSurface("cylinder", {{"R", 2}, {"H", 3}});
  EXPECT_NEAR(PatchArea(cylinder, cylinder.Domain()), 2 * M_PI * 2 * 3, 12 * M_PI * kQuadrature);
  const Surface torus = MakeSurface("torus", {{"R", 3}, {"r", 1}});
  const double torus_area = 4 * M_PI * M_PI * 3 * 1;
  EXPECT_NEAR(PatchArea(torus, torus.Domain()), torus_area, torus_area * kQuadrature);
}

TEST(GridCover, AUniformGridCoversItsPatch) {
  const Surface plane = MakeSurface("plane", {{"a", 20}, {"b", 10}});
  const Grid g = MakeUniformGrid(plane, 11, 6, GridType::kOpen);
  const GridCoverage c = MeasureCoverage(g, g, plane, PatchArea(plane, plane.Domain()));
  EXPECT_NEAR(c.grid_area, 200.0, 200.0 * kExact);
  EXPECT_NEAR(c.area_fraction, 1.0, kExact);
  EXPECT_NEAR(c.parameter_fraction, 1.0, kExact);

  // A cylinder closed in u: n chords of the circle, so the grid's area is
  // n · 2R sin(π/n) · H against 2πRH.
  const int n = 12;
  const Surface cylinder = MakeSurface("cylinder", {{"R", 2}, {"H", 3}});
  const Grid closed = MakeUniformGrid(cylinder, n, 5, GridType::kClosedU);
  const GridCoverage k =
      MeasureCoverage(closed, closed, cylinder, PatchArea(cylinder, cylinder.Domain()));
  EXPECT_NEAR(k.area_fraction, std::sin(M_PI / n) / (M_PI / n), kQuadrature);
  EXPECT_NEAR(k.parameter_fraction, 1.0, kExact);

  // A torus closed both ways: its quads cover the whole parameter domain.
  const Surface torus = MakeSurface("torus", {{"R", 3}, {"r", 1}});
  const Grid both = MakeUniformGrid(torus, 24, 12, GridType::kClosedBoth);
  const GridCoverage t = MeasureCoverage(both, both, torus, PatchArea(torus, torus.Domain()));
  EXPECT_NEAR(t.parameter_fraction, 1.0, kExact);
  EXPECT_GT(t.area_fraction, 0.95);
  EXPECT_LT(t.area_fraction, 1.0);
}

TEST(GridCover, AShrunkGridCoversTheSquareOfItsFactor) {
  const Surface plane = MakeSurface("plane", {{"a", 10}, {"b", 10}});
  const Grid g = MakeUniformGrid(plane, 9, 9, GridType::kOpen);
  Grid shrunk = g;
  const Eigen::Vector2d centre(5, 5);
  for (Eigen::Vector2d& p : shrunk.uv) p = centre + 0.5 * (p - centre);
  const GridCoverage c = MeasureCoverage(shrunk, g, plane, PatchArea(plane, plane.Domain()));
  EXPECT_NEAR(c.area_fraction, 0.25, kExact);
  EXPECT_NEAR(c.parameter_fraction, 0.25, kExact);
}

TEST(GridCover, AFoldedQuadSubtractsItsParameterArea) {
  // A 2 × 2-quad plane grid whose centre vertex is moved beyond the corner
  // (2, 2): the boundary polygon is unchanged, so the oriented areas still
  // sum to the square's (4), while the unsigned sum would exceed it.
  const Surface plane = MakeSurface("plane", {{"a", 2}, {"b", 2}});
  const Grid g = MakeUniformGrid(plane, 3, 3, GridType::kOpen);
  Grid folded = g;
  folded.uv[size_t(g.Index(1, 1))] = Eigen::Vector2d(2.5, 2.5);
  const GridCoverage c = MeasureCoverage(folded, g, plane, PatchArea(plane, plane.Domain()));
  EXPECT_NEAR(c.parameter_area, 4.0, kExact);
  EXPECT_NEAR(c.parameter_fraction, 1.0, kExact);
}

TEST(GridCover, TheCoveredDomainHasTheFractionAskedFor) {
  const ParameterDomain d{0, 20, -5, 5, false, false, false};
  Grid open;
  open.nu = 5;
  open.nv = 4;
  const ParameterDomain half = CoveredDomain(d, open, 0.5);
  EXPECT_NEAR(half.PeriodU() * half.PeriodV() / (d.PeriodU() * d.PeriodV()), 0.5, kExact);
  EXPECT_NEAR(0.5 * (half.u0 + half.u1), 10.0, kExact);
  EXPECT_NEAR(0.5 * (half.v0 + half.v1), 0.0, kExact);
  const ParameterDomain whole = CoveredDomain(d, open, 1.0);
  EXPECT_EQ(whole.u0, d.u0);
  EXPECT_EQ(whole.u1, d.u1);
  EXPECT_EQ(whole.v0, d.v0);
  EXPECT_EQ(whole.v1, d.v1);
  Grid closed_u = open;
  closed_u.closed_u = true;
  const ParameterDomain band = CoveredDomain(d, closed_u, 0.5);
  EXPECT_EQ(band.u0, d.u0);
  EXPECT_EQ(band.u1, d.u1);
  EXPECT_NEAR(band.PeriodV(), 5.0, kExact);
}

TEST(GridCover, BoundaryVerticesHoldOneParameterAndCornersBoth) {
  const ParameterDomain d{0, 4, 0, 3, false, false, false};
  Grid g;
  g.nu = 5;
  g.nv = 4;
  const BoundaryHold corner = HoldOf(g, g.Index(4, 3), d);
  EXPECT_TRUE(corner.u && corner.v);
  EXPECT_EQ(corner.u_value, 4.0);
  EXPECT_EQ(corner.v_value, 3.0);
  const BoundaryHold side = HoldOf(g, g.Index(0, 2), d);
  EXPECT_TRUE(side.u && !side.v);
  EXPECT_EQ(side.u_value, 0.0);
  const BoundaryHold bottom = HoldOf(g, g.Index(2, 0), d);
  EXPECT_TRUE(!bottom.u && bottom.v);
  EXPECT_EQ(bottom.v_value, 0.0);
  EXPECT_FALSE(HoldOf(g, g.Index(2, 2), d).Any());
  g.closed_u = true;  // no sides in u
  const BoundaryHold ring = HoldOf(g, g.Index(0, 3), d);
  EXPECT_TRUE(!ring.u && ring.v);
}

}  // namespace
}  // namespace archgeo
