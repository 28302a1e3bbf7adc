// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Base complex → charts → parameterisation → quads (spectral/base_complex_charts.h,
// problem base_complex_quads): a sphere from an octahedron and a torus from a
// 4 × 4 quad complex give no flipped parameter triangle, a closed conforming
// quad mesh on the input surface whose irregular vertices are exactly the
// base complex's (the octahedron's six valence-4 nodes stay regular, its
// eight triangles' centres have valence 3); bad base complexes exit 2 naming
// the file and the element.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "geometry/reference.h"
#include "io/io.h"
#include "scratch_dir.h"
#include "shell.h"
#include "spectral/base_complex_charts.h"
#include "tests/closed_meshes.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using V3 = Eigen::Vector3d;
using Triangles = std::vector<std::array<int, 3>>;

constexpr double kOnSurface = 1e-9;    // of the diagonal
constexpr double kSameSample = 1e-12;  // of the diagonal

const std::vector<std::vector<int>> kOctahedronFaces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                                        {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};

// OctahedronSphere(levels) into p, t and the octahedron on its first six vertices.
BaseComplex OctahedronOnSphere(int levels, std::vector<V3>& p, Triangles& t) {
  OctahedronSphere(levels, p, t);
  BaseComplex base;
  base.nodes = {0, 1, 2, 3, 4, 5};
  base.faces = kOctahedronFaces;
  return base;
}

// The 4 × 4 quad complex on GridTorus(u, v): nodes at every u/4-th and v/4-th vertex.
BaseComplex TorusComplex(int u, int v) {
  BaseComplex b;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) b.nodes.push_back(j * (v / 4) * u + i * (u / 4));
  }
  auto n = [](int i, int j) { return (j % 4) * 4 + i % 4; };
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) b.faces.push_back({n(i, j), n(i + 1, j), n(i + 1, j + 1), n(i, j + 1)});
  }
  return b;
}

Mesh ToMesh(const std::vector<V3>& p, const Triangles& t) {
  Mesh m;
  for (const V3& x : p) m.add_vertex(Point(x.x(), x.y(), x.z()));
  for (const auto& f : t) m.add_face(VertexIndex(f[0]), VertexIndex(f[1]), VertexIndex(f[2]));
  return m;
}

double Diagonal(const std::vector<V3>& p) {
  V3 lo = p[0], hi = p[0];
  for (const V3& x : p) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return (hi - lo).norm();
}

// Largest distance of the output vertices to the input surface (AABB closest point).
double OffSurface(const std::vector<V3>& p, const Triangles& t, const QuadExtraction& q) {
  const ReferenceSurface surface(ToMesh(p, t));
  double worst = 0;
  for (const V3& x : q.points) {
    const Vec3 y = surface.Closest(Vec3{x.x(), x.y(), x.z()}).point;
    worst = std::max(worst, (V3(y[0], y[1], y[2]) - x).norm());
  }
  return worst;
}

// V − E + F of the output quads.
int QuadEuler(const QuadExtraction& q) {
  std::set<std::pair<int, int>> edges;
  for (const auto& f : q.quads) {
    for (int k = 0; k < 4; ++k) edges.insert({std::min(f[k], f[(k + 1) % 4]), std::max(f[k], f[(k + 1) % 4])});
  }
  return int(q.points.size()) - int(edges.size()) + int(q.quads.size());
}

class BaseComplexSphere : public ::testing::TestWithParam<ChartWeights> {};

