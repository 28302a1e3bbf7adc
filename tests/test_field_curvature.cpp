// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for the per-face frames, frame transport and curvature of fields/:
//  - frames are orthonormal and tangent; the smooth frame of a plane is
//    constant; the transport around a vertex rotates by −(angle defect);
//  - the conjugacy algebra of fields/conjugate.h (Prop. 1, 2) against direct
//    evaluation of vᵀ M w;
//  - jet curvature against analytic surfaces: sphere (M = −I/R), ellipsoid
//    (analytic principal directions), surface of revolution (meridians and
//    parallels), hyperbolic paraboloid (K < 0, asymptotic = rulings).
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "fields/conjugate.h"
#include "fields/face_curvature.h"
#include "fields/face_frames.h"
#include "fields/singularities.h"
#include "fields/triangle_surfaces.h"
#include "tests/make_mesh.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using Vec2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

constexpr double kTolerance = 1e-10;
constexpr double kDeg = M_PI / 180.0;

// Angle in degrees between two lines (directions modulo sign).
double LineDeg(const V3& a, const V3& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) / kDeg;
}

TEST(FaceFrames, OrthonormalTangentAndConstantOnAPlane) {
  TriangleGridOptions opt;
  opt.jitter = 0.3;
  const Mesh plane = TriangulatedGrid(12, 9, [](double u, double v) -> Vec3 {
    return {2.0 * u + 0.3 * v, 1.5 * v, 0.5 * u - 0.2 * v};
  }, opt);
  const FaceFrames fr = ComputeSmoothFrames(plane);
  for (FaceIndex f : plane.faces()) {
    const size_t i = f.idx();
    EXPECT_NEAR(fr.e1[i].norm(), 1.0, kTolerance);
    EXPECT_NEAR(fr.e1[i].dot(fr.e2[i]), 0.0, kTolerance);
    EXPECT_NEAR(fr.e1[i].dot(fr.normal[i]), 0.0, kTolerance);
    EXPECT_LT((fr.e2[i] - fr.normal[i].cross(fr.e1[i])).norm(), kTolerance);
    // One plane: the Dirichlet minimiser with b fixed in one face is constant.
    EXPECT_LT((fr.e1[i] - fr.e1[0]).norm(), 1e-9);
  }
  for (const EdgeTransport& t : ComputeTransports(plane, fr)) EXPECT_NEAR(t.angle, 0.0, 1e-9);
  EXPECT_EQ(fr.fallback_faces, 0);
  // Corners in the frame are counter-clockwise and reproduce the edge lengths.
  for (FaceIndex f : plane.faces()) {
    const auto c = FaceCorners2D(plane, fr, f);
    const Vec2 a = c[1] - c[0], b = c[2] - c[0];
    EXPECT_GT(a.x() * b.y() - a.y() * b.x(), 0.0);
    const HalfedgeIndex h0 = plane.halfedge(f), h1 = plane.next(h0);
    EXPECT_NEAR(a.norm(), (Pos(plane, plane.target(h1)) - Pos(plane, plane.target(h0))).norm(),
                kTolerance);
  }
}

TEST(FaceFrames, TransportAroundAVertexTurnsByMinusTheAngleDefect) {
  const Mesh mesh = TriangulatedEllipsoid(1.0, 0.8, 0.6, 2);
  for (const FaceFrames& fr : {ComputeSmoothFrames(mesh), ComputeEdgeFrames(mesh)}) {
    std::vector<int> e2t;
    const std::vector<EdgeTransport> tr = ComputeTransports(mesh, fr, &e2t);
    for (VertexIndex v : mesh.vertices()) {
      // Clockwise halfedges into v; composing the transports counter-clockwise.
      std::vector<HalfedgeIndex> cw;
      double angles = 0.0;
      for (HalfedgeIndex h : mesh.halfedges_around_target(mesh.halfedge(v))) {
        cw.push_back(h);
        const V3 a = Pos(mesh, mesh.source(h)) - Pos(mesh, v);
        const V3 b = Pos(mesh, mesh.target(mesh.next(h))) - Pos(mesh, v);
        angles += std::atan2(a.cross(b).norm(), a.dot(b));
      }
      double sum = 0.0;
      const size_t k = cw.size();
      for (size_t j = 0; j < k; ++j) {
        const size_t i = (k - j) % k, n = (k - j - 1 + k) % k;
        const EdgeTransport& t = tr[e2t[mesh.edge(mesh.next(cw[n])).idx()]];
        sum += TransportAngle(t, mesh.face(cw[n]), mesh.face(cw[i]));
      }
      const double defect = 2 * M_PI - angles;
      EXPECT_NEAR(std::remainder(sum + defect, 2 * M_PI), 0.0, 1e-9);
    }
  }
}

