// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for mesh/reference, mesh/topology, mesh/metrics and mesh/generators.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "make_mesh.h"
#include "generators/generators.h"
#include "analysis/metrics.h"
#include "geometry/reference.h"
#include "mesh/eigen_point.h"
#include "mesh/topology.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

constexpr double kExact = 1e-12;
const double kDegree = M_PI / 180.0;

using V = Eigen::Vector3d;

V E(const Vec3& x) { return {x[0], x[1], x[2]}; }
Vec3 ToArray(const V& x) { return {x[0], x[1], x[2]}; }

double AngleBetween(const Vec3& a, const Vec3& b) {
  return std::atan2(E(a).cross(E(b)).norm(), E(a).dot(E(b)));
}

void ExpectNear(const Vec3& actual, const Vec3& expected, double tolerance) {
  EXPECT_LE((E(actual) - E(expected)).norm(), tolerance)
      << "actual (" << actual[0] << ", " << actual[1] << ", " << actual[2] << "), expected ("
      << expected[0] << ", " << expected[1] << ", " << expected[2] << ")";
}

// Unit cube [0,1]^3, six outward-oriented quads.
Mesh Cube() {
  return MakeMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                   {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
                  {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                   {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}});
}


Vec3 FlatSquare(double u, double v) { return {u, v, 0.0}; }

Vec3 SphereCap(double u, double v) {  // unit sphere, a 1 x 1 radian patch around +z
  const double theta = u - 0.5, phi = v - 0.5;
  return {std::cos(phi) * std::sin(theta), std::sin(phi), std::cos(phi) * std::cos(theta)};
}

Mesh Transformed(const Mesh& mesh, double scale, const Vec3& axis, double angle,
                 const Vec3& translation) {
  const V k = E(axis).normalized();
  Mesh out = mesh;
  for (VertexIndex v : out.vertices()) {
    const V p = Pos(out, v);
    // Rodrigues: R p = p cos + (k x p) sin + k (k.p)(1 - cos)
    const V r = std::cos(angle) * p + std::sin(angle) * k.cross(p) +
                k.dot(p) * (1 - std::cos(angle)) * k;
    out.point(v) = ToPoint(ToArray(scale * r + E(translation)));
  }
  return out;
}

// ---------------------------------------------------------------- generators

TEST(QuadGrid, VertexOrderAndCounts) {
  const Mesh grid = QuadGrid(4, 3, RoofSurface);
  EXPECT_EQ(grid.number_of_vertices(), 20u);
  EXPECT_EQ(grid.number_of_faces(), 12u);
  EXPECT_EQ(grid.number_of_edges(), 31u);
  for (int j = 0; j <= 3; ++j) {
    for (int i = 0; i <= 4; ++i) {
      ExpectNear(ToVec3(grid.point(VertexIndex(j * 5 + i))), RoofSurface(i / 4.0, j / 3.0), kExact);
    }
  }
  // Counter-clockwise in (u, v): the first face's normal points up on a flat square.
  const Mesh flat = QuadGrid(2, 2, FlatSquare);
  const auto h = flat.halfedge(FaceIndex(0));
  const V a = Pos(flat, flat.source(h)), b = Pos(flat, flat.target(h)),
          c = Pos(flat, flat.target(flat.next(h)));
  EXPECT_GT((b - a).cross(c - b)[2], 0);
}

TEST(QuadGrid, NoiseIsBoundedAndSeeded) {
  const double noise = 0.2;
  const Mesh clean = QuadGrid(10, 8, RoofSurface);
  const Mesh noisy = QuadGrid(10, 8, RoofSurface, noise, 7);
  const double bound = noise * ComputeMetrics(clean, nullptr, nullptr).mean_edge_length;
  double largest = 0;
  for (VertexIndex v : clean.vertices()) {
    largest = std::max(largest, (Pos(noisy, v) - Pos(clean, v)).norm());
  }
  EXPECT_LE(largest, bound);
  EXPECT_GT(largest, 0.8 * bound);  // 99 uniform draws: the largest is near the bound
  const Mesh same = QuadGrid(10, 8, RoofSurface, noise, 7);
  const Mesh other = QuadGrid(10, 8, RoofSurface, noise, 8);
  EXPECT_EQ(ToVec3(same.point(VertexIndex(17))), ToVec3(noisy.point(VertexIndex(17))));
  EXPECT_NE(ToVec3(other.point(VertexIndex(17))), ToVec3(noisy.point(VertexIndex(17))));
}

