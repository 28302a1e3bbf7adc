// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of constrained Loop / Catmull–Clark subdivision, limit positions,
// tangency to boundary surfaces and reverse subdivision [Gebreiter 2012,
// §9.1.2, §9.2.1, §9.2.2, §9.2.3]
// (geometry/constrained_subdivision.h).
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "geometry/constrained_subdivision.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using Eigen::Vector3d;
constexpr double kLimitTolerance = 1e-12;    // the figure for the CC limit
constexpr double kCurveTolerance = 1e-9;     // × diagonal, after four levels
constexpr double kReverseTolerance = 1e-10;  // coarse positions recovered

// Control grid (i, j, z_ij), i, j = 0 … n−1, quads counter-clockwise.
PolyMesh QuadGrid(int n, std::mt19937& rng, double zscale = 1) {
  std::uniform_real_distribution<double> u(-1, 1);
  PolyMesh m;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) m.points.emplace_back(i, j, zscale * u(rng));
  }
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) m.faces.push_back({j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i});
  }
  return m;
}

// Regular triangle lattice (i + j/2, j·√3/2), i, j = 0 … n−1, z from `height`.
template <class F>
PolyMesh TriangleLattice(int n, F height) {
  PolyMesh m;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double x = i + 0.5 * j, y = j * std::sqrt(3.0) / 2;
      m.points.emplace_back(x, y, height(x, y));
    }
  }
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      m.faces.push_back({a, b, c});
      m.faces.push_back({b, d, c});
    }
  }
  return m;
}

// Uniform cubic B-spline basis centred at 0.
double CubicB(double t) {
  t = std::abs(t);
  if (t < 1) return (4 - 6 * t * t + 3 * t * t * t) / 6;
  if (t < 2) return (2 - t) * (2 - t) * (2 - t) / 6;
  return 0;
}

PolyMesh Cube() {
  PolyMesh m;
  for (int k = 0; k < 8; ++k) m.points.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  m.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return m;
}

// A torus of n × m quads.
PolyMesh Torus(int n, int m) {
  PolyMesh t;
  for (int j = 0; j < m; ++j) {
    for (int i = 0; i < n; ++i) {
      const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / m;
      t.points.emplace_back((2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v));
    }
  }
  for (int j = 0; j < m; ++j) {
    for (int i = 0; i < n; ++i) {
      t.faces.push_back({j * n + i, j * n + (i + 1) % n, ((j + 1) % m) * n + (i + 1) % n, ((j + 1) % m) * n + i});
    }
  }
  return t;
}

PolyMesh Icosahedron() {
  const double g = (1 + std::sqrt(5.0)) / 2;
  PolyMesh m;
  m.points = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
              {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  m.faces = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
             {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  return m;
}

// The unconstrained CC limit of a regular patch is the bicubic B-spline of
// the control grid: after two levels, every vertex at least 2.5 coarse
// spacings from the boundary (beyond the reach of the boundary rules) has the
// limit position S(x, y) of the analytic B-spline, (x, y) its parameter.
TEST(ConstrainedSubdivision, CatmullClarkLimitIsTheBicubicBSpline) {
  std::mt19937 rng(7);
  const int n = 10;
  const PolyMesh coarse = QuadGrid(n, rng);
  ConstrainedSubdivision cs(coarse, {}, {SubdivisionScheme::kCatmullClark});
  cs.Step();
  cs.Step();
  const auto limit = cs.LimitPositions();
  int checked = 0;
  double worst = 0, moved = 0;
  for (size_t v = 0; v < limit.size(); ++v) {
    const Vector3d& p = cs.mesh().points[v];
    if (p.x() < 2.5 || p.x() > n - 3.5 || p.y() < 2.5 || p.y() > n - 3.5) continue;
    Vector3d s = Vector3d::Zero();
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) s += CubicB(p.x() - i) * CubicB(p.y() - j) * coarse.points[j * n + i];
    }
    worst = std::max(worst, (limit[v] - s).norm());
    moved = std::max(moved, (p - s).norm());
    ++checked;
  }
  EXPECT_GT(checked, 100);
  EXPECT_LE(worst, kLimitTolerance);
  EXPECT_GT(moved, 1e-3);  // the level-2 vertices themselves are not on the limit
}

