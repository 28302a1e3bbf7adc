// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for fabrication/: panel flatness and measures, flat outlines, the
// sheet layout, node axes and beams, each against an analytic value or a
// construction whose answer is known.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "fabrication/nodes.h"
#include "fabrication/panels.h"
#include "fabrication/sheet_layout.h"
#include "fabrication/units.h"
#include "tests/segments_meet.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

constexpr double kRounding = 1e-12;

// A rigid motion far from the origin (millimetre coordinates of a roof).
Eigen::Vector3d Moved(const Eigen::Vector3d& p) {
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())).toRotationMatrix();
  return turn * p + Eigen::Vector3d(12000, -3500, 8000);
}

std::vector<Eigen::Vector3d> MovedAll(std::vector<Eigen::Vector3d> corners) {
  for (Eigen::Vector3d& c : corners) c = Moved(c);
  return corners;
}

TEST(PanelFlatness, TwistedSquareIsOffItsPlaneByTheTwist) {
  // Corners alternately ±h above z = 0: by symmetry the least-squares plane
  // is z = 0 and every corner is h from it, wherever the panel is.
  const double h = 0.25;
  const std::vector<Eigen::Vector3d> corners =
      MovedAll({{0, 0, h}, {1000, 0, -h}, {1000, 1000, h}, {0, 1000, -h}});
  EXPECT_NEAR(PanelFlatness(corners), h, 1e-9);
  const BestFitPlane plane = FitPlane(corners);
  EXPECT_NEAR(std::abs(plane.normal.dot(Moved({0, 0, 1}) - Moved({0, 0, 0}))), 1.0, kRounding);
  EXPECT_EQ(PanelFlatness(MovedAll({{0, 0, 0}, {1, 0, 0}, {0, 1, 5}})), 0.0);
}

TEST(MeasurePanel, RectangleAndLShapeHaveTheirAnglesDiagonalsAndArea) {
  const PanelGeometry r = MeasurePanel(MovedAll({{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {0, 2, 0}}));
  EXPECT_NEAR(r.area, 6.0, 1e-9);
  ASSERT_EQ(r.edges.size(), 4u);
  EXPECT_NEAR(r.edges[0], 3.0, 1e-9);
  EXPECT_NEAR(r.edges[1], 2.0, 1e-9);
  for (double a : r.angles) EXPECT_NEAR(a, 90.0, 1e-9);
  ASSERT_EQ(r.diagonals.size(), 2u);
  EXPECT_NEAR(r.diagonals[0], std::sqrt(13.0), 1e-9);
  EXPECT_NEAR(r.flatness, 0.0, 1e-9);
  EXPECT_NEAR(r.projection_change, 0.0, 1e-12);
  // An L of six corners: one reflex corner of 270°, angles summing to 720°,
  // 6·3/2 = 9 diagonals.
  const PanelGeometry l =
      MeasurePanel(MovedAll({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}}));
  EXPECT_NEAR(l.angles[3], 270.0, 1e-9);
  double sum = 0;
  for (double a : l.angles) sum += a;
  EXPECT_NEAR(sum, 720.0, 1e-9);
  EXPECT_EQ(l.diagonals.size(), 9u);
  EXPECT_NEAR(l.area, 3.0, 1e-9);
}

