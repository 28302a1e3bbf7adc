// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The hnet builder end to end (ReadSpec + RunSpec) on small nets: the exact
// A-net of a hyperbolic paraboloid stays exact, a small Enneper piece meets
// the acceptance bounds of Shi 2014 Table 1's "minimal surface 2" row, non-quad
// input is refused, and measuring the written net reproduces the reported kinks.
// Nets stored along their diagonals (hnet.net: auto): the rotated hyperbolic
// paraboloid and the negshell A-net of ../shared/data, which must meet the
// issue's bounds; step-3 rounds that raise α_max are undone.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "generators/asymptotic_nets.h"
#include "geometry/diagonal_net.h"
#include "generators/generators.h"
#include "geometry/hnet.h"
#include "core/input_error.h"
#include "io/io.h"
#include "analysis/metrics.h"
#include "mesh/topology.h"
#include "problems/declarations/hnet_net.h"
#include "problems/commands/run.h"
#include "problems/spec/spec.h"
#include "scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

constexpr double kExactStarPlanarity = 1e-12;  // relative, hyperbolic paraboloid
constexpr double kExactW = 1e-9;
constexpr double kExactKinkDegrees = 1e-6;
constexpr double kStarPlanarity = 1e-5;        // relative, Enneper
constexpr double kKinkMaxDegrees = 0.5;
constexpr double kKinkMeanDegrees = 0.07;
constexpr double kReferenceDistance = 0.005;   // of the reference's bbox diagonal
constexpr double kMeasureAgreement = 1e-6;     // degrees, kinks of the re-read net
// The issue's targets on the negshell's own A-net (its colour-1 diagonal net).
constexpr double kNegshellStarPlanarity = 1e-6;  // relative, after the pipeline
constexpr double kNegshellDisplacement = 0.001;  // of the bbox diagonal
constexpr double kNegshellKinkDegrees = 0.5;     // Shi Table 1's real shells: 0.4–4.5°
const char* const kNegshell = ARCHGEO_DATA_DIR "/dos_free_negshell_marc_anet.obj";

class HNetBuilder : public ScratchDirTest {
 protected:
  // Writes the net (and its reference) and a spec running the hnet builder.
  std::string Spec(const Mesh& net, const Mesh* reference, const std::string& extra = "") {
    WriteMesh(Path("net.obj"), net);
    std::string text = "mesh: net.obj\nproblem: hnet\n";
    if (reference) {
      WriteMesh(Path("ref.obj"), *reference);
      // The reference extends beyond the net: boundary vertices go to its
      // surface, not to its boundary curve (no boundary_proximity).
      text += "reference: ref.obj\nterms: {anet_planarity: 10, fairness: {weight: 0.01, on: polyline_quadruples}, "
              "proximity: {weight: 1, point_weight: 0.1}, anchor: 0.1, frame_coplanarity: 10}\n";
    }
    text += "solver: {max_num_iterations: 50}\n" + extra;
    if (extra.find("schedule:") == std::string::npos) text += "schedule: {outer_iterations: 8}\n";
    return WriteFile("spec.yaml", text);
  }
  // Every vertex moved by a fixed pseudo-random vector of length ≤
  // amplitude × mean edge length.
  static Mesh Shaken(Mesh mesh, double amplitude) {
    const double h = ComputeMetrics(mesh, nullptr, nullptr).mean_edge_length;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (VertexIndex v : mesh.vertices()) {
      const Point& p = mesh.point(v);
      const double a = amplitude * h / std::sqrt(3.0);
      mesh.point(v) = Point(p.x() + a * u(random), p.y() + a * u(random), p.z() + a * u(random));
    }
    return mesh;
  }
  // A figure of the report's problem details.
  static double Num(const nlohmann::json& report, const char* key) {
    const nlohmann::json& j = report.at("details");
    EXPECT_TRUE(j.contains(key) && j[key].is_number()) << key;
    return j.value(key, std::nan(""));
  }
};

TEST_F(HNetBuilder, HyperbolicParaboloidIsAnExactHNet) {
  const Mesh net = MakeAsymptoticTestNet(AsymptoticTestNet::kHyperbolicParaboloid);
  const HNet input = BuildHNet(net);
  EXPECT_LE(input.star_planarity_max, kExactStarPlanarity);
  const RunResult run = RunSpec(ReadSpec(Spec(net, nullptr)), {});
  ASSERT_EQ(run.exit_code, 0);
  const nlohmann::json& r = run.report;
  EXPECT_LE(Num(r, "star_planarity_max"), kExactStarPlanarity);
  EXPECT_NEAR(Num(r, "W_min"), 1.0, kExactW);
  EXPECT_NEAR(Num(r, "W_max"), 1.0, kExactW);
  EXPECT_LE(Num(r, "alpha_max"), kExactKinkDegrees);
  EXPECT_LE(Num(r, "mismatch_max"), kExactW);
  EXPECT_TRUE(r["details"]["bipartite"].get<bool>());
  EXPECT_LE(r["after"]["displacement_max_relative"].get<double>(), 1e-9);
}