// Loop on a regular lattice is the quartic box spline, which maps a quadratic
// p to p + (1/24)Σ_6 dᵀHd = p + (a + c)/4 for p = ax² + bxy + cy² (the
// second moment of the limit mask ½, 1/12 × 6 over the six unit directions).
TEST(ConstrainedSubdivision, LoopLimitIsTheBoxSplineOfAQuadratic) {
  const double a = 0.3, b = -0.7, c = 0.45;
  auto p = [&](double x, double y) { return a * x * x + b * x * y + c * y * y; };
  const int n = 12;
  ConstrainedSubdivision cs(TriangleLattice(n, p), {}, {SubdivisionScheme::kLoop});
  for (int k = 0; k < 3; ++k) cs.Step();
  const auto limit = cs.LimitPositions();
  int checked = 0;
  double worst = 0;
  for (size_t v = 0; v < limit.size(); ++v) {
    const Vector3d& q = cs.mesh().points[v];
    const double j = q.y() / (std::sqrt(3.0) / 2), i = q.x() - 0.5 * j;
    if (i < 3 || i > n - 4 || j < 3 || j > n - 4) continue;
    EXPECT_NEAR(limit[v].x(), q.x(), kLimitTolerance);
    EXPECT_NEAR(limit[v].y(), q.y(), kLimitTolerance);
    worst = std::max(worst, std::abs(limit[v].z() - (p(q.x(), q.y()) + (a + c) / 4)));
    ++checked;
  }
  EXPECT_GT(checked, 200);
  EXPECT_LE(worst, kLimitTolerance);
}

// The limit masks are left eigenvectors of the subdivision matrix: a vertex's
// limit is the same before and after a step, at valences 3 … 6.
TEST(ConstrainedSubdivision, LimitPositionsAreInvariantUnderSubdivision) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (auto scheme : {SubdivisionScheme::kCatmullClark, SubdivisionScheme::kLoop}) {
    PolyMesh m = scheme == SubdivisionScheme::kLoop ? Icosahedron() : Cube();
    for (auto& p : m.points) p += Vector3d(u(rng), u(rng), u(rng));
    ConstrainedSubdivision cs(m, {}, {scheme});
    cs.Step();
    const auto before = cs.LimitPositions();
    cs.Step();
    const auto after = cs.LimitPositions();
    double worst = 0;
    for (size_t v = 0; v < before.size(); ++v) worst = std::max(worst, (before[v] - after[v]).norm());
    EXPECT_LE(worst, 1e-12) << (scheme == SubdivisionScheme::kLoop ? "loop" : "catmull_clark");
  }
}

// A disc whose boundary vertices lie on a circle given as a dense polyline:
// after four levels every boundary vertex is on the polyline (1e-9 × the
// diagonal); the standard boundary rules leave it.
PolyMesh Fan(int sides, double radius) {
  PolyMesh m;
  m.points.emplace_back(0, 0, 0.3);
  for (int k = 0; k < sides; ++k) {
    const double t = 2 * M_PI * k / sides;
    m.points.emplace_back(radius * std::cos(t), radius * std::sin(t), 0.2 * std::sin(2 * t));
  }
  for (int k = 0; k < sides; ++k) m.faces.push_back({0, 1 + k, 1 + (k + 1) % sides});
  return m;
}

SubdivisionCurve Circle(double radius, int points) {
  SubdivisionCurve c;
  c.closed = true;
  c.boundary = true;
  c.name = "circle";
  for (int k = 0; k < points; ++k) {
    const double t = 2 * M_PI * k / points;
    c.points.emplace_back(radius * std::cos(t), radius * std::sin(t), 0.2 * std::sin(2 * t));
  }
  return c;
}

