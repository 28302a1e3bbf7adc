// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The goal library as registered terms composed in `problem: custom` specs
// [Gebreiter 2012, §10, §11]: the three examples' figures end to end (the
// hanging net on its own 12 × 12 grid; conical.yaml on a noisy torus principal
// net — the real Smooth/Conjugate runs are in benchmarks/goal_examples.cpp;
// even_boundary.yaml on a small dome whose boundary is spaced unevenly), the
// other terms in small solves (frame conversion of lengths and directions,
// shear, bending, curvature flow, a curve file), `terms.<t>.select`, and
// goal terms on meshes they do not fit.
#include <Eigen/Core>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "energies/registry.h"
#include "geometry/curves.h"
#include "mesh/elements.h"
#include "generators/generators.h"
#include "analysis/goal_metrics.h"
#include "core/input_error.h"
#include "io/io.h"
#include "analysis/metrics.h"
#include "geometry/reference.h"
#include "mesh/similarity.h"
#include "generators/smoothness_surfaces.h"
#include "mesh/topology.h"
#include "problems/commands/generate.h"
#include "problems/runtime/solve.h"
#include "problems/spec/spec.h"
#include "tests/make_mesh.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

const std::string kExamples = std::string(ARCHGEO_SOURCE_DIR) + "/examples/";
// No output files from the examples' specs.
const std::vector<std::string> kNoOutputs = {"output.mesh=", "output.report="};

std::vector<std::string> With(std::vector<std::string> overrides) {
  overrides.insert(overrides.end(), kNoOutputs.begin(), kNoOutputs.end());
  return overrides;
}

std::unique_ptr<Solution> SolveSpec(const ProblemSpec& spec, const Mesh& mesh) {
  std::unique_ptr<Solution> s = Solve(spec, mesh, nullptr, {});
  EXPECT_TRUE(s->loop.usable) << s->loop.message;
  // Every round is checked for validity (analysis/validity.h, the spec's
  // limits): the output is the last round, not an earlier valid one.
  EXPECT_FALSE(s->loop.restored_valid) << "output is round " << s->loop.output_round;
  return s;
}

double MaxDisplacement(const Mesh& a, const Mesh& b) {
  double m = 0;
  for (VertexIndex v : a.vertices()) {
    m = std::max(m, (Pos(a, v) - Pos(b, v)).norm());
  }
  return m;
}

double MaxPlanarity(const Mesh& mesh) {
  const PlanarityMeasure p = MeasureFacePlanarity(mesh);
  return p.normalized.empty() ? 0.0 : *std::max_element(p.normalized.begin(), p.normalized.end());
}

// A square grid of n × n quads, side `side`, in the plane z = 0.
Mesh FlatGrid(int n, double side) {
  return QuadGrid(n, n, [side](double u, double v) { return Vec3{side * u, side * v, 0.0}; });
}

// ---------------------------------------------------------------------------
// examples/hanging_net.yaml: a 24 × 24 square of 12 × 12 quads, boundary
// fixed, zero-length springs k = 9, load q = 1 per area upwards.

class HangingNetExample : public ::testing::Test {
 protected:
  void SetUp() override {
    spec_ = std::make_unique<ProblemSpec>(ReadSpec(kExamples + "hanging_net.yaml", kNoOutputs));
    input_ = ReadMesh(spec_->mesh());
    solution_ = SolveSpec(*spec_, input_);
  }
  static constexpr int kN = 12;
  static constexpr double kSide = 24, kLoad = 1, kStiffness = 9;
  std::unique_ptr<ProblemSpec> spec_;
  Mesh input_;
  std::unique_ptr<Solution> solution_;
};

// Equilibrium, measured on the written mesh (file units) with the loads of
// the flat net: every free vertex's resultant ≤ 1e-6 of the mean load.
TEST_F(HangingNetExample, IsInEquilibrium) {
  const Mesh& out = solution_->output;
  const std::vector<double> areas = TributaryAreas(input_);
  std::vector<Vec3> loads;
  for (double a : areas) loads.push_back({0, 0, kLoad * a});
  const ForceBalanceMeasure balance =
      MeasureForceBalance(out, loads, std::vector<double>(out.number_of_edges(), kStiffness),
                          std::vector<double>(out.number_of_edges(), 0.0), BoundaryVertices(out));
  EXPECT_EQ(balance.free_vertices, (kN - 1) * (kN - 1));
  EXPECT_LE(balance.max_relative, 1e-6);
  std::printf("hanging net: force balance %.3e of the load\n", balance.max_relative);
}

