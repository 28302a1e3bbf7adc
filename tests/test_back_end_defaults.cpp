// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The problems whose default back end is LeanSolve (solver.back_end: lean;
// docs/methods/engine.md, Solver back ends) solve every round by its
// Cholesky steps and reach what Ceres reaches with the same spec: hnet and
// total_absolute_curvature the same rounds, iterations and objective; the
// rounds of every multiresolution level of principal_symmetric are counted
// in the report's cholesky_rounds (the totals of all levels); conjugate_field
// and level_sets the same rounds and objective.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "problems/commands/run.h"
#include "problems/spec/spec.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

class BackEndDefaults : public ScratchDirTest {
 protected:
  nlohmann::json Run(const std::string& example, std::vector<std::string> overrides,
                     int exit_code = 0) {
    overrides.push_back("output.report=" + Path("report.json"));
    const ProblemSpec spec =
        ReadSpec(std::string(ARCHGEO_SOURCE_DIR "/examples/") + example + ".yaml", overrides);
    const RunResult run = RunSpec(spec, {});
    EXPECT_EQ(run.exit_code, exit_code) << example;
    return run.report;
  }

  // The example by its default back end and by Ceres: every round of the
  // first by LeanSolve, none of the second; the same rounds (and, with
  // `same_iterations`, iterations); objectives within `relative`.
  void ExpectLeanReachesCeres(const std::string& example, const std::vector<std::string>& keys,
                              double relative, bool same_iterations) {
    const nlohmann::json lean = Run(example, keys);
    std::vector<std::string> with_ceres = keys;
    with_ceres.push_back("solver.back_end=ceres");
    const nlohmann::json ceres = Run(example, with_ceres);
    const int rounds = lean["iterations"]["outer"].get<int>();
    ASSERT_GT(rounds, 0) << example;
    EXPECT_EQ(lean["cholesky_rounds"].get<int>(), rounds) << example << ": every round by LeanSolve";
    EXPECT_EQ(ceres["cholesky_rounds"].get<int>(), 0) << example;
    EXPECT_EQ(ceres["iterations"]["outer"].get<int>(), rounds) << example;
    if (same_iterations) {
      EXPECT_EQ(ceres["iterations"]["inner"].get<int>(), lean["iterations"]["inner"].get<int>()) << example;
    }
    const double a = lean["objective"]["total"].get<double>();
    const double b = ceres["objective"]["total"].get<double>();
    EXPECT_NEAR(a, b, relative * b) << example;
  }
};

TEST_F(BackEndDefaults, HnetAndTotalAbsoluteCurvatureReachCeresObjectiveByLeanSolve) {
  ExpectLeanReachesCeres("hnet", {"output.mesh=", "output.patchwork=", "output.rulings="}, 1e-6, true);
  ExpectLeanReachesCeres("total_absolute_curvature", {"output.mesh=", "schedule.outer_iterations=2"},
                         1e-6, true);
}

// The field and level-set problems (and so every stage of conjugate_layout,
// which solves them nested) take LeanSolve's Cholesky steps by default: the
// same rounds and the same objective to 1e-9 (their last bits differ).
TEST_F(BackEndDefaults, FieldAndLevelSetsReachCeresObjectiveByLeanSolve) {
  ExpectLeanReachesCeres("conjugate_field", {"output.field="}, 1e-9, false);
  ExpectLeanReachesCeres("level_sets", {"output.field=", "output.layout="}, 1e-9, false);
}

TEST_F(BackEndDefaults, MultiresolutionCountsTheLeanRoundsOfEveryLevel) {
  const nlohmann::json report =
      Run("multiresolution", {"output.mesh=", "output.principal_edges=", "schedule.outer_iterations=2",
                           "solver.max_num_iterations=5"},
          4);  // five iterations a round do not meet the tolerances
  const nlohmann::json& levels = report["multiresolution"]["levels"];
  ASSERT_EQ(levels.size(), 2u);
  const int first = levels[0]["rounds"].get<int>(), last = levels[1]["rounds"].get<int>();
  ASSERT_GT(first, 0);
  ASSERT_GT(last, 0);
  EXPECT_EQ(report["iterations"]["outer"].get<int>(), first + last);
  EXPECT_EQ(report["cholesky_rounds"].get<int>(), first + last);
}

}  // namespace
}  // namespace archgeo