// ------------------------------------------------------------------ conjugate.h

TEST(Conjugate, Prop1PointAndProp2PairAreConjugateByConstruction) {
  std::mt19937 rng(11);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(-0.95, 0.95);
  for (int s = 0; s < 200; ++s) {
    Eigen::Matrix2d M;
    M << g(rng), g(rng), 0, g(rng);
    M(1, 0) = M(0, 1);
    Vec2 zm;
    ASSERT_TRUE(ZOfMatrix(M, &zm));
    // Prop. 1: conjugate directions v, w = J M v have circle points collinear
    // with z_M.
    const double a = u(rng) * M_PI;
    const Vec2 v(std::cos(a), std::sin(a));
    const Vec2 mv = M * v, w(-mv.y(), mv.x());
    ASSERT_NEAR(v.dot(M * w), 0.0, 1e-12);
    const Vec2 p = CirclePoint(v), q = CirclePoint(w);
    const Vec2 d1 = q - p, d2 = zm - p;
    EXPECT_NEAR(d1.x() * d2.y() - d1.y() * d2.x(), 0.0, 1e-9 * (1 + d2.norm()));
    // Inside c iff det M > 0.
    EXPECT_EQ((zm - Vec2(1, 0)).norm() < 1.0, M.determinant() > 0);
    // Prop. 2: the pair of a z_N inside c is conjugate to 1e-8 (in fact to
    // rounding) and N-conjugate.
    Vec2 z;
    do z = Vec2(1 + u(rng), u(rng));
    while ((z - Vec2(1, 0)).norm() >= 0.99);
    const ConjugatePair pair = ConjugatePairOf(M, z);
    ASSERT_TRUE(pair.valid);
    EXPECT_LE(ConjugacyError(M, pair.v, pair.w), 1e-8);
    EXPECT_NEAR(pair.v.dot(NOfZ(z) * pair.w), 0.0, 1e-9);
    // The chord through z_M and z_N meets c at the pair's points.
    const Vec2 pv = CirclePoint(pair.v), pw = CirclePoint(pair.w);
    const Vec2 c1 = pw - pv, c2 = z - pv;
    EXPECT_NEAR(c1.x() * c2.y() - c1.y() * c2.x(), 0.0, 1e-8 * (1 + c2.norm()));
    // Eq. 1.
    EXPECT_LE(std::abs(pair.v.dot(pair.w)), (z - Vec2(1, 0)).norm() + 1e-12);
  }
}

TEST(Conjugate, E1SelectsThePrincipalDirections) {
  Eigen::Matrix2d M;
  M << 0.3, 0.8, 0.8, -1.1;
  const ConjugatePair pair = ConjugatePairOf(M, Vec2(1, 0));
  const Principal p = PrincipalOf(M);
  ASSERT_TRUE(pair.valid);
  EXPECT_NEAR(std::abs(pair.v.dot(p.d1)), 1.0, 1e-12);  // v: larger eigenvalue, k1
  EXPECT_NEAR(std::abs(pair.w.dot(p.d2)), 1.0, 1e-12);
  Vec2 as[2];
  ASSERT_EQ(AsymptoticDirections(M, as), 2);
  for (const Vec2& a : as) EXPECT_NEAR(a.dot(M * a), 0.0, 1e-12);
  // Outside c: no pair; the bisector of a principal pair is at 45°.
  EXPECT_FALSE(ConjugatePairOf(M, Vec2(2.5, 0)).valid);
  EXPECT_NEAR(std::abs(WrapLineAngle(BisectorAngle(pair.v, pair.w) - LineAngle(p.d1))),
              M_PI / 4, 1e-12);
}