TEST(QuadGrid, RejectsBadArguments) {
  EXPECT_THROW(QuadGrid(0, 3, RoofSurface), std::invalid_argument);
  EXPECT_THROW(QuadGrid(3, 3, RoofSurface, -0.1), std::invalid_argument);
}

TEST(RoofSurface, Formula) {
  ExpectNear(RoofSurface(0.5, 0.4), {1.0, 0.6, 0.3 * std::sin(2.0) + 0.25 * std::cos(1.2)}, kExact);
  ExpectNear(RoofSurface(1, 1), {2.0, 1.5, 0.3 * std::sin(4.0) + 0.25 * std::cos(3.0)}, kExact);
}

// ---------------------------------------------------------------- reference

TEST(ReferenceSurface, PlaneClosestPointAndNormalAreExact) {
  const V origin(0.2, -0.1, 0.3), a(1.0, 0.0, 0.5), b(0.0, 1.0, -0.25);
  const Mesh plane =
      QuadGrid(6, 5, [&](double u, double v) { return ToArray(origin + (u * a + v * b)); });
  const ReferenceSurface reference(plane);
  const V n = a.cross(b).normalized();  // S_u x S_v: the grid's orientation
  for (const auto& [u, v, h] : std::vector<std::array<double, 3>>{
           {0.37, 0.61, 0.8}, {0.5, 0.5, -0.3}, {0.01, 0.93, 2.0}}) {
    const V foot = origin + (u * a + v * b);
    const ReferenceSurface::SurfacePoint closest = reference.Closest(ToArray(foot + h * n));
    ExpectNear(closest.point, ToArray(foot), kExact);
    ExpectNear(closest.normal, ToArray(n), kExact);
  }
}

TEST(ReferenceSurface, SphereCapClosestPointAndSmoothNormal) {
  const Mesh cap = QuadGrid(60, 60, SphereCap);
  const ReferenceSurface reference(cap);
  double worst_radius = 0, worst_angle = 0;
  for (double u = 0.1; u < 0.95; u += 0.0731) {
    for (double v = 0.1; v < 0.95; v += 0.0617) {
      const Vec3 direction = SphereCap(u, v);
      for (double radius : {0.8, 1.3}) {
        const auto closest = reference.Closest(ToArray(radius * E(direction)));
        worst_radius = std::max(worst_radius, std::abs(E(closest.point).norm() - 1.0));
        // the sphere's normal at the closest point is its direction
        worst_angle = std::max(worst_angle, AngleBetween(closest.normal, closest.point));
        EXPECT_NEAR(E(closest.normal).norm(), 1.0, kExact);
        // The facet through the foot point tilts by up to ~1/60 rad from the
        // sphere's tangent plane: the foot moves sideways by |radius - 1| / 60.
        ExpectNear(closest.point, direction, std::abs(radius - 1) / 60 * 1.5);
      }
    }
  }
  // Chord sagitta of a 1/60-radian edge: 1/(8 * 60^2) = 3.5e-5.
  EXPECT_LT(worst_radius, 1e-4);
  EXPECT_LT(worst_angle, 0.1 * kDegree);
}

TEST(ReferenceSurface, NormalIsContinuousAcrossTriangleEdges) {
  const Mesh roof = QuadGrid(10, 8, RoofSurface);
  const ReferenceSurface reference(roof);
  // Walk just above the surface across five quads; the facet normals jump by
  // degrees at every edge, the interpolated normal moves by a tiny step.
  const double step = 1e-4;
  const V lift(0, 0, 1e-3);
  Vec3 previous = reference.Closest(ToArray(E(RoofSurface(0.3, 0.42)) + lift)).normal;
  double largest_jump = 0;
  for (double u = 0.3 + step; u < 0.8; u += step) {
    const Vec3 normal = reference.Closest(ToArray(E(RoofSurface(u, 0.42)) + lift)).normal;
    largest_jump = std::max(largest_jump, AngleBetween(normal, previous));
    previous = normal;
  }
  EXPECT_LT(largest_jump, 0.05 * kDegree);
}

