// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Outputs are byte-identical run to run at a fixed thread count (README,
// Guarantees): the same spec, mesh and `solver.num_threads` give the same
// output mesh and the same report figures. (Threads 1 and 2 may differ in the
// last bits: Ceres sums the Jacobian blocks of a thread in its own order.)
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "problems/generate.h"
#include "problems/run.h"
#include "problems/spec.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace {

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
                    const std::string& tag, nlohmann::json* report) {
    const std::string out = Path(tag + ".ply");
    const RunResult run =
        RunSpec(ReadSpec(std::string(ARCHGEO_SOURCE_DIR) + "/examples/" + example,
                         {"mesh=" + mesh, "output.mesh=" + out, "output.report=",
                          "output.image=", "solver.num_threads=" + std::to_string(threads)}),
                {});
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
    for (int threads : {1, 2}) {
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

}  // namespace
}  // namespace archgeo