// ------------------------------------------------------------------ jets

// Analytic M of the ellipsoid x²/a² + y²/b² + z²/c² = 1 at the surface point
// nearest (radially) to face f's centroid, in f's frame, w.r.t. the outward
// normal: II(u, v) = −uᵀ H v / ‖∇F‖, H = diag(2/a², 2/b², 2/c²).
Eigen::Matrix2d EllipsoidM(const FaceFrames& fr, FaceIndex f, double a, double b, double c) {
  const V3 x0 = fr.centroid[f.idx()];
  const double s = 1.0 / std::sqrt(x0.x() * x0.x() / (a * a) + x0.y() * x0.y() / (b * b) +
                                   x0.z() * x0.z() / (c * c));
  const V3 x = s * x0;
  const V3 grad(2 * x.x() / (a * a), 2 * x.y() / (b * b), 2 * x.z() / (c * c));
  const Eigen::Matrix3d H = Eigen::Vector3d(2 / (a * a), 2 / (b * b), 2 / (c * c)).asDiagonal();
  Eigen::Matrix<double, 3, 2> E;
  E.col(0) = fr.e1[f.idx()];
  E.col(1) = fr.e2[f.idx()];
  return -E.transpose() * H * E / grad.norm();
}

TEST(FaceCurvature, SphereHasMEqualMinusIdentityOverR) {
  const double R = 2.0;
  const Mesh sphere = TriangulatedEllipsoid(R, R, R, 4);
  const FaceFrames fr = ComputeSmoothFrames(sphere);
  const std::vector<FaceCurvature> curv = ComputeFaceCurvature(sphere, fr);
  double worst = 0.0;
  for (FaceIndex f : sphere.faces()) {
    const FaceCurvature& c = curv[f.idx()];
    worst = std::max(worst, (c.M + Eigen::Matrix2d::Identity() / R).norm() * R);
    EXPECT_EQ(c.gaussian_sign, 1);
    EXPECT_FALSE(c.flat);
    EXPECT_EQ(c.num_asymptotic, 0);
    ASSERT_TRUE(c.z_m_finite);
  }
  // Relative error of the curvature tensor (edge length ≈ R/15): 1%.
  std::printf("sphere: worst relative error of M %.2e\n", worst);
  EXPECT_LT(worst, 0.01);
}

TEST(FaceCurvature, EllipsoidPrincipalDirectionsWithin2DegreesAwayFromUmbilics) {
  const double a = 1.5, b = 1.0, c = 0.6;
  const Mesh mesh = TriangulatedEllipsoid(a, b, c, 4);
  const FaceFrames fr = ComputeSmoothFrames(mesh);
  const std::vector<FaceCurvature> curv = ComputeFaceCurvature(mesh, fr);
  double sum = 0.0;
  int n = 0;
  for (FaceIndex f : mesh.faces()) {
    const Principal exact = PrincipalOf(EllipsoidM(fr, f, a, b, c));
    // Away from umbilics: principal curvatures differ by ≥ 20%.
    if (std::abs(exact.k1 - exact.k2) < 0.2 * std::max(std::abs(exact.k1), std::abs(exact.k2)))
      continue;
    sum += LineDeg(FromFrame(fr, f, curv[f.idx()].d1), FromFrame(fr, f, exact.d1));
    ++n;
  }
  ASSERT_GT(n, static_cast<int>(mesh.number_of_faces()) / 2);
  std::printf("ellipsoid: mean principal direction error %.3f deg on %d faces\n", sum / n, n);
  EXPECT_LT(sum / n, 2.0);
}