TEST(ReferenceSurface, BoundaryOfPlanarSquareIsExact) {
  const ReferenceSurface reference(QuadGrid(4, 4, FlatSquare));
  ASSERT_TRUE(reference.HasBoundary());
  const auto ExpectLine = [&](const Vec3& query, const Vec3& point, const Vec3& tangent) {
    const auto closest = reference.ClosestOnBoundary(query);
    ASSERT_TRUE(closest.has_value());
    ExpectNear(closest->point, point, kExact);
    EXPECT_NEAR(std::abs(E(closest->tangent).dot(E(tangent))), 1.0, kExact);
    EXPECT_NEAR(E(closest->tangent).norm(), 1.0, kExact);
  };
  ExpectLine({0.3, -0.2, 0.5}, {0.3, 0, 0}, {1, 0, 0});
  ExpectLine({1.3, 0.6, -0.2}, {1, 0.6, 0}, {0, 1, 0});
  ExpectLine({0.6, 0.9, 0.4}, {0.6, 1, 0}, {1, 0, 0});  // from inside the square
  // At a corner the tangent bisects the two boundary edges.
  const Vec3 bisector = ToArray(V(1, -1, 0).normalized());
  ExpectLine({-0.1, -0.2, 0}, {0, 0, 0}, bisector);
  ExpectLine({1.2, 1.1, 0.3}, {1, 1, 0}, bisector);
}

TEST(ReferenceSurface, ClosedCubeHasNoBoundary) {
  const ReferenceSurface reference(Cube());
  EXPECT_FALSE(reference.HasBoundary());
  EXPECT_FALSE(reference.ClosestOnBoundary({2, 0.5, 0.5}).has_value());
  const auto closest = reference.Closest({2, 0.5, 0.25});
  ExpectNear(closest.point, {1, 0.5, 0.25}, kExact);
  EXPECT_GT(closest.normal[0], 1 / std::sqrt(3.0) - kExact);  // outward, tilted to the corners
  EXPECT_EQ(reference.Triangles().number_of_faces(), 12u);
}

// Sorted vertex triples of the triangles.
std::set<std::array<int, 3>> TriangleSet(const Mesh& mesh) {
  std::set<std::array<int, 3>> triangles;
  for (FaceIndex f : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) t[k++] = int(v.idx());
    std::sort(t.begin(), t.end());
    triangles.insert(t);
  }
  return triangles;
}

TEST(TriangulatedCopy, KeepsVerticesAndSplitsIndependentlyOfPosition) {
  const Mesh grid = QuadGrid(9, 7, RoofSurface);  // near-tied diagonals everywhere
  const Mesh triangles = TriangulatedCopy(grid);
  EXPECT_EQ(triangles.number_of_vertices(), grid.number_of_vertices());
  EXPECT_EQ(triangles.number_of_faces(), 2 * grid.number_of_faces());
  for (VertexIndex v : grid.vertices()) EXPECT_EQ(triangles.point(v), grid.point(v));
  for (double angle : {0.3, 1.1, 2.9}) {
    const Mesh moved = Transformed(grid, 3.7, {1.0, 0.2, -0.4}, angle, {10.0, -3.0, 0.5});
    EXPECT_EQ(TriangleSet(TriangulatedCopy(moved)), TriangleSet(triangles)) << angle;
  }
  // A dart (reflex vertex 3) is split along the inner diagonal (1, 3): the
  // outer one would give two triangles facing opposite ways.
  const Mesh dart = MakeMesh({{0, 0, 0}, {4, 2, 0}, {0, 4, 0}, {1, 2, 0}}, {{0, 1, 2, 3}});
  EXPECT_EQ(TriangleSet(TriangulatedCopy(dart)),
            (std::set<std::array<int, 3>>{{0, 1, 3}, {1, 2, 3}}));
  std::vector<Vec3> hexagon;
  for (int i = 0; i < 6; ++i) {
    hexagon.push_back({std::cos(i * M_PI / 3), std::sin(i * M_PI / 3), 0});
  }
  EXPECT_EQ(TriangulatedCopy(MakeMesh(hexagon, {{0, 1, 2, 3, 4, 5}})).number_of_faces(), 4u);
}