// Zero-length springs on a regular grid: x and y stay (they are harmonic),
// z solves k Σ_j (z_j − z_v) + q A_v = 0 with z = 0 on the boundary — solved
// here independently by Gauss–Seidel. The centre is the highest point and the
// square's symmetries hold to 1e-9.
TEST_F(HangingNetExample, IsTheDiscreteFunicularShape) {
  const Mesh& out = solution_->output;
  const int n = kN;
  const double h = kSide / n;
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  std::vector<double> z((n + 1) * (n + 1), 0.0);
  for (int sweep = 0; sweep < 20000; ++sweep) {
    for (int j = 1; j < n; ++j) {
      for (int i = 1; i < n; ++i) {
        z[id(i, j)] = 0.25 * (z[id(i - 1, j)] + z[id(i + 1, j)] + z[id(i, j - 1)] +
                              z[id(i, j + 1)] + kLoad * h * h / kStiffness);
      }
    }
  }
  double worst = 0, symmetry = 0;
  const VertexIndex centre(id(n / 2, n / 2));
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const Point p = out.point(VertexIndex(id(i, j)));
      worst = std::max(worst, std::abs(p.z() - z[id(i, j)]));
      worst = std::max(worst, std::hypot(p.x() - i * h, p.y() - j * h));
      EXPECT_LE(p.z(), out.point(centre).z() + 1e-12);
      const Point mx = out.point(VertexIndex(id(n - i, j)));
      const Point sw = out.point(VertexIndex(id(j, i)));
      symmetry = std::max({symmetry, std::abs(p.x() - (kSide - mx.x())), std::abs(p.z() - mx.z()),
                           std::abs(p.x() - sw.y()), std::abs(p.z() - sw.z())});
    }
  }
  EXPECT_LE(worst, 1e-7 * kSide);
  EXPECT_LE(symmetry, 1e-9);
  EXPECT_GT(out.point(centre).z(), 0.1 * kSide);  // a vault, not a flat net
  // The report's span and rise: the supports' plan diameter and the centre's height.
  const nlohmann::json& form = solution_->details.at("load");
  EXPECT_NEAR(form.at("span").get<double>(), kSide * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(form.at("rise").get<double>(), out.point(centre).z(), 1e-12);
  std::printf("hanging net: rise %.6g, span %.6g, off the Gauss-Seidel solution %.2e of the "
              "side, symmetry %.2e\n",
              out.point(centre).z(), form.at("span").get<double>(), worst / kSide, symmetry);
}

// Fixed corners only: the boundary is pulled in as well; still in balance.
TEST(HangingNet, FixedCornersReachEquilibrium) {
  const Mesh grid = FlatGrid(6, 12);
  const ProblemSpec spec = ParseSpec(
      "problem: custom\nfixed: corners\nterms:\n  load: {per: vertex, load: 2, stiffness: 3, "
      "direction: [0, 0, -1]}\ntolerance: {force_balance_max: 1e-10}\n");
  const std::unique_ptr<Solution> s = SolveSpec(spec, grid);
  const Mesh& out = s->output;
  std::vector<bool> fixed(out.number_of_vertices(), false);
  for (VertexIndex v : Corners(grid)) fixed[v.idx()] = true;
  const ForceBalanceMeasure balance = MeasureForceBalance(
      out, std::vector<Vec3>(out.number_of_vertices(), Vec3{0, 0, -2}),
      std::vector<double>(out.number_of_edges(), 3.0),
      std::vector<double>(out.number_of_edges(), 0.0), fixed);
  EXPECT_EQ(balance.free_vertices, 49 - 4);
  EXPECT_LE(balance.max_relative, 1e-6);
  const double centre = out.point(VertexIndex(3 * 7 + 3)).z();
  EXPECT_LT(centre, -1.0);  // it hangs (gravity)
}

