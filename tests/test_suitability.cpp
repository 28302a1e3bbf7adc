// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Input suitability warnings (problems/declarations/suitability.h), end to end: each
// problem warns, before solving and in the summary, when its input net is far
// from what it can make buildable, with the figures in details.suitability,
// and stays quiet on the inputs it is made for:
//  - hnet: the negshell's own quad mesh (edges 48° from the asymptotic
//    directions) warns; its diagonal A-net (3°) does not;
//  - planar_quads: DOS M2 (conjugacy 0.47) warns; libigl's conjugate layout
//    (0.17) does not;
//  - principal_symmetric: a torus patch split with its quad edges as the
//    principal family is quiet; with the diagonals labelled principal it
//    warns (they are ~40° off), and the solve is then refused as invalid.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "generators/generators.h"
#include "io/io.h"
#include "problems/commands/run.h"
#include "problems/spec/spec.h"
#include "scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

const std::string kData = ARCHGEO_DATA_DIR;
const std::string kExamples = ARCHGEO_SOURCE_DIR "/examples/";

class Suitability : public ScratchDirTest {
 protected:
  RunResult Run(const std::string& example, std::vector<std::string> sets) {
    sets.push_back("output={report: " + Path("r.json") + "}");
    return RunSpec(ReadSpec(kExamples + example, sets), {});
  }
  static const nlohmann::json& Figures(const RunResult& r) {
    return r.report.at("details").at("suitability");
  }
  static bool Warned(const RunResult& r) {
    return r.summary.find("WARNING (input suitability)") != std::string::npos;
  }
};

TEST_F(Suitability, HNetWarnsOnANetThatIsNotAlongAsymptoticDirections) {
  const std::string shell = kData + "/dos_free_negshell_marc_anet.obj";
  const RunResult mesh = Run("hnet.yaml", {"mesh=" + shell, "hnet.net=mesh",
                                           "schedule.outer_iterations=1", "hnet.alternations=0"});
  EXPECT_TRUE(Warned(mesh)) << mesh.summary;
  EXPECT_FALSE(Figures(mesh).at("suitable").get<bool>());
  EXPECT_GT(Figures(mesh).at("asymptotic_angle_mean_degrees").get<double>(), 30.0);
  const RunResult anet = Run("hnet.yaml", {"mesh=" + shell});
  EXPECT_FALSE(Warned(anet)) << anet.summary;
  EXPECT_TRUE(Figures(anet).at("suitable").get<bool>());
  EXPECT_LT(Figures(anet).at("asymptotic_angle_mean_degrees").get<double>(), 5.0);
  EXPECT_EQ(Figures(anet).at("positive_curvature_fraction").get<double>(), 0.0);
}

TEST_F(Suitability, PlanarQuadsWarnsOnANetFarFromConjugate) {
  const RunResult m2 = Run("planar_quads.yaml", {"mesh=" + kData + "/dos_M2_eq_quad2.obj",
                                                 "schedule.outer_iterations=1", "output.image="});
  EXPECT_TRUE(Warned(m2)) << m2.summary;
  EXPECT_GT(Figures(m2).at("conjugacy_mean").get<double>(), 0.4);
  const RunResult conjugate =
      Run("planar_quads.yaml", {"mesh=" + kData + "/libigl_inspired_mesh_quads_Conjugate.off",
                                "schedule.outer_iterations=1", "output.image="});
  EXPECT_FALSE(Warned(conjugate)) << conjugate.summary;
  EXPECT_LT(Figures(conjugate).at("conjugacy_mean").get<double>(), 0.25);
}

Vec3 TorusPatch(double u, double v) {
  const double a = 1.2 * u, b = 2.5 * v;  // radians along the tube and around it
  return {(3 + std::cos(b)) * std::cos(a), (3 + std::cos(b)) * std::sin(a), std::sin(b)};
}

TEST_F(Suitability, PrincipalSymmetricWarnsOnLabelsOffThePrincipalDirections) {
  WriteMesh(Path("torus.obj"), QuadGrid(16, 12, TorusPatch));
  const auto run = [&](const std::string& principal) {
    const std::string spec = WriteFile(
        "ps.yaml", "mesh: torus.obj\nproblem: principal_symmetric\nsplit: {diagonal: first, "
                   "principal: " + principal + "}\nschedule: {outer_iterations: 1}\n"
                   "output: {report: r.json}\n");
    return RunSpec(ReadSpec(spec), {});
  };
  const RunResult along = run("first");
  EXPECT_FALSE(Warned(along)) << along.summary;
  EXPECT_LT(Figures(along).at("principal_angle_mean_degrees").get<double>(), 2.0);
  // Warned before solving; the solve then folds the torus and is refused
  // (exit 3), and the refusal repeats the warning.
  const RunResult diagonals = run("diagonals");
  EXPECT_EQ(diagonals.exit_code, 3);
  EXPECT_TRUE(Warned(diagonals)) << diagonals.summary;
  EXPECT_FALSE(Figures(diagonals).at("suitable").get<bool>());
  EXPECT_GT(Figures(diagonals).at("principal_angle_mean_degrees").get<double>(), 20.0);
}

}  // namespace
}  // namespace archgeo