// A polygon whose outline crosses itself (a pentagram: the constrained
// triangulation gives up on it) is split as a fan from its first corner,
// so any polygon mesh can serve as a reference (an extracted layout did not).
TEST(TriangulatedCopy, SelfOverlappingPolygonsBecomeFans) {
  std::vector<Vec3> star;
  for (int i = 0; i < 5; ++i) {
    const double a = i * 4 * M_PI / 5;
    star.push_back({std::cos(a), std::sin(a), 0.05 * i});
  }
  const Mesh triangles = TriangulatedCopy(MakeMesh(star, {{0, 1, 2, 3, 4}}));
  EXPECT_EQ(triangles.number_of_faces(), 3u);
  EXPECT_EQ(TriangleSet(triangles), (std::set<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
}

// A simple polygon with reflex corners (a U, area 5) is cut into n − 2
// triangles that all face its way and cover exactly its area: a fan from
// most of its corners would fold over the notch.
TEST(TriangulatedCopy, ReflexPolygonsAreCutByEars) {
  const std::vector<Vec3> u = {{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {2, 2, 0},
                               {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  for (int shift = 0; shift < 8; ++shift) {
    std::vector<int> face;
    for (int k = 0; k < 8; ++k) face.push_back((k + shift) % 8);
    const Mesh triangles = TriangulatedCopy(MakeMesh(u, {face}));
    ASSERT_EQ(triangles.number_of_faces(), 6u);
    double area = 0;
    for (FaceIndex f : triangles.faces()) {
      std::vector<Eigen::Vector3d> p;
      for (VertexIndex v : triangles.vertices_around_face(triangles.halfedge(f))) {
        p.push_back(EigenPoint(triangles, v));
      }
      const double z = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).z();
      EXPECT_GT(z, 0.1) << "shift " << shift;
      area += z;
    }
    EXPECT_NEAR(area, 5.0, 1e-12) << "shift " << shift;
  }
}

TEST(ReferenceSurface, RejectsEmptyMesh) {
  EXPECT_THROW(ReferenceSurface{Mesh()}, std::invalid_argument);
}

// ---------------------------------------------------------------- topology

TEST(Topology, GridBoundaryAndCorners) {
  const Mesh grid = QuadGrid(4, 3, RoofSurface);
  const std::vector<bool> boundary = BoundaryVertices(grid);
  ASSERT_EQ(boundary.size(), 20u);
  EXPECT_EQ(std::count(boundary.begin(), boundary.end(), true), 14);
  EXPECT_FALSE(boundary[6]);
  EXPECT_TRUE(boundary[5]);
  const std::vector<VertexIndex> corners = Corners(grid);
  EXPECT_EQ(corners, (std::vector<VertexIndex>{VertexIndex(0), VertexIndex(4), VertexIndex(15),
                                               VertexIndex(19)}));
}

TEST(Topology, GridPolylinesAreRowsAndColumns) {
  const int nu = 4, nv = 3;
  const Mesh grid = QuadGrid(nu, nv, RoofSurface);
  const auto polylines = MeshPolylines(grid);
  ASSERT_EQ(polylines.size(), size_t((nu + 1) + (nv + 1)));
  int rows = 0, columns = 0;
  std::multiset<std::pair<int, int>> edges;
  for (const auto& line : polylines) {
    EXPECT_NE(line.front(), line.back());
    const int step = std::abs(int(line[1].idx()) - int(line[0].idx()));
    if (line.size() == size_t(nu + 1)) {
      ++rows;
      EXPECT_EQ(step, 1);
    } else {
      ASSERT_EQ(line.size(), size_t(nv + 1));
      ++columns;
      EXPECT_EQ(step, nu + 1);
    }
    for (size_t i = 0; i + 1 < line.size(); ++i) {
      // straight: constant index step along the polyline
      EXPECT_EQ(std::abs(int(line[i + 1].idx()) - int(line[i].idx())), step);
      edges.insert(std::minmax(int(line[i].idx()), int(line[i + 1].idx())));
    }
  }
  EXPECT_EQ(rows, nv + 1);
  EXPECT_EQ(columns, nu + 1);
  // Every edge on exactly one polyline.
  ASSERT_EQ(edges.size(), grid.number_of_edges());
  for (EdgeIndex e : grid.edges()) {
    const std::pair<int, int> key =
        std::minmax(int(grid.vertex(e, 0).idx()), int(grid.vertex(e, 1).idx()));
    EXPECT_EQ(edges.count(key), 1u);
  }
  const auto triples = PolylineTriples(polylines);
  EXPECT_EQ(triples.size(), size_t((nv + 1) * (nu - 1) + (nu + 1) * (nv - 1)));  // 22
  for (const auto& [a, b, c] : triples) {
    EXPECT_EQ(int(b.idx()) - int(a.idx()), int(c.idx()) - int(b.idx()));
  }
}

TEST(Topology, CylinderRingsAreClosedPolylines) {
  const int around = 8, rows = 2;
  const Mesh cylinder = QuadCylinder(1.0, double(rows), around, rows);
  EXPECT_TRUE(Corners(cylinder).empty());  // the boundary rings turn by 45 degrees
  const auto polylines = MeshPolylines(cylinder);
  ASSERT_EQ(polylines.size(), size_t((rows + 1) + around));
  int closed = 0;
  size_t edge_count = 0;
  for (const auto& line : polylines) {
    edge_count += line.size() - 1;
    if (line.front() == line.back()) {
      ++closed;
      ASSERT_EQ(line.size(), size_t(around + 1));
      const int ring = int(line[0].idx()) / around;
      for (VertexIndex v : line) EXPECT_EQ(int(v.idx()) / around, ring);
    } else {
      EXPECT_EQ(line.size(), size_t(rows + 1));
    }
  }
  EXPECT_EQ(closed, rows + 1);  // both boundary rings and the interior ring
  EXPECT_EQ(edge_count, cylinder.number_of_edges());
  // Closed rings contribute a triple at every vertex, the seam included.
  EXPECT_EQ(PolylineTriples(polylines).size(), size_t((rows + 1) * around + around * (rows - 1)));
}

TEST(Topology, PolylinesEndAtIrregularVertices) {
  // Three quads around an interior vertex of valence 3 (a hexagon split from
  // its centre 0): every spoke ends at the centre and at the boundary, and the
  // boundary runs through the valence-3 vertices 1, 3, 5 and ends at the
  // corners 2, 4, 6.
  std::vector<Vec3> points{{0, 0, 0}};
  for (int i = 0; i < 6; ++i) {
    points.push_back({std::cos(i * M_PI / 3), std::sin(i * M_PI / 3), 0});
  }
  const Mesh mesh = MakeMesh(points, {{0, 1, 2, 3}, {0, 3, 4, 5}, {0, 5, 6, 1}});
  std::set<std::vector<int>> lines;
  for (const auto& line : MeshPolylines(mesh)) {
    std::vector<int> ids;
    for (VertexIndex v : line) ids.push_back(int(v.idx()));
    if (ids.front() > ids.back()) std::reverse(ids.begin(), ids.end());
    lines.insert(ids);
  }
  EXPECT_EQ(lines, (std::set<std::vector<int>>{
                       {0, 1}, {0, 3}, {0, 5}, {2, 3, 4}, {4, 5, 6}, {2, 1, 6}}));
}

// ---------------------------------------------------------------- metrics

TEST(Metrics, PlanarGridIsPlanar) {
  const Mesh plane = QuadGrid(7, 5, [](double u, double v) {
    return Vec3{u, 0.5 * v, 0.3 * u - 0.7 * v};
  });
  const PlanarityMeasure planarity = MeasureFacePlanarity(plane);
  for (double d : planarity.distance) EXPECT_LT(d, kExact);
  const Metrics m = ComputeMetrics(plane, nullptr, nullptr);
  EXPECT_EQ(m.quads, 35);
  EXPECT_LT(m.pq_max, kExact);
  EXPECT_LT(m.pq_normalized_max, kExact);
  EXPECT_LT(m.warp_max, kExact);
}

TEST(Metrics, TwistedQuadHasAnalyticDiagonalDistance) {
  const double h = 0.5;
  const Mesh quad = MakeMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, h}, {0, 1, 0}}, {{0, 1, 2, 3}});
  // Diagonals (0,0,0) + s (1,1,h) and (1,0,0) + t (-1,1,0): n ∝ (-h, -h, 2),
  // distance = |n·(1,0,0)| / |n| = h / sqrt(2h² + 4).
  const double distance = h / std::sqrt(2 * h * h + 4);
  const double mean_diagonal = 0.5 * (std::sqrt(2 + h * h) + std::sqrt(2.0));
  const PlanarityMeasure planarity = MeasureFacePlanarity(quad);
  EXPECT_NEAR(planarity.distance[0], distance, kExact);
  EXPECT_NEAR(planarity.normalized[0], distance / mean_diagonal, kExact);
  EXPECT_NEAR(planarity.warp[0], distance / 1.0, kExact);  // shortest edge 1
  const Metrics m = ComputeMetrics(quad, nullptr, nullptr);
  EXPECT_NEAR(m.pq_max, distance, kExact);
  EXPECT_NEAR(m.pq_mean, distance, kExact);
  EXPECT_NEAR(m.aabb_diagonal, std::sqrt(2 + h * h), kExact);
  EXPECT_NEAR(m.mean_edge_length, 0.5 * (2 + 2 * std::sqrt(1 + h * h)) / 2, kExact);
}

TEST(Metrics, ZigZagHexagonUsesPlaneFit) {
  const double h = 0.1;
  std::vector<Vec3> points;
  for (int i = 0; i < 6; ++i) {
    points.push_back({std::cos(i * M_PI / 3), std::sin(i * M_PI / 3), i % 2 ? -h : h});
  }
  const Mesh hexagon = MakeMesh(points, {{0, 1, 2, 3, 4, 5}});
  const PlanarityMeasure planarity = MeasureFacePlanarity(hexagon);
  // Least-squares plane z = 0; diagonals (i, i+2) have length sqrt(3).
  EXPECT_NEAR(planarity.distance[0], h, kExact);
  EXPECT_NEAR(planarity.normalized[0], h / std::sqrt(3.0), kExact);
  EXPECT_NEAR(planarity.warp[0], h / std::sqrt(1 + 4 * h * h), kExact);
  const Metrics m = ComputeMetrics(hexagon, nullptr, nullptr);
  EXPECT_EQ(m.polygons, 1);
  EXPECT_NEAR(m.pq_max, h, kExact);
}

TEST(Metrics, TrianglesCountAsPlanar) {
  const Mesh mesh = MakeMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
  const PlanarityMeasure planarity = MeasureFacePlanarity(mesh);
  EXPECT_EQ(planarity.distance, (std::vector<double>{0, 0}));
  const Metrics m = ComputeMetrics(mesh, nullptr, nullptr);
  EXPECT_EQ(m.triangles, 2);
  EXPECT_EQ(m.pq_max, 0);
}

TEST(Metrics, OffsetPlaneProximityAndHausdorff) {
  const double offset = 0.1;
  const Mesh mesh = QuadGrid(6, 6, FlatSquare);
  const ReferenceSurface reference(QuadGrid(5, 4, [&](double u, double v) {
    return Vec3{u, v, offset};
  }));
  const Metrics m = ComputeMetrics(mesh, &reference, nullptr);
  EXPECT_NEAR(m.prox_max, offset, kExact);
  EXPECT_NEAR(m.boundary_prox_max, offset, kExact);
  EXPECT_NEAR(m.surface_distance_max, offset, kExact);
  EXPECT_NEAR(m.surface_distance_mean, offset, kExact);
  EXPECT_NEAR(m.hausdorff, offset, kExact);
  EXPECT_EQ(m.displacement_max, -1);

  const ReferenceSurface self(mesh);
  const Metrics s = ComputeMetrics(mesh, &self, &mesh);
  EXPECT_LT(s.hausdorff, kExact);
  EXPECT_LT(s.prox_max, kExact);
  EXPECT_LT(s.boundary_prox_max, kExact);
  EXPECT_EQ(s.displacement_max, 0);
}

TEST(Metrics, ClosedReferenceHasNoBoundaryProximity) {
  const Mesh cube = Cube();
  const ReferenceSurface reference(cube);
  const Metrics m = ComputeMetrics(cube, &reference, nullptr);
  EXPECT_EQ(m.boundary_prox_max, -1);
  EXPECT_LT(m.prox_max, kExact);
  EXPECT_LT(m.hausdorff, kExact);
}

TEST(Metrics, DisplacementAgainstTranslatedCopy) {
  const Mesh mesh = QuadGrid(5, 4, RoofSurface, 0.1, 3);
  const Mesh moved = Transformed(mesh, 1.0, {0, 0, 1}, 0.0, {0.3, -0.4, 1.2});
  const Metrics m = ComputeMetrics(moved, nullptr, &mesh);
  EXPECT_NEAR(m.displacement_max, 1.3, kExact);
  EXPECT_NEAR(m.displacement_mean, 1.3, kExact);
  const Mesh smaller = QuadGrid(2, 2, RoofSurface);
  EXPECT_EQ(ComputeMetrics(moved, nullptr, &smaller).displacement_max, -1);
}

TEST(Metrics, InvariantUnderRigidMotionAndScaling) {
  const Mesh reference_mesh = QuadGrid(12, 9, RoofSurface);
  const Mesh mesh = QuadGrid(12, 9, RoofSurface, 0.15, 5);
  const ReferenceSurface reference(reference_mesh);
  const Metrics a = ComputeMetrics(mesh, &reference, &reference_mesh);

  const double s = 2.5;
  const Vec3 axis{0.3, -1.0, 0.6}, shift{4.0, -2.0, 7.5};
  const Mesh moved_reference = Transformed(reference_mesh, s, axis, 0.7, shift);
  const ReferenceSurface moved(moved_reference);
  const Mesh moved_mesh = Transformed(mesh, s, axis, 0.7, shift);
  const Metrics b = ComputeMetrics(moved_mesh, &moved, &moved_reference);

  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.quads, b.quads);
  const double tol = 1e-9;
  EXPECT_NEAR(b.mean_edge_length, s * a.mean_edge_length, tol);
  EXPECT_NEAR(b.pq_max, s * a.pq_max, tol);
  EXPECT_NEAR(b.pq_mean, s * a.pq_mean, tol);
  EXPECT_NEAR(b.pq_normalized_max, a.pq_normalized_max, tol);
  EXPECT_NEAR(b.pq_normalized_mean, a.pq_normalized_mean, tol);
  EXPECT_NEAR(b.warp_max, a.warp_max, tol);
  EXPECT_NEAR(b.warp_mean, a.warp_mean, tol);
  EXPECT_NEAR(b.prox_max, s * a.prox_max, tol);
  EXPECT_NEAR(b.boundary_prox_max, s * a.boundary_prox_max, tol);
  EXPECT_NEAR(b.surface_distance_max, s * a.surface_distance_max, tol);
  EXPECT_NEAR(b.surface_distance_mean, s * a.surface_distance_mean, tol);
  EXPECT_NEAR(b.displacement_max, s * a.displacement_max, tol);
  EXPECT_NEAR(b.displacement_mean, s * a.displacement_mean, tol);
  EXPECT_NEAR(b.hausdorff, s * a.hausdorff, tol);
  EXPECT_GT(a.pq_max, 0);
  EXPECT_GT(a.prox_max, 0);
  EXPECT_GT(a.hausdorff, 0);
  // Bounding-box diagonals differ under rotation, so compare relative values
  // with the same relative scale: s times the first.
  const nlohmann::json ja = MetricsToJson(a, 1.0), jb = MetricsToJson(b, s);
  for (const char* key : {"pq_max_relative", "prox_max_relative", "displacement_max_relative",
                          "surface_distance_mean_relative"}) {
    EXPECT_NEAR(jb[key].get<double>(), ja[key].get<double>(), tol) << key;
  }
}