TEST_F(HNetBuilder, SmallEnneperPieceMeetsTheTableBounds) {
  // The sampled asymptotic net of Enneper's surface is an exact A-net: shake
  // it (2% of the edge length) so that the pipeline has something to do.
  const Mesh net = Shaken(MakeAsymptoticTestNet(AsymptoticTestNet::kEnneperSmall), 0.02);
  const Mesh reference = MakeAsymptoticTestReference(AsymptoticTestNet::kEnneperSmall, 2);
  const HNet input = BuildHNet(net);
  ASSERT_GT(input.star_planarity_max, 100 * kStarPlanarity);
  const RunResult run = RunSpec(ReadSpec(Spec(net, &reference)), {});
  ASSERT_EQ(run.exit_code, 0);
  const nlohmann::json& r = run.report;
  EXPECT_LE(Num(r, "star_planarity_max"), kStarPlanarity);
  EXPECT_LE(Num(r, "alpha_max"), kKinkMaxDegrees);
  EXPECT_LE(Num(r, "alpha_mean"), kKinkMeanDegrees);
  EXPECT_LT(Num(r, "alpha_max"), input.kink_max);
  const double diagonal = ComputeMetrics(reference, nullptr, nullptr).bbox_diagonal;
  EXPECT_LE(r["after"]["surface_distance_max"].get<double>() / diagonal, kReferenceDistance);
  EXPECT_TRUE(r["tolerances"]["hnet.star_planarity"]["met"].get<bool>());
  EXPECT_GT(Num(r, "W_min"), 0);
}

TEST_F(HNetBuilder, NonQuadInputIsRefused) {
  WriteFile("tri.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\n"
                       "f 1 2 3 4\nf 2 5 3\n");
  const std::string spec = WriteFile("spec.yaml", "mesh: tri.obj\nproblem: hnet\n");
  try {
    RunSpec(ReadSpec(spec), {});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "mesh");
    EXPECT_NE(std::string(e.what()).find("tri.obj"), std::string::npos) << e.what();
  }
}

TEST_F(HNetBuilder, BadKeysAreRefused) {
  const Mesh net = MakeAsymptoticTestNet(AsymptoticTestNet::kHyperbolicParaboloid);
  EXPECT_THROW(ReadSpec(Spec(net, nullptr, "terms: {anet_planarity: {variant: triangles}}\n")),
               InputError);
  EXPECT_THROW(ReadSpec(Spec(net, nullptr, "hnet: {alternation: 2}\n")), InputError);
  EXPECT_THROW(ReadSpec(Spec(net, nullptr, "patchwork: {isophotes: {direction: [0, 0, 0]}}\n")),
               InputError);
  EXPECT_THROW(ReadSpec(Spec(net, nullptr, "hnet: {net: primal}\n")), InputError);
  // A strip has no interior vertex: no diagonal net to solve.
  const Mesh strip = QuadGrid(4, 1, [](double u, double v) -> Vec3 { return {u, v, u * v}; });
  try {
    RunSpec(ReadSpec(Spec(strip, nullptr, "hnet: {net: diagonal_1}\n")), {});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "hnet.net");
    EXPECT_GT(e.line(), 0);
    EXPECT_NE(e.message().find("net.obj"), std::string::npos) << e.what();
  }
}

