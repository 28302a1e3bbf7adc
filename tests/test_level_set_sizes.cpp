// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for the curl correction of the level sets' sizes
// (fields/level_set_sizes.h) on a plane patch x ∈ [1, 2], |y| ≤ 0.5 with the
// radial field v = r̂, w = θ̂:
//  - g's target R v = θ̂ has curl 1/r; θ̂/r = ∇θ is curl-free, so the
//    corrected log size is log r + const (level lines of g are the rays,
//    whose spacing grows with r): with a long reach the fitted slope of s̃
//    against log r is 1 within 5% and the curl drops tenfold;
//  - h's target R w = −r̂ = −∇r is curl-free: its sizes stay 1;
//  - a short reach holds g's sizes near the target;
//  - a size ratio bound holds them within it, where they would spread
//    past it, and the curl still drops.
#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "fields/cuts.h"
#include "fields/face_frames.h"
#include "fields/level_set_sizes.h"
#include "fields/triangle_surfaces.h"
#include "tests/make_mesh.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

struct RadialPatch {
  Mesh mesh;
  FaceFrames frames;
  CutGraph cut;
  std::vector<V2> v, w;
};

RadialPatch MakeRadialPatch() {
  RadialPatch p;
  p.mesh = TriangulatedGrid(40, 40, [](double u, double v) -> Vec3 {
    return {1.0 + u, v - 0.5, 0.0};
  });
  p.frames = ComputeSmoothFrames(p.mesh);
  p.cut = ComputeCutGraph(p.mesh, {});
  for (FaceIndex f : p.mesh.faces()) {
    const V3 c = p.frames.centroid[f.idx()];
    const V3 radial = V3(c.x(), c.y(), 0).normalized();
    const V3 around(-radial.y(), radial.x(), 0);
    const V3& e1 = p.frames.e1[f.idx()];
    const V3& e2 = p.frames.e2[f.idx()];
    p.v.emplace_back(radial.dot(e1), radial.dot(e2));
    p.w.emplace_back(around.dot(e1), around.dot(e2));
  }
  return p;
}

// Least-squares slope of s̃_f against log r_f on the faces along the x axis
// (|y| < 0.05). Any s̃ = log r + k(θ) makes θ̂ e^{−s̃} curl-free; the target
// term chooses k, so only the slope at a fixed θ is the curl's.
double SlopeAgainstLogRadius(const RadialPatch& p, const std::vector<double>& s) {
  std::vector<double> x, y;
  for (FaceIndex f : p.mesh.faces()) {
    const V3& c = p.frames.centroid[f.idx()];
    if (std::abs(c.y()) >= 0.05) continue;
    x.push_back(std::log(c.head<2>().norm()));
    y.push_back(s[f.idx()]);
  }
  double mx = 0, my = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    mx += x[i] / double(x.size());
    my += y[i] / double(x.size());
  }
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  return sxy / sxx;
}

TEST(LevelSetSizes, RadialLinesGetSizesGrowingWithTheRadius) {
  const RadialPatch p = MakeRadialPatch();
  const std::vector<int> signs(p.cut.chains.size(), 1);
  const LevelSetSizes sizes =
      CorrectLevelSetSizes(p.mesh, p.frames, p.cut, p.v, p.w, signs, signs, 0.05, 1000, 100);
  const double slope_g = SlopeAgainstLogRadius(p, sizes.g.log_size);
  const double slope_h = SlopeAgainstLogRadius(p, sizes.h.log_size);
  std::printf("slope of log size vs log r: g %.4f, h %.4f; g curl %.3e -> %.3e; g sizes "
              "%.3f-%.3f\n",
              slope_g, slope_h, sizes.g.curl_before, sizes.g.curl_after, sizes.g.size_min,
              sizes.g.size_max);
  EXPECT_NEAR(slope_g, 1.0, 0.05);
  EXPECT_LT(std::abs(slope_h), 0.05);
  EXPECT_GT(sizes.g.vertices, 1000);
  EXPECT_LT(sizes.g.curl_after, 0.1 * sizes.g.curl_before);
  // r runs from 1 to |(2, 0.5)|: the spacing of the rays grows by that ratio.
  EXPECT_NEAR(sizes.g.size_max / sizes.g.size_min, std::hypot(2.0, 0.5), 0.15);
}

TEST(LevelSetSizes, AShortReachHoldsTheSizesToTheSpacing) {
  const RadialPatch p = MakeRadialPatch();
  const std::vector<int> signs(p.cut.chains.size(), 1);
  const LevelSetSizes sizes =
      CorrectLevelSetSizes(p.mesh, p.frames, p.cut, p.v, p.w, signs, signs, 0.05, 0.2, 100);
  EXPECT_GT(sizes.g.size_p5, 0.97);
  EXPECT_LT(sizes.g.size_p95, 1.03);
  EXPECT_GT(sizes.g.curl_after, 0.5 * sizes.g.curl_before);
}

TEST(LevelSetSizes, TheRatioBoundHoldsTheSizesWithinIt) {
  const RadialPatch p = MakeRadialPatch();
  const std::vector<int> signs(p.cut.chains.size(), 1);
  const LevelSetSizes sizes =
      CorrectLevelSetSizes(p.mesh, p.frames, p.cut, p.v, p.w, signs, signs, 0.05, 1000, 1.2);
  std::printf("bounded at 1.2: g sizes %.4f-%.4f, curl %.3e -> %.3e\n", sizes.g.size_min,
              sizes.g.size_max, sizes.g.curl_before, sizes.g.curl_after);
  // Unbounded they span 0.7-1.44 (the test above); bounded, the band's ends
  // are reached (face values are means of bounded corners).
  EXPECT_GE(sizes.g.size_min, 1 / 1.2 - 1e-9);
  EXPECT_LE(sizes.g.size_max, 1.2 + 1e-9);
  EXPECT_LT(sizes.g.size_min, 0.85);
  EXPECT_GT(sizes.g.size_max, 1.18);
  EXPECT_LT(sizes.g.curl_after, 0.7 * sizes.g.curl_before);
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