TEST(Metrics, JsonHasRelativeLengthsAndNulls) {
  const Mesh mesh = QuadGrid(3, 3, RoofSurface, 0.1, 2);
  const Metrics m = ComputeMetrics(mesh, nullptr, nullptr);
  const nlohmann::json json = MetricsToJson(m, 2.0);
  EXPECT_EQ(json["quads"], 9);
  EXPECT_DOUBLE_EQ(json["pq_max"].get<double>(), m.pq_max);
  EXPECT_DOUBLE_EQ(json["pq_max_relative"].get<double>(), m.pq_max / 2.0);
  EXPECT_DOUBLE_EQ(json["bbox_diagonal_relative"].get<double>(), m.bbox_diagonal / 2.0);
  EXPECT_DOUBLE_EQ(json["warp_max"].get<double>(), m.warp_max);
  EXPECT_FALSE(json.contains("warp_max_relative"));
  EXPECT_FALSE(json.contains("pq_normalized_max_relative"));
  for (const char* key : {"prox_max", "boundary_prox_max", "surface_distance_max",
                          "surface_distance_mean", "hausdorff", "displacement_max",
                          "displacement_mean"}) {
    ASSERT_TRUE(json.contains(key)) << key;
    EXPECT_TRUE(json[key].is_null()) << key;
    EXPECT_TRUE(json[std::string(key) + "_relative"].is_null()) << key;
  }
}

