// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for the bounded Hausdorff sample grid (geometry/hausdorff_sampling.h):
// the sample count is CGAL's own, the spacing keeps it under the cap even
// when one vertex is moved far away (issue 17: 147 s on a 2,000-vertex mesh),
// and it is the plain 0.25 mean edge lengths when the cap does not apply.
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "generators/generators.h"
#include "geometry/hausdorff_sampling.h"
#include "geometry/reference.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

namespace PMP = CGAL::Polygon_mesh_processing;

// A triangulated n x n grid on the unit square (z = 0), with vertex `moved`
// lifted by `lift` along z.
Mesh PlaneTriangles(int n, int moved, double lift) {
  Mesh grid = QuadGrid(n, n, [](double u, double v) { return Vec3{u, v, 0.0}; });
  const VertexIndex v(moved);
  grid.point(v) = Point(grid.point(v).x(), grid.point(v).y(), lift);
  return TriangulatedCopy(grid);
}

double MeanEdge(const Mesh& tm) {
  double sum = 0;
  for (EdgeIndex e : tm.edges()) {
    sum += std::sqrt(CGAL::squared_distance(tm.point(tm.vertex(e, 0)), tm.point(tm.vertex(e, 1))));
  }
  return sum / tm.number_of_edges();
}

// HausdorffGridSampleCount is exactly the number of points CGAL's grid
// sampling produces besides the vertices, on slivers and regular triangles.
TEST(HausdorffSampling, CountIsCgalsOwn) {
  const Mesh tm = PlaneTriangles(4, 7, 3.0);
  for (const double spacing : {0.05, 0.13, 0.25, 1.0, 7.0}) {
    std::vector<Point> samples;
    PMP::sample_triangle_mesh(
        tm, std::back_inserter(samples),
        PMP::parameters::use_grid_sampling(true).grid_spacing(spacing));
    EXPECT_EQ(static_cast<double>(samples.size()),
              HausdorffGridSampleCount(tm, spacing) + tm.number_of_vertices())
        << "spacing " << spacing;
  }
}

// One vertex 1e4 away on a 100 x 100 grid: at 0.25 mean edge lengths the
// slivers around it would take ~1e9 samples; the spacing chosen keeps the
// grid under the cap.
TEST(HausdorffSampling, SpacingCapsTheSamples) {
  const Mesh tm = PlaneTriangles(100, 5050, 1e4);
  const double plain = kHausdorffGridSpacing * MeanEdge(tm);
  EXPECT_GT(HausdorffGridSampleCount(tm, plain), 100 * kHausdorffMaxGridSamples);
  const double spacing = HausdorffGridSpacing(tm);
  EXPECT_GT(spacing, plain);
  EXPECT_LE(HausdorffGridSampleCount(tm, spacing), kHausdorffMaxGridSamples);
  // Not far beyond what the cap needs: the spacing grows by factors of
  // sqrt(count / cap), so the count ends within a few times the cap.
  EXPECT_GT(HausdorffGridSampleCount(tm, spacing), 0.05 * kHausdorffMaxGridSamples);
}

TEST(HausdorffSampling, PlainSpacingWhenTheCapDoesNotApply) {
  const Mesh tm = PlaneTriangles(20, 0, 0.0);
  EXPECT_DOUBLE_EQ(HausdorffGridSpacing(tm), kHausdorffGridSpacing * MeanEdge(tm));
  EXPECT_LT(HausdorffGridSampleCount(tm, HausdorffGridSpacing(tm)), kHausdorffMaxGridSamples);
}

}  // namespace
}  // namespace archgeo