TEST_P(BaseComplexSphere, OctahedronGivesEightValenceThreeCentresAndRegularNodes) {
  std::vector<V3> p;
  Triangles t;
  const BaseComplex base = OctahedronOnSphere(4, p, t);  // 2048 triangles
  const ChartQuadsResult r = ChartQuads(p, t, base, 8, 0, GetParam());
  ASSERT_EQ(r.layout.charts.size(), 8u);
  for (const Chart& c : r.layout.charts) {
    EXPECT_EQ(c.euler, 1);
    EXPECT_EQ(c.boundary_loops, 1);
  }
  size_t triangles = 0;
  for (const Chart& c : r.layout.charts) triangles += c.triangles.size();
  EXPECT_EQ(triangles, t.size());  // every triangle in exactly one chart
  EXPECT_EQ(r.flipped, 0);
  EXPECT_GT(r.min_area, 0);
  // 8 charts × 3 quads × (n/2)²; a closed sphere: V − E + F = 2.
  EXPECT_EQ(r.quads.quads.size(), 8u * 3 * 16);
  EXPECT_EQ(QuadEuler(r.quads), 2);
  EXPECT_EQ(r.boundary_edges, 0);
  EXPECT_EQ(r.non_manifold_edges, 0);
  EXPECT_EQ(r.t_junctions, 0);
  // Irregular: exactly the eight triangle centres, of valence 3; the six
  // nodes keep valence 4.
  ASSERT_EQ(r.irregular.size(), 8u);
  EXPECT_EQ(r.irregular, r.expected_irregular);
  for (int c : r.quads.centre_vertex) {
    ASSERT_GE(c, 0);
    EXPECT_EQ(r.valence[c], 3);
  }
  for (int v : r.quads.node_vertex) EXPECT_EQ(r.valence[v], 4);
  const double diagonal = Diagonal(p);
  EXPECT_LE(r.quads.shared_edge_mismatch, kSameSample * diagonal);
  EXPECT_EQ(r.quads.unlocated, 0);
  EXPECT_LE(OffSurface(p, t, r.quads), kOnSurface * diagonal);
}

// Triangle output (charts.output: triangles; thesis §4.1.4 for a triangle
// complex, §9.2.4 remeshing using subdivision): each chart the whole lattice,
// n² triangles. At n = 4 the octahedron gives the connectivity of two Loop
// steps — 66 vertices, 128 triangles, the six nodes of valence 4 the only
// irregular ones — with every vertex on the input surface.
TEST(BaseComplexTriangles, OctahedronLatticeHasTheConnectivityOfTwoLoopSteps) {
  std::vector<V3> p;
  Triangles t;
  const BaseComplex base = OctahedronOnSphere(4, p, t);
  const ChartQuadsResult r = ChartQuads(p, t, base, 4, 0, ChartWeights::kCotangent, ChartFill::kTriangles);
  EXPECT_TRUE(r.quads.quads.empty());
  EXPECT_EQ(r.quads.triangles.size(), 128u);
  EXPECT_EQ(r.quads.points.size(), 66u);
  EXPECT_EQ(r.boundary_edges, 0);
  EXPECT_EQ(r.non_manifold_edges, 0);
  EXPECT_EQ(r.t_junctions, 0);
  ASSERT_EQ(r.irregular.size(), 6u);
  EXPECT_EQ(r.irregular, r.expected_irregular);
  for (int v : r.quads.node_vertex) EXPECT_EQ(r.valence[v], 4);
  for (size_t v = 0; v < r.valence.size(); ++v) {
    if (std::find(r.irregular.begin(), r.irregular.end(), int(v)) == r.irregular.end()) {
      EXPECT_EQ(r.valence[v], 6) << v;
    }
  }
  const double diagonal = Diagonal(p);
  EXPECT_LE(r.quads.shared_edge_mismatch, kSameSample * diagonal);
  EXPECT_EQ(r.quads.unlocated, 0);
  EXPECT_LE(OffSurface(p, t, r.quads), kOnSurface * diagonal);
  // An odd n is fine (no triangle is split).
  EXPECT_EQ(ChartQuads(p, t, base, 3, 0, ChartWeights::kCotangent, ChartFill::kTriangles).quads.triangles.size(), 72u);
}

INSTANTIATE_TEST_SUITE_P(Weights, BaseComplexSphere,
                         ::testing::Values(ChartWeights::kCotangent, ChartWeights::kMeanValue),
                         [](const auto& info) {
                           return std::string(info.param == ChartWeights::kCotangent ? "Cotan"
                                                                                     : "MeanValue");
                         });

// charts.weights is used: cotangent and mean-value weights place the
// interior of a chart differently (the boundary, by arc length, alike).
TEST(BaseComplexCharts, WeightsChangeTheInterior) {
  std::vector<V3> p;
  Triangles t;
  const BaseComplex base = OctahedronOnSphere(3, p, t);
  const ChartLayout layout = BuildChartLayout(p, t, base);
  const ChartMap cotan = ParameteriseChart(p, t, layout, 0, ChartWeights::kCotangent);
  const ChartMap mean = ParameteriseChart(p, t, layout, 0, ChartWeights::kMeanValue);
  ASSERT_EQ(cotan.uv.size(), mean.uv.size());
  const size_t border = layout.charts[0].boundary.size();
  double boundary = 0, interior = 0;
  for (size_t i = 0; i < cotan.uv.size(); ++i) {
    (i < border ? boundary : interior) =
        std::max(i < border ? boundary : interior, (cotan.uv[i] - mean.uv[i]).norm());
  }
  EXPECT_EQ(boundary, 0.0);
  EXPECT_GT(interior, 1e-3);
}