TEST(ConstrainedSubdivision, BoundaryVerticesStayOnTheirCurve) {
  for (auto scheme : {SubdivisionScheme::kLoop, SubdivisionScheme::kCatmullClark}) {
    const PolyMesh fan = Fan(6, 2);
    ConstrainedSubdivision cs(fan, {Circle(2, 600)}, {scheme});
    ConstrainedSubdivision free(fan, {}, {scheme});
    for (int k = 0; k < 4; ++k) {
      cs.Step();
      free.Step();
    }
    const int boundary = scheme == SubdivisionScheme::kLoop ? 6 * 16 : 6 * 16;
    EXPECT_EQ(cs.CurveVertexCount(), boundary);
    EXPECT_LE(cs.MaxCurveDistance(), kCurveTolerance * cs.diagonal());
    // The same mesh without the curve: its boundary leaves the circle.
    double off = 0;
    for (const Vector3d& p : free.mesh().points) {
      const double r = std::hypot(p.x(), p.y());
      if (r > 1.5) off = std::max(off, std::abs(r - 2));
    }
    EXPECT_GT(off, 0.05);
  }
}

// The new edge point of a tagged edge is the curve's arc-length halfway point,
// also where the polyline's points are unevenly spaced.
TEST(ConstrainedSubdivision, EdgePointIsTheArcLengthMidpoint) {
  PolyMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}};
  m.faces = {{0, 1, 2}};
  SubdivisionCurve c;
  c.name = "arc";
  c.boundary = true;
  // From (0,0,0) to (1,0,0) over a bump, sampled densely near the start.
  const int k = 400;
  for (int i = 0; i <= k; ++i) {
    const double t = std::pow(static_cast<double>(i) / k, 2);
    c.points.emplace_back(t, -0.3 * std::sin(M_PI * t), 0);
  }
  ConstrainedSubdivision cs(m, {c}, {SubdivisionScheme::kLoop});
  cs.Step();
  // Edge 0–1 is the first edge: its point follows the three old vertices.
  double total = 0;
  std::vector<double> cumulative = {0};
  for (int i = 0; i < k; ++i) cumulative.push_back(total += (c.points[i + 1] - c.points[i]).norm());
  const Vector3d mid = cs.mesh().points[3];
  // Arc length from the start to the closest point of `mid`.
  double best = 1e9, s = 0;
  for (int i = 0; i < k; ++i) {
    const Vector3d d = c.points[i + 1] - c.points[i];
    const double u = std::clamp((mid - c.points[i]).dot(d) / d.squaredNorm(), 0.0, 1.0);
    const double dist = (mid - (c.points[i] + u * d)).norm();
    if (dist < best) {
      best = dist;
      s = cumulative[i] + u * d.norm();
    }
  }
  EXPECT_LE(best, 1e-12);
  EXPECT_NEAR(s, total / 2, 1e-12);
  EXPECT_GT((mid - c.points[k / 2]).norm(), 0.1);  // not the polyline's middle point
}

// An interior crease curve through a row of grid vertices is taken up by the
// subdivided mesh; the interior masks alone do not follow it.
TEST(ConstrainedSubdivision, CreaseCurveIsKept) {
  std::mt19937 rng(5);
  const int n = 7;
  PolyMesh grid = QuadGrid(n, rng, 0.0);
  SubdivisionCurve crease;
  crease.name = "crease";
  for (int i = 0; i <= 600; ++i) {
    const double x = (n - 1) * i / 600.0;
    crease.points.emplace_back(x, 3 + 0.4 * std::sin(M_PI * x / 2), 0.5 * std::sin(M_PI * x / 3));
  }
  for (int i = 0; i < n; ++i) grid.points[3 * n + i] = crease.points[100 * i];
  for (auto scheme : {SubdivisionScheme::kCatmullClark}) {
    ConstrainedSubdivision cs(grid, {crease}, {scheme});
    for (int k = 0; k < 4; ++k) cs.Step();
    EXPECT_EQ(cs.CurveVertexCount(), (n - 1) * 16 + 1);
    EXPECT_EQ(cs.CornerCount() >= 2, true);
    EXPECT_LE(cs.MaxCurveDistance(), kCurveTolerance * cs.diagonal());
    // Without the curve the row's vertices leave it (the interior masks smooth the crease).
    ConstrainedSubdivision free(grid, {}, {scheme});
    for (int k = 0; k < 4; ++k) free.Step();
    EXPECT_GT(std::abs(free.mesh().points[3 * n + 1].z() - crease.points[100].z()), 0.01);
  }
}

