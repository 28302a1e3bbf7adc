// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Composed problems (problem: custom): examples/planar_smooth.yaml — planar
// quads with Pellis' visual smoothness and the validity barriers — and the
// barrier terms' functors (convexity, min_edge_length).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <nlohmann/json.hpp>

#include "energies/convexity.h"
#include "energies/autodiff.h"
#include "energies/min_edge_length.h"
#include "problems/commands/run.h"
#include "problems/spec/spec.h"
#include "tests/energy_checks.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using energy_checks::Blocks;
using energy_checks::Vec3;

TEST(Convexity, ZeroInsideTheMarginAndTheTurnSineOutside) {
  const double n[3] = {0, 0, 1};
  const double threshold = std::sin(2.0 * M_PI / 180);
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(Convexity(n, threshold)));
  // A right-angle corner of a counter-clockwise square: s = 1, no residual.
  EXPECT_EQ(energy_checks::Evaluate(*cost, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}})[0], 0.0);
  // A reflex corner bent 30° inward: turn −30°, s = −1/2, r = t + 1/2.
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const double r = energy_checks::Evaluate(*cost, {{0, 0, 0}, {1, 0, 0}, {1 + c, -s, 0}})[0];
  EXPECT_NEAR(r, threshold + 0.5, 1e-12);
  // A straight corner (180°): s = 0, r = t.
  EXPECT_NEAR(energy_checks::Evaluate(*cost, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}})[0], threshold,
              1e-12);
}

TEST(Convexity, GradientAndInvariance) {
  std::mt19937 rng(7);
  const double n[3] = {0, 0, 1};
  // Active (reflex) corner, away from the hinge.
  const Blocks blocks = {{0, 0, 0.1}, {1, 0.05, -0.1}, {1.8, -0.4, 0.05}};
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(Convexity(n, 0.05)));
  ASSERT_GT(energy_checks::Evaluate(*cost, blocks)[0], 0.1);
  energy_checks::ExpectGradientsMatch(*cost, blocks);
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::Matrix3d R = energy_checks::RandomRotation(rng);
    const Vec3 t = energy_checks::RandomVec(rng, 3);
    const double scale = 0.5 + trial;
    Blocks moved;
    for (const auto& b : blocks) moved.push_back(energy_checks::ToBlock(scale * (R * energy_checks::AsVec(b)) + t));
    const Vec3 rn = R * Vec3(0, 0, 1);
    std::unique_ptr<ceres::CostFunction> rotated(MakeAutoDiff(Convexity(rn.data(), 0.05)));
    EXPECT_NEAR(energy_checks::Evaluate(*rotated, moved)[0],
                energy_checks::Evaluate(*cost, blocks)[0], 1e-12);
  }
}

TEST(MinEdgeLength, HingeGradientAndInvariance) {
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(MinEdgeLength(0.5)));
  EXPECT_EQ(energy_checks::Evaluate(*cost, {{0, 0, 0}, {0.6, 0, 0}})[0], 0.0);
  EXPECT_NEAR(energy_checks::Evaluate(*cost, {{0, 0, 0}, {0.2, 0, 0}})[0], 0.6, 1e-12);
  const Blocks blocks = {{0.1, 0.2, 0.3}, {0.2, 0.1, 0.25}};
  energy_checks::ExpectGradientsMatch(*cost, blocks);
  std::mt19937 rng(3);
  const Eigen::Matrix3d R = energy_checks::RandomRotation(rng);
  Blocks moved;
  for (const auto& b : blocks) moved.push_back(energy_checks::ToBlock(3.0 * (R * energy_checks::AsVec(b))));
  std::unique_ptr<ceres::CostFunction> scaled(MakeAutoDiff(MinEdgeLength(1.5)));
  EXPECT_NEAR(energy_checks::Evaluate(*scaled, moved)[0], energy_checks::Evaluate(*cost, blocks)[0],
              1e-12);
}

class PlanarSmooth : public ScratchDirTest {};

// examples/planar_smooth.yaml on libigl's conjugate layout of the inspired
// mesh (1,633 quads, δ_PQ,n max 1.37e-2, Pellis E 75.92 in file units). The
// bounds are the issue's: δ_PQ,n max ≤ 1e-3 (the tolerance), every panel
// convex (the convexity barrier; planarity alone bends 9 quads inward by ~20°
// here), E no higher than the input's (the dihedral energy; planar_quads
// alone raises E to 105.5), exit 0 (valid and the tolerance met). Without the
// fairness term the barriers stall it at 2.7e-3 (exit 4); without the
// dihedral energy E ends at 76.9.
TEST_F(PlanarSmooth, PlanarConvexAndNoBumpierThanTheInput) {
  const ProblemSpec spec =
      ReadSpec(ARCHGEO_SOURCE_DIR "/examples/planar_smooth.yaml",
               {"output.mesh=" + Path("out.ply"), "output.report=" + Path("report.json")});
  const RunResult run = RunSpec(spec, {});
  ASSERT_EQ(run.exit_code, 0);
  const nlohmann::json& before = run.report["before"];
  const nlohmann::json& after = run.report["after"];
  EXPECT_NEAR(before["E"].get<double>(), 75.9206142148672, 1e-9);
  EXPECT_LE(after["pq_normalized_max"].get<double>(), 1e-3);
  EXPECT_EQ(after["nonconvex_panels"].get<double>(), 0.0);
  EXPECT_EQ(after["worst_reflex_degrees"].get<double>(), 0.0);
  EXPECT_LE(after["E"].get<double>(), before["E"].get<double>());
  EXPECT_TRUE(run.report["validity"]["valid"].get<bool>());
}