TEST(BaseComplexTorus, FourByFourQuadsGiveARegularClosedQuadMesh) {
  std::vector<V3> p;
  Triangles t;
  GridTorus(48, 24, p, t);
  const ChartQuadsResult r = ChartQuads(p, t, TorusComplex(48, 24), 6, 0, ChartWeights::kCotangent);
  ASSERT_EQ(r.layout.charts.size(), 16u);
  EXPECT_EQ(r.flipped, 0);
  EXPECT_EQ(r.quads.quads.size(), 16u * 36);
  EXPECT_EQ(r.quads.points.size(), 16u * 36);  // a torus: V = F
  EXPECT_EQ(QuadEuler(r.quads), 0);
  EXPECT_EQ(r.boundary_edges, 0);
  EXPECT_EQ(r.t_junctions, 0);
  EXPECT_TRUE(r.irregular.empty());
  EXPECT_TRUE(r.expected_irregular.empty());
  for (int v : r.valence) EXPECT_EQ(v, 4);
  const double diagonal = Diagonal(p);
  EXPECT_LE(r.quads.shared_edge_mismatch, kSameSample * diagonal);
  EXPECT_LE(OffSurface(p, t, r.quads), kOnSurface * diagonal);
}

// The boundary is placed by arc length: a node's side samples split its
// path into n equal lengths, whichever chart maps them.
TEST(BaseComplexTorus, SideSamplesAreAtEqualArcLength) {
  std::vector<V3> p;
  Triangles t;
  GridTorus(48, 24, p, t);
  const int n = 6;
  const ChartQuadsResult r = ChartQuads(p, t, TorusComplex(48, 24), n, 0, ChartWeights::kMeanValue);
  const BaseEdgePath& e = r.layout.edges[0];
  // Samples of edge 0 are output vertices 16 … 16 + n − 2 (after the 16 nodes).
  for (int i = 1; i < n; ++i) {
    const V3& s = r.quads.points[size_t(16 + i - 1)];
    double at = 0, found = -1;
    for (size_t k = 1; k < e.path.size() && found < 0; ++k) {
      const V3 a = p[e.path[k - 1]], b = p[e.path[k]];
      const double l = (b - a).norm(), along = (s - a).dot(b - a) / l;
      if (along >= -1e-12 && along <= l + 1e-12 && (a + along / l * (b - a) - s).norm() < 1e-12) {
        found = at + along;
      }
      at += l;
    }
    EXPECT_NEAR(found, e.length * i / n, 1e-12 * e.length) << "sample " << i;
  }
}

TEST(BaseComplexCharts, TetrahedronOnATorusIsNotADisc) {
  std::vector<V3> p;
  Triangles t;
  GridTorus(48, 24, p, t);
  BaseComplex base;
  base.nodes = {0, 12, 24, 36 + 12 * 48};
  base.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  try {
    ChartQuads(p, t, base, 4, 0, ChartWeights::kCotangent);
    FAIL() << "a genus-0 complex on a torus was accepted";
  } catch (const BaseComplexError& e) {
    EXPECT_EQ(e.element().rfind("base face ", 0), 0u) << e.what();
  }
}

TEST(BaseComplexCharts, OddSamplesWithTrianglesAreRefused) {
  std::vector<V3> p;
  Triangles t;
  const BaseComplex base = OctahedronOnSphere(2, p, t);
  EXPECT_THROW(ChartQuads(p, t, base, 5, 0, ChartWeights::kCotangent), std::invalid_argument);
  // From an edge length: the quarter great circle over 0.2 rounds to 8 (even).
  EXPECT_EQ(ChartQuads(p, t, base, 0, 0.2, ChartWeights::kCotangent).n, 8);
}