TEST(FlattenPanel, KeepsEveryEdgeLengthOfATwistedQuad) {
  const std::vector<Eigen::Vector3d> corners =
      MovedAll({{0, 0, 20}, {1000, 0, -20}, {1100, 900, 20}, {-50, 1000, -20}});
  const FlatOutline flat = FlattenPanel(corners);
  ASSERT_EQ(flat.corners.size(), 4u);
  for (size_t k = 0; k < 4; ++k) {
    const double edge = (corners[(k + 1) % 4] - corners[k]).norm();
    EXPECT_NEAR((flat.corners[(k + 1) % 4] - flat.corners[k]).norm() / edge, 1.0, kRounding);
  }
  // The diagonal from corner 0 is kept; the other one is where the twist shows.
  const double d02 = (corners[2] - corners[0]).norm(), d13 = (corners[3] - corners[1]).norm();
  EXPECT_NEAR((flat.corners[2] - flat.corners[0]).norm() / d02, 1.0, kRounding);
  const double change13 = std::abs((flat.corners[3] - flat.corners[1]).norm() - d13) / d13;
  EXPECT_GT(change13, 1e-5);
  EXPECT_NEAR(flat.change, change13, kRounding);
  // Seen from the side of the normal: counter-clockwise (positive area).
  double area2 = 0;
  for (size_t k = 0; k < 4; ++k) {
    const Eigen::Vector2d& a = flat.corners[k];
    const Eigen::Vector2d& b = flat.corners[(k + 1) % 4];
    area2 += a.x() * b.y() - a.y() * b.x();
  }
  EXPECT_GT(area2, 0);
  // The projection of the same panel shortens its edges.
  EXPECT_GT(MeasurePanel(corners).projection_change, 1e-5);
}

TEST(FlattenPanel, PlanarHexagonIsCongruent) {
  std::vector<Eigen::Vector3d> corners;
  for (int k = 0; k < 6; ++k) {
    const double t = 2 * M_PI * k / 6;
    corners.push_back(Moved({700 * std::cos(t), 450 * std::sin(t), 0}));
  }
  const FlatOutline flat = FlattenPanel(corners);
  EXPECT_LE(flat.change, 1e-12);
  for (size_t i = 0; i < 6; ++i) {
    for (size_t j = i + 1; j < 6; ++j) {
      EXPECT_NEAR((flat.corners[j] - flat.corners[i]).norm(), (corners[j] - corners[i]).norm(),
                  1e-9);
    }
  }
}

TEST(LayOutOnSheets, RandomPanelsFitTheirSheetsApartAndUnchanged) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> size(200, 1400), turn(0, 2 * M_PI);
  std::vector<std::vector<Eigen::Vector2d>> outlines;
  for (int i = 0; i < 60; ++i) {  // convex quads and pentagons, turned anyhow
    const int n = 4 + i % 2;
    const double w = size(random), h = size(random), t = turn(random);
    std::vector<Eigen::Vector2d> outline;
    for (int k = 0; k < n; ++k) {
      const double a = 2 * M_PI * k / n + 0.1 * (k % 2);
      outline.push_back(Eigen::Rotation2Dd(t) * Eigen::Vector2d(w * std::cos(a), h * std::sin(a)) +
                        Eigen::Vector2d(5000, -300));
    }
    outlines.push_back(outline);
  }
  outlines.push_back({{0, 0}, {7000, 0}, {7000, 100}, {0, 100}});  // longer than any sheet
  const Eigen::Vector2d sheet(3000, 6000);
  const double gap = 10;
  const SheetLayout layout = LayOutOnSheets(outlines, sheet, gap);
  ASSERT_EQ(layout.outlines.size(), outlines.size());
  ASSERT_EQ(layout.oversize, std::vector<int>{60});
  EXPECT_EQ(layout.outlines[60].sheet, int(layout.sheets.size()) - 1);
  EXPECT_GE(layout.sheets.back().x(), 7000 + 2 * gap);
  EXPECT_GT(layout.sheets.size(), 2u);
  for (size_t i = 0; i < outlines.size(); ++i) {
    const PlacedOutline& p = layout.outlines[i];
    EXPECT_EQ(p.panel, int(i));
    const Eigen::Vector2d& s = layout.sheets[size_t(p.sheet)];
    for (const Eigen::Vector2d& c : p.corners) {  // inside its sheet, gap from the edge
      EXPECT_GE(c.minCoeff(), gap - 1e-9);
      EXPECT_LE(c.x(), s.x() - gap + 1e-9);
      EXPECT_LE(c.y(), s.y() - gap + 1e-9);
    }
    for (size_t a = 0; a < outlines[i].size(); ++a) {  // congruent: turned and moved only
      for (size_t b = a + 1; b < outlines[i].size(); ++b) {
        EXPECT_NEAR((p.corners[b] - p.corners[a]).norm(), (outlines[i][b] - outlines[i][a]).norm(),
                    1e-9);
      }
    }
  }
  for (size_t i = 0; i < outlines.size(); ++i) {  // no two outlines on a sheet meet
    for (size_t j = i + 1; j < outlines.size(); ++j) {
      const PlacedOutline& p = layout.outlines[i];
      const PlacedOutline& q = layout.outlines[j];
      if (p.sheet != q.sheet) continue;
      for (size_t a = 0; a < p.corners.size(); ++a) {
        for (size_t b = 0; b < q.corners.size(); ++b) {
          EXPECT_FALSE(SegmentsMeet(p.corners[a], p.corners[(a + 1) % p.corners.size()],
                                    q.corners[b], q.corners[(b + 1) % q.corners.size()]))
              << "outlines " << i << " and " << j;
        }
      }
      // Neither inside the other: their rectangles are apart.
      EXPECT_TRUE(p.high.x() + gap <= q.low.x() + 1e-9 || q.high.x() + gap <= p.low.x() + 1e-9 ||
                  p.high.y() + gap <= q.low.y() + 1e-9 || q.high.y() + gap <= p.low.y() + 1e-9);
    }
  }
}

