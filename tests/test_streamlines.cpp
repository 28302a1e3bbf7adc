// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for fields/streamlines.h [Gebreiter 2012, §8.2, §8.1.3; Jobard &
// Lefer 1997] on the principal (z_N = e1) TCD field of [Zadravec 2010]:
//  - a constant field on a jittered plane: straight lines across the plane,
//    parallel, d_sep apart (analytic);
//  - a closed ellipsoid: its four +1/2 umbilics sum to χ = 2 and give one
//    separatrix per family each (2|1 − k|); same-family lines no closer than
//    d_test = 0.5 d_sep (measured segment to segment on the output) and no
//    line closer to itself than d_test;
//  - a torus: no singularity (χ = 0), the lines are its parallels and
//    meridians, closed loops;
//  - a monkey saddle: its −1/2 singularity is a trisector (three separatrices
//    per family).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "fields/field_io.h"
#include "fields/streamlines.h"
#include "fields/tcd_field.h"
#include "fields/triangle_surfaces.h"
#include "tests/make_mesh.h"
#include "tests/monkey_saddle.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using V3 = Eigen::Vector3d;

// The principal field of `mesh` and its streamline input.
struct Principal {
  FieldGeometry geometry;
  TcdField field;
  StreamlineInput input;
};

Principal PrincipalField(const Mesh& mesh) {
  Principal p;
  p.geometry = ComputeFieldGeometry(mesh, JetOptions{});
  p.field = EvaluateField(mesh, p.geometry,
                          std::vector<Eigen::Vector2d>(mesh.number_of_faces(), {1.0, 0.0}));
  p.input = StreamlineInputOf(mesh, p.geometry, p.field);
  return p;
}

double Diagonal(const StreamlineInput& in) {
  V3 lo = in.points[0], hi = in.points[0];
  for (const V3& x : in.points) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return (hi - lo).norm();
}

// The checks every traced field must pass: same-family lines at least
// d_test apart, no line within d_test of itself.
void ExpectSpacing(const StreamlineResult& r) {
  const double separation = SmallestSeparation(r.lines, r.d_sep);
  const double self = SmallestSelfDistance(r.lines, 3 * r.d_test, r.d_sep);
  std::printf("  smallest same-family separation %.4f d_sep, self distance %s\n",
              separation / r.d_sep,
              std::isfinite(self) ? std::to_string(self / r.d_sep).c_str() : "> d_sep");
  EXPECT_GE(separation, 0.5 * r.d_sep * (1 - 1e-9));
  EXPECT_GE(self, r.d_test * (1 - 1e-9));
}

TEST(Streamlines, ConstantFieldOnAPlaneGivesParallelLinesDSepApart) {
  TriangleGridOptions opt;
  opt.jitter = 0.3;
  const Mesh mesh = TriangulatedGrid(
      24, 24, [](double u, double v) -> Vec3 { return {2 * u - 1, 2 * v - 1, 0.0}; }, opt);
  StreamlineInput in;
  for (VertexIndex v : mesh.vertices()) in.points.push_back(Pos(mesh, v));
  for (FaceIndex f : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) t[size_t(k++)] = int(v.idx());
    in.triangles.push_back(t);
    in.directions.push_back({V3::UnitX(), V3::UnitY()});
    in.valid.push_back(true);
  }
  StreamlineOptions o;
  o.separation = 0.2;
  o.separatrices = false;
  const StreamlineResult r = TraceStreamlines(in, o);
  for (int family = 0; family < 2; ++family) {
    std::vector<double> offsets;  // y of the v-lines, x of the w-lines
    for (const Streamline& l : r.lines) {
      if (l.family != family) continue;
      const double offset = family == 0 ? l.points[0].y() : l.points[0].x();
      for (const V3& p : l.points) {
        EXPECT_NEAR(family == 0 ? p.y() : p.x(), offset, 1e-12);  // straight, parallel
        EXPECT_NEAR(p.z(), 0.0, 1e-15);
      }
      EXPECT_NEAR(l.length, 2.0, 1e-9);  // boundary to boundary
      offsets.push_back(offset);
    }
    std::sort(offsets.begin(), offsets.end());
    ASSERT_GE(offsets.size(), 9u);
    // Seeded d_sep from their neighbours; the outermost may be seeded from a
    // face centroid in a strip narrower than d_sep (≥ 0.9 d_sep from its line).
    for (size_t i = 1; i < offsets.size(); ++i) {
      const double gap = offsets[i] - offsets[i - 1];
      if (i == 1 || i + 1 == offsets.size()) {
        EXPECT_GE(gap, 0.9 * 0.2 - 1e-12);
        EXPECT_LE(gap, 0.2 + 1e-12);
      } else {
        EXPECT_NEAR(gap, 0.2, 1e-12) << "family " << family << ", line " << i;
      }
    }
    EXPECT_LE(offsets.front(), -1 + 0.2);
    EXPECT_GE(offsets.back(), 1 - 0.2);
  }
  ExpectSpacing(r);
}

