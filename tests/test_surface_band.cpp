// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The deviation band (problems/declarations/design_band.h): the bounded
// manifold of energies/surface_band.h (never outside, Plus/Minus inverse,
// Jacobians against differences) and planar_quads on a noisy roof whose
// planarisation needs about 0.75% of the diagonal: at a 0.3% band it ends
// exit 4 (missed) with the band held, naming the band and the deviation its
// band tightening met the goals at (without the tightening: the deviation
// the same run reaches without the band); at 0.5% it meets the tolerance
// inside the band (the band shapes the result); at 1% it is not in the way.
// The band tightening on the shared botanic bubble, whose default rounds
// stall above δ_PQ,n 1e-3 inside 0.3%: with it, exit 0 inside the band.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "analysis/metrics.h"
#include "io/io.h"
#include "energies/surface_band.h"
#include "generators/generators.h"
#include "mesh/similarity.h"
#include "problems/commands/run.h"
#include "problems/runtime/solve.h"
#include "problems/spec/spec.h"
#include "scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using Directions = Eigen::Matrix<double, 3, Eigen::Dynamic>;

Directions Normal() { return Eigen::Vector3d(0.6, 0.0, 0.8); }
Directions Across() {
  Directions d(3, 2);
  d.col(0) = Eigen::Vector3d(1, 0, 0);
  d.col(1) = Eigen::Vector3d(0, 0.6, 0.8);
  return d;
}
Directions Ball() { return Eigen::Matrix3d::Identity(); }

Eigen::Vector3d Plus(const BandManifold& m, const Eigen::Vector3d& x, const Eigen::Vector3d& d) {
  Eigen::Vector3d y;
  m.Plus(x.data(), d.data(), y.data());
  return y;
}

TEST(SurfaceBand, NoStepLeavesTheBand) {
  const Eigen::Vector3d p(1, 2, 3);
  std::mt19937 rng(7);
  std::normal_distribution<double> g(0, 1);
  for (const Directions& d : {Normal(), Across(), Ball()}) {
    const BandManifold m(p, d, 0.2);
    Eigen::Vector3d x = p + Eigen::Vector3d(0.05, -0.03, 0.1);
    for (int k = 0; k < 200; ++k) {
      const Eigen::Vector3d step(g(rng) * 10, g(rng) * 10, g(rng) * 10);
      x = Plus(m, x, step);
      ASSERT_LT(m.Offset(x.data()).norm(), 0.2) << "step " << k;
    }
  }
}

TEST(SurfaceBand, TangentialStepsAreFreeAndSmallStepsLinear) {
  const Eigen::Vector3d p(0, 0, 0);
  const BandManifold m(p, Normal(), 0.2);
  const Eigen::Vector3d x(0.3, 1.0, 0.0);  // on the plane: offset 0.18 of 0.2
  const Eigen::Vector3d tangent(0, 5, 0);   // orthogonal to n
  EXPECT_NEAR((Plus(m, x, tangent) - (x + tangent)).norm(), 0, 1e-12);
  // Far from the edge (o = 0) the map is the identity to first order.
  const Eigen::Vector3d centre(0, 1, 0), tiny(1e-7, 2e-7, -1e-7);
  EXPECT_NEAR((Plus(m, centre, tiny) - (centre + tiny)).norm(), 0, 1e-16);
}