// The meridian/parallel net of a torus (R = 3000, r = 1000): planar
// trapezoids whose stars are symmetric about the meridian plane, so
// conical [Liu et al. 2006]; vertex (i, j) at u_i = 2πi/nu, v_j = 2πj/nv.
PlainMesh Torus(int nu, int nv) {
  PlainMesh m;
  const auto id = [&](int i, int j) { return ((i + nu) % nu) * nv + (j + nv) % nv; };
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      const double rho = 3000 + 1000 * std::cos(v);
      m.points.push_back({rho * std::cos(u), rho * std::sin(u), 1000 * std::sin(v)});
    }
  }
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j)
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  }
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {  // faces (i, j), (i−1, j), (i−1, j−1), (i, j−1): cyclic
      m.vertex_faces.push_back({id(i, j), id(i - 1, j), id(i - 1, j - 1), id(i, j - 1)});
      m.boundary.push_back(false);
      m.edges.push_back({id(i, j), id(i + 1, j)});
      m.edges.push_back({id(i, j), id(i, j + 1)});
    }
  }
  return m;
}

TEST(NodeAxes, ConicalTorusNetGetsItsConeAxesAndUntwistedBeams) {
  const PlainMesh torus = Torus(24, 12);
  // The unit normal of quad f (the cross product of its diagonals).
  const auto QuadNormal = [&torus](int f) {
    const std::vector<int>& q = torus.faces[size_t(f)];
    return Eigen::Vector3d((torus.points[size_t(q[2])] - torus.points[size_t(q[0])])
                               .cross(torus.points[size_t(q[3])] - torus.points[size_t(q[1])])
                               .normalized());
  };
  const std::vector<NodeAxis> nodes = NodeAxes(torus, 1e-9);
  for (size_t v = 0; v < nodes.size(); ++v) {
    const NodeAxis& n = nodes[v];
    ASSERT_TRUE(n.cone) << "vertex " << v << ": conical residual " << n.conical;
    EXPECT_LE(n.conical, 1e-12);
    // Equal angles with the four face normals, and 1 / cos of that angle.
    std::vector<double> cosines;
    for (int f : torus.vertex_faces[v]) {
      const Eigen::Vector3d normal = QuadNormal(f);
      cosines.push_back(normal.dot(n.axis));
    }
    for (double c : cosines) EXPECT_NEAR(c, cosines[0], 1e-12);
    EXPECT_NEAR(n.offset_factor, 1 / cosines[0], 1e-9);
    // By symmetry the axis lies in the vertex's meridian plane.
    const Eigen::Vector3d& p = torus.points[v];
    EXPECT_NEAR(n.axis.dot(Eigen::Vector3d(-p.y(), p.x(), 0).normalized()), 0.0, 1e-12);
    EXPECT_GT(n.axis.dot(n.normal), 0.99);
  }
  // Neighbouring cone axes lie in the bisector plane of the edge's faces.
  for (const Beam& b : Beams(torus, nodes)) EXPECT_LE(b.twist_degrees, 1e-9);
  // The beams' far edges at depth d: at v + d / cos φ · axis, where the
  // face planes offset by d meet (a face offset, on either side).
  for (const double depth : {7.5, -3.0}) {
    const std::vector<Eigen::Vector3d> far = OffsetNodes(torus, nodes, depth);
    EXPECT_LE(FaceOffsetError(torus, far, depth), 1e-9 * std::abs(depth));
    for (size_t v = 0; v < far.size(); ++v) {
      EXPECT_LE((far[v] - torus.points[v] - depth * nodes[v].offset_factor * nodes[v].axis).norm(),
                1e-9 * std::abs(depth));
    }
    for (const Beam& b : Beams(torus, nodes, depth)) {
      EXPECT_EQ(b.offset0, far[size_t(b.v0)]);
      EXPECT_EQ(b.offset1, far[size_t(b.v1)]);
    }
  }
  // Without a cone bound: area-weighted vertex normals, which make unequal
  // angles with the faces where the faces above and below a vertex differ
  // in size (the axis of a cone is then not the normal).
  const std::vector<NodeAxis> normals = NodeAxes(torus, 0);
  double spread = 0;
  for (size_t v = 0; v < normals.size(); ++v) {
    EXPECT_FALSE(normals[v].cone);
    double low = 2, high = -2;
    for (int f : torus.vertex_faces[v]) {
      const Eigen::Vector3d normal = QuadNormal(f);
      low = std::min(low, normal.dot(normals[v].axis));
      high = std::max(high, normal.dot(normals[v].axis));
    }
    spread = std::max(spread, high - low);
  }
  EXPECT_GT(spread, 1e-3);
  // Offset along those normals the nodes miss the offset face planes.
  EXPECT_GT(FaceOffsetError(torus, OffsetNodes(torus, normals, 7.5), 7.5), 1e-3 * 7.5);
  // A net moved off the torus at random: its vertex normals twist the beams.
  PlainMesh moved = torus;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> shift(-50, 50);
  for (Eigen::Vector3d& p : moved.points)
    p += Eigen::Vector3d(shift(random), shift(random), shift(random));
  double twist = 0;
  for (const Beam& b : Beams(moved, NodeAxes(moved, 0))) twist = std::max(twist, b.twist_degrees);
  EXPECT_GT(twist, 0.1);
}

