// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for grids on parametric surfaces, their quality measures and the
// force-directed method (surfaces/grid, grid_quality, force_directed;
// mesh/grid_mesh, grid_metrics):
//  (a) grid topology of every type, with the Klein bottle's flipping seam:
//      counts, symmetric neighbours, quads made of neighbours, closed lines;
//  (b) MDO/ADO/MDE/ADE on analytic grids: square, rectangular and rhombic
//      plane grids, a cylinder (the periodic spline's tangents and arc lengths);
//  (c) the same measures from any quad mesh that is a grid (GridToMesh, then
//      MeasureQuadGridMesh) equal the grid's, and grid files keep (u, v);
//  (d) the force method: a square plane grid stays put; a skewed cylinder grid
//      closed in u becomes square (MDO < 0.01°, MDE < 0.1%); the boundary force
//      (eq. 2) turns a rhombic open plane grid orthogonal; on every Table 1
//      stand-in the measures improve, to the paper's after row where our
//      stand-in reaches it; the thresholds of §4 stop the run; every output
//      vertex lies on its surface.
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <CGAL/Surface_mesh/IO/PLY.h>
#include <gtest/gtest.h>

#include "generators/grid_mesh.h"
#include "analysis/grid_metrics.h"
#include "core/input_error.h"
#include "surfaces/force_directed.h"
#include "surfaces/grid.h"
#include "surfaces/grid_quality.h"
#include "surfaces/surface_factory.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

// Agreement of quantities equal in exact arithmetic (degrees or percent).
constexpr double kTolerance = 1e-9;
// "Stays put" and "on the surface" [issue 12 acceptance].
constexpr double kStaysPut = 1e-9;    // degrees
constexpr double kOnSurface = 1e-12;  // relative to the surface's size

using Uv = Eigen::Vector2d;

// A grid with the given (u, v) per vertex (index j·nu + i).
template <typename F>
Grid GridOf(int nu, int nv, bool closed_u, bool closed_v, F uv_of) {
  Grid g;
  g.nu = nu;
  g.nv = nv;
  g.closed_u = closed_u;
  g.closed_v = closed_v;
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) g.uv.push_back(uv_of(i, j));
  }
  return g;
}

// ---------------------------------------------------------------- topology

void ExpectConsistentTopology(const Grid& g) {
  const int n = g.NumVertices();
  const auto neighbours_of = [&](int v) {
    const GridNeighbours nb = Neighbours(g, v);
    std::multiset<int> s;
    for (int w : {nb.l0, nb.l1, nb.t0, nb.t1}) {
      if (w >= 0) s.insert(w);
    }
    return s;
  };
  for (int v = 0; v < n; ++v) {
    for (int w : neighbours_of(v)) EXPECT_EQ(neighbours_of(w).count(v), 1u) << v << " " << w;
  }
  std::set<std::pair<int, int>> edges;
  for (const auto& e : GridEdges(g)) {
    EXPECT_EQ(neighbours_of(e[0]).count(e[1]), 1u);
    EXPECT_TRUE(edges.insert({std::min(e[0], e[1]), std::max(e[0], e[1])}).second) << "duplicate edge";
  }
  int degree_sum = 0;
  for (int v = 0; v < n; ++v) degree_sum += Neighbours(g, v).Count();
  EXPECT_EQ(2 * static_cast<int>(edges.size()), degree_sum);
  for (const auto& q : GridQuads(g)) {
    for (int k = 0; k < 4; ++k) {
      EXPECT_TRUE(edges.count({std::min(q[k], q[(k + 1) % 4]), std::max(q[k], q[(k + 1) % 4])}));
    }
  }
  // Every vertex on exactly one u-line and one v-line.
  std::vector<int> seen(n, 0);
  for (const GridLine& line : GridLines(g)) {
    for (int v : line.vertices) ++seen[v];
  }
  for (int v = 0; v < n; ++v) EXPECT_EQ(seen[v], 2) << v;
}

