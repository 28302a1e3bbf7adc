// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for fields/singularities.h:
//  - indices are multiples of 1/2 and sum to the Euler characteristic on a
//    closed surface for ANY field (discrete Poincaré–Hopf);
//  - a radial field on a flat fan has index +1 at its centre, the field of
//    z^(1/2) level sets +1/2, of z^(3/2) −1/2;
//  - the principal field (z_N = e1) of an ellipsoid has four +1/2 singularities
//    at the umbilics (analytic M and jet M), the monkey saddle one −1/2 at the
//    origin;
//  - every pair of a TCD field is conjugate to ≤ 1e-8;
//  - σ of eq. 4, and moving a singularity with it (§4) moves the index.
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "fields/conjugate.h"
#include "fields/face_curvature.h"
#include "fields/face_frames.h"
#include "fields/singularities.h"
#include "fields/triangle_surfaces.h"
#include "tests/make_mesh.h"
#include "tests/monkey_saddle.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using Vec2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

struct Field {
  FaceFrames frames;
  std::vector<EdgeTransport> transports;
  std::vector<int> edge_to_transport;
};

Field MakeField(const Mesh& mesh) {
  Field f;
  f.frames = ComputeSmoothFrames(mesh);
  f.transports = ComputeTransports(mesh, f.frames, &f.edge_to_transport);
  return f;
}

// Line angle, in each face frame, of a 3-D direction field given per point.
template <typename Direction>
std::vector<double> AnglesOf(const Mesh& mesh, const FaceFrames& fr, Direction dir) {
  std::vector<double> out(mesh.number_of_faces());
  for (FaceIndex f : mesh.faces()) out[f.idx()] = LineAngle(ToFrame(fr, f, dir(fr.centroid[f.idx()])));
  return out;
}

double Sum(const std::vector<double>& x) {
  double s = 0;
  for (double v : x) s += v;
  return s;
}

TEST(VertexIndices, PoincareHopfForRandomFieldsOnAClosedSurface) {
  const Mesh mesh = TriangulatedEllipsoid(1.0, 0.7, 0.5, 2);
  const Field fd = MakeField(mesh);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(0, M_PI);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<double> beta(mesh.number_of_faces());
    for (double& b : beta) b = angle(rng);
    const std::vector<double> ind = VertexIndices(mesh, fd.transports, fd.edge_to_transport, beta);
    for (double i : ind) EXPECT_EQ(2 * i, std::round(2 * i));
    EXPECT_EQ(Sum(ind), 2.0);  // χ(sphere)
  }
}

TEST(VertexIndices, RadialAndBranchedFieldsOnAPlane) {
  // A jittered square grid whose centre is a vertex.
  TriangleGridOptions opt;
  opt.jitter = 0.2;
  const Mesh mesh = TriangulatedGrid(20, 20, [](double u, double v) -> Vec3 {
    return {2 * u - 1, 2 * v - 1, 0.0};
  }, opt);
  const Field fd = MakeField(mesh);
  VertexIndex centre(static_cast<int>(10 * 21 + 10));  // grid vertex (10, 10)
  const V3 c0 = Pos(mesh, centre);
  ASSERT_LT(c0.norm(), 0.05);
  struct Case {
    double exponent;  // level sets of Re z^p; their tangent has index 1 − p
    double index;
  };
  for (const Case& c : {Case{0.0, 1.0}, Case{0.5, 0.5}, Case{1.5, -0.5}, Case{2.0, -1.0}}) {
    // Gradient of Re z^p is conj(p z^(p−1)): angle −(p − 1) arg z. p = 0 is
    // the radial field (index 1).
    auto dir = [&](const V3& x) {
      const double a = std::atan2(x.y() - c0.y(), x.x() - c0.x());
      const double t = c.exponent == 0.0 ? a : -(c.exponent - 1.0) * a;
      return V3(std::cos(t), std::sin(t), 0.0);
    };
    const std::vector<double> ind =
        VertexIndices(mesh, fd.transports, fd.edge_to_transport, AnglesOf(mesh, fd.frames, dir));
    EXPECT_EQ(ind[centre.idx()], c.index) << "exponent " << c.exponent;
    int others = 0;
    for (VertexIndex v : mesh.vertices())
      if (v != centre && ind[v.idx()] != 0.0) ++others;
    EXPECT_EQ(others, 0) << "exponent " << c.exponent;
  }
}

