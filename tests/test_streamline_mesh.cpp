// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for fields/streamline_mesh.h (the streamline-intersection layout,
// [Gebreiter 2012, §8.2]) on surfaces where the answer is known:
//  - a plane with a constant field: n_v straight lines across one way, n_w the
//    other; every face a quad, (n_v + 1)(n_w + 1) faces and
//    n_v n_w + 2 (n_v + n_w) + 4 vertices (crossings, line ends, the corners);
//  - an open cylinder with its principal field (closed circles, straight
//    rulings): n_r (n_c + 1) quads, n_r (n_c + 2) vertices;
//  - edges along the field: the measured edge-to-field angle is ~0.
#include <cmath>
#include <cstdio>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "fields/streamline_mesh.h"
#include "fields/streamlines.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using V3 = Eigen::Vector3d;

// A (nu × nv)-cell grid of points x(i, j), two triangles per cell
// (counter-clockwise seen from x_u × x_v); `periodic`: column nu is column 0.
template <class X>
StreamlineInput Grid(int nu, int nv, bool periodic, X x) {
  StreamlineInput in;
  const int cols = periodic ? nu : nu + 1;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i < cols; ++i) in.points.push_back(x(i, j));
  auto id = [&](int i, int j) { return j * cols + (periodic ? i % nu : i); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      in.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      in.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  in.valid.assign(in.triangles.size(), true);
  in.directions.resize(in.triangles.size());
  return in;
}

V3 Normal(const StreamlineInput& in, size_t f) {
  const auto& t = in.triangles[f];
  return (in.points[size_t(t[1])] - in.points[size_t(t[0])])
      .cross(in.points[size_t(t[2])] - in.points[size_t(t[0])])
      .normalized();
}

int Count(const StreamlineResult& r, int family) {
  int n = 0;
  for (const Streamline& l : r.lines) n += l.family == family;
  return n;
}

void ExpectAllQuads(const StreamlineMesh& m) {
  for (const auto& f : m.faces) EXPECT_EQ(f.size(), 4u);
  EXPECT_EQ(m.dangling_ends, 0);
  EXPECT_EQ(m.dropped_faces, 0);
}

TEST(StreamlineMesh, ConstantFieldOnAPlaneIsAGridOfQuads) {
  StreamlineInput in = Grid(24, 24, false, [](int i, int j) {
    // Jittered interior vertices: the lines cross triangles at any angle.
    const double jx = (i % 24 && j % 24) ? 0.01 * std::sin(7.0 * i + 3.0 * j) : 0.0;
    const double jy = (i % 24 && j % 24) ? 0.01 * std::cos(5.0 * i - 2.0 * j) : 0.0;
    return V3(2.0 * i / 24 - 1 + jx, 2.0 * j / 24 - 1 + jy, 0.0);
  });
  for (auto& d : in.directions) d = {V3::UnitX(), V3::UnitY()};
  StreamlineOptions o;
  o.separation = 0.2;
  o.separatrices = false;
  const StreamlineResult r = TraceStreamlines(in, o);
  const int nv = Count(r, 0), nw = Count(r, 1);
  const StreamlineMesh m = MeshFromStreamlines(in, r.lines, r.d_sep);
  std::printf("plane: %d v-lines, %d w-lines -> %zu faces, %zu vertices\n", nv, nw,
              m.faces.size(), m.points.size());
  ASSERT_GE(nv, 9);
  ASSERT_GE(nw, 9);
  ExpectAllQuads(m);
  EXPECT_EQ(int(m.faces.size()), (nv + 1) * (nw + 1));
  EXPECT_EQ(int(m.points.size()), nv * nw + 2 * (nv + nw) + 4);
  EXPECT_EQ(m.crossings, nv * nw);
  EXPECT_EQ(m.boundary_ends, 2 * (nv + nw));
  // The faces keep the triangles' orientation (+z).
  for (const auto& f : m.faces) {
    V3 n = V3::Zero();
    for (size_t k = 0; k < f.size(); ++k) n += m.points[size_t(f[k])].cross(m.points[size_t(f[(k + 1) % f.size()])]);
    EXPECT_GT(n.z(), 0);
  }
  const EdgeFieldAngle angle = MeasureEdgeFieldAngle(in, m.points, m.faces);
  EXPECT_GT(angle.edges, 2 * nv * nw);
  EXPECT_LT(angle.max_deg, 1e-6);
}

TEST(StreamlineMesh, OpenCylinderCirclesAndRulingsGiveQuads) {
  const int around = 48, rows = 16;
  StreamlineInput in = Grid(around, rows, true, [&](int i, int j) {
    const double a = 2 * M_PI * i / around;
    return V3(std::cos(a), std::sin(a), 2.0 * j / rows);
  });
  // The principal field: the circle's tangent and the ruling, in each face's plane.
  for (size_t f = 0; f < in.triangles.size(); ++f) {
    V3 c = V3::Zero();
    for (int v : in.triangles[f]) c += in.points[size_t(v)] / 3;
    const V3 n = Normal(in, f);
    const V3 circle = V3(-c.y(), c.x(), 0).normalized();
    in.directions[f] = {(circle - circle.dot(n) * n).normalized(), V3::UnitZ()};
  }
  StreamlineOptions o;
  o.separation = 0.3;
  o.separatrices = false;
  const StreamlineResult r = TraceStreamlines(in, o);
  const int circles = Count(r, 0), rulings = Count(r, 1);
  int closed = 0;
  for (const Streamline& l : r.lines) closed += l.closed;
  const StreamlineMesh m = MeshFromStreamlines(in, r.lines, r.d_sep);
  std::printf("cylinder: %d circles (%d closed), %d rulings -> %zu faces, %zu vertices\n", circles,
              closed, rulings, m.faces.size(), m.points.size());
  ASSERT_EQ(closed, circles);
  ASSERT_GE(circles, 5);
  ASSERT_GE(rulings, 18);
  ExpectAllQuads(m);
  EXPECT_EQ(int(m.faces.size()), rulings * (circles + 1));
  EXPECT_EQ(int(m.points.size()), rulings * (circles + 2));
  const EdgeFieldAngle angle = MeasureEdgeFieldAngle(in, m.points, m.faces);
  std::printf("  edge-to-field angle mean %.3g°, max %.3g°\n", angle.mean_deg, angle.max_deg);
  EXPECT_LT(angle.mean_deg, 2.0);
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