TEST(Metrics, HausdorffBoundsOnANoisyGrid) {
  const Mesh reference_mesh = QuadGrid(45, 45, RoofSurface);
  const Mesh mesh = QuadGrid(45, 45, RoofSurface, 0.1, 9);
  const ReferenceSurface reference(reference_mesh);
  MetricsOptions no_hausdorff;
  no_hausdorff.hausdorff = false;
  const Metrics without = ComputeMetrics(mesh, &reference, nullptr, no_hausdorff);
  const Metrics with = ComputeMetrics(mesh, &reference, nullptr);
  EXPECT_EQ(without.hausdorff, -1);
  // Vertices are samples: at least their distance; vertices move by at most
  // 0.1 mean edge lengths and the chords add little, so not much more.
  EXPECT_GE(with.hausdorff, with.surface_distance_max - kExact);
  const double grid_edge = ComputeMetrics(reference_mesh, nullptr, nullptr).mean_edge_length;
  EXPECT_LE(with.hausdorff, 1.2 * 0.1 * grid_edge);
}

// The farthest point can lie inside a triangle, away from every vertex: one
// flat unit quad over a flat reference with a square hole [0.3, 0.7]² under
// its middle. Every corner and every point of the reference lies on the other
// surface; only the quad's centre (a grid sample on its diagonal) is 0.2 from
// the reference. The vertices alone would give 0: the triangles that may hold
// a farther point must still be sampled.
TEST(Metrics, HausdorffFindsTheFarthestPointInsideATriangle) {
  const int n = 20;
  std::vector<Vec3> points;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) points.push_back({double(i) / n, double(j) / n, 0.0});
  }
  std::vector<std::vector<int>> faces;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if (i >= 6 && i < 14 && j >= 6 && j < 14) continue;  // the hole
      const int a = j * (n + 1) + i;
      faces.push_back({a, a + 1, a + n + 2, a + n + 1});
    }
  }
  const ReferenceSurface reference(MakeMesh(points, faces));
  const Mesh quad = MakeMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}});
  const Metrics m = ComputeMetrics(quad, &reference, nullptr);
  EXPECT_LT(m.surface_distance_max, kExact);  // the corners
  EXPECT_NEAR(m.hausdorff, 0.2, 1e-9);
}

TEST(PlanarityColors, GreenToRed) {
  PlanarityMeasure planarity;
  planarity.normalized = {0.0, 0.005, 0.01, 0.5};
  const auto colors = PlanarityColors(planarity, 0.01);
  using Rgb = std::array<unsigned char, 3>;
  EXPECT_EQ(colors[0], (Rgb{0, 255, 0}));
  EXPECT_EQ(colors[1], (Rgb{255, 255, 0}));
  EXPECT_EQ(colors[2], (Rgb{255, 0, 0}));
  EXPECT_EQ(colors[3], (Rgb{255, 0, 0}));
}

}  // namespace
}  // namespace archgeo