TEST_F(HNetBuilder, MeasuringTheWrittenNetGivesTheReportedKinks) {
  const Mesh net = Shaken(MakeAsymptoticTestNet(AsymptoticTestNet::kEnneperSmall), 0.02);
  const Mesh reference = MakeAsymptoticTestReference(AsymptoticTestNet::kEnneperSmall, 1);
  const std::string spec = Spec(net, &reference,
                                "hnet: {alternations: 1}\n"
                                "patchwork: {samples: 3, ascii: true}\n"
                                "output: {mesh: out.obj, patchwork: patch.ply, rulings: rul.obj}\n");
  const RunResult run = RunSpec(ReadSpec(spec), {});
  ASSERT_EQ(run.exit_code, 0);
  const HNet measured = BuildHNet(ReadMesh(Path("out.obj")));
  EXPECT_NEAR(measured.kink_max, run.report["details"]["alpha_max"].get<double>(), kMeasureAgreement);
  EXPECT_NEAR(measured.kink_mean, run.report["details"]["alpha_mean"].get<double>(), kMeasureAgreement);
  EXPECT_NEAR(measured.W_min, run.report["details"]["W_min"].get<double>(), 1e-6);
  EXPECT_NEAR(measured.W_max, run.report["details"]["W_max"].get<double>(), 1e-6);

  // Patchwork: (3+1)² samples and 2·3² triangles per patch, normals and colours.
  std::ifstream ply(Path("patch.ply"));
  std::string header, line;
  while (std::getline(ply, line) && line != "end_header") header += line + "\n";
  const int faces = int(net.number_of_faces());
  EXPECT_NE(header.find("element vertex " + std::to_string(16 * faces)), std::string::npos);
  EXPECT_NE(header.find("element face " + std::to_string(18 * faces)), std::string::npos);
  EXPECT_NE(header.find("property float nx"), std::string::npos);
  EXPECT_NE(header.find("property uchar red"), std::string::npos);
  std::getline(ply, line);
  std::istringstream first(line);
  double x, y, z, nx, ny, nz;
  first >> x >> y >> z >> nx >> ny >> nz;
  EXPECT_NEAR(nx * nx + ny * ny + nz * nz, 1.0, 1e-6);

  // Rulings: one line per family and patch.
  std::ifstream obj(Path("rul.obj"));
  int lines = 0;
  while (std::getline(obj, line)) lines += line.rfind("l ", 0) == 0;
  EXPECT_EQ(lines, 2 * faces);
}

TEST_F(HNetBuilder, NetAlongItsDiagonalsIsSolvedAsItsDiagonalNet) {
  // z = xy sampled with its rulings along the face diagonals.
  const Mesh mesh = QuadGrid(10, 10, [](double u, double v) -> Vec3 {
    const double x = u + v - 1, y = u - v;
    return {x, y, x * y};
  });
  ASSERT_GT(BuildHNet(mesh).star_planarity_max, 1e-2);
  const RunResult run = RunSpec(ReadSpec(Spec(mesh, nullptr, "output: {mesh: out.obj}\n")), {});
  ASSERT_EQ(run.exit_code, 0);
  const nlohmann::json& r = run.report;
  ASSERT_TRUE(r["details"].contains("net"));  // report schema 1: problem data under details
  EXPECT_EQ(r["details"]["net"]["setting"], "auto");
  EXPECT_NE(r["details"]["net"]["net"].get<std::string>().find("diagonal_"), std::string::npos);
  EXPECT_LE(Num(r, "star_planarity_max"), kExactStarPlanarity);
  EXPECT_NEAR(Num(r, "W_min"), 1.0, kExactW);
  EXPECT_NEAR(Num(r, "W_max"), 1.0, kExactW);
  EXPECT_LE(Num(r, "alpha_max"), kExactKinkDegrees);
  EXPECT_LE(r["after"]["displacement_max_relative"].get<double>(), 1e-9);
  const Mesh out = ReadMesh(Path("out.obj"));
  EXPECT_EQ(out.number_of_vertices(), r["details"]["net"]["vertices"].get<size_t>());
  EXPECT_NE(run.summary.find("diagonal net"), std::string::npos) << run.summary;

  // hnet.net: mesh keeps the input (and cannot flatten it without moving):
  // one round leaves the star tolerance missed, a valid result with exit 4.
  const RunResult kept =
      RunSpec(ReadSpec(Spec(mesh, nullptr, "hnet: {net: mesh, alternations: 0}\n"
                                           "schedule: {outer_iterations: 1}\n")), {});
  ASSERT_EQ(kept.exit_code, 4);
  EXPECT_FALSE(kept.report["details"].contains("net"));
  EXPECT_EQ(kept.report["after"]["vertices"].get<size_t>(), mesh.number_of_vertices());
}

TEST_F(HNetBuilder, MeasureShowsTheFlatterDiagonalNet) {
  EXPECT_LE(DiagonalNetStarPlanarityMean(ReadMesh(kNegshell)), 1e-6);  // the mesh's: 5.8e-2
  const Mesh hp = MakeAsymptoticTestNet(AsymptoticTestNet::kHyperbolicParaboloid);
  EXPECT_GT(DiagonalNetStarPlanarityMean(hp), 1e-3);  // an A-net itself: not its diagonals
  const RunResult measured = MeasureFiles(kNegshell, "");
  EXPECT_LE(measured.report["metrics"]["diagonal_star_planarity_mean"].get<double>(), 1e-6);
  EXPECT_NE(measured.summary.find("of the flatter diagonal net"), std::string::npos);
}