// The direction is given in the file's axes: a net in a tilted plane, loaded
// along that plane's normal, moves along it and only along it.
TEST(HangingNet, LoadDirectionIsInTheFileAxes) {
  Mesh grid = FlatGrid(6, 6);
  const double c = std::cos(0.6), s = std::sin(0.6);
  for (VertexIndex v : grid.vertices()) {
    const Point p = grid.point(v);
    grid.point(v) = Point(c * p.x() + 3, p.y() - 2, s * p.x() + 1);
  }
  const Eigen::Vector3d normal(-s, 0, c);
  const ProblemSpec spec = ParseSpec(
      "problem: custom\nfixed: boundary\nterms:\n  load: {load: 1, direction: [" +
      std::to_string(normal[0]) + ", 0, " + std::to_string(normal[2]) + "]}\n");
  const std::unique_ptr<Solution> sol = SolveSpec(spec, grid);
  double along = 0, across = 0;
  for (VertexIndex v : grid.vertices()) {
    const Eigen::Vector3d d = Pos(sol->output, v) - Pos(grid, v);
    along = std::max(along, d.dot(normal));
    across = std::max(across, (d - d.dot(normal) * normal).norm());
  }
  EXPECT_GT(along, 0.5);
  EXPECT_LE(across, 1e-5);  // the direction's 6 printed digits
}

// ---------------------------------------------------------------------------
// examples/conical.yaml on a noisy copy of a conical mesh: the torus principal
// net of `archgeo generate --surface torus --noise 0.05`.

class ConicalExample : public ScratchDirTest {};

TEST_F(ConicalExample, RecoversAConicalMeshFromANoisyTorus) {
  GenerateOptions g;
  g.surface = "torus";
  g.nu = 24;
  g.nv = 12;
  g.noise = 0.05;
  GenerateSurface(Path("noisy_torus.obj"), g);
  const Mesh noisy = ReadMesh(Path("noisy_torus.obj"));
  const double diagonal = PrincipalBoxDiagonal(noisy);
  const double edge = EdgeLengthSpread(noisy).mean;
  ASSERT_GT(MeasureConical(noisy).max, 0.05);  // the noise breaks the conical property
  ASSERT_GT(MaxPlanarity(noisy), 0.01);

  const ProblemSpec spec =
      ReadSpec(kExamples + "conical.yaml", With({"mesh=" + Path("noisy_torus.obj")}));
  const std::unique_ptr<Solution> s = SolveSpec(spec, noisy);
  const Mesh& out = s->output;
  const ConicalMeasure conical = MeasureConical(out);
  EXPECT_EQ(conical.vertices, 24 * 12);  // every vertex of the closed torus net
  EXPECT_LE(conical.max, 1e-3);
  EXPECT_LE(MaxPlanarity(out), 1e-3);
  EXPECT_EQ(NonConvexQuads(out), 0);
  EXPECT_LE(MaxDisplacement(out, noisy), 0.03 * diagonal);
  const FaceOffsetMeasure offsets = MeasureFaceOffsets(out, edge);
  EXPECT_EQ(offsets.vertices, 24 * 12);
  EXPECT_LE(offsets.max_relative, 1e-3);
  std::printf("noisy torus -> conical %.2e rad, δ_PQ,n %.2e, offset miss %.2e, moved %.2e of "
              "the diagonal\n",
              conical.max, MaxPlanarity(out), offsets.max_relative,
              MaxDisplacement(out, noisy) / diagonal);
}

// ---------------------------------------------------------------------------
// examples/even_boundary.yaml on a dome over a disc: a square grid mapped
// onto the disc (corners on the circle), boundary spacing uneven.

Mesh Dome(int n) {
  return QuadGrid(n, n, [](double u, double v) {
    const double x = 2 * u - 1, y = 2 * v - 1;
    const double X = x * std::sqrt(1 - 0.5 * y * y), Y = y * std::sqrt(1 - 0.5 * x * x);
    return Vec3{5 * X, 5 * Y, 1.5 * (1 - X * X - Y * Y)};
  });
}

class EvenBoundaryExample : public ScratchDirTest {};