TEST(Streamlines, ClosedEllipsoidUmbilicsSumToChiAndHaveOneSeparatrixPerFamily) {
  const Mesh mesh = TriangulatedEllipsoid(1.5, 1.0, 0.6, 4);
  const Principal p = PrincipalField(mesh);
  ASSERT_EQ(p.field.singularities.size(), 4u);
  EXPECT_EQ(p.field.index_sum, 2.0);  // Poincaré–Hopf: χ of the sphere
  StreamlineOptions o;
  o.separation = 0.05 * Diagonal(p.input);
  const StreamlineResult r = TraceStreamlines(p.input, o);
  int separatrices = 0, lines[2] = {0, 0};
  for (const Streamline& l : r.lines) (l.separatrix ? separatrices : lines[l.family])++;
  std::printf("ellipsoid: %d v-lines, %d w-lines, %d separatrices\n", lines[0], lines[1],
              separatrices);
  for (size_t j = 0; j < p.input.singularities.size(); ++j) {
    EXPECT_EQ(ExpectedSeparatrices(p.input.singularities[j].index), 1);
    EXPECT_EQ(r.separatrix_directions[j][0], 1) << "singularity " << j;
    EXPECT_EQ(r.separatrix_directions[j][1], 1) << "singularity " << j;
  }
  EXPECT_GE(separatrices, 4);
  EXPECT_GE(lines[0], 10);
  EXPECT_GE(lines[1], 10);
  ExpectSpacing(r);
}