// Analytic M of the ellipsoid at the radial projection of the face centroid
// (see test_field_curvature.cpp).
Eigen::Matrix2d EllipsoidM(const FaceFrames& fr, FaceIndex f, double a, double b, double c) {
  const V3 x0 = fr.centroid[f.idx()];
  const double s = 1.0 / std::sqrt(x0.x() * x0.x() / (a * a) + x0.y() * x0.y() / (b * b) +
                                   x0.z() * x0.z() / (c * c));
  const V3 x = s * x0;
  const V3 grad(2 * x.x() / (a * a), 2 * x.y() / (b * b), 2 * x.z() / (c * c));
  const Eigen::Matrix3d H = V3(2 / (a * a), 2 / (b * b), 2 / (c * c)).asDiagonal();
  Eigen::Matrix<double, 3, 2> E;
  E.col(0) = fr.e1[f.idx()];
  E.col(1) = fr.e2[f.idx()];
  return -E.transpose() * H * E / grad.norm();
}

// The four umbilics of an ellipsoid with a > b > c (in the x–z plane).
std::vector<V3> Umbilics(double a, double b, double c) {
  const double x = a * std::sqrt((a * a - b * b) / (a * a - c * c));
  const double z = c * std::sqrt((b * b - c * c) / (a * a - c * c));
  return {V3(x, 0, z), V3(-x, 0, z), V3(x, 0, -z), V3(-x, 0, -z)};
}

void ExpectFourHalfSingularitiesAtUmbilics(const Mesh& mesh, const std::vector<double>& ind,
                                           double a, double b, double c, double radius) {
  const std::vector<Singularity> s = Singularities(mesh, ind);
  ASSERT_EQ(s.size(), 4u);
  for (const Singularity& x : s) {
    EXPECT_EQ(x.index, 0.5);
    double nearest = INFINITY;
    for (const V3& u : Umbilics(a, b, c)) nearest = std::min(nearest, (x.position - u).norm());
    EXPECT_LT(nearest, radius);
  }
}

TEST(Singularities, PrincipalFieldOfAnEllipsoidHasFourHalvesAtTheUmbilics) {
  const double a = 1.5, b = 1.0, c = 0.6;
  const Mesh mesh = TriangulatedEllipsoid(a, b, c, 4);
  const Field fd = MakeField(mesh);
  const double edge = 1.2 * 1.05 / 16;  // icosphere edge ≈ 1.05 R / 2^s, R ≤ 1.5
  const std::vector<Vec2> principal(mesh.number_of_faces(), Vec2(1, 0));
  // Analytic M.
  std::vector<FaceCurvature> exact(mesh.number_of_faces());
  for (FaceIndex f : mesh.faces())
    exact[f.idx()] = CurvatureOfMatrix(EllipsoidM(fd.frames, f, a, b, c), 1e-9, 1e-3);
  const std::vector<ConjugatePair> pairs = TcdPairs(exact, principal);
  std::vector<double> ind =
      VertexIndices(mesh, fd.transports, fd.edge_to_transport, BisectorAngles(pairs));
  ExpectFourHalfSingularitiesAtUmbilics(mesh, ind, a, b, c, 2 * edge);
  // Jet M.
  const std::vector<FaceCurvature> jets = ComputeFaceCurvature(mesh, fd.frames);
  const std::vector<ConjugatePair> jet_pairs = TcdPairs(jets, principal);
  ind = VertexIndices(mesh, fd.transports, fd.edge_to_transport, BisectorAngles(jet_pairs));
  EXPECT_EQ(Sum(ind), 2.0);
  ExpectFourHalfSingularitiesAtUmbilics(mesh, ind, a, b, c, 3 * edge);
  // Conjugate by construction, on every face, for the principal field and a
  // random one inside the circle.
  TcdFieldStats st = FieldStats(jets, jet_pairs);
  EXPECT_EQ(st.invalid_faces, 0);
  EXPECT_LE(st.max_conjugacy_error, 1e-8);
  EXPECT_NEAR(st.min_angle_deg, 90.0, 1e-6);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  std::vector<Vec2> random(mesh.number_of_faces());
  for (Vec2& z : random) z = Vec2(1 + u(rng), u(rng));
  st = FieldStats(jets, TcdPairs(jets, random));
  EXPECT_GT(st.valid_faces, static_cast<int>(mesh.number_of_faces()) - 5);
  EXPECT_LE(st.max_conjugacy_error, 1e-8);
  std::printf("ellipsoid: %d valid faces, max conjugacy error %.2e, min angle %.1f deg\n",
              st.valid_faces, st.max_conjugacy_error, st.min_angle_deg);
}