TEST_F(EvenBoundaryExample, SpacesTheBoundaryEvenlyOnThePerimeter) {
  const Mesh dome = Dome(10);
  WriteMesh(Path("dome.obj"), dome);
  const double diagonal = PrincipalBoxDiagonal(dome);
  ASSERT_GT(BoundaryEdgeLengthSpread(dome).max_relative_deviation, 0.1);
  const ProblemSpec spec =
      ReadSpec(kExamples + "even_boundary.yaml", With({"mesh=" + Path("dome.obj")}));
  const std::unique_ptr<Solution> s = SolveSpec(spec, dome);
  const Mesh& out = s->output;
  const LengthSpread spacing = BoundaryEdgeLengthSpread(out);
  EXPECT_LE(spacing.max_relative_deviation, 0.01);
  // On the perimeter: the input's boundary loop.
  const std::vector<std::vector<VertexIndex>> loops = BoundaryLoops(dome);
  ASSERT_EQ(loops.size(), 1u);
  const PolylineLocator perimeter(LoopPolyline(dome, loops[0]));
  double off = 0;
  for (VertexIndex v : loops[0]) {
    off = std::max(off, perimeter.Closest(ToVec3(out.point(v))).distance);
  }
  EXPECT_LE(off, 1e-9 * diagonal);
  // The surface is kept: every vertex near the input surface.
  const ReferenceSurface surface(dome);
  double away = 0;
  for (VertexIndex v : out.vertices()) {
    const Eigen::Vector3d closest(surface.Closest(ToVec3(out.point(v))).point.data());
    away = std::max(away, (closest - Pos(out, v)).norm());
  }
  EXPECT_LE(away, 0.005 * diagonal);
  std::printf("dome: boundary spacing %.2e -> %.2e, off the perimeter %.2e, off the surface "
              "%.2e of the diagonal\n",
              BoundaryEdgeLengthSpread(dome).max_relative_deviation,
              spacing.max_relative_deviation, off / diagonal, away / diagonal);
}

// A designer's curve file: the boundary vertices of the same dome go onto a
// finely sampled circle of radius 5.5 at z = 0 and spread evenly on it.
TEST_F(EvenBoundaryExample, FollowsAGivenCurveFile) {
  const Mesh dome = Dome(8);
  WriteMesh(Path("dome.obj"), dome);
  std::string obj;
  const int m = 720;
  for (int k = 0; k < m; ++k) {
    const double a = 2 * M_PI * k / m;
    obj += "v " + std::to_string(5.5 * std::cos(a)) + " " + std::to_string(5.5 * std::sin(a)) +
           " 0\n";
  }
  obj += "l";
  for (int k = 1; k <= m; ++k) obj += " " + std::to_string(k);
  obj += " 1\n";
  WriteFile("circle.obj", obj);
  const std::vector<Polyline> circle = ReadPolylines(Path("circle.obj"));
  const ProblemSpec spec = ReadSpec(
      kExamples + "even_boundary.yaml",
      With({"mesh=" + Path("dome.obj"), "terms.on_curve={weight: 1, curve: " + Path("circle.obj") +
                                            "}"}));
  const std::unique_ptr<Solution> s = SolveSpec(spec, dome);
  const PolylineLocator locator(circle[0]);
  double off = 0;
  const std::vector<std::vector<VertexIndex>> loops = BoundaryLoops(dome);
  for (VertexIndex v : loops[0]) {
    off = std::max(off, locator.Closest(ToVec3(s->output.point(v))).distance);
  }
  EXPECT_LE(off, 1e-9 * PrincipalBoxDiagonal(dome));
  EXPECT_LE(BoundaryEdgeLengthSpread(s->output).max_relative_deviation, 0.01);
}

