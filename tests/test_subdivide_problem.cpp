// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// End to end: `archgeo solve` with problem `subdivide` [Gebreiter 2012, §9]
// (problems/declarations/subdivide.cpp): the example roof with perimeter and
// ridge curves, reverse subdivision of its output, the funnel meeting its
// column tangentially (§9.2.2), and the refusals of bad curve files and
// tangent surfaces (exit 2 naming file and element).
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/io.h"
#include "tests/scratch_dir.h"
#include "tests/shell.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

constexpr double kOnCurve = 1e-9;   // × diagonal, the figure
constexpr double kRecover = 1e-10;  // reverse subdivision of archgeo's own output

class Subdivide_ : public ScratchDirTest {
 protected:
  Outcome Solve(const std::string& sets) {
    return Shell(std::string(ARCHGEO_BINARY) + " solve " + ARCHGEO_SOURCE_DIR +
                 "/examples/subdivide_roof.yaml --quiet --set output.report=" + Path("r.json") +
                 " --set output.mesh=" + Path("out.obj") + " " + sets);
  }
  nlohmann::json Details() {
    return nlohmann::json::parse(std::ifstream(Path("r.json"))).at("details").at("subdivision");
  }
  static std::string Example(const std::string& name) { return std::string(ARCHGEO_SOURCE_DIR) + "/examples/" + name; }
};

// 6 × 6 quads, 24 perimeter edges, a ridge of 6 edges: after L levels
// 24·2^L + 6·2^L − 1 curve vertices (the ridge's ends are on the perimeter).
TEST_F(Subdivide_, ExampleRoofKeepsPerimeterAndRidgeOnTheirCurves) {
  const Outcome o = Solve("");
  ASSERT_EQ(o.code, 0) << o.output;
  const nlohmann::json d = Details();
  const int levels = d.at("levels");
  EXPECT_EQ(levels, 3);
  EXPECT_LE(d.at("mean_edge_length").get<double>(), 0.6);
  EXPECT_EQ(d.at("curve_vertices"), 30 * (1 << levels) - 1);
  EXPECT_EQ(d.at("corners"), 2);
  EXPECT_LE(d.at("curve_distance_max_relative").get<double>(), kOnCurve);
  EXPECT_EQ(d.at("output").at("faces"), 36 * (1 << (2 * levels)));
  // Four levels of Loop on the triangulated roof: the same figure.
  const Outcome loop = Solve("--set subdivision.scheme=loop --set subdivision.target_edge_length=0 "
                             "--set subdivision.levels=4 --set subdivision.limit=false");
  EXPECT_EQ(loop.code, 2) << loop.output;  // quads: Loop needs triangles
  EXPECT_NE(loop.output.find("triangle mesh"), std::string::npos) << loop.output;
}

TEST_F(Subdivide_, ReverseRecoversTheCoarseRoof) {
  ASSERT_EQ(Solve("--set subdivision.boundary=standard --set \"subdivision.boundary_curves=''\" "
                  "--set \"subdivision.crease_curves=''\" --set subdivision.target_edge_length=0 "
                  "--set subdivision.levels=2 --set subdivision.limit=false").code, 0);
  const std::string fine = Path("fine.obj");
  std::filesystem::rename(Path("out.obj"), fine);
  const Outcome o = Solve("--set mesh=" + fine + " --set subdivision.target_edge_length=0 --set subdivision.levels=0 "
                          "--set subdivision.limit=false --set subdivision.boundary=standard "
                          "--set \"subdivision.boundary_curves=''\" --set \"subdivision.crease_curves=''\" "
                          "--set subdivision.reverse=2");
  ASSERT_EQ(o.code, 0) << o.output;
  const nlohmann::json d = Details();
  ASSERT_EQ(d.at("reverse").size(), 2u);
  for (const auto& level : d.at("reverse")) {
    EXPECT_LE(level.at("residual_max_relative").get<double>(), kRecover);
    EXPECT_TRUE(level.at("unique").get<bool>());
  }
  const Mesh coarse = ReadMesh(Example("subdivide_roof.obj"));
  const Mesh back = ReadMesh(Path("out.obj"));
  ASSERT_EQ(back.number_of_vertices(), coarse.number_of_vertices());
  ASSERT_EQ(back.number_of_faces(), coarse.number_of_faces());
  double worst = 0;
  for (VertexIndex v : coarse.vertices()) {
    worst = std::max(worst, std::sqrt(CGAL::squared_distance(coarse.point(v), back.point(v))));
  }
  EXPECT_LE(worst, kRecover * 25);  // diagonal ≈ 24.6
}