// A kink of the curve at a mesh vertex keeps that vertex fixed (a corner);
// with the kink test off, the crease mask slides it along the curve.
TEST(ConstrainedSubdivision, KinksStayCorners) {
  // A flat 4 × 4 grid whose rows and columns are unevenly spaced; the boundary curve
  // is its square outline (kinks of 90° at the four corners).
  const std::vector<double> xs = {0, 0.5, 2, 2.5, 4}, ys = {0, 1.5, 2, 3.5, 4};
  PolyMesh grid;
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 5; ++i) grid.points.emplace_back(xs[i], ys[j], 0);
  }
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) grid.faces.push_back({j * 5 + i, j * 5 + i + 1, (j + 1) * 5 + i + 1, (j + 1) * 5 + i});
  }
  SubdivisionCurve square;
  square.name = "square";
  square.closed = true;
  square.boundary = true;
  square.points = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}};
  SubdivisionOptions o;
  o.scheme = SubdivisionScheme::kCatmullClark;
  ConstrainedSubdivision kinked(grid, {square}, o);
  o.kink_degrees = 180;
  ConstrainedSubdivision smooth(grid, {square}, o);
  EXPECT_EQ(kinked.CornerCount(), 4);
  EXPECT_EQ(smooth.CornerCount(), 0);
  for (int k = 0; k < 2; ++k) {
    kinked.Step();
    smooth.Step();
  }
  for (int corner : {0, 4, 20, 24}) EXPECT_EQ(kinked.mesh().points[corner], grid.points[corner]);
  // Corners 0 and 24 have unequal curve neighbours (0.5 and 1.5 away): the
  // crease mask moves them when they are not kinks.
  for (int corner : {0, 24}) EXPECT_GT((smooth.mesh().points[corner] - grid.points[corner]).norm(), 0.01);
  EXPECT_LE(kinked.MaxCurveDistance(), kCurveTolerance * kinked.diagonal());
}

// Refusals: crossing curves, a boundary curve through the interior.
TEST(ConstrainedSubdivision, RefusesCrossingCurvesAndCurvesOffTheBoundary) {
  std::mt19937 rng(5);
  PolyMesh grid = QuadGrid(5, rng, 0.0);
  SubdivisionCurve a, b;
  a.name = "curve A";
  b.name = "curve B";
  a.points = {{0, 2, 0}, {4, 2, 0}};
  b.points = {{2, 0, 0}, {2, 4, 0}};
  try {
    ConstrainedSubdivision cs(grid, {a, b}, {SubdivisionScheme::kCatmullClark});
    ADD_FAILURE() << "crossing curves accepted";
  } catch (const SubdivisionError& e) {
    EXPECT_NE(std::string(e.what()).find("curve A and curve B cross"), std::string::npos) << e.what();
  }
  a.boundary = true;
  try {
    ConstrainedSubdivision cs(grid, {a}, {SubdivisionScheme::kCatmullClark});
    ADD_FAILURE() << "interior boundary curve accepted";
  } catch (const SubdivisionError& e) {
    EXPECT_NE(std::string(e.what()).find("curve A is not on the mesh boundary"), std::string::npos) << e.what();
  }
  // Along the boundary it is accepted.
  a.points = {{0, 0, 0}, {4, 0, 0}};
  EXPECT_NO_THROW(ConstrainedSubdivision(grid, {a}, {SubdivisionScheme::kCatmullClark}));
}