TEST(NodeAxes, VertexNormalIsTheAreaWeightedSumOfItsFaces) {
  // Two unequal faces meeting at a ridge along the y axis: the normal is
  // the sum of area × unit normal (areas 2 and √2 here), normalised.
  PlainMesh m;
  m.points = {{0, 0, 0}, {0, 1, 0}, {-2, 1, 0}, {-2, 0, 0}, {1, 0, 1}, {1, 1, 1}};
  m.faces = {{0, 1, 2, 3}, {0, 4, 5, 1}};
  m.vertex_faces = {{0, 1}, {0, 1}, {0}, {0}, {1}, {1}};
  m.boundary.assign(6, true);
  const std::vector<NodeAxis> nodes = NodeAxes(m, 1e-6);
  const Eigen::Vector3d expected =
      (2.0 * Eigen::Vector3d(0, 0, 1) + std::sqrt(2.0) * Eigen::Vector3d(-1, 0, 1).normalized())
          .normalized();
  EXPECT_NEAR((nodes[0].axis - expected).norm(), 0.0, kRounding);
  EXPECT_FALSE(nodes[0].cone);
}

TEST(Units, MillimetresPerUnit) {
  EXPECT_EQ(MillimetresPerUnit("mm"), 1.0);
  EXPECT_EQ(MillimetresPerUnit("m"), 1000.0);
  EXPECT_EQ(MillimetresPerUnit("in"), 25.4);
  EXPECT_EQ(MillimetresPerUnit("ft"), 304.8);
  EXPECT_EQ(MillimetresPerUnit("none"), 0.0);
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