// The curve-constrained roof is not a standard subdivision: least squares,
// its residual reported.
TEST_F(Subdivide_, ReverseOfACurveConstrainedMeshReportsItsResidual) {
  const std::string fine = Path("fine.obj");
  ASSERT_EQ(Solve("--set subdivision.target_edge_length=0 --set subdivision.levels=1 --set subdivision.limit=false").code, 0);
  std::filesystem::rename(Path("out.obj"), fine);
  ASSERT_EQ(Solve("--set mesh=" + fine + " --set subdivision.target_edge_length=0 --set subdivision.levels=0 "
                  "--set subdivision.limit=false --set subdivision.boundary=standard "
                  "--set \"subdivision.boundary_curves=''\" --set \"subdivision.crease_curves=''\" "
                  "--set subdivision.reverse=1").code, 0);
  EXPECT_GT(Details().at("reverse").at(0).at("residual_max_relative").get<double>(), 1e-6);
}

// The same roof reversed with its curves: the curve rules reversed in
// arc-length parameters, exact to rounding; the coarse roof back up to the
// snap of its vertices onto the sampled curves (curve_tolerance).
TEST_F(Subdivide_, ReverseWithTheCurvesRecoversTheCurveConstrainedRoof) {
  const std::string fine = Path("fine.obj");
  ASSERT_EQ(Solve("--set subdivision.target_edge_length=0 --set subdivision.levels=2 --set subdivision.limit=false").code, 0);
  std::filesystem::rename(Path("out.obj"), fine);
  const Outcome o = Solve("--set mesh=" + fine + " --set subdivision.target_edge_length=0 --set subdivision.levels=0 "
                          "--set subdivision.limit=false --set subdivision.reverse=2");
  ASSERT_EQ(o.code, 0) << o.output;
  const nlohmann::json d = Details();
  EXPECT_EQ(d.at("curves"), 2);
  ASSERT_EQ(d.at("reverse").size(), 2u);
  for (const auto& level : d.at("reverse")) EXPECT_LE(level.at("residual_max_relative").get<double>(), kRecover);
  const Mesh coarse = ReadMesh(Example("subdivide_roof.obj"));
  const Mesh back = ReadMesh(Path("out.obj"));
  ASSERT_EQ(back.number_of_vertices(), coarse.number_of_vertices());
  double worst = 0;
  for (VertexIndex v : coarse.vertices()) {
    worst = std::max(worst, std::sqrt(CGAL::squared_distance(coarse.point(v), back.point(v))));
  }
  EXPECT_LE(worst, 1e-6 * 25);  // subdivision.curve_tolerance × the diagonal (≈ 24.6)
}

TEST_F(Subdivide_, CrossingCurvesExit2NamingFileAndCurves) {
  std::string text = ReadFile(Example("subdivide_roof_ridge.obj"));
  text += "v 0 -6 3\nv 0 6 3\nl 402 403\n";
  const std::string creases = WriteFile("creases.obj", text);
  const Outcome o = Solve("--set subdivision.crease_curves=" + creases);
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find("creases.obj:403: key 'subdivision.crease_curves': curve 1 and"), std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("curve 2 (line 406) cross"), std::string::npos) << o.output;
  EXPECT_FALSE(std::filesystem::exists(Path("out.obj")));
}

