// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A net's edges against the surface's curvature directions
// (fields/net_curvature.h), on nets whose relation to the curvature is known
// analytically: the parameter grid of z = xy is its asymptotic net, the grid
// of z = x² − y² its principal net (conjugate, at 45° to the asymptotic
// lines), the grid of a translational surface is conjugate, and the rulings
// and circles of a cylinder are its principal directions.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "fields/net_curvature.h"
#include "generators/generators.h"
#include "io/io.h"
#include "geometry/reference.h"
#include "tests/make_mesh.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

Vec3 HyperbolicParaboloid(double u, double v) {
  const double x = 2 * u - 1, y = 2 * v - 1;
  return {x, y, x * y};
}

Vec3 Saddle(double u, double v) {
  const double x = 2 * u - 1, y = 2 * v - 1;
  return {x, y, 0.5 * (x * x - y * y)};
}

TEST(NetCurvature, TheGridOfZEqualsXYIsAsymptotic) {
  const NetCurvatureFigures f = MeasureNetCurvature(QuadGrid(24, 24, HyperbolicParaboloid));
  EXPECT_EQ(f.quads, 576);
  EXPECT_EQ(f.measured, 576);
  EXPECT_EQ(f.positive_curvature_fraction, 0.0);
  EXPECT_LT(f.asymptotic_angle_mean, 0.5);  // degrees; exactly 0 on the surface
  EXPECT_LT(f.asymptotic_angle_max, 2.0);
  // Asymptotic directions are not conjugate: II(u, v) = κ-sized.
  EXPECT_GT(f.conjugacy_mean, 0.3);
}

TEST(NetCurvature, ThePrincipalGridOfASaddleIsConjugateAndFarFromAsymptotic) {
  const NetCurvatureFigures f = MeasureNetCurvature(QuadGrid(24, 24, Saddle));
  EXPECT_LT(f.conjugacy_mean, 0.02);
  EXPECT_EQ(f.positive_curvature_fraction, 0.0);
  // The asymptotic lines x = ±y of the saddle's centre are at 45° to the
  // grid; away from the centre they turn but stay far.
  EXPECT_GT(f.asymptotic_angle_mean, 30.0);
}

TEST(NetCurvature, ATranslationalRoofIsConjugate) {
  const NetCurvatureFigures f = MeasureNetCurvature(QuadGrid(30, 20, RoofSurface));
  EXPECT_LT(f.conjugacy_mean, 0.02);
  // Its diagonal directions are not.
  const NetCurvatureFigures noisy = MeasureNetCurvature(QuadGrid(30, 20, RoofSurface, 0.3));
  EXPECT_GT(noisy.conjugacy_mean, f.conjugacy_mean);
}

// Past kSampledQuads quads the measure reads an even sample: on a 200 × 150
// grid of z = xy (30,000 quads) it looks at up to 20,000 of them (a few of
// the golden-ratio picks coincide) and still finds the asymptotic net, with
// a conjugacy mean within 10% of the 30 × 20 grid's (every quad measured).
TEST(NetCurvature, ALargeNetIsMeasuredOnAnEvenSample) {
  const NetCurvatureFigures f = MeasureNetCurvature(QuadGrid(200, 150, HyperbolicParaboloid));
  EXPECT_EQ(f.quads, 30000);
  EXPECT_LE(f.sampled, kSampledQuads);
  EXPECT_GT(f.sampled, 0.9 * kSampledQuads);
  EXPECT_LT(f.sampled, f.quads);
  EXPECT_EQ(f.measured, f.sampled);
  EXPECT_EQ(f.positive_curvature_fraction, 0.0);
  EXPECT_LT(f.asymptotic_angle_mean, 0.5);
  EXPECT_GT(f.conjugacy_mean, 0.3);
  const NetCurvatureFigures small = MeasureNetCurvature(QuadGrid(30, 20, HyperbolicParaboloid));
  EXPECT_EQ(small.sampled, small.quads);
  EXPECT_NEAR(f.conjugacy_mean, small.conjugacy_mean, 0.1 * small.conjugacy_mean);
}

TEST(NetCurvature, CylinderRulingsAndCirclesArePrincipalTheirDiagonalsAreNot) {
  const int around = 32, rows = 16;
  const double radius = 1.0, height = 2.0;
  const Mesh cylinder = QuadCylinder(radius, height, around, rows);
  std::vector<std::pair<int, int>> along;
  for (EdgeIndex e : cylinder.edges()) {
    along.emplace_back(int(cylinder.vertex(e, 0).idx()), int(cylinder.vertex(e, 1).idx()));
  }
  const PrincipalLabelFigures p = MeasurePrincipalLabels(cylinder, along);
  EXPECT_EQ(p.edges, int(along.size()));
  EXPECT_EQ(p.measured, p.edges);
  EXPECT_LT(p.angle_max, 0.5);  // degrees
  // The diagonals of a triangulation: the chord of 1/32 of the circle and
  // 1/16 of the height, at atan(h / c) from the circle direction.
  const Mesh triangles = TriangulatedCopy(cylinder);
  std::vector<std::pair<int, int>> diagonals;
  for (EdgeIndex e : triangles.edges()) {
    const VertexIndex a = triangles.vertex(e, 0), b = triangles.vertex(e, 1);
    if (cylinder.halfedge(a, b) == Mesh::null_halfedge()) diagonals.emplace_back(int(a.idx()), int(b.idx()));
  }
  ASSERT_EQ(int(diagonals.size()), around * rows);
  const PrincipalLabelFigures d = MeasurePrincipalLabels(triangles, diagonals);
  const double chord = 2 * radius * std::sin(M_PI / around), step = height / rows;
  const double expected = std::atan(step / chord) * 180 / M_PI;  // 32.5°
  EXPECT_NEAR(d.angle_mean, std::min(expected, 90 - expected), 1.0);
}

}  // namespace
}  // namespace archgeo