TEST(GridTopology, CountsOfEveryType) {
  struct Case {
    const char* surface;
    GridType type;
    int edges, quads, interior, boundary, corners, lines;
  };
  // 5 × 4 grids.
  const Case cases[] = {
      {"plane", GridType::kOpen, 4 * 4 + 5 * 3, 4 * 3, 3 * 2, 2 * (3 + 2), 4, 4 + 5},
      {"cylinder", GridType::kClosedU, 5 * 4 + 5 * 3, 5 * 3, 5 * 2, 2 * 5, 0, 4 + 5},
      {"torus", GridType::kClosedBoth, 5 * 4 + 5 * 4, 5 * 4, 20, 0, 0, 4 + 5},
      // Klein bottle: σ(j) = (4 − j) mod 4 pairs rows 1 and 3.
      {"klein_bottle", GridType::kClosedBoth, 5 * 4 + 5 * 4, 5 * 4, 20, 0, 0, 3 + 5},
      // Möbius: v open, σ(j) = 3 − j pairs rows 0, 3 and 1, 2.
      {"klein_bottle", GridType::kClosedU, 5 * 4 + 5 * 3, 5 * 3, 10, 10, 0, 2 + 5},
  };
  for (const Case& c : cases) {
    const Surface s = MakeSurface(c.surface);
    const Grid g = MakeUniformGrid(s, 5, 4, c.type);
    SCOPED_TRACE(std::string(c.surface) + " " + GridTypeName(c.type));
    EXPECT_EQ(static_cast<int>(GridEdges(g).size()), c.edges);
    EXPECT_EQ(static_cast<int>(GridQuads(g).size()), c.quads);
    int roles[3] = {0, 0, 0};
    for (int v = 0; v < g.NumVertices(); ++v) ++roles[static_cast<int>(Role(g, v))];
    EXPECT_EQ(roles[0], c.interior);
    EXPECT_EQ(roles[1], c.boundary);
    EXPECT_EQ(roles[2], c.corners);
    EXPECT_EQ(static_cast<int>(GridLines(g).size()), c.lines);
    ExpectConsistentTopology(g);
  }
}

TEST(GridTopology, FlippingSeamJoinsMirroredRows) {
  // On the Klein bottle the u-seam joins (n_u − 1, j) to (0, σ(j)), and both
  // are the same surface point one grid step apart: the closing edge is as
  // long as its neighbours.
  const Surface s = MakeSurface("klein_bottle");
  const Grid g = MakeUniformGrid(s, 12, 8, GridType::kClosedBoth);
  EXPECT_TRUE(g.flip);
  for (int j = 0; j < 8; ++j) {
    const int last = g.Index(11, j);
    const int across = Neighbours(g, last).l1;
    EXPECT_EQ(across, g.Index(0, (8 - j) % 8));
    // x(u + P, v) = x(u, −v): the vertex across the seam is x(2π, v_j).
    EXPECT_LT((s.Point(g.uv[across]) - s.Point(Uv(2 * M_PI, g.uv[last][1]))).norm(), 1e-12);
  }
  // Rows j and σ(j) form one closed u-line of 24 vertices (j ≠ 0, 4).
  int long_lines = 0;
  for (const GridLine& line : GridLines(g)) {
    EXPECT_TRUE(line.closed);
    long_lines += line.vertices.size() == 24;
  }
  EXPECT_EQ(long_lines, 3);
}

// ---------------------------------------------------------------- measures