// The file's own A-net is its colour-1 diagonal net (stars 4.5e-6), which has
// 9 holes; auto takes it (the flatter net) and the least-squares W closes
// around the holes: step 1 alone meets the targets, so no step-3 round runs.
TEST_F(HNetBuilder, NegshellMeetsTheIssueBounds) {
  // examples/hnet.yaml unchanged but for the outputs.
  const std::string patchwork = Path("negshell_patchwork.ply");
  const RunResult run = RunSpec(
      ReadSpec(ARCHGEO_SOURCE_DIR "/examples/hnet.yaml",
               {"mesh=" + std::string(kNegshell),
                "output={mesh: " + Path("negshell.obj") + ", patchwork: " + patchwork + "}"}),
      {});
  ASSERT_EQ(run.exit_code, 0);
  const nlohmann::json& r = run.report;
  EXPECT_EQ(r["details"]["net"]["net"], "diagonal_1");
  EXPECT_EQ(r["details"]["net"]["holes"], 9);
  EXPECT_GT(r["details"]["net"]["candidates"]["mesh"]["star_planarity_max"].get<double>(), 0.14);
  EXPECT_LE(Num(r, "star_planarity_max"), kNegshellStarPlanarity);
  EXPECT_LE(r["after"]["displacement_max_relative"].get<double>(), kNegshellDisplacement);
  EXPECT_GT(Num(r, "W_min"), 0);
  EXPECT_LE(Num(r, "alpha_max"), kNegshellKinkDegrees);
  EXPECT_LT(Num(r, "alpha_mean"), 0.534);  // the paper's Cagliari row
  EXPECT_GT(std::filesystem::file_size(patchwork), 0u);
  const HNet measured = BuildHNet(ReadMesh(Path("negshell.obj")));
  EXPECT_NEAR(measured.kink_max, Num(r, "alpha_max"), kMeasureAgreement);
  EXPECT_NEAR(measured.kink_mean, Num(r, "alpha_mean"), kMeasureAgreement);
}

// Step 3 on a net with holes (the negshell's own A-net), forced by a kink
// bound of 0.02° that step 1 does not meet: with the least-squares W every
// round lowers α_max (none is undone), the result is valid and meets the
// targets; with the paper's propagated W (whole holonomy on one edge per
// hole) the same run has to move the vertices at least twice as far — or,
// without the barriers, is undone (next tests).
TEST_F(HNetBuilder, StepThreeSucceedsOnANetWithHoles) {
  const auto run = [&](const std::string& shape) {
    return RunSpec(ReadSpec(ARCHGEO_SOURCE_DIR "/examples/hnet.yaml",
                            {"mesh=" + std::string(kNegshell), "hnet.alpha_max=0.02",
                             "hnet.alternations=4", "hnet.shape_parameters=" + shape,
                             "output={report: " + Path(shape + ".json") + "}"}),
                   {});
  };
  const RunResult spread = run("least_squares");
  ASSERT_EQ(spread.exit_code, 0);
  const nlohmann::json& r = spread.report;
  EXPECT_EQ(r["details"]["net"]["net"], "diagonal_1");
  EXPECT_TRUE(r["validity"]["valid"].get<bool>());
  double step1_alpha = -1;
  int frame_rounds = 0;
  for (const auto& round : r["rounds"]) {
    if (round["stage"] == "A-net") step1_alpha = round["measures"]["alpha_max"].get<double>();
    if (round["stage"] != "frame") continue;
    ++frame_rounds;
    EXPECT_FALSE(round["undone"].get<bool>());
  }
  EXPECT_GE(frame_rounds, 1);
  EXPECT_GT(step1_alpha, 0.1);  // 0.20° after step 1
  EXPECT_LE(Num(r, "alpha_max"), 0.02);
  EXPECT_LE(Num(r, "star_planarity_max"), kNegshellStarPlanarity);
  const RunResult tree = run("propagated");
  EXPECT_LT(r["after"]["displacement_max_relative"].get<double>(),
            0.5 * tree.report["after"]["displacement_max_relative"].get<double>());
}