// The same perimeter given in the spec as a list of points (closed: the last
// point repeats the first); malformed lists and both forms at once are input
// errors naming the key.
TEST_F(EvenBoundaryExample, FollowsAPointListInTheSpec) {
  const Mesh dome = Dome(8);
  WriteMesh(Path("dome.obj"), dome);
  const int m = 360;
  std::vector<Vec3> circle;
  std::string points = "[";
  for (int k = 0; k <= m; ++k) {
    const double a = 2 * M_PI * (k % m) / m;
    circle.push_back({5.5 * std::cos(a), 5.5 * std::sin(a), 0.0});
    char p[80];
    std::snprintf(p, sizeof p, "%s[%.17g, %.17g, 0]", k ? ", " : "", circle.back()[0],
                  circle.back()[1]);
    points += p;
  }
  points += "]";
  const ProblemSpec spec =
      ReadSpec(kExamples + "even_boundary.yaml",
               With({"mesh=" + Path("dome.obj"),
                     "terms.on_curve={weight: 1, curve_points: " + points + "}"}));
  const std::unique_ptr<Solution> s = SolveSpec(spec, dome);
  circle.pop_back();
  const PolylineLocator locator(MakePolyline(circle, true));
  double off = 0;
  const std::vector<std::vector<VertexIndex>> loops = BoundaryLoops(dome);
  for (VertexIndex v : loops[0]) {
    off = std::max(off, locator.Closest(ToVec3(s->output.point(v))).distance);
  }
  EXPECT_LE(off, 1e-9 * PrincipalBoxDiagonal(dome));
  EXPECT_LE(BoundaryEdgeLengthSpread(s->output).max_relative_deviation, 0.01);

  const auto error = [&](const std::string& on_curve) {
    try {
      const ProblemSpec bad = ReadSpec(
          kExamples + "even_boundary.yaml",
          With({"mesh=" + Path("dome.obj"), "terms.on_curve=" + on_curve}));
      Solve(bad, dome, nullptr, {});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("{weight: 1, curve_points: [[0, 0, 0], [1, 2]]}")
                .find("terms.on_curve.curve_points': expected a list of points [x, y, z] (file "
                      "units); point 2 is not three finite numbers"),
            std::string::npos);
  EXPECT_NE(error("{weight: 1, curve_points: 7}").find("expected a list of points"),
            std::string::npos);
  EXPECT_NE(error("{weight: 1, curve_points: [[0, 0, 0], [0, 0, 0]]}").find("curve_points"),
            std::string::npos);
  WriteFile("line.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n");
  EXPECT_NE(error("{weight: 1, curve: " + Path("line.obj") +
                  ", curve_points: [[0, 0, 0], [1, 0, 0]]}")
                .find("give either terms.on_curve.curve or terms.on_curve.curve_points"),
            std::string::npos);
}

// ---------------------------------------------------------------------------
// Other terms in small solves.

// rest: length is in file units: edges of length 10 become 15.
TEST(Spring, RestLengthIsInFileUnits) {
  const Mesh grid = FlatGrid(4, 40);
  const ProblemSpec spec =
      ParseSpec("problem: custom\nterms:\n  spring: {rest: length, length: 15}\n");
  const std::unique_ptr<Solution> s = SolveSpec(spec, grid);
  const LengthSpread lengths = EdgeLengthSpread(s->output);
  EXPECT_NEAR(lengths.min, 15, 1e-6);
  EXPECT_NEAR(lengths.max, 15, 1e-6);
}

// Shear alone turns a grid of parallelograms into rectangles (boundary row
// fixed); bending straightens the mesh lines of a wavy grid.
TEST(ShearAndBending, RectanglesAndStraightLines) {
  const Mesh sheared =
      QuadGrid(4, 3, [](double u, double v) { return Vec3{4 * u + 1.5 * v, 3 * v, 0.0}; });
  const ProblemSpec shear = ParseSpec("problem: custom\nfixed: [0, 1, 2, 3, 4]\nterms:\n  shear: 1\n");
  const std::unique_ptr<Solution> a = SolveSpec(shear, sheared);
  double worst = 0;
  for (FaceIndex f : a->output.faces()) {
    std::vector<Eigen::Vector3d> p;
    for (VertexIndex v : CGAL::vertices_around_face(a->output.halfedge(f), a->output)) {
      p.push_back(Pos(a->output, v));
    }
    worst = std::max(worst, std::abs((p[2] - p[0]).norm() - (p[3] - p[1]).norm()));
  }
  EXPECT_LE(worst, 1e-8);

  const Mesh wavy = QuadGrid(6, 6, [](double u, double v) {
    return Vec3{6 * u, 6 * v, 0.3 * std::sin(2 * M_PI * u) * std::sin(2 * M_PI * v)};
  });
  const ProblemSpec bend = ParseSpec("problem: custom\nfixed: boundary\nterms:\n  bending: 1\n");
  const std::unique_ptr<Solution> b = SolveSpec(bend, wavy);
  double height = 0;
  for (VertexIndex v : b->output.vertices()) height = std::max(height, std::abs(b->output.point(v).z()));
  EXPECT_LE(height, 1e-6);  // the boundary is flat: straight lines make the plane
}

// Mean-curvature flow with a planar boundary held: the minimal surface is the
// plane; a bump on a triangulated disc flattens.
TEST(MeanCurvatureFlow, FlattensToThePlaneOfItsBoundary) {
  Mesh mesh;
  const int n = 6;
  std::vector<VertexIndex> id;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const double x = double(i) / n - 0.5, y = double(j) / n - 0.5;
      id.push_back(mesh.add_vertex(Point(x, y, 0.4 * std::cos(M_PI * x) * std::cos(M_PI * y))));
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const VertexIndex a = id[j * (n + 1) + i], b = id[j * (n + 1) + i + 1];
      const VertexIndex c = id[(j + 1) * (n + 1) + i + 1], d = id[(j + 1) * (n + 1) + i];
      mesh.add_face(a, b, c);
      mesh.add_face(a, c, d);
    }
  }
  // frozen (the default) alone; live damped by `step` (alone it stalls).
  for (const std::string terms : {"{form: frozen}", "{form: live}\n  step: 0.1"}) {
    const ProblemSpec spec = ParseSpec(
        "problem: custom\nfixed: boundary\nschedule: {outer_iterations: 40}\nterms:\n"
        "  mean_curvature_flow: " + terms + "\n");
    const std::unique_ptr<Solution> s = SolveSpec(spec, mesh);
    double height = 0;
    for (VertexIndex v : s->output.vertices()) {
      height = std::max(height, std::abs(s->output.point(v).z()));
    }
    EXPECT_LE(height, 1e-6) << terms;
  }
}