TEST(GridQuality, AnalyticPlaneGrids) {
  const Surface plane = MakeSurface("plane", {{"a", 40}, {"b", 40}});
  // Square: all zero.
  GridQuality q = MeasureGrid(GridOf(6, 5, false, false, [](int i, int j) { return Uv(i, j); }), plane);
  EXPECT_EQ(q.crossings, 4 * 3);
  EXPECT_EQ(q.quads, 5 * 4);
  for (const QualityMeasures& m : {q.spline, q.discrete}) {
    EXPECT_NEAR(m.mdo, 0, kTolerance);
    EXPECT_NEAR(m.ado, 0, kTolerance);
    EXPECT_NEAR(m.mde, 0, kTolerance);
    EXPECT_NEAR(m.ade, 0, kTolerance);
  }
  // Rectangles 1 × 2.5: MDE = ADE = 150%, still orthogonal.
  q = MeasureGrid(GridOf(6, 5, false, false, [](int i, int j) { return Uv(i, 2.5 * j); }), plane);
  for (const QualityMeasures& m : {q.spline, q.discrete}) {
    EXPECT_NEAR(m.mdo, 0, kTolerance);
    EXPECT_NEAR(m.mde, 150, kTolerance);
    EXPECT_NEAR(m.ade, 150, kTolerance);
  }
  // Rhombi with 60° angles: |90° − θ| = 30° at every crossing, equal sides.
  q = MeasureGrid(GridOf(6, 5, false, false,
                         [](int i, int j) { return Uv(10 + i + 0.5 * j, 10 + std::sqrt(0.75) * j); }),
                  plane);
  for (const QualityMeasures& m : {q.spline, q.discrete}) {
    EXPECT_NEAR(m.mdo, 30, kTolerance);
    EXPECT_NEAR(m.ado, 30, kTolerance);
    EXPECT_NEAR(m.mde, 0, kTolerance);
  }
  // One interior vertex moved: MDO picks it, ADO averages it.
  q = MeasureGrid(GridOf(3, 3, false, false,
                         [](int i, int j) { return i == 1 && j == 1 ? Uv(1.2, 1) : Uv(i, j); }),
                  plane);
  EXPECT_EQ(q.crossings, 1);
  // Discrete: the largest angle at (1.2, 1) is between (−1.2, 0) and (−0.2, 1).
  const double largest = std::atan2(1.0, -0.2) * 180 / M_PI;
  EXPECT_NEAR(q.discrete.mdo, largest - 90, kTolerance);
}

TEST(GridQuality, CylinderSplinesFollowTheCircles) {
  // 24 × 6 grid closed in u on a cylinder of radius 1, row spacing = the
  // chord 2 sin(π/24): the quads are squares in the chords (discrete MDE 0)
  // and the periodic splines follow the circles, whose tangents are
  // horizontal (spline MDO 0) and whose arcs exceed the chords by
  // θ / (2 sin(θ/2)), θ = 2π/24 (spline MDE 0.2859%).
  const Surface cylinder = MakeSurface("cylinder", {{"R", 1}, {"H", 4}});
  const double theta = 2 * M_PI / 24, chord = 2 * std::sin(theta / 2);
  const Grid g = GridOf(24, 6, true, false, [&](int i, int j) { return Uv(theta * i, 1 + chord * j); });
  const GridQuality q = MeasureGrid(g, cylinder);
  EXPECT_NEAR(q.spline.mdo, 0, kTolerance);
  EXPECT_NEAR(q.discrete.mdo, 0, kTolerance);
  EXPECT_NEAR(q.discrete.mde, 0, kTolerance);
  EXPECT_NEAR(q.spline.mde, 100 * (theta / chord - 1), 1e-3);  // spline error O(θ⁴)
  EXPECT_NEAR(q.spline.ade, 100 * (theta / chord - 1), 1e-3);
  EXPECT_EQ(q.crossings, 24 * 4);
}

// ------------------------------------------------------- meshes and files

// A skewed grid of every type, a little way into the force method.
std::vector<std::pair<Grid, Surface>> SampleGrids() {
  std::vector<std::pair<Grid, Surface>> out;
  ForceDirectedOptions few;
  few.max_iterations = 20;
  const auto add = [&](const char* name, int nu, int nv, GridType type) {
    const Surface s = MakeSurface(name);
    out.push_back({RunForceDirected(s, MakeUniformGrid(s, nu, nv, type), few).grid, s});
  };
  add("function_graph", 9, 7, GridType::kOpen);
  add("tower", 12, 8, GridType::kClosedU);
  // The torus's uniform grid is its (orthogonal) curvature-line net: jitter it.
  const Surface torus = MakeSurface("torus");
  Grid g = MakeUniformGrid(torus, 10, 6, GridType::kClosedBoth);
  for (int v = 0; v < g.NumVertices(); ++v) g.uv[v] += 0.08 * Uv(std::sin(7.0 * v), std::cos(5.0 * v));
  out.push_back({g, torus});
  return out;
}

