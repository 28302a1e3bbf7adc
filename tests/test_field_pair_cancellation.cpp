// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Cancelling needless ± singularity pairs by local field surgery
// (fields/pair_cancellation.h) [Gebreiter 2012, §8.1.4].
//
// The surfaces with known pairs: an elliptic paraboloid z = ½x² + ¼y² with a
// Gaussian dip −A exp(−r²/s²). The dip's trace-free curvature
// (κ_r − κ_t = −4A r²/s⁴ exp(−r²/s²)) is radial, the paraboloid's (κ_x > κ_y)
// constant: on the y axis they cancel where its size equals the paraboloid's,
// at two radii on each side, so the principal field has two umbilics of
// opposite index on each side of the dip (the inner ones +1/2, the outer
// ones −1/2: the dip's term winds twice inside the ring between them and not
// outside it). The paraboloid's own umbilics (y = ±√2) are off the patch.
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "fields/pair_cancellation.h"
#include "fields/singularities.h"
#include "fields/tcd_field.h"
#include "fields/triangle_surfaces.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using V2 = Eigen::Vector2d;

constexpr double kDipWidth = 0.3;
constexpr double kLineToleranceDeg = 1.0;  // the field away from the pairs

Vec3 DippedParaboloid(double x, double y, double amplitude) {
  const double r2 = x * x + y * y;
  return {x, y, 0.5 * x * x + 0.25 * y * y - amplitude * std::exp(-r2 / (kDipWidth * kDipWidth))};
}

struct PrincipalField {
  Mesh mesh;
  FieldGeometry geometry;
  TcdField field;
};

PrincipalField Principal(Mesh mesh) {
  PrincipalField p;
  p.mesh = std::move(mesh);
  p.geometry = ComputeFieldGeometry(p.mesh, JetOptions{});
  p.field = EvaluateField(p.mesh, p.geometry,
                          std::vector<V2>(p.mesh.number_of_faces(), V2(1, 0)));
  return p;
}

int Count(const std::vector<Singularity>& s, double index) {
  int n = 0;
  for (const Singularity& x : s) n += x.index == index ? 1 : 0;
  return n;
}

double LineDeg(const V2& a, const V2& b) {
  return std::abs(WrapLineAngle(LineAngle(a) - LineAngle(b))) * 180.0 / M_PI;
}

// The ellipsoid x²/1.3² + y² + z²/0.9² = 1 with the same dip at its top
// (0, 0, 0.9) along the normal (κ_x = 0.53, κ_y = 0.9 there): its four
// umbilics (+1/2, in the xz plane, 1.2 from the top) and the dip's two pairs.
Mesh DippedEllipsoid(double amplitude) {
  const double a = 1.3, b = 1.0, c = 0.9;
  Mesh mesh = TriangulatedEllipsoid(a, b, c, 5);
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    const Eigen::Vector3d x(p.x(), p.y(), p.z());
    const Eigen::Vector3d n = Eigen::Vector3d(x.x() / (a * a), x.y() / (b * b), x.z() / (c * c)).normalized();
    const double d2 = (x - Eigen::Vector3d(0, 0, c)).squaredNorm();
    const Eigen::Vector3d y = x - amplitude * std::exp(-d2 / (kDipWidth * kDipWidth)) * n;
    mesh.point(v) = Point(y.x(), y.y(), y.z());
  }
  return mesh;
}

constexpr double kDipAmplitude = 0.03;   // just above the pairs' threshold
constexpr double kMaxDistance = 0.5;     // the pairs are 0.18 (open), 0.26 (closed) apart

// Largest change of the lines of v and w on the faces farther than `away`
// from every singularity of `before`.
double ChangeAwayDeg(const PrincipalField& p, const TcdField& after, double away) {
  double worst = 0;
  for (FaceIndex f : p.mesh.faces()) {
    const Eigen::Vector3d& x = p.geometry.frames.centroid[f.idx()];
    bool far = true;
    for (const Singularity& s : p.field.singularities) far = far && (x - s.position).norm() > away;
    if (!far) continue;
    const ConjugatePair &a = p.field.pairs[f.idx()], &b = after.pairs[f.idx()];
    worst = std::max({worst, LineDeg(a.v, b.v), LineDeg(a.w, b.w)});
  }
  return worst;
}