TEST_F(HNetBuilder, StepThreeRoundsThatRaiseTheKinksAreUndone) {
  // The negshell's colour-1 diagonal net has 9 holes: the propagated W cannot
  // agree around them and, without the validity barriers, the frame terms
  // degenerate patches (α_max → 180°).
  const RunResult run = RunSpec(
      ReadSpec(ARCHGEO_SOURCE_DIR "/examples/hnet.yaml",
               {"mesh=" + std::string(kNegshell), "hnet.net=diagonal_1", "hnet.alternations=2",
                "hnet.shape_parameters=propagated", "hnet.alpha_max=0",
                "terms.convexity.weight=0", "terms.min_edge_length.weight=0",
                // no deviation band: the undone rounds are what is tested
                "tolerance.surface_distance_max=0",
                "output={report: " + Path("r.json") + "}"}),
      {});
  ASSERT_EQ(run.exit_code, 0);
  const nlohmann::json& rounds = run.report["rounds"];
  ASSERT_GE(rounds.size(), 2u);
  const nlohmann::json& last = rounds.back();
  ASSERT_TRUE(last["undone"].get<bool>());
  double before = 0;
  for (const auto& round : rounds) {
    if (!round["undone"].get<bool>()) before = round["measures"]["alpha_max"].get<double>();
  }
  EXPECT_GT(last["measures"]["alpha_max"].get<double>(), before);
  EXPECT_DOUBLE_EQ(Num(run.report, "alpha_max"), before);
  EXPECT_LT(Num(run.report, "alpha_max"), 10.0);
}

// With the barriers (convexity, min_edge_length: on by default) the same
// step 3 with the propagated W keeps every patch valid and flattens the kinks
// from 3.2° to below Shi's real shells (0.4–4.5°, Table 1) instead of being
// undone; the price is movement and star planarity, and the missed star
// tolerance is an exit 4, not a success (measured: α_max 0.045°, stars
// 1.8e-5, 1.6% of the diagonal).
TEST_F(HNetBuilder, BarriersKeepStepThreeValidOnANetWithHoles) {
  const RunResult run = RunSpec(
      ReadSpec(ARCHGEO_SOURCE_DIR "/examples/hnet.yaml",
               {"mesh=" + std::string(kNegshell), "hnet.net=diagonal_1", "hnet.alternations=2",
                "hnet.shape_parameters=propagated", "hnet.alpha_max=0",
                "output={report: " + Path("r.json") + "}"}),
      {});
  EXPECT_EQ(run.exit_code, 4);
  EXPECT_TRUE(run.report["validity"]["valid"].get<bool>());
  const nlohmann::json& last = run.report["rounds"].back();
  EXPECT_EQ(last["stage"], "frame");
  EXPECT_FALSE(last["undone"].get<bool>());
  EXPECT_LT(Num(run.report, "alpha_max"), 0.5);
  EXPECT_FALSE(run.report["tolerances"]["hnet.star_planarity"]["met"].get<bool>());
}

TEST_F(HNetBuilder, FixedIdsReferToTheInputAndMustLieOnTheNet) {
  const Mesh input = ReadMesh(kNegshell);
  const DiagonalNet net = MakeDiagonalNet(input, 0);
  const int on = net.source[net.source.size() / 2];
  // A neighbour of `on` has colour 1: not on the net.
  const int off = int(input.source(input.halfedge(VertexIndex(on))).idx());
  ASSERT_EQ(TwoColouring(input)[off], 1);
  const auto run = [&](int fixed) {
    return RunSpec(ReadSpec(ARCHGEO_SOURCE_DIR "/examples/hnet.yaml",
                            {"mesh=" + std::string(kNegshell), "hnet.net=diagonal_0",
                             "hnet.alternations=0", "schedule.outer_iterations=1",
                             "fixed=[" + std::to_string(fixed) + "]",
                             "output={mesh: " + Path("fixed.obj") + "}"}),
                   {});
  };
  try {
    run(off);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "fixed");
    EXPECT_NE(e.message().find("not a vertex of the net"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(Path("fixed.obj")));
  ASSERT_EQ(run(on).exit_code, 4);  // one round: valid, the star tolerance not yet met
  const Mesh out = ReadMesh(Path("fixed.obj"));
  ASSERT_EQ(out.number_of_vertices(), net.mesh.number_of_vertices());
  const int k = int(net.source.size() / 2);  // the net vertex of input vertex `on`
  // Fixed up to the round trip through the canonical frame.
  EXPECT_LE(std::sqrt(CGAL::squared_distance(out.point(VertexIndex(k)), input.point(VertexIndex(on)))),
            1e-12);
  EXPECT_GT(std::sqrt(CGAL::squared_distance(out.point(VertexIndex(k + 1)),
                                             input.point(VertexIndex(net.source[k + 1])))),
            1e-9);
}

}  // namespace
}  // namespace archgeo
