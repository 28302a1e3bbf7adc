// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Outputs are byte-identical run to run at a fixed thread count (README,
// "Exit codes and guarantees"): the same spec, mesh and `solver.num_threads` give the same
// output mesh and the same report figures, with Ceres' rounds and with
// LeanSolve's (solver.pcg_above=1), for 1, 2 and 4 threads. (Thread counts
// may differ in the last bits: each sums in its own order.) OpenMP runs the
// 4 threads on any number of cores, so LeanSolve's parallel assembly and
// sums run here even on one core.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "problems/commands/generate.h"
#include "problems/commands/run.h"
#include "problems/spec/spec.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

class Determinism : public ScratchDirTest {
 protected:
  std::string Bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  // Solves `example` on `mesh` and returns the output mesh's bytes.
  std::string Solve(const std::string& example, const std::string& mesh, int threads,
                    const std::string& tag, nlohmann::json* report,
                    const std::vector<std::string>& more = {}) {
    const std::string out = Path(tag + ".ply");
    std::vector<std::string> overrides = {"mesh=" + mesh, "output.mesh=" + out, "output.report=",
                                          "output.image=",
                                          "solver.num_threads=" + std::to_string(threads)};
    overrides.insert(overrides.end(), more.begin(), more.end());
    const RunResult run =
        RunSpec(ReadSpec(std::string(ARCHGEO_SOURCE_DIR) + "/examples/" + example, overrides), {});
    EXPECT_NE(run.exit_code, 3);
    *report = run.report;
    return Bytes(out);
  }
};

TEST_F(Determinism, SameThreadsSameBytes) {
  GenerateOptions roof;
  roof.nu = 24;
  roof.nv = 18;
  const std::string quads = Path("roof.obj");
  GenerateSurface(quads, roof);
  GenerateOptions cone;
  cone.surface = "cone_start";
  cone.nu = 24;
  cone.nv = 8;
  const std::string triangles = Path("cone.obj");
  GenerateSurface(triangles, cone);
  for (const auto& [example, mesh] :
       {std::pair<std::string, std::string>{"planar_quads.yaml", quads},
        std::pair<std::string, std::string>{"smooth_mesh.yaml", triangles}}) {
    for (int threads : {1, 2, 4}) {
      SCOPED_TRACE(example + " threads " + std::to_string(threads));
      nlohmann::json a, b;
      const std::string first = Solve(example, mesh, threads, "a", &a);
      const std::string second = Solve(example, mesh, threads, "b", &b);
      ASSERT_FALSE(first.empty());
      EXPECT_EQ(first, second);
      EXPECT_EQ(a["objective"], b["objective"]);
      EXPECT_EQ(a["after"], b["after"]);
    }
  }
}

// LeanSolve's rounds: every round of a planar_quads solve by LeanSolve, each
// thread count twice; the rounds did run on LeanSolve.
TEST_F(Determinism, LeanSolveSameThreadsSameBytes) {
  GenerateOptions roof;
  roof.nu = 30;
  roof.nv = 24;
  roof.noise = 0.1;
  const std::string quads = Path("roof.obj");
  GenerateSurface(quads, roof);
  for (int threads : {1, 2, 4}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    nlohmann::json a, b;
    const std::string first =
        Solve("planar_quads.yaml", quads, threads, "a", &a, {"solver.pcg_above=1"});
    const std::string second =
        Solve("planar_quads.yaml", quads, threads, "b", &b, {"solver.pcg_above=1"});
    ASSERT_FALSE(first.empty());
    EXPECT_GT(a["pcg"]["rounds"].get<int>(), 0) << a["pcg"];
    EXPECT_EQ(a["pcg"]["rounds"], a["iterations"]["outer"]);
    EXPECT_EQ(first, second);
    EXPECT_EQ(a["objective"], b["objective"]);
    EXPECT_EQ(a["after"], b["after"]);
  }
}

}  // namespace
}  // namespace archgeo