// Reverse subdivision recovers the coarse mesh exactly (1e-10) for meshes
// subdivided with the standard masks, two levels deep, closed and open, both
// schemes; a perturbed fine mesh gives the least-squares residual.
TEST(ConstrainedSubdivision, ReverseSubdivisionRecoversTheCoarseMesh) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  struct Case {
    PolyMesh mesh;
    SubdivisionScheme scheme;
  };
  std::vector<Case> cases = {{Torus(5, 6), SubdivisionScheme::kCatmullClark},
                             {QuadGrid(5, rng), SubdivisionScheme::kCatmullClark},
                             {Icosahedron(), SubdivisionScheme::kLoop},
                             {TriangleLattice(5, [](double x, double y) { return 0.1 * x * y; }),
                              SubdivisionScheme::kLoop}};
  for (Case& c : cases) {
    for (auto& p : c.mesh.points) p += Vector3d(u(rng), u(rng), u(rng));
    const PolyMesh fine = SubdivideStandard(SubdivideStandard(c.mesh, c.scheme), c.scheme);
    ReverseResult once = ReverseSubdivision(fine, c.scheme);
    ReverseResult twice = ReverseSubdivision(once.coarse, c.scheme);
    ASSERT_EQ(twice.coarse.points.size(), c.mesh.points.size());
    ASSERT_EQ(twice.coarse.faces.size(), c.mesh.faces.size());
    double worst = 0;
    for (size_t v = 0; v < c.mesh.points.size(); ++v) {
      worst = std::max(worst, (twice.coarse.points[v] - c.mesh.points[v]).norm());
    }
    EXPECT_LE(worst, kReverseTolerance) << c.mesh.faces.size();
    EXPECT_LE(once.residual_max, kReverseTolerance);
    EXPECT_TRUE(once.unique && twice.unique);
    for (auto& f : c.mesh.faces) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    for (auto& f : twice.coarse.faces) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    EXPECT_EQ(twice.coarse.faces, c.mesh.faces);
    EXPECT_LE(twice.residual_max, kReverseTolerance);
    // Noise on the fine mesh: not a subdivided mesh, the residual says so.
    PolyMesh noisy = fine;
    for (auto& p : noisy.points) p += Vector3d(u(rng), u(rng), u(rng)) * 0.1;
    const ReverseResult ls = ReverseSubdivision(noisy, c.scheme);
    EXPECT_GT(ls.residual_max, 1e-3);
    EXPECT_LT(ls.residual_max, 0.1 * std::sqrt(3.0));
  }
  // A mesh without the connectivity is refused.
  PolyMesh cube = Cube();
  EXPECT_THROW(ReverseSubdivision(cube, SubdivisionScheme::kCatmullClark), SubdivisionError);
  // The cube's Catmull–Clark masks are singular (valence 3, bipartite): exact
  // but not unique, and said so.
  const ReverseResult cube_back = ReverseSubdivision(SubdivideStandard(cube, SubdivisionScheme::kCatmullClark),
                                                     SubdivisionScheme::kCatmullClark);
  EXPECT_LE(cube_back.residual_max, kReverseTolerance);
  EXPECT_FALSE(cube_back.unique);
}

// The boundary ring locked: boundary vertices and their neighbours keep their
// positions at every level.
TEST(ConstrainedSubdivision, LockedBoundaryRingKeepsItsPositions) {
  std::mt19937 rng(2);
  const PolyMesh grid = QuadGrid(6, rng);
  SubdivisionOptions o;
  o.scheme = SubdivisionScheme::kCatmullClark;
  o.boundary = SubdivisionBoundary::kLocked;
  ConstrainedSubdivision cs(grid, {}, o);
  for (int k = 0; k < 3; ++k) cs.Step();
  int ring = 0;
  for (int v = 0; v < 36; ++v) {
    const int i = v % 6, j = v / 6;
    if (i > 1 && i < 4 && j > 1 && j < 4) continue;
    EXPECT_EQ(cs.mesh().points[v], grid.points[v]);
    ++ring;
  }
  EXPECT_EQ(ring, 32);
  // New vertices between locked ones are locked too (the strip between the
  // boundary and the first ring is subdivided linearly).
  const auto kinds = cs.VertexKinds();
  int locked = 0;
  for (int k : kinds) locked += k == 2 ? 1 : 0;
  EXPECT_GT(locked, 32 * 8);
}