TEST(Streamlines, TorusHasNoSingularityAndClosedParallelsAndMeridians) {
  const int nu = 64, nv = 24;
  Mesh torus;
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const double a = 2 * M_PI * i / nu, b = 2 * M_PI * j / nv;
      torus.add_vertex(Point((2 + std::cos(b)) * std::cos(a), (2 + std::cos(b)) * std::sin(a),
                             std::sin(b)));
    }
  }
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      auto id = [&](int x, int y) { return VertexIndex(((y + nv) % nv) * nu + (x + nu) % nu); };
      ASSERT_NE(torus.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1)), Mesh::null_face());
      ASSERT_NE(torus.add_face(id(i, j), id(i + 1, j + 1), id(i, j + 1)), Mesh::null_face());
    }
  }
  const Principal p = PrincipalField(torus);
  EXPECT_TRUE(p.field.singularities.empty());
  EXPECT_EQ(p.field.index_sum, 0.0);  // χ of the torus
  // Traced in the analytic principal field (the tangents of the parallel and
  // the meridian through each face centroid, in the face plane): the lines
  // then show the tracer's error alone, not the jets'.
  StreamlineInput in = p.input;
  for (size_t f = 0; f < in.triangles.size(); ++f) {
    V3 c = V3::Zero();
    for (int v : in.triangles[f]) c += in.points[size_t(v)] / 3;
    const double a = std::atan2(c.y(), c.x());
    const double b = std::atan2(c.z(), std::hypot(c.x(), c.y()) - 2);
    const V3 n = (in.points[size_t(in.triangles[f][1])] - in.points[size_t(in.triangles[f][0])])
                     .cross(in.points[size_t(in.triangles[f][2])] - in.points[size_t(in.triangles[f][0])])
                     .normalized();
    for (int k = 0; k < 2; ++k) {
      const V3 t = k == 0 ? V3(-std::sin(a), std::cos(a), 0)
                          : V3(-std::sin(b) * std::cos(a), -std::sin(b) * std::sin(a), std::cos(b));
      in.directions[f][size_t(k)] = (t - t.dot(n) * n).normalized();
    }
  }
  StreamlineOptions o;
  o.separation = 0.5;
  const StreamlineResult r = TraceStreamlines(in, o);
  int closed = 0;
  for (const Streamline& l : r.lines) {
    closed += l.closed;
    // A parallel keeps its tube angle b, a meridian its azimuth a (to within
    // the chords of the mesh: a face is 2π/24 of the tube across).
    double b_lo = 1e9, b_hi = -1e9, a_lo = 1e9, a_hi = -1e9;
    const double a0 = std::atan2(l.points[0].y(), l.points[0].x());
    const double b0 = std::atan2(l.points[0].z(), std::hypot(l.points[0].x(), l.points[0].y()) - 2);
    for (const V3& x : l.points) {
      const double a = std::remainder(std::atan2(x.y(), x.x()) - a0, 2 * M_PI);
      const double b =
          std::remainder(std::atan2(x.z(), std::hypot(x.x(), x.y()) - 2) - b0, 2 * M_PI);
      a_lo = std::min(a_lo, a);
      a_hi = std::max(a_hi, a);
      b_lo = std::min(b_lo, b);
      b_hi = std::max(b_hi, b);
    }
    const bool parallel = b_hi - b_lo < 0.05, meridian = a_hi - a_lo < 0.02;
    EXPECT_TRUE(parallel || meridian) << "tube angle " << b_lo << ".." << b_hi << ", azimuth "
                                      << a_lo << ".." << a_hi;
  }
  std::printf("torus: %zu lines, %d closed\n", r.lines.size(), closed);
  EXPECT_GE(closed, int(r.lines.size()) / 2);
  ExpectSpacing(r);
}

TEST(Streamlines, MonkeySaddleMinusHalfIsATrisector) {
  const Mesh mesh = JitteredMonkeySaddle();
  const Principal p = PrincipalField(mesh);
  ASSERT_EQ(p.field.singularities.size(), 1u);
  ASSERT_EQ(p.field.singularities[0].index, -0.5);
  EXPECT_EQ(ExpectedSeparatrices(-0.5), 3);
  StreamlineOptions o;
  o.separation = 0.05 * Diagonal(p.input);
  const StreamlineResult r = TraceStreamlines(p.input, o);
  EXPECT_EQ(r.separatrix_directions[0][0], 3);
  EXPECT_EQ(r.separatrix_directions[0][1], 3);
  // The separatrices of the principal field of z = Re (x + iy)³ run along the
  // lines of symmetry, at angles that are multiples of 30° from the x axis.
  int separatrices = 0;
  for (const Streamline& l : r.lines) {
    if (!l.separatrix) continue;
    ++separatrices;
    const V3 d = l.points[std::min<size_t>(l.points.size() - 1, 5)] - l.points[0];
    const double deg = std::atan2(d.y(), d.x()) * 180 / M_PI;
    const double off = std::abs(std::remainder(deg, 30.0));
    EXPECT_LT(off, 8.0) << "separatrix leaving at " << deg << "°";
  }
  EXPECT_EQ(separatrices, 6);
  ExpectSpacing(r);
}

TEST(Streamlines, ExpectedSeparatrixCounts) {
  EXPECT_EQ(ExpectedSeparatrices(0.5), 1);
  EXPECT_EQ(ExpectedSeparatrices(-0.5), 3);
  EXPECT_EQ(ExpectedSeparatrices(-1), 4);
  EXPECT_EQ(ExpectedSeparatrices(1), -1);
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