// End to end: `archgeo solve` with the base complex as OBJ (snapped) and as ids.
class BaseComplexQuads_ : public ScratchDirTest {
 protected:
  std::string WriteSphere(const std::string& name) {
    std::vector<V3> p;
    Triangles t;
    OctahedronSphere(3, p, t);
    WriteMesh(Path(name), ToMesh(p, t));
    return Path(name);
  }
  std::string WriteTorus(const std::string& name) {
    std::vector<V3> p;
    Triangles t;
    GridTorus(48, 24, p, t);
    WriteMesh(Path(name), ToMesh(p, t));
    return Path(name);
  }
  std::string WriteTorusIds(const std::string& name) {
    const BaseComplex b = TorusComplex(48, 24);
    std::string text;
    for (int v : b.nodes) text += "v " + std::to_string(v) + "\n";
    for (const auto& f : b.faces) {
      text += "f";
      for (int v : f) text += " " + std::to_string(v + 1);
      text += "\n";
    }
    return WriteFile(name, text);
  }
  std::string WriteOctahedron(const std::string& name, double scale) {
    std::ostringstream s;
    const std::vector<V3> v = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (size_t i = 0; i < v.size(); ++i) {
      const double k = i == 3 ? scale : 1.0;  // base vertex 3 moved by `scale`
      s << "v " << k * v[i].x() << " " << k * v[i].y() << " " << k * v[i].z() << "\n";
    }
    for (const auto& f : kOctahedronFaces) s << "f " << f[0] + 1 << " " << f[1] + 1 << " " << f[2] + 1 << "\n";
    return WriteFile(name, s.str());
  }
  Outcome Solve(const std::string& sets) {
    return Shell(std::string(ARCHGEO_BINARY) + " solve " + ARCHGEO_SOURCE_DIR +
                 "/examples/base_complex_quads.yaml --quiet --set output.report=" + Path("r.json") +
                 " --set output.mesh=" + Path("out.obj") + " " + sets);
  }
  nlohmann::json Charts() {
    return nlohmann::json::parse(std::ifstream(Path("r.json"))).at("details").at("charts");
  }
};

TEST_F(BaseComplexQuads_, ExampleSphereFromOctahedron) {
  const Outcome o = Solve("");
  ASSERT_EQ(o.code, 0) << o.output;
  const nlohmann::json c = Charts();
  EXPECT_EQ(c.at("charts"), 8);
  EXPECT_EQ(c.at("n"), 8);
  EXPECT_EQ(c.at("flipped_parameter_triangles"), 0);
  EXPECT_EQ(c.at("output_quads"), 8 * 3 * 16);
  EXPECT_EQ(c.at("base_irregular_nodes"), 0);
  EXPECT_EQ(c.at("irregular_vertices"), 8);
  EXPECT_EQ(c.at("expected_irregular_vertices"), 8);
  EXPECT_TRUE(c.at("irregular_as_predicted").get<bool>());
  EXPECT_EQ(c.at("boundary_edges"), 0);
  EXPECT_EQ(c.at("t_junctions"), 0);
  EXPECT_LE(c.at("shared_edge_mismatch_relative").get<double>(), kSameSample);
  EXPECT_LE(c.at("surface_distance_max_relative").get<double>(), kOnSurface);
  const Mesh out = ReadMesh(Path("out.obj"));
  EXPECT_EQ(out.number_of_faces(), 8u * 3 * 16);
  for (FaceIndex f : out.faces()) EXPECT_EQ(out.degree(f), 4u);
}

// A vertex count the decimation cannot reach is a goal missed, not bad
// input: the unit sphere (examples/sphere.obj) stops at 8 base vertices
// when 4 are asked (no collapse left keeps the normals within bounds); the
// layout of those 8 is made and written, exit 4 naming the miss; asked 8,
// the same complex, exit 0; asked 3, the 8 reached are more than twice the
// count asked: refused (exit 2) naming them.
TEST_F(BaseComplexQuads_, AnUnreachableVertexCountChartsTheComplexReachedAndSaysSo) {
  const std::string sphere = std::string(ARCHGEO_SOURCE_DIR) + "/examples/sphere.obj";
  const Outcome o = Solve("--set mesh=" + sphere + " --set base_complex.mesh= --set base_complex.decimate=4");
  ASSERT_EQ(o.code, 4) << o.output;
  EXPECT_NE(o.output.find("decimated to 8 vertices, 4 asked"), std::string::npos) << o.output;
  const nlohmann::json r = nlohmann::json::parse(std::ifstream(Path("r.json")));
  EXPECT_NE(r.at("missed").get<std::string>().find("base_complex.decimate"), std::string::npos);
  EXPECT_FALSE(r.at("details").at("decimation").at("reached").get<bool>());
  EXPECT_EQ(r.at("details").at("decimation").at("vertices"), 8);
  EXPECT_TRUE(r.at("validity").at("valid").get<bool>());
  EXPECT_EQ(ReadMesh(Path("out.obj")).number_of_faces(), 12u * 3 * 16);
  const Outcome eight = Solve("--set mesh=" + sphere + " --set base_complex.mesh= --set base_complex.decimate=8");
  EXPECT_EQ(eight.code, 0) << eight.output;
  // Asked 3, the 8 reached are more than twice as many: refused, naming them.
  const Outcome three = Solve("--set mesh=" + sphere + " --set base_complex.mesh= --set base_complex.decimate=3");
  EXPECT_EQ(three.code, 2) << three.output;
  EXPECT_NE(three.output.find("base_complex.decimate of at least 8"), std::string::npos) << three.output;
}