TEST(Singularities, MonkeySaddleHasOneMinusHalfAtTheOrigin) {
  const Mesh mesh = JitteredMonkeySaddle();
  const Field fd = MakeField(mesh);
  const std::vector<FaceCurvature> jets = ComputeFaceCurvature(mesh, fd.frames);
  const std::vector<Vec2> principal(mesh.number_of_faces(), Vec2(1, 0));
  const std::vector<double> ind = VertexIndices(mesh, fd.transports, fd.edge_to_transport,
                                                BisectorAngles(TcdPairs(jets, principal)));
  const std::vector<Singularity> s = Singularities(mesh, ind);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].index, -0.5);
  // The origin lies in a face at the jittered grid vertex (15, 15): the
  // singular vertex is within one edge (2/30) of it.
  EXPECT_LT(s[0].position.head<2>().norm(), 2.0 / 30);
}

TEST(SigmaBlend, Equation4) {
  EXPECT_EQ(SigmaBlend(0.0, 1.0, 3.0), 1.0);
  EXPECT_EQ(SigmaBlend(1.0, 1.0, 3.0), 1.0);
  EXPECT_NEAR(SigmaBlend(2.0, 1.0, 3.0), 0.5, 1e-15);
  EXPECT_NEAR(SigmaBlend(1.5, 1.0, 3.0), 0.5 + 0.5 * std::cos(M_PI / 4), 1e-15);
  EXPECT_EQ(SigmaBlend(3.0, 1.0, 3.0), 0.0);
  EXPECT_EQ(SigmaBlend(7.0, 1.0, 3.0), 0.0);
}

TEST(Singularities, MovingASingularityWithTheSigmaBlend) {
  const double a = 1.5, b = 1.0, c = 0.6;
  const Mesh mesh = TriangulatedEllipsoid(a, b, c, 4);
  const Field fd = MakeField(mesh);
  std::vector<FaceCurvature> exact(mesh.number_of_faces());
  for (FaceIndex f : mesh.faces())
    exact[f.idx()] = CurvatureOfMatrix(EllipsoidM(fd.frames, f, a, b, c), 1e-9, 1e-3);
  const std::vector<Vec2> principal(mesh.number_of_faces(), Vec2(1, 0));
  auto indices = [&](const std::vector<Vec2>& z) {
    return VertexIndices(mesh, fd.transports, fd.edge_to_transport,
                         BisectorAngles(TcdPairs(exact, z)));
  };
  const std::vector<Singularity> before = Singularities(mesh, indices(principal));
  ASSERT_EQ(before.size(), 4u);
  // From a face at the first singularity to a face ≈ 0.25 away (≈ 3 edges).
  const V3 p0 = before[0].position;
  FaceIndex f0, f1;
  double best0 = INFINITY, best1 = INFINITY;
  V3 target = p0 + 0.25 * V3(0, 1, 0);
  for (FaceIndex f : mesh.faces()) {
    const double d0 = (fd.frames.centroid[f.idx()] - p0).norm();
    const double d1 = (fd.frames.centroid[f.idx()] - target).norm();
    if (d0 < best0) best0 = d0, f0 = f;
    if (d1 < best1) best1 = d1, f1 = f;
  }
  const SingularityMove move = MoveSingularity(mesh, fd.frames, fd.transports, exact, principal,
                                               f0, f1, 0.35, 0.7);
  ASSERT_TRUE(move.reached);
  EXPECT_LT((move.z_n[f1.idx()] - exact[f1.idx()].z_m).norm(), 1e-12);
  int unchanged = 0;
  for (FaceIndex f : mesh.faces()) {
    if (move.beta[f.idx()] == 0.0) {
      EXPECT_EQ(move.z_n[f.idx()], principal[f.idx()]);
      ++unchanged;
    }
  }
  EXPECT_GT(unchanged, static_cast<int>(mesh.number_of_faces()) / 2);
  const std::vector<Singularity> after = Singularities(mesh, indices(move.z_n));
  double sum = 0;
  int near_old = 0, near_new = 0;
  const V3 c1 = fd.frames.centroid[f1.idx()];
  for (const Singularity& s : after) {
    sum += s.index;
    if ((s.position - p0).norm() < 0.08) ++near_old;
    if ((s.position - c1).norm() < 0.08) {
      ++near_new;
      EXPECT_EQ(s.index, 0.5);
    }
  }
  EXPECT_EQ(sum, 2.0);
  EXPECT_EQ(near_old, 0);
  EXPECT_EQ(near_new, 1);
  EXPECT_EQ(after.size(), 4u);
  // A target face without a finite z_M: reported, nothing moved.
  std::vector<FaceCurvature> flat = exact;
  flat[f1.idx()] = CurvatureOfMatrix(Eigen::Matrix2d::Zero(), 1e-9, 1e-3);
  const SingularityMove none =
      MoveSingularity(mesh, fd.frames, fd.transports, flat, principal, f0, f1, 0.35, 0.7);
  EXPECT_FALSE(none.error.empty());
  EXPECT_FALSE(none.reached);
  EXPECT_EQ(none.z_n, principal);
}

}  // namespace
}  // namespace archgeo