// ---------------------------------------------------------------------------
// The element sets the goal terms act on (mesh/elements.h).

TEST(GoalElementSets, OnAGridAndItsTriangulation) {
  const Mesh grid = FlatGrid(3, 3);  // 16 vertices, 24 edges (12 on the boundary), 9 quads
  EXPECT_EQ(BuildElementSet(grid, "edges").size(), 24u);
  const ElementSet border = BuildElementSet(grid, "boundary_edges");
  ASSERT_EQ(border.size(), 12u);
  // Head to tail around the loop: every edge's end starts another edge.
  for (size_t i = 0; i < border.size(); ++i) {
    int starts = 0;
    for (size_t j = 0; j < border.size(); ++j) starts += border.Vertices(j)[0] == border.Vertices(i)[1];
    EXPECT_EQ(starts, 1);
    EXPECT_TRUE(border.Has(i, kBoundary));
  }
  EXPECT_EQ(BuildElementSet(grid, "boundary_vertices").size(), 12u);
  const ElementSet rings = BuildElementSet(grid, "one_rings");
  ASSERT_EQ(rings.size(), 16u);
  EXPECT_EQ(rings.Count(0), 3);  // a corner and its two neighbours
  const ElementSet stars = BuildElementSet(grid, "valence4_stars");
  EXPECT_EQ(stars.size(), 4u);   // the interior vertices
  EXPECT_EQ(BuildElementSet(grid, "triangle_fans").size(), 0u);
  // The same grid triangulated: no valence-4 star without triangles, and a
  // triangle fan at every vertex with an interior edge.
  Mesh triangles;
  for (VertexIndex v : grid.vertices()) triangles.add_vertex(grid.point(v));
  for (FaceIndex f : grid.faces()) {
    std::vector<VertexIndex> q;
    for (VertexIndex v : CGAL::vertices_around_face(grid.halfedge(f), grid)) q.push_back(v);
    triangles.add_face(q[0], q[1], q[2]);
    triangles.add_face(q[0], q[2], q[3]);
  }
  EXPECT_EQ(BuildElementSet(triangles, "valence4_stars").size(), 0u);
  EXPECT_EQ(BuildElementSet(triangles, "triangle_fans").size(),
            BuildElementSet(triangles, "fans").size());
  EXPECT_GT(BuildElementSet(triangles, "triangle_fans").size(), 0u);
}

// ---------------------------------------------------------------------------
// terms.<t>.select