// A funnel on a column (x² + y² = r², z ≤ 0): rings of `around` vertices at
// (radius, height) = (r, 0), (1.8r, r), (4r, 2r), the first on the column's
// top circle (the one boundary curve, sampled finely).
struct Funnel {
  static constexpr double r = 0.5;
  PolyMesh mesh;
  SubdivisionCurve top;
  Funnel() {
    const int around = 8;
    const double rings[3][2] = {{r, 0}, {1.8 * r, r}, {4 * r, 2 * r}};
    for (const auto& ring : rings) {
      for (int k = 0; k < around; ++k) {
        const double t = 2 * M_PI * k / around;
        mesh.points.emplace_back(ring[0] * std::cos(t), ring[0] * std::sin(t), ring[1]);
      }
    }
    for (int i = 0; i < 2; ++i) {
      for (int k = 0; k < around; ++k) {
        mesh.faces.push_back({i * around + k, i * around + (k + 1) % around, (i + 1) * around + (k + 1) % around,
                              (i + 1) * around + k});
      }
    }
    for (int j = 0; j < 720; ++j) {
      const double t = 2 * M_PI * j / 720;
      top.points.emplace_back(r * std::cos(t), r * std::sin(t), 0);
    }
    top.closed = true;
    top.boundary = true;
    top.name = "column top";
  }
  // The coarse mesh for `scheme`: for Loop the quads split along their first diagonals.
  PolyMesh Coarse(SubdivisionScheme scheme) const {
    if (scheme == SubdivisionScheme::kCatmullClark) return mesh;
    PolyMesh t = mesh;
    t.faces.clear();
    for (const auto& f : mesh.faces) {
      t.faces.push_back({f[0], f[1], f[2]});
      t.faces.push_back({f[0], f[2], f[3]});
    }
    return t;
  }
  static SubdivisionOptions Options(SubdivisionScheme scheme) {
    SubdivisionOptions options;
    options.scheme = scheme;
    return options;
  }
  // The column's normal (radial) at a point of its top circle.
  static bool Normal(const Vector3d& p, Vector3d* n) {
    if (std::abs(p.z()) > 1e-9 || std::abs(std::hypot(p.x(), p.y()) - r) > 1e-4) return false;
    *n = Vector3d(p.x(), p.y(), 0).normalized();
    return true;
  }
  // Largest angle (degrees) between the mesh's tangent plane at a vertex of
  // the top circle (normal: the sum of its faces' Newell normals) and the
  // column's, computed here without the class's own measure.
  static double MaxTurn(const PolyMesh& m, const std::vector<Vector3d>& points) {
    std::vector<Vector3d> normals(points.size(), Vector3d::Zero());
    for (const auto& f : m.faces) {
      Vector3d newell = Vector3d::Zero();
      for (size_t i = 0; i < f.size(); ++i) newell += points[f[i]].cross(points[f[(i + 1) % f.size()]]);
      for (int v : f) normals[v] += newell;
    }
    double worst = -1;
    Vector3d column;
    for (size_t v = 0; v < points.size(); ++v) {
      if (!Normal(points[v], &column)) continue;
      const double c = std::min(1.0, std::abs(normals[v].normalized().dot(column)));
      worst = std::max(worst, std::acos(c) * 180 / M_PI);
    }
    return worst;
  }
};

