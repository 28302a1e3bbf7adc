// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// planar_quads on a net far from conjugate (problems/declarations/relayout.h):
// the stall rule ends the run early with the reason, a missed tolerance
// offers the conjugate_layout command for the net's surface, relayout: auto
// replaces the net by that layout and planarises it, and conjugate_layout
// takes a quad net as its design surface; relayout: never goes after the
// worst quads of the DOS pillow.
//
// The net: a 16 × 16 grid on the saddle z = 0.6 x² − 0.3 y² whose edges run
// along the diagonals x = ±y, where II(u, v) = 2(0.6 + 0.3) ≠ 0: far from
// conjugate (suitability conjugacy mean 0.80).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "analysis/validity.h"
#include "core/input_error.h"
#include "generators/generators.h"
#include "io/io.h"
#include "problems/commands/run.h"
#include "problems/declarations/relayout.h"
#include "problems/spec/spec.h"
#include "scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

Vec3 DiagonalSaddle(double u, double v) {
  const double s = 2 * u - 1, t = 2 * v - 1;
  const double x = (s + t) / std::sqrt(2.0), y = (s - t) / std::sqrt(2.0);
  return {x, y, 0.6 * x * x - 0.3 * y * y};
}

class Relayout : public ScratchDirTest {
 protected:
  void SetUp() override {
    ScratchDirTest::SetUp();
    net_ = Path("saddle.obj");
    WriteMesh(net_, QuadGrid(16, 16, DiagonalSaddle));
  }
  // examples/planar_quads.yaml on the net with `sets`, the mesh written.
  RunResult Run(std::vector<std::string> sets) const {
    sets.push_back("mesh=" + net_);
    sets.push_back("output={mesh: " + Path("out.obj") + ", report: " + Path("r.json") + "}");
    return RunSpec(ReadSpec(ARCHGEO_SOURCE_DIR "/examples/planar_quads.yaml", sets), {});
  }
  std::string net_;
};

TEST_F(Relayout, AStalledNetEndsEarlyWithTheReasonAndTheWayOut) {
  const RunResult run = Run({"schedule.outer_iterations=8"});
  const nlohmann::json& r = run.report;
  EXPECT_EQ(run.exit_code, 4);
  EXPECT_EQ(r.at("stop").get<std::string>().rfind("stalled: no gain in the best valid", 0), 0u)
      << r.at("stop");
  EXPECT_EQ(r.at("iterations").at("outer").get<int>(), 3);  // stall.rounds
  // The suitability figures and the command for this net's surface.
  EXPECT_GT(r.at("details").at("suitability").at("conjugacy_mean").get<double>(), 0.35);
  const std::string command = "archgeo solve examples/conjugate_layout.yaml --set mesh=" + net_ +
                              " --set level_sets.target_faces=256";
  EXPECT_EQ(r.at("details").at("relayout").at("command").get<std::string>(), command);
  EXPECT_NE(run.summary.find(command), std::string::npos) << run.summary;
  EXPECT_NE(run.summary.find("conjugacy mean 0.80"), std::string::npos) << run.summary;
}

TEST_F(Relayout, WithoutTheStallRuleEveryRoundRuns) {
  const RunResult run = Run({"schedule.outer_iterations=8", "stall.fraction=0"});
  EXPECT_EQ(run.exit_code, 4);
  EXPECT_EQ(run.report.at("iterations").at("outer").get<int>(), 8);
  EXPECT_EQ(run.report.at("stop").get<std::string>().rfind("rounds exhausted", 0), 0u);
}

TEST_F(Relayout, NeverOffersNothing) {
  const RunResult run = Run({"schedule.outer_iterations=8", "relayout=never"});
  EXPECT_EQ(run.exit_code, 4);
  EXPECT_FALSE(run.report.at("details").contains("relayout"));
  EXPECT_EQ(run.summary.find("conjugate_layout.yaml"), std::string::npos);
}