// examples/planar_quads.yaml (planar_quads' defaults: planarity, fairness
// relative to the input, the dihedral energy and the barriers) on the same
// layout: issue 14's figures — δ_PQ,n max ≤ 1e-3, E no higher than the
// input's 75.92, max displacement ≤ 0.8% of the diagonal — with every quad
// convex and exit 0. Without the fairness term the barriers stall planarity
// at 2.9e-3 (exit 4); without the dihedral energy E ends at 80.8.
TEST_F(PlanarSmooth, PlanarQuadsExampleKeepsTheRoofSmooth) {
  const ProblemSpec spec = ReadSpec(ARCHGEO_SOURCE_DIR "/examples/planar_quads.yaml",
                                    {"output.mesh=" + Path("out.ply"), "output.image=",
                                     "output.report=" + Path("report.json")});
  const RunResult run = RunSpec(spec, {});
  ASSERT_EQ(run.exit_code, 0);
  const nlohmann::json& before = run.report["before"];
  const nlohmann::json& after = run.report["after"];
  EXPECT_NEAR(before["E"].get<double>(), 75.9206142148672, 1e-9);
  EXPECT_LE(after["pq_normalized_max"].get<double>(), 1e-3);
  EXPECT_LE(after["E"].get<double>(), before["E"].get<double>());
  EXPECT_LE(after["displacement_max_relative"].get<double>(), 0.008);
  EXPECT_EQ(after["nonconvex_panels"].get<double>(), 0.0);
  EXPECT_TRUE(run.report["validity"]["valid"].get<bool>());
}

// examples/planar_quads.yaml on libigl's Smooth layout of the inspired mesh
// (1,838 quads, δ_PQ,n max 1.26e-2, far from conjugate in its middle):
// issue 14's pattern (δ_PQ,n ≤ 1e-3, E no higher than the input's) with every
// quad convex and exit 0, in 6 rounds. With the convexity margin at 2° (its
// earlier default) a corner held at 178° and a quad's planarity pulled
// against each other at the hinge's kink: from round 8 on it stalled at
// 1.0016e-3 while the weights grew to 1e12 (exit 4), and its smallest panel
// corner was 13°.
TEST_F(PlanarSmooth, PlanarQuadsExampleMeetsTheToleranceOnTheSmoothLayout) {
  const ProblemSpec spec = ReadSpec(
      ARCHGEO_SOURCE_DIR "/examples/planar_quads.yaml",
      {"mesh=" ARCHGEO_DATA_DIR "/libigl_inspired_mesh_quads_Smooth.off", "output.mesh=",
       "output.image=", "output.report=" + Path("report.json")});
  const RunResult run = RunSpec(spec, {});
  ASSERT_EQ(run.exit_code, 0) << run.summary;
  const nlohmann::json& before = run.report["before"];
  const nlohmann::json& after = run.report["after"];
  EXPECT_LE(after["pq_normalized_max"].get<double>(), 1e-3);
  EXPECT_LE(after["E"].get<double>(), before["E"].get<double>());
  EXPECT_EQ(after["nonconvex_panels"].get<double>(), 0.0);
  EXPECT_LE(after["displacement_max_relative"].get<double>(), 0.0245);  // 2.43% at 2°
  // Met, not stalled: the tolerance ends the run before the example's rounds
  // (schedule.outer_iterations) run out.
  EXPECT_EQ(run.report["stop"].get<std::string>(), "tolerances met");
  EXPECT_LT(run.report["rounds"].size() - 1,
            run.report["settings"]["schedule"]["outer_iterations"].get<size_t>());
}

// The convexity barrier on its own: planar_quads on the same layout without
// the fairness term. Planarity then presses quads to fold (without the
// barrier round 5 bends quads inward, is refused, and the output round 4
// has 7 non-convex panels); with it every round stays valid, every panel
// convex, and the run honestly misses the tolerance (exit 4).
TEST_F(PlanarSmooth, ConvexityBarrierKeepsEveryRoundValidWithoutFairness) {
  const ProblemSpec spec = ReadSpec(ARCHGEO_SOURCE_DIR "/examples/planar_quads.yaml",
                                    {"output.mesh=", "output.image=", "terms.fairness.weight=0",
                                     "schedule.outer_iterations=8",
                                     "output.report=" + Path("report.json")});
  const RunResult run = RunSpec(spec, {});
  ASSERT_EQ(run.exit_code, 4);
  for (const nlohmann::json& round : run.report["rounds"]) {
    EXPECT_TRUE(round["valid"].get<bool>()) << "round " << round["round"];
  }
  EXPECT_EQ(run.report["after"]["nonconvex_panels"].get<double>(), 0.0);
  EXPECT_LT(run.report["after"]["pq_normalized_max"].get<double>(),
            run.report["before"]["pq_normalized_max"].get<double>() / 3);
}

}  // namespace
}  // namespace archgeo
