// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// `archgeo spec PROBLEM > s.yaml && archgeo solve s.yaml --set mesh=…
// --set output.mesh=… --set output.report=…` runs for every problem: the
// template of each registered problem, read back and solved on a small mesh
// of the kind it takes with only `mesh` (and a problem's required keys) set,
// ends with a result (exit 0, 3, 4 or 5), never an input error, and writes
// its outputs when it has a result.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "core/input_error.h"
#include "problems/commands/generate.h"
#include "problems/declarations/custom.h"
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
  const std::map<std::string, std::vector<std::string>> inputs = {
      {"planar_quads", {"mesh=" + quads}},
      {"smooth_mesh", {"mesh=" + triangles}},
      {"total_absolute_curvature", {"mesh=" + triangles}},
      {"principal_symmetric", {"mesh=" + torus_quads, "split.diagonal=first"}},
      {"hnet", {"mesh=" + anet}},
      {"conjugate_field", {"mesh=" + triangles}},
      {"level_sets", {"mesh=" + triangles}},
      // 300 faces instead of the template's 1,600: this cone of 192
      // triangles makes a layout of 1,400 faces in ~20 s otherwise.
      {"conjugate_layout", {"mesh=" + triangles, "level_sets.target_faces=300"}},
      {"grid", {}},
      {"wave_quads", {"mesh=" + triangles}},
      {"spectral_quads", {std::string("mesh=") + ARCHGEO_SOURCE_DIR + "/examples/sphere.obj"}},
      {"custom", {"mesh=" + quads}},
      {"base_complex_quads",
       {std::string("mesh=") + ARCHGEO_SOURCE_DIR + "/examples/octahedron_sphere.obj",
        std::string("base_complex.mesh=") + ARCHGEO_SOURCE_DIR + "/examples/octahedron.obj"}},
      {"subdivide", {"mesh=" + quads}},
      {"remesh", {"mesh=" + triangles}},
  };
  const ProblemDecl custom = CustomExample();
  for (const std::string& name : ProblemNames()) {
    SCOPED_TRACE(name);
    const ProblemDecl* d = name == "custom" ? &custom : FindProblem(name);
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
    EXPECT_TRUE(run.exit_code == 0 || run.exit_code == 3 || run.exit_code == 4 ||
                run.exit_code == 5)
        << run.exit_code;
    EXPECT_EQ(std::filesystem::exists(Path(name + "_out.obj")), run.exit_code != 3);
    EXPECT_TRUE(std::filesystem::exists(Path(name + ".json")) || run.exit_code == 3);
  }
}

// A template gives only defaults: read back, every key it sets holds its
// default, but for the keys a spec must give (the grid's surface, a custom
// problem's terms); keys without a default (field.moves, handles,
// output.color_max, …) are comments, so a template moves no singularity and
// no vertex the user did not ask for.
TEST_F(SpecRoundTrip, TemplatesSetDefaultsOnly) {
  const ProblemDecl custom = CustomExample();
  for (const std::string& name : ProblemNames()) {
    SCOPED_TRACE(name);
    const ProblemDecl* d = name == "custom" ? &custom : FindProblem(name);
    const std::string text = SpecTemplate(*d);
    const ProblemSpec spec = ParseSpec(text, Path(name + ".yaml"), {"mesh=in.obj"});
    int unset_examples = 0;
    for (const Key& k : spec.settings.schema().keys()) {
      if (k.name == "mesh" || k.required) continue;
      if (name == "custom" && k.name.rfind("terms.", 0) == 0) continue;
      const bool unset = std::holds_alternative<std::monostate>(k.fallback);
      if (unset && !k.example.empty()) {
        EXPECT_FALSE(spec.settings.Given(k.name)) << k.name << " has no default but is set";
        ++unset_examples;
        continue;
      }
      if (unset) {  // a path: written as "", which is none
        EXPECT_EQ(ToText(spec.settings.Get(k.name)), "") << k.name;
        continue;
      }
      if (k.type == Type::kCustom) continue;  // its default is written as such (select: all)
      EXPECT_EQ(ToText(spec.settings.Get(k.name)), ToText(k.fallback)) << k.name;
    }
    EXPECT_GE(unset_examples, 1);  // output.color_max at least, shown as a comment
  }
  EXPECT_NE(SpecTemplate(*FindProblem("conjugate_layout")).find("# moves: [{from:"),
            std::string::npos);
  EXPECT_NE(SpecTemplate(*FindProblem("planar_quads")).find("# color_max: "), std::string::npos);
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