class SelectTest : public ScratchDirTest {
 protected:
  // The sites term `term` acts on after one (cheap) round of the spec on `mesh`.
  std::vector<int> Sites(const std::string& yaml, const Mesh& mesh, const std::string& term) {
    const ProblemSpec spec = ParseSpec("problem: custom\nschedule: {outer_iterations: 1}\n"
                                       "solver: {max_num_iterations: 1}\n" + yaml,
                                       Path("spec.yaml"));
    const std::unique_ptr<Solution> s = Solve(spec, mesh, nullptr, {});
    return s->model->Selected(*FindTerm(term)).sites;
  }
  InputError Error(const std::string& yaml, const Mesh& mesh) {
    try {
      Sites(yaml, mesh, "spring");
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << "no InputError for " << yaml;
    return InputError("", 0, "", "");
  }
};

// A 4 × 4 grid: 25 vertices, 40 edges, 16 of them on the boundary.
TEST_F(SelectTest, BoundaryInteriorFreeAndIds) {
  const Mesh grid = FlatGrid(4, 4);
  EXPECT_EQ(Sites("terms: {spring: 1}\n", grid, "spring").size(), 40u);
  EXPECT_EQ(Sites("terms: {spring: {select: boundary}}\n", grid, "spring").size(), 16u);
  EXPECT_EQ(Sites("terms: {spring: {select: interior}}\n", grid, "spring").size(), 24u);
  EXPECT_EQ(Sites("terms: {spring: {on: boundary_edges}}\n", grid, "spring").size(), 16u);
  // Laplacian on the vertices: all but the four fixed corners.
  EXPECT_EQ(Sites("fixed: corners\nterms: {laplacian: {select: free}}\n", grid, "laplacian").size(),
            21u);
  EXPECT_EQ(Sites("fixed: corners\nterms: {laplacian: {select: {boundary: true, free: true}}}\n",
                  grid, "laplacian")
                .size(),
            12u);
  EXPECT_EQ(Sites("terms: {laplacian: {select: [3, 7, 11]}}\n", grid, "laplacian"),
            (std::vector<int>{3, 7, 11}));
  EXPECT_EQ(Sites("terms: {laplacian: {select: {ids: [7]}}}\n", grid, "laplacian"),
            (std::vector<int>{7}));
}

// An annulus (a 6 × 6 grid without its middle 2 × 2 quads): loop 0 is the
// outer boundary (24 vertices), loop 1 the hole (8).
TEST_F(SelectTest, LoopsDegreesAndCurves) {
  Mesh ring;
  const int n = 6;
  std::vector<VertexIndex> id;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) id.push_back(ring.add_vertex(Point(i, j, 0.1 * i * j)));
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if (i >= 2 && i < 4 && j >= 2 && j < 4) continue;
      const auto at = [&](int a, int b) { return id[b * (n + 1) + a]; };
      if (i == 5 && j == 5) {  // one corner as two triangles
        ring.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
        ring.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
      } else {
        ring.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
      }
    }
  }
  EXPECT_EQ(Sites("terms: {laplacian: {select: {loop: 0}}}\n", ring, "laplacian").size(), 24u);
  EXPECT_EQ(Sites("terms: {laplacian: {select: {loop: 1}}}\n", ring, "laplacian").size(), 8u);
  EXPECT_EQ(Sites("terms: {spring: {on: boundary_edges, select: {loop: 1}}}\n", ring, "spring")
                .size(),
            8u);
  // Faces by degree: 31 quads and 2 triangles.
  EXPECT_EQ(Sites("terms: {spring: 1, shear: {on: quads}}\n", ring, "shear").size(), 31u);
  EXPECT_EQ(
      Sites("terms: {face_planarity: {on: faces, select: {degree: 3}}}\n", ring, "face_planarity")
          .size(),
      2u);
  EXPECT_EQ(Sites("terms: {face_planarity: {on: faces, select: {degree: [3, 4]}}}\n", ring,
                  "face_planarity")
                .size(),
            33u);
  // Vertex sites: valence.
  EXPECT_EQ(Sites("terms: {laplacian: {select: {degree: 2}}}\n", ring, "laplacian").size(), 3u);
  // The vertices of a curve file: the bottom row y = 0 (exported with z = 0.1 i j = 0).
  WriteFile("bottom.obj", "v 0 0 0\nv 6 0 0\nl 1 2\n");
  EXPECT_EQ(Sites("terms: {laplacian: {select: {curve: bottom.obj}}}\n", ring, "laplacian").size(),
            7u);
  EXPECT_EQ(Sites("terms: {spring: {select: {curve: bottom.obj}}}\n", ring, "spring").size(), 6u);
  // `within` widens the band (mean edge lengths): the row y = 1 is ~1 away.
  EXPECT_EQ(
      Sites("terms: {laplacian: {select: {curve: bottom.obj, within: 1.2}}}\n", ring, "laplacian")
          .size(),
      14u);
}