TEST(FaceCurvature, SurfaceOfRevolutionMeridiansAndParallels) {
  // r(t) = 1 + 0.4 sin(2t), t ∈ [0, 3]: both principal curvatures vary, and
  // they coincide only on isolated parallels (excluded below).
  TriangleGridOptions opt;
  opt.closed_u = true;
  opt.jitter = 0.2;
  auto r = [](double t) { return 1.0 + 0.4 * std::sin(2.0 * t); };
  const Mesh mesh = TriangulatedGrid(80, 60, [&](double u, double v) -> Vec3 {
    const double th = 2 * M_PI * u, t = 3.0 * v;
    return {r(t) * std::cos(th), r(t) * std::sin(th), t};
  }, opt);
  const FaceFrames fr = ComputeSmoothFrames(mesh);
  const std::vector<FaceCurvature> curv = ComputeFaceCurvature(mesh, fr);
  double sum = 0.0;
  int n = 0;
  for (FaceIndex f : mesh.faces()) {
    const V3 x = fr.centroid[f.idx()];
    const double t = x.z();
    if (t < 0.3 || t > 2.7) continue;  // away from the boundary
    const FaceCurvature& cf = curv[f.idx()];
    if (std::abs(cf.k1 - cf.k2) < 0.2 * std::max(std::abs(cf.k1), std::abs(cf.k2))) continue;
    const V3 normal = fr.normal[f.idx()];
    V3 parallel(-x.y(), x.x(), 0.0);
    parallel -= parallel.dot(normal) * normal;
    // The parallel is a principal direction: d1 or d2 is along it.
    const double e = std::min(LineDeg(FromFrame(fr, f, cf.d1), parallel),
                              LineDeg(FromFrame(fr, f, cf.d2), parallel));
    sum += e;
    ++n;
  }
  ASSERT_GT(n, 1000);
  std::printf("surface of revolution: mean principal direction error %.3f deg on %d faces\n",
              sum / n, n);
  EXPECT_LT(sum / n, 2.0);
}

TEST(FaceCurvature, HyperbolicParaboloidIsNegativelyCurvedWithRulingsAsAsymptotes) {
  TriangleGridOptions opt;
  opt.jitter = 0.25;
  const Mesh mesh = TriangulatedGrid(30, 30, [](double u, double v) -> Vec3 {
    const double x = 2 * u - 1, y = 2 * v - 1;
    return {x, y, x * y};
  }, opt);
  const FaceFrames fr = ComputeSmoothFrames(mesh);
  const std::vector<FaceCurvature> curv = ComputeFaceCurvature(mesh, fr);
  double worst = 0.0;
  for (FaceIndex f : mesh.faces()) {
    const FaceCurvature& c = curv[f.idx()];
    EXPECT_EQ(c.gaussian_sign, -1);
    ASSERT_EQ(c.num_asymptotic, 2);
    const V3 x = fr.centroid[f.idx()];
    // The two rulings through x, projected onto the face plane (M_f lives
    // there; the face is tilted against the tangent plane by O(h κ)).
    const V3 n = fr.normal[f.idx()];
    V3 rx(1, 0, x.y()), ry(0, 1, x.x());
    rx -= rx.dot(n) * n;
    ry -= ry.dot(n) * n;
    const V3 a0 = FromFrame(fr, f, c.asymptotic[0]), a1 = FromFrame(fr, f, c.asymptotic[1]);
    worst = std::max(worst, std::min(std::max(LineDeg(a0, rx), LineDeg(a1, ry)),
                                     std::max(LineDeg(a0, ry), LineDeg(a1, rx))));
  }
  std::printf("hyperbolic paraboloid: worst asymptotic direction error %.3f deg\n", worst);
  EXPECT_LT(worst, 1.0);
}

TEST(FaceCurvature, FlatPlaneHasNoCurvatureAndNoZM) {
  const Mesh plane = TriangulatedGrid(8, 8, [](double u, double v) -> Vec3 {
    return {u, v, 0.0};
  });
  const FaceFrames fr = ComputeSmoothFrames(plane);
  for (const FaceCurvature& c : ComputeFaceCurvature(plane, fr)) {
    EXPECT_TRUE(c.flat);
    EXPECT_FALSE(c.z_m_finite);
    EXPECT_EQ(c.gaussian_sign, 0);
  }
}

}  // namespace
}  // namespace archgeo