TEST_F(BaseComplexQuads_, SphereWithMeanValueWeights) {
  const std::string sphere = WriteSphere("sphere.obj");
  const std::string base = WriteOctahedron("octahedron.obj", 1.0);
  const Outcome o = Solve("--set mesh=" + sphere + " --set base_complex.mesh=" + base +
                          " --set charts.n=6 --set charts.weights=mean_value");
  ASSERT_EQ(o.code, 0) << o.output;
  const nlohmann::json c = Charts();
  EXPECT_EQ(c.at("weights"), "mean_value");
  EXPECT_EQ(c.at("irregular_vertices"), 8);
  EXPECT_TRUE(c.at("irregular_as_predicted").get<bool>());
  EXPECT_EQ(c.at("output_quads"), 8 * 3 * 9);
  EXPECT_EQ(c.at("flipped_parameter_triangles"), 0);
  EXPECT_LE(c.at("surface_distance_max_relative").get<double>(), kOnSurface);
}

TEST_F(BaseComplexQuads_, TorusFromIds) {
  const std::string torus = WriteTorus("torus.obj");
  const Outcome o = Solve("--set mesh=" + torus + " --set \"base_complex.mesh=''\" --set base_complex.ids=" +
                          WriteTorusIds("torus.txt") + " --set charts.n=6");
  ASSERT_EQ(o.code, 0) << o.output;
  const nlohmann::json c = Charts();
  EXPECT_EQ(c.at("charts"), 16);
  EXPECT_EQ(c.at("output_quads"), 16 * 36);
  EXPECT_EQ(c.at("irregular_vertices"), 0);
  EXPECT_EQ(c.at("boundary_edges"), 0);
  EXPECT_EQ(c.at("t_junctions"), 0);
  EXPECT_EQ(c.at("flipped_parameter_triangles"), 0);
  EXPECT_LE(c.at("surface_distance_max_relative").get<double>(), kOnSurface);
}

TEST_F(BaseComplexQuads_, BaseVertexOffTheSurfaceExits2NamingFileAndVertex) {
  const std::string sphere = WriteSphere("sphere.obj");
  const std::string base = WriteOctahedron("octahedron.obj", 1.5);
  const Outcome o = Solve("--set mesh=" + sphere + " --set base_complex.mesh=" + base);
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find("octahedron.obj"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("base vertex 3"), std::string::npos) << o.output;
  // Within a looser tolerance it is snapped and accepted.
  EXPECT_EQ(Solve("--set mesh=" + sphere + " --set base_complex.mesh=" + base +
                  " --set base_complex.tolerance=0.2").code, 0);
}

TEST_F(BaseComplexQuads_, ChartNotADiscExits2NamingFileAndFace) {
  // A tetrahedron (genus 0) on a torus: a chart holds the handle.
  const std::string ids = WriteFile("tetrahedron.txt", "v 0\nv 12\nv 24\nv 612\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n");
  const Outcome o = Solve("--set mesh=" + WriteTorus("torus.obj") +
                          " --set \"base_complex.mesh=''\" --set base_complex.ids=" + ids);
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find("tetrahedron.txt"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("base face"), std::string::npos) << o.output;
}

TEST_F(BaseComplexQuads_, BadIdsLineExits2NamingFileAndLine) {
  const std::string ids = WriteFile("bad.txt", "v 0\nv 6\nv x\n");
  const Outcome o = Solve("--set \"base_complex.mesh=''\" --set base_complex.ids=" + ids);
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find("bad.txt:3"), std::string::npos) << o.output;
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