TEST(SurfaceBand, JacobiansMatchDifferencesAndMinusInvertsPlus) {
  const Eigen::Vector3d p(0.1, -0.2, 0.3);
  for (const Directions& d : {Normal(), Across(), Ball()}) {
    const BandManifold m(p, d, 0.25);
    for (const Eigen::Vector3d& x : {Eigen::Vector3d(p + Eigen::Vector3d(0.1, 0.05, 0.12)),
                                     Eigen::Vector3d(p + Eigen::Vector3d(0.0, 0.2, 0.0))}) {
      double plus[9], minus[9];
      m.PlusJacobian(x.data(), plus);
      m.MinusJacobian(x.data(), minus);
      const Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> jp(plus), jm(minus);
      const double h = 1e-6;
      for (int c = 0; c < 3; ++c) {
        const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(c);
        const Eigen::Vector3d numeric = (Plus(m, x, e) - Plus(m, x, -e)) / (2 * h);
        EXPECT_NEAR((numeric - jp.col(c)).norm(), 0, 1e-7);
      }
      EXPECT_NEAR((jm * jp - Eigen::Matrix3d::Identity()).norm(), 0, 1e-9);
      const Eigen::Vector3d delta(0.3, -0.7, 0.4);
      const Eigen::Vector3d y = Plus(m, x, delta);
      Eigen::Vector3d back;
      m.Minus(y.data(), x.data(), back.data());
      EXPECT_NEAR((back - delta).norm(), 0, 1e-9);
    }
  }
}

TEST(SurfaceBand, InRoundBound) {
  EXPECT_DOUBLE_EQ(BandBound(0.1, 1, 0.95), 0.95);   // inside: s·b
  EXPECT_DOUBLE_EQ(BandBound(0.97, 1, 0.95), 0.985);  // beyond s·b: halfway to b
  EXPECT_DOUBLE_EQ(BandBound(2, 1, 0.95), 2.002);     // beyond b: no farther out
}

// A noisy roof (12 × 10 quads, noise 0.15 mean edges) in its canonical
// frame; planar_quads with the band `band` against the roof itself.
struct BandRun {
  std::unique_ptr<Solution> solution;
  double deviation = 0;  // of the output, analysis/metrics.h, / the diagonal
};

BandRun Roof(double band, int rounds = 16, int tightening = 16) {
  Mesh roof = QuadGrid(12, 10, RoofSurface, 0.15, 1);
  const Mesh original = roof;
  const ProblemSpec spec = ParseSpec(
      "problem: planar_quads\ntolerance: {surface_distance_max: " + std::to_string(band) +
      "}\nschedule: {outer_iterations: " + std::to_string(rounds) +
      "}\nstall: {band_tightening: " + std::to_string(tightening) + "}\n");
  BandRun r;
  r.solution = Solve(spec, roof, &original, {});
  const ReferenceSurface reference(original);
  const Metrics m = ComputeMetrics(r.solution->output, &reference, &original);
  r.deviation = m.surface_distance_max / PrincipalBoxDiagonal(original);
  return r;
}

bool PlanarityMet(const BandRun& r) {
  return r.solution->loop.tolerances.at("tolerance.pq_normalized_max");
}

void ExpectBindsAtThreeTenthsPercent(const BandRun& r) {
  EXPECT_FALSE(PlanarityMet(r));
  EXPECT_TRUE(r.solution->loop.tolerances.at("tolerance.surface_distance_max"));
  EXPECT_LE(r.deviation, 0.003 + 1e-9);
  EXPECT_GE(r.deviation, 0.9 * 0.003);  // at the band: it binds
  EXPECT_TRUE(r.solution->details.at("surface_band").at("binds").get<bool>());
  EXPECT_NE(r.solution->headline.find("BAND BINDS: the goals were missed at the deviation "
                                      "band (0.3% of the diagonal"),
            std::string::npos);
}