TEST(PairCancellation, RemovesTheDipsPairsAndKeepsTheFieldElsewhere) {
  const PrincipalField p = Principal(TriangulatedGrid(80, 80, [](double u, double v) {
    return DippedParaboloid(2 * u - 1, 2 * v - 1, kDipAmplitude);
  }));
  ASSERT_EQ(p.field.singularities.size(), 4u);
  EXPECT_EQ(Count(p.field.singularities, 0.5), 2);
  EXPECT_EQ(Count(p.field.singularities, -0.5), 2);
  PairCancellationOptions options;
  options.max_distance = kMaxDistance;
  const PairCancellation pc = CancelSingularityPairs(p.mesh, p.geometry, p.field, options);
  EXPECT_EQ(pc.found, 2);
  EXPECT_EQ(pc.cancelled, 2);
  const TcdField after = EvaluateField(p.mesh, p.geometry, pc.z_n);
  EXPECT_TRUE(after.singularities.empty());
  EXPECT_EQ(after.index_sum, 0.0);
  EXPECT_EQ(after.stats.invalid_faces, 0);
  EXPECT_LE(after.stats.max_conjugacy_error, 1e-8);
  // Away from the pairs (beyond twice their distance) the field is as it was.
  const double change = ChangeAwayDeg(p, after, 2 * pc.pairs[0].distance);
  EXPECT_LE(change, kLineToleranceDeg);
  EXPECT_LT(pc.faces_changed, int(p.mesh.number_of_faces()) / 4);
  std::printf("dipped paraboloid: pairs %.3f and %.3f apart cancelled, %d of %zu faces changed, "
              "largest line change away from them %.3g°, angle between v and w min %.1f° "
              "(before %.1f°)\n",
              pc.pairs[0].distance, pc.pairs[1].distance, pc.faces_changed,
              size_t(p.mesh.number_of_faces()), change, after.stats.min_angle_deg,
              p.field.stats.min_angle_deg);
}

// A pair farther apart than max_distance is kept: nothing changes.
TEST(PairCancellation, KeepsPairsFartherThanTheDistance) {
  const PrincipalField p = Principal(TriangulatedGrid(80, 80, [](double u, double v) {
    return DippedParaboloid(2 * u - 1, 2 * v - 1, kDipAmplitude);
  }));
  PairCancellationOptions options;
  options.max_distance = 0.1;
  const PairCancellation pc = CancelSingularityPairs(p.mesh, p.geometry, p.field, options);
  EXPECT_EQ(pc.found, 0);
  EXPECT_EQ(pc.faces_changed, 0);
  EXPECT_EQ(pc.z_n, p.field.z_n);
}

// Poincaré–Hopf after the surgery on a closed surface: the dip's two pairs
// go, the ellipsoid's four umbilics (+1/2 at |x| = 1.15) stay, Σ = χ = 2.
TEST(PairCancellation, PoincareHopfHoldsOnAClosedSurface) {
  const PrincipalField p = Principal(DippedEllipsoid(kDipAmplitude));
  ASSERT_EQ(p.field.singularities.size(), 8u);
  EXPECT_EQ(p.field.index_sum, 2.0);
  PairCancellationOptions options;
  options.max_distance = kMaxDistance;
  const PairCancellation pc = CancelSingularityPairs(p.mesh, p.geometry, p.field, options);
  EXPECT_EQ(pc.found, 2);
  EXPECT_EQ(pc.cancelled, 2);
  const TcdField after = EvaluateField(p.mesh, p.geometry, pc.z_n);
  ASSERT_EQ(after.singularities.size(), 4u);
  EXPECT_EQ(after.index_sum, 2.0);
  for (const Singularity& s : after.singularities) {
    EXPECT_EQ(s.index, 0.5);
    EXPECT_NEAR(std::abs(s.position.x()), 1.15, 0.05);
  }
  // The field is unchanged beyond the accepted regions, a small part.
  const double reach = std::max(pc.pairs[0].radius, pc.pairs[1].radius) +
                       std::max(pc.pairs[0].distance, pc.pairs[1].distance);
  EXPECT_LE(ChangeAwayDeg(p, after, reach), kLineToleranceDeg);
  EXPECT_LT(pc.faces_changed, int(p.mesh.number_of_faces()) / 5);
  std::printf("dipped ellipsoid: %d of %zu faces changed, regions of radius %.3f and %.3f\n",
              pc.faces_changed, size_t(p.mesh.number_of_faces()), pc.pairs[0].radius, pc.pairs[1].radius);
}

// A singularity near the open boundary is pushed out of the domain
// [Gebreiter 2012, §8.1.1]: the dipped paraboloid cut at x = 0.3 keeps its
// left pair (−1/2 at x = −0.4, +1/2 at −0.225) and the +1/2 at 0.225, 0.075
// from the boundary; with pairs left alone and boundary_distance 0.15 that
// one goes, the pair stays.
TEST(PairCancellation, PushesASingularityOutAcrossTheNearBoundary) {
  const PrincipalField p = Principal(TriangulatedGrid(52, 80, [](double u, double v) {
    return DippedParaboloid(-1 + 1.3 * u, 2 * v - 1, kDipAmplitude);
  }));
  ASSERT_EQ(p.field.singularities.size(), 3u);
  PairCancellationOptions options;
  options.boundary_distance = 0.15;
  const PairCancellation pc = CancelSingularityPairs(p.mesh, p.geometry, p.field, options);
  EXPECT_EQ(pc.found, 0);
  EXPECT_EQ(pc.near_boundary, 1);
  EXPECT_EQ(pc.pushed_out, 1);
  const TcdField after = EvaluateField(p.mesh, p.geometry, pc.z_n);
  ASSERT_EQ(after.singularities.size(), 2u);
  for (const Singularity& s : after.singularities) EXPECT_LT(s.position.x(), -0.2);
  EXPECT_EQ(after.stats.invalid_faces, 0);
  std::printf("cut paraboloid: the +1/2 0.075 from the boundary pushed out, %d of %zu faces "
              "changed\n", pc.faces_changed, size_t(p.mesh.number_of_faces()));
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