// §9.2.2: with the column as tangent surface the funnel leaves it in its
// tangent plane (the acceptance's 0.5°), with the same curve; the standard
// rules meet it at the coarse mesh's flare angle.
TEST(ConstrainedSubdivision, TangentSurfaceMakesTheJointSmooth) {
  const Funnel funnel;
  for (const SubdivisionScheme scheme : {SubdivisionScheme::kCatmullClark, SubdivisionScheme::kLoop}) {
    SCOPED_TRACE(scheme == SubdivisionScheme::kLoop ? "Loop" : "Catmull-Clark");
    const PolyMesh coarse = funnel.Coarse(scheme);
    SubdivisionOptions options = Funnel::Options(scheme);
    ConstrainedSubdivision standard(coarse, {funnel.top}, options);
    options.tangent = &Funnel::Normal;
    ConstrainedSubdivision tangent(coarse, {funnel.top}, options);
    for (int level = 0; level < 4; ++level) {
      standard.Step();
      tangent.Step();
    }
    EXPECT_GT(Funnel::MaxTurn(standard.mesh(), standard.mesh().points), 20.0);
    const double turn = Funnel::MaxTurn(tangent.mesh(), tangent.mesh().points);
    EXPECT_LE(turn, 0.5);
    const TangencyMeasure measure = tangent.Tangency(tangent.mesh().points);
    EXPECT_EQ(measure.vertices, 8 << 4);
    EXPECT_NEAR(measure.max_degrees, turn, 1e-9);
    EXPECT_LE(tangent.MaxCurveDistance() / tangent.diagonal(), kCurveTolerance);
    const std::vector<Vector3d> limit = tangent.LimitPositions();
    EXPECT_LE(Funnel::MaxTurn(tangent.mesh(), limit), 0.5);
    EXPECT_LE(tangent.MaxCurveDistance(limit) / tangent.diagonal(), kCurveTolerance);
    // Away from the joint the correction leaves the rules alone: the outer
    // ring (the roof edge, standard boundary) is where it was.
    double far = 0;
    for (size_t v = 0; v < tangent.mesh().points.size(); ++v) {
      if (tangent.mesh().points[v].z() > 0.99 * 2 * Funnel::r) {
        far = std::max(far, (tangent.mesh().points[v] - standard.mesh().points[v]).norm());
      }
    }
    EXPECT_LE(far, 0.05 * Funnel::r);
  }
}

// §9.2.3 with curves: a mesh subdivided with the curve rules (the funnel's
// column top, its coarse vertices among the curve's points) comes back to
// its coarse mesh to 1e-10 through Reverse() with the same curve, level by
// level; the standard masks alone leave a residual.
TEST(ConstrainedSubdivision, ReverseWithTheCurvesRecoversACurveSubdividedMesh) {
  const Funnel funnel;
  for (const SubdivisionScheme scheme : {SubdivisionScheme::kCatmullClark, SubdivisionScheme::kLoop}) {
    SCOPED_TRACE(scheme == SubdivisionScheme::kLoop ? "Loop" : "Catmull-Clark");
    const PolyMesh coarse = funnel.Coarse(scheme);
    SubdivisionOptions options = Funnel::Options(scheme);
    ConstrainedSubdivision forward(coarse, {funnel.top}, options);
    forward.Step();
    forward.Step();
    const double diagonal = forward.diagonal();
    PolyMesh m = forward.mesh();
    EXPECT_GT(ReverseSubdivision(m, scheme).residual_max / diagonal, 1e-6);
    for (int level = 0; level < 2; ++level) {
      const ReverseResult r = ConstrainedSubdivision(m, {funnel.top}, options).Reverse();
      EXPECT_LE(r.residual_max / diagonal, kReverseTolerance);
      EXPECT_TRUE(r.unique);
      m = r.coarse;
    }
    ASSERT_EQ(m.points.size(), coarse.points.size());
    double worst = 0;
    for (size_t v = 0; v < m.points.size(); ++v) worst = std::max(worst, (m.points[v] - coarse.points[v]).norm());
    EXPECT_LE(worst / diagonal, kReverseTolerance);
  }
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