TEST_F(SelectTest, ErrorsNameFileLineAndKey) {
  const Mesh grid = FlatGrid(3, 3);
  const InputError unknown = Error("terms:\n  spring:\n    select: {lop: 0}\n", grid);
  EXPECT_EQ(unknown.file(), Path("spec.yaml"));
  EXPECT_EQ(unknown.line(), 6);  // after the three lines Sites() puts first
  EXPECT_EQ(unknown.key(), "terms.spring.select.lop");
  EXPECT_EQ(Error("terms: {spring: {select: everything}}\n", grid).key(), "terms.spring.select");
  const InputError loop = Error("terms: {spring: {select: {loop: 1}}}\n", grid);
  EXPECT_EQ(loop.key(), "terms.spring.select");
  EXPECT_NE(loop.message().find("1 boundary loop"), std::string::npos) << loop.what();
  EXPECT_NE(Error("terms: {spring: {select: {degree: 4}}}\n", grid).message().find("edges"),
            std::string::npos);
  EXPECT_EQ(Error("terms: {spring: {select: [999]}}\n", grid).key(), "terms.spring.select");
  EXPECT_NE(Error("terms: {spring: {select: {curve: nowhere.obj}}}\n", grid).message().find(
                "nowhere.obj"),
            std::string::npos);
  WriteFile("far.obj", "v 100 100 0\nv 101 100 0\nl 1 2\n");
  EXPECT_NE(Error("terms: {spring: {select: {curve: far.obj}}}\n", grid).message().find(
                "selects none"),
            std::string::npos);
}

// ---------------------------------------------------------------------------
// A goal term on a mesh it does not fit is an input error naming the term.

TEST(GoalTerms, OnMeshesTheyDoNotFitAreInputErrorsNamingTheTerm) {
  Mesh triangles;
  {
    const Mesh grid = FlatGrid(3, 3);
    for (VertexIndex v : grid.vertices()) triangles.add_vertex(grid.point(v));
    for (FaceIndex f : grid.faces()) {
      std::vector<VertexIndex> q;
      for (VertexIndex v : CGAL::vertices_around_face(grid.halfedge(f), grid)) q.push_back(v);
      triangles.add_face(q[0], q[1], q[2]);
      triangles.add_face(q[0], q[2], q[3]);
    }
  }
  const Mesh quads = FlatGrid(3, 3);
  const Mesh torus = TorusPrincipalQuads(3, 1, 8, 6);
  struct Case {
    std::string term;
    const Mesh* mesh;
    std::string says;
  };
  for (const Case& c : std::vector<Case>{{"conical", &triangles, "valence4_stars"},
                                         {"shear", &triangles, "quads"},
                                         {"mean_curvature_flow", &quads, "triangle_fans"},
                                         {"on_curve", &torus, "boundary_vertices"}}) {
    const ProblemSpec spec = ParseSpec("problem: custom\nterms: {" + c.term + ": 1}\n");
    try {
      Solve(spec, *c.mesh, nullptr, {});
      ADD_FAILURE() << c.term << ": no InputError";
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "terms." + c.term) << e.what();
      EXPECT_NE(e.message().find(c.says), std::string::npos) << e.what();
    }
  }
  // A closed mesh has no boundary to slide on, even when selected by hand.
  const ProblemSpec curve =
      ParseSpec("problem: custom\nterms: {on_curve: {on: vertices}, laplacian: 1}\n");
  try {
    Solve(curve, torus, nullptr, {});
    ADD_FAILURE() << "on_curve on a closed mesh: no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "terms.on_curve.curve") << e.what();
  }
  // A load without a direction.
  const ProblemSpec zero = ParseSpec("problem: custom\nterms: {load: {direction: [0, 0, 0]}}\n");
  try {
    Solve(zero, quads, nullptr, {});
    ADD_FAILURE() << "zero load direction: no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "terms.load.direction") << e.what();
  }
}

// Custom offers a tolerance for what its terms drive, and continues their weights.
TEST(GoalTerms, CustomOffersTheToleranceOfWhatItsTermsDrive) {
  const ProblemSpec spec = ParseSpec(
      "problem: custom\nterms: {conical: 1, pq_diagonal: 1, load: 1}\n"
      "tolerance: {conical_max: 1e-4, pq_normalized_max: 1e-3, force_balance_max: 1e-8}\n");
  EXPECT_DOUBLE_EQ(spec.settings.Number("tolerance.conical_max"), 1e-4);
  EXPECT_DOUBLE_EQ(spec.settings.Number("tolerance.force_balance_max"), 1e-8);
  try {
    ParseSpec("problem: custom\nterms: {spring: 1, pq_diagonal: 1}\ntolerance: {conical_max: 1e-4}\n");
    ADD_FAILURE() << "tolerance.conical_max without the conical term";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "tolerance.conical_max");
  }
}

}  // namespace
}  // namespace archgeo