TEST(GridMesh, MeshMeasuresEqualGridMeasures) {
  for (const auto& [grid, surface] : SampleGrids()) {
    SCOPED_TRACE(surface.KindName());
    int omitted = -1;
    const Mesh mesh = GridToMesh(grid, surface, &omitted);
    EXPECT_EQ(omitted, 0);
    EXPECT_EQ(static_cast<int>(mesh.number_of_faces()), static_cast<int>(GridQuads(grid).size()));
    const GridQuality a = MeasureGrid(grid, surface), b = MeasureQuadGridMesh(mesh);
    EXPECT_EQ(a.crossings, b.crossings);
    EXPECT_EQ(a.quads, b.quads);
    for (auto [x, y] : {std::pair{a.spline, b.spline}, std::pair{a.discrete, b.discrete}}) {
      EXPECT_NEAR(x.mdo, y.mdo, kTolerance);
      EXPECT_NEAR(x.ado, y.ado, kTolerance);
      EXPECT_NEAR(x.mde, y.mde, kTolerance);
      EXPECT_NEAR(x.ade, y.ade, kTolerance);
    }
    EXPECT_GT(a.spline.mdo, 0.1);  // a skewed grid, not a trivial zero
    const nlohmann::json j = GridQualityToJson(b);
    EXPECT_DOUBLE_EQ(j["mdo"].get<double>(), b.spline.mdo);
    EXPECT_DOUBLE_EQ(j["mde"].get<double>(), b.discrete.mde);
    EXPECT_DOUBLE_EQ(j["spline"]["mde"].get<double>(), b.spline.mde);
  }
}

TEST(GridMesh, KleinBottleSeamIsLeftOutOfTheMesh) {
  const Surface s = MakeSurface("klein_bottle");
  const Grid g = MakeUniformGrid(s, 12, 8, GridType::kClosedBoth);
  int omitted = 0;
  const Mesh mesh = GridToMesh(g, s, &omitted);
  EXPECT_EQ(omitted, 8);
  EXPECT_EQ(mesh.number_of_faces(), 12u * 8 - 8);
  EXPECT_EQ(mesh.number_of_vertices(), 96u);
  EXPECT_TRUE(mesh.is_valid(false));
}

class GridFiles : public ScratchDirTest {};

TEST_F(GridFiles, PlyAndObjKeepTheParameters) {
  const auto samples = SampleGrids();
  const auto& [grid, surface] = samples[1];
  const Mesh mesh = GridToMesh(grid, surface);
  for (bool ascii : {false, true}) {
    const std::string path = Path(ascii ? "grid_ascii.ply" : "grid.ply");
    WriteGridMesh(path, mesh, grid.uv, ascii);
    Mesh back;
    std::ifstream in(path, std::ios::binary);
    ASSERT_TRUE(CGAL::IO::read_PLY(in, back));
    ASSERT_EQ(back.number_of_vertices(), mesh.number_of_vertices());
    auto [u, has_u] = back.property_map<VertexIndex, double>("v:u");
    auto [v, has_v] = back.property_map<VertexIndex, double>("v:v");
    ASSERT_TRUE(has_u && has_v);
    for (VertexIndex w : back.vertices()) {
      EXPECT_EQ(u[w], grid.uv[w.idx()][0]);
      EXPECT_EQ(v[w], grid.uv[w.idx()][1]);
      EXPECT_EQ(back.point(w), mesh.point(w));
    }
  }
  const std::string obj = Path("grid.obj");
  WriteGridMesh(obj, mesh, grid.uv);
  std::ifstream in(obj);
  std::string line;
  int vertices = 0, uvs = 0, faces = 0;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "v") ++vertices;
    if (tag == "f") ++faces;
    if (tag == "vt") {
      double a, b;
      ls >> a >> b;
      EXPECT_EQ(a, grid.uv[uvs][0]);
      EXPECT_EQ(b, grid.uv[uvs][1]);
      ++uvs;
    }
  }
  EXPECT_EQ(vertices, grid.NumVertices());
  EXPECT_EQ(uvs, grid.NumVertices());
  EXPECT_EQ(faces, static_cast<int>(mesh.number_of_faces()));
  EXPECT_THROW(WriteGridMesh(Path("grid.off"), mesh, grid.uv), InputError);
}

// ------------------------------------------------------------ force method