TEST_F(Subdivide_, BoundaryCurveOffTheBoundaryExits2) {
  const Outcome o = Solve("--set subdivision.boundary_curves=" + Example("subdivide_roof_ridge.obj") +
                          " --set \"subdivision.crease_curves=''\"");
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find("subdivide_roof_ridge.obj:403: key 'subdivision.boundary_curves': curve 1 is not on "
                          "the mesh boundary"),
            std::string::npos)
      << o.output;
  EXPECT_FALSE(std::filesystem::exists(Path("out.obj")));
}

TEST_F(Subdivide_, CurveFileWithNaNExits2NamingFileAndLine) {
  std::string text = ReadFile(Example("subdivide_roof_perimeter.obj"));
  const size_t at = text.find("\nv ", text.find("\nv ") + 1);  // the second point (line 4)
  text.replace(at + 1, text.find('\n', at + 1) - at - 1, "v nan 0 0");
  const std::string perimeter = WriteFile("perimeter.obj", text);
  const Outcome o = Solve("--set subdivision.boundary_curves=" + perimeter);
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find("perimeter.obj"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find(":4"), std::string::npos) << o.output;
  EXPECT_FALSE(std::filesystem::exists(Path("out.obj")));
}

// §9.2.2 end to end: examples/subdivide_funnel.yaml, four levels of
// Catmull–Clark whose first row meets the column in its tangent plane
// (the acceptance's 0.5°) with both boundary curves kept.
TEST_F(Subdivide_, FunnelMeetsItsColumnTangentially) {
  const Outcome o = Shell(std::string(ARCHGEO_BINARY) + " solve " + Example("subdivide_funnel.yaml") +
                          " --quiet --set output.report=" + Path("r.json") + " --set output.mesh=" + Path("out.obj"));
  ASSERT_EQ(o.code, 0) << o.output;
  const nlohmann::json d = Details();
  EXPECT_EQ(d.at("levels"), 4);
  EXPECT_LE(d.at("curve_distance_max_relative").get<double>(), kOnCurve);
  const nlohmann::json& t = d.at("tangency");
  EXPECT_EQ(t.at("vertices"), 8 << 4);  // the column top's 8 coarse edges, 4 levels
  EXPECT_LE(t.at("deviation_max_deg").get<double>(), 0.5);
  EXPECT_NE(o.output.find("tangent planes turn from its by"), std::string::npos) << o.output;
}

TEST_F(Subdivide_, TangentSurfaceAwayFromTheCurvesOrWithALockedRingExits2) {
  // The column moved 10 units aside: no curve vertex lies on it.
  std::string text = ReadFile(Example("subdivide_funnel_column.obj"));
  std::string moved;
  for (size_t at = 0; at < text.size();) {
    const size_t end = text.find('\n', at);
    std::string line = text.substr(at, end - at);
    if (line.rfind("v ", 0) == 0) line = "v " + std::to_string(std::stod(line.substr(2)) + 10) + line.substr(line.find(' ', 2));
    moved += line + "\n";
    at = end == std::string::npos ? text.size() : end + 1;
  }
  const std::string column = WriteFile("column.obj", moved);
  const std::string base = std::string(ARCHGEO_BINARY) + " solve " + Example("subdivide_funnel.yaml") +
                           " --quiet --set output.report=" + Path("r.json") + " --set output.mesh=" + Path("out.obj");
  const Outcome away = Shell(base + " --set subdivision.tangent_surface=" + column);
  EXPECT_EQ(away.code, 2) << away.output;
  EXPECT_NE(away.output.find("key 'subdivision.tangent_surface': no curve vertex"), std::string::npos) << away.output;
  const Outcome locked = Shell(base + " --set subdivision.boundary=locked --set \"subdivision.boundary_curves=''\"");
  EXPECT_EQ(locked.code, 2) << locked.output;
  EXPECT_NE(locked.output.find("key 'subdivision.tangent_surface'"), std::string::npos) << locked.output;
  EXPECT_FALSE(std::filesystem::exists(Path("out.obj")));
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