// relayout: auto: the net's surface laid out anew, planar to the tolerance
// with every panel convex; the report says the connectivity changed and
// gives the counts, which are the output's.
TEST_F(Relayout, AutoPlanarisesAConjugateLayoutOfTheSurface) {
  const RunResult run = Run({"relayout=auto"});
  const nlohmann::json& r = run.report;
  const nlohmann::json& relayout = r.at("details").at("relayout");
  EXPECT_EQ(run.exit_code, 0) << run.summary;
  EXPECT_TRUE(relayout.at("relaid").get<bool>());
  EXPECT_TRUE(relayout.at("connectivity_changed").get<bool>());
  EXPECT_EQ(relayout.at("faces_before").get<int>(), 256);
  EXPECT_EQ(relayout.at("panels_before").get<int>(), 256);
  const Mesh out = ReadMesh(Path("out.obj"));
  EXPECT_EQ(relayout.at("faces_after").get<int>(), int(out.number_of_faces()));
  EXPECT_NE(int(out.number_of_faces()), 256);
  const PanelShapes shapes = MeasurePanelShapes(out);
  EXPECT_EQ(relayout.at("panels_after").get<int>(), shapes.panels);
  EXPECT_EQ(relayout.at("panel_difference").get<int>(), shapes.panels - 256);
  EXPECT_EQ(shapes.nonconvex, 0);
  EXPECT_LE(r.at("after").at("pq_normalized_max").get<double>(), 1e-3);
  EXPECT_NE(run.summary.find("the connectivity changed"), std::string::npos) << run.summary;
}

// A net the suitability check finds conjugate enough is solved as it is.
TEST_F(Relayout, AutoKeepsASuitableNet) {
  WriteMesh(net_, QuadGrid(12, 9, RoofSurface, 0.05, 3));
  const RunResult run = Run({"relayout=auto"});
  EXPECT_EQ(run.exit_code, 0) << run.summary;
  EXPECT_FALSE(run.report.at("details").at("relayout").at("relaid").get<bool>());
  EXPECT_EQ(run.report.at("after").at("faces").get<int>(), 12 * 9);
}

// The suggested command works: conjugate_layout takes the quad net as its
// design surface (its triangulation) and refuses keys that name faces; the
// empty defaults `archgeo spec` writes name none.
TEST_F(Relayout, ConjugateLayoutTakesAQuadNetAsItsDesignSurface) {
  const std::string spec =
      "mesh: " + net_ + "\nproblem: conjugate_layout\nlevel_sets: {target_faces: 256}\n";
  const RunResult run = RunSpec(
      ReadSpec(WriteFile("layout.yaml", spec + "field: {singularities: []}\n")),
      {});
  EXPECT_EQ(run.exit_code, 0) << run.summary;
  EXPECT_LE(run.report.at("after").at("pq_normalized_max").get<double>(), 1e-3);
  try {
    RunSpec(ReadSpec(WriteFile("bad.yaml", spec + "field: {singularities: [3]}\n")), {});
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "field.singularities") << e.what();
  }
}

// relayout: never keeps the net: after the stall the worst-quads stage (term
// pq_worst, problems/declarations/worst_quads.h) goes after the maximum of δ_PQ,n.
// On the DOS pillow (input 0.0470, every round of the first stage that
// lowers it folds a crease) it ends below 0.0402, the Shape-Up iteration's
// best state with every panel convex on this net (libigl's
// planarize_quad_mesh, benchmarks/planar_quads_stall), with every panel
// convex and the whole validity passed. The same stage with pq_worst's
// power 2 (the sum of squares, every quad alike) returns the input.
class WorstQuads : public ScratchDirTest {
 protected:
  RunResult Run(std::vector<std::string> sets) const {
    sets.push_back("mesh=" ARCHGEO_DATA_DIR "/dos_pillow_1.obj");
    sets.push_back("relayout=never");
    sets.push_back("output={mesh: " + Path("out.obj") + ", report: " + Path("r.json") + "}");
    return RunSpec(ReadSpec(ARCHGEO_SOURCE_DIR "/examples/planar_quads.yaml", sets), {});
  }
};