// Every vertex of `grid` is on `surface`: its position (the mesh point made
// from its (u, v)) has distance ≤ kOnSurface·size from the surface, found
// independently by the closest-parameter search (open directions free: the
// force method may carry an open grid beyond the domain's bounds).
void ExpectOnSurface(const Grid& grid, const Surface& surface) {
  const Mesh mesh = GridToMesh(grid, surface);
  double size = 0.0;
  for (VertexIndex v : mesh.vertices()) {
    size = std::max(size, (mesh.point(v) - mesh.point(VertexIndex(0))).squared_length());
  }
  size = std::sqrt(size);
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    const Eigen::Vector3d x(p.x(), p.y(), p.z());
    const Uv foot = surface.ClosestParameter(x, grid.uv[v.idx()], /*keep_in_domain=*/false);
    EXPECT_LE((surface.Point(foot) - x).norm(), kOnSurface * size) << v.idx();
  }
}

TEST(ForceDirected, SquarePlaneGridStaysPut) {
  const Surface plane = MakeSurface("plane");
  const Grid g = MakeUniformGrid(plane, 11, 11, GridType::kOpen);  // spacing 1
  const ForceDirectedResult r = RunForceDirected(plane, g, {});
  EXPECT_EQ(r.stop, ForceStop::kStalled);
  EXPECT_LT(r.after.spline.mdo, kStaysPut);
  EXPECT_LT(r.after.spline.ado, kStaysPut);
  EXPECT_LT(r.after.discrete.mdo, kStaysPut);
  for (int v = 0; v < g.NumVertices(); ++v) EXPECT_LT((r.grid.uv[v] - g.uv[v]).norm(), 1e-12);
}

TEST(ForceDirected, SkewedCylinderGridClosedInUBecomesSquare) {
  // 24 × 9, closed in u, each row turned by 0.6 grid steps against the one
  // below (the v-lines are helices 28° off vertical), rows 0.3 apart. The
  // square grid of side L = 2 sin(π/24) (the chord of the closed rows) is the
  // only one that is orthogonal and equilateral [issue 12: MDO < 0.01°,
  // MDE < 0.1%].
  const Surface cylinder = MakeSurface("cylinder", {{"R", 1}, {"H", 6}});
  const double h = 2 * M_PI / 24;
  const Grid g = GridOf(24, 9, true, false, [&](int i, int j) { return Uv(h * (i + 0.6 * j), 2 + 0.3 * j); });
  ForceDirectedOptions o;
  o.ideal_length = 2 * std::sin(M_PI / 24);
  o.stop_mdo = 0.005;
  o.stop_mde = 0.05;
  o.max_iterations = 20000;
  const ForceDirectedResult r = RunForceDirected(cylinder, g, o);
  EXPECT_GT(r.before.Table1().mdo, 25.0);
  EXPECT_EQ(r.stop, ForceStop::kThresholds);
  EXPECT_LT(r.after.Table1().mdo, 0.01);
  EXPECT_LT(r.after.Table1().ado, 0.01);
  EXPECT_LT(r.after.Table1().mde, 0.1);
  EXPECT_LT(r.after.Table1().ade, 0.1);
  ExpectOnSurface(r.grid, cylinder);
}

TEST(ForceDirected, BoundaryForceMakesARhombicPlaneGridOrthogonal) {
  // Rhombi of side 1 and angle 60°: straight lines of equal edges, a fixed
  // point of eq. 1 and of the edge-length forces (L = 1). Only eq. 2 at the
  // boundary, sliding the boundary vertices until the transversal edges are
  // orthogonal to it, turns it into the square grid.
  const Surface plane = MakeSurface("plane", {{"a", 60}, {"b", 60}});
  const Grid g = GridOf(9, 9, false, false, [](int i, int j) {
    return Uv(25 + i + 0.5 * j, 25 + std::sqrt(0.75) * j);
  });
  ForceDirectedOptions o;
  o.ideal_length = 1.0;
  o.stop_mdo = 0.01;
  o.max_iterations = 20000;
  const ForceDirectedResult r = RunForceDirected(plane, g, o);
  EXPECT_NEAR(r.before.Table1().mdo, 30.0, kTolerance);
  EXPECT_LT(r.after.Table1().mdo, 0.01);
  EXPECT_LT(r.after.Table1().mde, 0.1);
}