TEST(SurfaceBand, PlanarQuadsHoldsTheBand) {
  // Unbounded, the planarisation moves the roof about 0.75% of its diagonal.
  const BandRun unbounded = Roof(0);
  ASSERT_TRUE(PlanarityMet(unbounded));
  ASSERT_GT(unbounded.deviation, 0.006);

  // Missed at 0.3%: exit 4, the band held. The band tightening opened the
  // band, met the goals and closed it again; the report gives the smallest
  // deviation a round met them at.
  const BandRun tight = Roof(0.003, 6);
  ExpectBindsAtThreeTenthsPercent(tight);
  const nlohmann::json& band = tight.solution->details.at("surface_band");
  ASSERT_GE(band.at("tightening").size(), 2u);
  EXPECT_EQ(band.at("tightening")[0].at("band_relative").get<double>(), 0.0);  // opened
  const double needed = band.at("goals_needed_relative").get<double>();
  EXPECT_GT(needed, 0.003);
  EXPECT_LE(needed, 1.05 * unbounded.deviation);
  EXPECT_NE(tight.solution->headline.find("; a round met them at a deviation of 0."),
            std::string::npos);

  // Without the tightening no round met the planarity, so the report
  // measures what it needs: the same run without the band, whose deviation
  // is the unbounded one's.
  const BandRun plain = Roof(0.003, 6, 0);
  ExpectBindsAtThreeTenthsPercent(plain);
  EXPECT_FALSE(plain.solution->details.at("surface_band").contains("tightening"));
  const nlohmann::json& need = plain.solution->details.at("surface_band").at("unbounded");
  EXPECT_TRUE(need.at("goals_met").get<bool>());
  EXPECT_NEAR(need.at("deviation_relative").get<double>(), unbounded.deviation,
              0.05 * unbounded.deviation);
  EXPECT_NE(plain.solution->headline.find("without the band the same run met them at a "
                                          "deviation of 0."),
            std::string::npos);

  const BandRun within = Roof(0.005);  // met inside the band
  EXPECT_TRUE(PlanarityMet(within));
  EXPECT_LE(within.deviation, 0.005 + 1e-9);

  const BandRun loose = Roof(0.01);
  EXPECT_TRUE(PlanarityMet(loose));
  EXPECT_LE(loose.deviation, 0.01);
  EXPECT_FALSE(loose.solution->details.at("surface_band").at("binds").get<bool>());
}

// examples/planar_quads.yaml on the shared botanic bubble (DOS) at a 0.3%
// band: the rounds at the band stall above the planarity tolerance; the
// band tightening reaches it inside the band from the planar state the open
// band gives, with E not above the input's (exit 0). The deviation is
// measured again here against the input surface, and by MeasureFiles.
class BandTightening : public ScratchDirTest {};

TEST_F(BandTightening, BubbleMeetsPlanarityInsideThreeTenthsPercent) {
  const std::string input = std::string(ARCHGEO_DATA_DIR) + "/dos_botanic-garden-bubble-0.obj";
  // Without the tightening (stall.band_tightening: 0) the same run ends
  // exit 4 at δ_PQ,n 1.9e-3 (docs/methods/design_band.md).
  const RunResult tightened =
      RunSpec(ReadSpec(ARCHGEO_SOURCE_DIR "/examples/planar_quads.yaml",
                       {"mesh=" + input, "output.mesh=" + Path("out.obj"),
                        "output.report=" + Path("r.json"), "tolerance.surface_distance_max=0.003"}),
              {});
  ASSERT_EQ(tightened.exit_code, 0) << tightened.summary;
  EXPECT_LE(tightened.report.at("after").at("pq_normalized_max").get<double>(), 1e-3);
  const Mesh original = ReadMesh(input), output = ReadMesh(Path("out.obj"));
  const ReferenceSurface reference(original);
  const Metrics m = ComputeMetrics(output, &reference, &original);
  EXPECT_LE(m.surface_distance_max / PrincipalBoxDiagonal(original), 0.003 + 1e-9);
  // `archgeo measure OUT --reference IN` gives the report's relative
  // deviation: both relative to the input's diagonal.
  const RunResult measured = MeasureFiles(Path("out.obj"), input, false, false);
  EXPECT_NEAR(measured.report.at("metrics").at("surface_distance_max_relative").get<double>(),
              tightened.report.at("after").at("surface_distance_max_relative").get<double>(), 1e-9);
  EXPECT_TRUE(tightened.report.at("details").at("surface_band").contains("tightening"));
  EXPECT_TRUE(tightened.report.at("tolerances")
                  .at("tolerance.energy_not_above_input")
                  .at("met")
                  .get<bool>());
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
