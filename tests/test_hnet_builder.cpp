// The hnet builder end to end (ReadSpec + RunSpec) on small nets: the exact
// A-net of a hyperbolic paraboloid stays exact, a small Enneper piece meets
// the acceptance bounds of Shi 2014 Table 1's "minimal surface 2" row, non-quad
// input is refused, and measuring the written net reproduces the reported kinks.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "mesh/asymptotic_nets.h"
#include "mesh/hnet.h"
#include "mesh/input_error.h"
#include "mesh/io.h"
#include "mesh/metrics.h"
#include "problems/run.h"
#include "problems/spec.h"
#include "scratch_dir.h"

namespace archgeo {
namespace {

constexpr double kExactStarPlanarity = 1e-12;  // relative, hyperbolic paraboloid
constexpr double kExactW = 1e-9;
constexpr double kExactKinkDegrees = 1e-6;
constexpr double kStarPlanarity = 1e-5;        // relative, Enneper
constexpr double kKinkMaxDegrees = 0.5;
constexpr double kKinkMeanDegrees = 0.07;
constexpr double kReferenceDistance = 0.005;   // of the reference's bbox diagonal
constexpr double kMeasureAgreement = 1e-6;     // degrees, kinks of the re-read net

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
      text += "reference: ref.obj\nterms: {anet_planarity: 10, fairness: {weight: 0.01, order: 3}, "
              "proximity: {weight: 1, point_weight: 0.1}, anchor: 0.1, frame_coplanarity: 10}\n";
    }
    text += "solver: {max_iterations: 50, outer_iterations: 8}\n" + extra;
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
  static double Num(const nlohmann::json& j, const char* key) {
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
  EXPECT_TRUE(r["bipartite"].get<bool>());
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
  EXPECT_TRUE(r["tolerance"]["met"].get<bool>());
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
  EXPECT_NEAR(measured.kink_max, run.report["alpha_max"].get<double>(), kMeasureAgreement);
  EXPECT_NEAR(measured.kink_mean, run.report["alpha_mean"].get<double>(), kMeasureAgreement);
  EXPECT_NEAR(measured.W_min, run.report["W_min"].get<double>(), 1e-6);
  EXPECT_NEAR(measured.W_max, run.report["W_max"].get<double>(), 1e-6);

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

}  // namespace
}  // namespace archgeo