TEST(ForceDirected, ThresholdsStopTheRun) {
  const Surface s = MakeSurface("function_graph");
  const Grid g = MakeUniformGrid(s, 12, 12, GridType::kOpen);
  ForceDirectedOptions o;
  o.stop_ado = 2.0;  // degrees
  o.history_stride = 5;
  const ForceDirectedResult r = RunForceDirected(s, g, o);
  EXPECT_GT(r.before.Table1().ado, 2.0);
  EXPECT_EQ(r.stop, ForceStop::kThresholds);
  EXPECT_LE(r.after.Table1().ado, 2.0);
  EXPECT_EQ(r.iterations % 5, 0);
  // The previous history entry had not reached it.
  ASSERT_GE(r.history.size(), 2u);
  EXPECT_GT(r.history[r.history.size() - 2].quality.Table1().ado, 2.0);
  EXPECT_EQ(r.history.front().iteration, 0);
  EXPECT_EQ(r.history.back().iteration, r.iterations);
}

struct PaperRow {
  double mdo, ado, mde, ade;
};

struct SceneCase {
  const char* surface;
  GridType type;
  int nu, nv, iterations;
  bool paper_after;  // bound by the paper's after row (else its before row)
  PaperRow paper;    // Table 1 of the paper
};

// Table 1 [force-directed grids paper]: Klein Bottle C2 before 33.78°, 11.75°,
// 404%, 90% (after 5.43°, 0.48°, 152%, 28%); Tower C1 after 1.43°, 0.28°, 15%,
// 9%; Tower (Rings) C0 5.84°, 1.73°, 8%, 4%; Bridge C0 5.37°, 2.28°, 12%, 4%;
// Function Graph C0 4.30°, 1.09°, 9%, 3%. Our grids are smaller than the
// benchmark's (test time); at this size the Klein bottle stays above the
// paper's after row (benchmarks/grids_table1 reaches it on MDO and MDE at
// 60 × 24), so it is bounded by the paper's before row and must improve on
// every measure.
const SceneCase kScenes[] = {
    {"klein_bottle", GridType::kClosedBoth, 40, 16, 5000, false, {33.78, 11.75, 404, 90}},
    {"tower", GridType::kClosedU, 24, 25, 12000, true, {1.43, 0.28, 15, 9}},
    {"tower_rings", GridType::kOpen, 10, 20, 5000, true, {5.84, 1.73, 8, 4}},
    {"dupin_bridge", GridType::kOpen, 20, 10, 5000, true, {5.37, 2.28, 12, 4}},
    {"function_graph", GridType::kOpen, 15, 15, 5000, true, {4.30, 1.09, 9, 3}},
};

void PrintTo(const SceneCase& c, std::ostream* os) { *os << c.surface; }

class Table1Scene : public ::testing::TestWithParam<SceneCase> {};

TEST_P(Table1Scene, ForceMethodImprovesTheGrid) {
  const SceneCase& c = GetParam();
  const Surface s = MakeSurface(c.surface);
  const Grid g = MakeUniformGrid(s, c.nu, c.nv, c.type);
  ForceDirectedOptions o;
  o.max_iterations = c.iterations;
  const ForceDirectedResult r = RunForceDirected(s, g, o);
  const QualityMeasures before = r.before.Table1(), after = r.after.Table1();
  // A skewed, unequal input.
  EXPECT_GT(before.mdo, 10.0);
  EXPECT_GT(before.mde, 10.0);
  // Better on every measure.
  EXPECT_LT(after.mdo, before.mdo);
  EXPECT_LT(after.ado, before.ado);
  EXPECT_LT(after.mde, before.mde);
  EXPECT_LT(after.ade, before.ade);
  // The paper's bound.
  EXPECT_LE(after.mdo, c.paper.mdo);
  EXPECT_LE(after.ado, c.paper.ado);
  EXPECT_LE(after.mde, c.paper.mde);
  EXPECT_LE(after.ade, c.paper.ade);
  ExpectOnSurface(r.grid, s);
}

INSTANTIATE_TEST_SUITE_P(ForceDirected, Table1Scene, ::testing::ValuesIn(kScenes),
                         [](const ::testing::TestParamInfo<SceneCase>& info) {
                           return std::string(info.param.surface);
                         });

}  // namespace
}  // namespace archgeo
