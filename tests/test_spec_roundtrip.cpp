// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// `archgeo spec PROBLEM > s.yaml && archgeo solve s.yaml --set mesh=…
// --set output.mesh=… --set output.report=…` runs for every problem: the
// template of each registered problem, read back and solved on a small mesh
// of the kind it takes, ends with a result (exit 0, 3 or 4), never an input
// error, and writes its outputs when it has a valid result.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "problems/commands/generate.h"
#include "problems/declarations/registry.h"
#include "problems/commands/run.h"
#include "problems/spec/schema.h"
#include "problems/spec/spec.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

class SpecRoundTrip : public ScratchDirTest {
 protected:
  std::string Generated(const std::string& name, GenerateOptions options) {
    const std::string path = Path(name + ".obj");
    GenerateSurface(path, options);
    return path;
  }
};

TEST_F(SpecRoundTrip, EveryProblemsTemplateSolves) {
  GenerateOptions roof;
  roof.nu = 6;
  roof.nv = 5;
  GenerateOptions net;
  net.surface = "hyperbolic_paraboloid";
  GenerateOptions torus;
  torus.surface = "torus";
  torus.nu = 12;
  torus.nv = 6;
  GenerateOptions cone;
  cone.surface = "cone_start";
  cone.nu = 16;
  cone.nv = 6;
  const std::string quads = Generated("roof", roof), anet = Generated("net", net),
                    torus_quads = Generated("torus", torus), triangles = Generated("cone", cone);
  // The input each problem takes, and what it needs besides (a problem made
  // later must be added here).
  const std::string faces = "60";  // a coarse layout (an overlapping face at 60 once broke the reference)
  const std::map<std::string, std::vector<std::string>> inputs = {
      {"planar_quads", {"mesh=" + quads}},
      {"smooth_mesh", {"mesh=" + triangles}},
      {"total_absolute_curvature", {"mesh=" + triangles}},
      {"principal_symmetric", {"mesh=" + torus_quads, "split.diagonal=first"}},
      {"hnet", {"mesh=" + anet}},
      {"conjugate_field", {"mesh=" + triangles}},
      {"level_sets", {"mesh=" + triangles, "level_sets.target_faces=" + faces}},
      {"conjugate_layout", {"mesh=" + triangles, "level_sets.target_faces=" + faces}},
      {"grid", {}},
  };
  for (const std::string& name : ProblemNames()) {
    if (name == "custom") continue;
    SCOPED_TRACE(name);
    const ProblemDecl* d = FindProblem(name);
    ASSERT_NE(d, nullptr);
    ASSERT_TRUE(inputs.count(name)) << "add an input for the new problem " << name;
    const std::string spec = WriteFile(name + ".yaml", SpecTemplate(*d));
    std::vector<std::string> overrides = inputs.at(name);
    overrides.push_back("output.mesh=" + Path(name + "_out.obj"));
    overrides.push_back("output.report=" + Path(name + ".json"));
    RunResult run;
    try {
      run = RunSpec(ReadSpec(spec, overrides), {});
    } catch (const std::exception& e) {
      FAIL() << name << ": " << e.what();
    }
    EXPECT_TRUE(run.exit_code == 0 || run.exit_code == 3 || run.exit_code == 4) << run.exit_code;
    EXPECT_EQ(std::filesystem::exists(Path(name + "_out.obj")), run.exit_code != 3);
    EXPECT_TRUE(std::filesystem::exists(Path(name + ".json")) || run.exit_code == 3);
  }
}

// Outputs written in one format only refuse another name before any work
// (hnet's patchwork used to be written as PLY under a .stl name).
TEST_F(SpecRoundTrip, FixedFormatOutputsRefuseOtherNames) {
  GenerateOptions net;
  net.surface = "hyperbolic_paraboloid";
  const std::string mesh = Generated("net", net);
  const std::string spec = WriteFile("hnet.yaml", SpecTemplate(*FindProblem("hnet")));
  for (const char* name : {"output.patchwork", "output.rulings", "output.image"}) {
    const std::string key = name;
    SCOPED_TRACE(key);
    const std::string target = Path("out.stl");
    try {
      RunSpec(ReadSpec(spec, {"mesh=" + mesh, key + "=" + target}), {});
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), key);
      EXPECT_NE(e.message().find("out.stl"), std::string::npos) << e.message();
    }
    EXPECT_FALSE(std::filesystem::exists(target));
  }
}

}  // namespace
}  // namespace archgeo