TEST_F(WorstQuads, PqWorstLowersThePillowsWorstQuadBelowShapeUpsWithConvexPanels) {
  constexpr double kInput = 0.0470, kShapeUpBestConvex = 0.0402;
  const RunResult run = Run({});
  const nlohmann::json& r = run.report;
  EXPECT_EQ(run.exit_code, 4) << run.summary;
  EXPECT_NEAR(r.at("before").at("pq_normalized_max").get<double>(), kInput, 5e-5);
  EXPECT_LT(r.at("after").at("pq_normalized_max").get<double>(), kShapeUpBestConvex);
  EXPECT_TRUE(r.at("validity").at("valid").get<bool>());
  EXPECT_EQ(MeasurePanelShapes(ReadMesh(Path("out.obj"))).nonconvex, 0);
  // The output is a round of the worst-quads stage.
  const int output = r.at("output_round").get<int>();
  bool worst = false;
  for (const nlohmann::json& row : r.at("rounds")) {
    worst = worst || (row.at("round").get<int>() == output &&
                      row.at("stage").get<std::string>() == "worst");
  }
  EXPECT_TRUE(worst) << "output round " << output;

  const RunResult sum = Run({"terms.pq_worst.power=2"});
  EXPECT_EQ(sum.exit_code, 4);
  EXPECT_NEAR(sum.report.at("after").at("pq_normalized_max").get<double>(), kInput, 5e-5);
}


// Two quads side by side; the left one's bottom side passes through x, a
// boundary vertex only it uses. On a straight boundary x is no corner: the
// quad is a triangle in shape and becomes that triangle (not two
// triangles), and x leaves the mesh. Where the boundary turns at x by more
// than the margin, x stays a corner and the quad a quad.
Mesh PanelsWithABoundaryPoint(double bend_degrees) {
  const double drop = 0.5 * std::tan(bend_degrees * M_PI / 180.0);
  Mesh m;
  const VertexIndex a = m.add_vertex(Point(0, 0, 0)), x = m.add_vertex(Point(0.5, -drop, 0)),
                    b = m.add_vertex(Point(1, 0, 0)), c = m.add_vertex(Point(1, 1, 0)),
                    d = m.add_vertex(Point(0, 1, 0)), e = m.add_vertex(Point(2, 0, 0)),
                    f = m.add_vertex(Point(2, 1, 0));
  m.add_face(a, x, b, c);
  m.add_face(a, c, d);
  m.add_face(b, e, f, c);
  return m;
}

TEST(SplitBentPanels, AStraightBoundaryPointOfOnePanelLeavesIt) {
  Mesh straight = PanelsWithABoundaryPoint(0.0);
  int dissolved = -1;
  EXPECT_EQ(SplitBentPanels(straight, 1.0, &dissolved), 0);
  EXPECT_EQ(dissolved, 1);
  EXPECT_EQ(straight.number_of_vertices(), 6u);
  EXPECT_EQ(straight.number_of_faces(), 3u);
  int triangles = 0;
  for (FaceIndex f : straight.faces()) triangles += straight.degree(f) == 3;
  EXPECT_EQ(triangles, 2);
  // The boundary turning at x by 1° (the corner 179°, within the 1° margin)
  // or 1.8° (178.2°, within 2°): straight. By 2.4° (177.6°) or 6° (174°): a
  // corner of the panel, kept, and not split (convex beyond the margin).
  for (const auto& [bend, leaves] : {std::pair{0.5, 1}, {0.9, 1}, {1.2, 0}, {3.0, 0}}) {
    Mesh m = PanelsWithABoundaryPoint(bend);
    EXPECT_EQ(SplitBentPanels(m, 1.0, &dissolved), 0) << "bend " << bend;
    EXPECT_EQ(dissolved, leaves) << "bend " << bend;
    EXPECT_EQ(m.number_of_vertices(), 7u - unsigned(leaves)) << "bend " << bend;
  }
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
