// The YAML problem spec: defaults, overrides and every class of bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "mesh/input_error.h"
#include "problems/spec.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace {

namespace fs = std::filesystem;

class SpecTest : public ScratchDirTest {
 protected:
  std::string Write(const std::string& text) { return WriteFile("spec.yaml", text); }

  // The InputError thrown by ReadSpec, or a failure.
  InputError Error(const std::string& text, const std::vector<std::string>& overrides = {}) {
    const std::string path = Write(text);
    try {
      ReadSpec(path, overrides);
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return InputError("", 0, "", "");
  }

};

TEST_F(SpecTest, DefaultsAndPathsRelativeToTheSpec) {
  const ProblemSpec s = ReadSpec(Write("mesh: roof.obj\noutput: {mesh: out/r.ply}\n"));
  EXPECT_EQ(s.mesh, (dir_ / "roof.obj").string());
  EXPECT_EQ(s.output_mesh, (dir_ / "out/r.ply").string());
  EXPECT_EQ(s.problem, "planar_quads");
  const nlohmann::json settings = s.builder->SettingsJson();
  EXPECT_DOUBLE_EQ(settings["tolerance"]["pq_normalized_max"].get<double>(), 1e-3);
  EXPECT_GT(settings["terms"]["proximity"]["weight"].get<double>(), 0);
  EXPECT_EQ(s.solver.linear_solver, "sparse_normal_cholesky");
  EXPECT_EQ(s.fixed, "none");
}

TEST_F(SpecTest, ListedTermsTurnTheOthersOff) {
  const ProblemSpec s =
      ReadSpec(Write("mesh: a.obj\nterms:\n  pq_diagonal: 2\n  fairness: {weight: 0.5}\n"));
  const nlohmann::json terms = s.builder->SettingsJson()["terms"];
  EXPECT_DOUBLE_EQ(terms["pq_diagonal"].get<double>(), 2);
  EXPECT_DOUBLE_EQ(terms["fairness"]["weight"].get<double>(), 0.5);
  EXPECT_TRUE(terms["fairness"]["relative_to_original"].get<bool>());
  EXPECT_DOUBLE_EQ(terms["proximity"]["weight"].get<double>(), 0);
  EXPECT_DOUBLE_EQ(terms["anchor"].get<double>(), 0);
}

TEST_F(SpecTest, SetOverridesByDottedPath) {
  const ProblemSpec s = ReadSpec(Write("mesh: a.obj\nsolver: {threads: 2}\n"),
                                 {"solver.threads=1", "mesh=/data/b.off",
                                  "tolerance.pq_normalized_max=5e-3", "fixed=[0, 3]"});
  EXPECT_EQ(s.solver.threads, 1);
  EXPECT_EQ(s.mesh, "/data/b.off");
  EXPECT_DOUBLE_EQ(
      s.builder->SettingsJson()["tolerance"]["pq_normalized_max"].get<double>(), 5e-3);
  EXPECT_EQ(s.fixed, "ids");
  EXPECT_EQ(s.fixed_ids, (std::vector<int>{0, 3}));
  EXPECT_EQ(s.fixed_file, "--set");
}

TEST_F(SpecTest, EmptyOutputsAreNotWritten) {
  const ProblemSpec s = ReadSpec(Write("mesh: a.obj\noutput: {mesh: out.ply, report: r.json}\n"),
                                 {"output.mesh=", "output.report="});
  EXPECT_TRUE(s.output_mesh.empty());
  EXPECT_TRUE(s.output_report.empty());
}

TEST_F(SpecTest, SetPathsAreRelativeToTheCurrentFolder) {
  const ProblemSpec s = ReadSpec(Write("mesh: a.obj\n"), {"output.mesh=x/y.obj"});
  EXPECT_EQ(s.output_mesh, (fs::current_path() / "x/y.obj").string());
}

TEST_F(SpecTest, MissingFile) {
  try {
    ReadSpec((dir_ / "nope.yaml").string());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nope.yaml"), std::string::npos);
  }
}

TEST_F(SpecTest, MalformedYamlNamesTheLine) {
  const InputError e = Error("mesh: a.obj\nsolver: {threads: 2\nterms: [\n");
  EXPECT_GE(e.line(), 2);
  EXPECT_NE(std::string(e.what()).find("malformed YAML"), std::string::npos);
}

TEST_F(SpecTest, UnknownKeyNamesLineAndKey) {
  const InputError e = Error("mesh: a.obj\nsolver:\n  treads: 2\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.key(), "solver.treads");
  EXPECT_NE(std::string(e.what()).find("unknown key"), std::string::npos);
}

TEST_F(SpecTest, UnknownTopLevelAndTermKeys) {
  EXPECT_EQ(Error("mesh: a.obj\nmesch: b\n").key(), "mesch");
  EXPECT_EQ(Error("mesh: a.obj\nterms: {planarity: 1}\n").key(), "terms.planarity");
}

TEST_F(SpecTest, WrongTypesNameLineAndKey) {
  InputError e = Error("mesh: a.obj\nsolver:\n  threads: two\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.key(), "solver.threads");
  EXPECT_NE(std::string(e.what()).find("expected an integer"), std::string::npos);
  EXPECT_EQ(Error("mesh: a.obj\nterms: {proximity: [1]}\n").key(), "terms.proximity");
  EXPECT_EQ(Error("mesh: [a.obj]\n").key(), "mesh");
  EXPECT_EQ(Error("mesh: a.obj\noutput: {ascii_ply: maybe}\n").key(), "output.ascii_ply");
  EXPECT_EQ(Error("mesh: a.obj\nsolver: {linear_solver: lu}\n").key(), "solver.linear_solver");
  EXPECT_EQ(Error("mesh: a.obj\nfixed: some\n").key(), "fixed");
}

TEST_F(SpecTest, OutOfRangeValues) {
  EXPECT_EQ(Error("mesh: a.obj\nterms: {anchor: -1}\n").key(), "terms.anchor");
  EXPECT_EQ(Error("mesh: a.obj\nsolver: {threads: 0}\n").key(), "solver.threads");
  EXPECT_EQ(Error("mesh: a.obj\ntolerance: {pq_normalized_max: .nan}\n").key(),
            "tolerance.pq_normalized_max");
}

TEST_F(SpecTest, MissingMeshKey) {
  const InputError e = Error("problem: planar_quads\n");
  EXPECT_EQ(e.key(), "mesh");
}

TEST_F(SpecTest, NotAMapping) { EXPECT_NE(Error("- a\n- b\n").line(), -1); }

TEST_F(SpecTest, BadOverridesNameTheOption) {
  InputError e = Error("mesh: a.obj\n", {"solver.threads=zwei"});
  EXPECT_EQ(e.file(), "--set");
  EXPECT_EQ(e.key(), "solver.threads");
  EXPECT_EQ(Error("mesh: a.obj\n", {"noequals"}).file(), "--set");
  EXPECT_EQ(Error("mesh: a.obj\n", {"solver.bogus=1"}).key(), "solver.bogus");
  EXPECT_EQ(Error("mesh: a.obj\n", {"mesh.x=1"}).file(), "--set");
}

}  // namespace
}  // namespace archgeo

namespace archgeo {
namespace {

// A --set that would create the `terms:` section (and so switch every
// unlisted default term off) is refused; with a `terms:` section it works.
TEST_F(SpecTest, SetOfATermNeedsATermsSection) {
  const std::string bare = Write("mesh: a.obj\n");
  try {
    ReadSpec(bare, {"terms.anchor=1"});
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "--set");
    EXPECT_EQ(e.key(), "terms.anchor");
  }
  const ProblemSpec s =
      ReadSpec(Write("mesh: a.obj\nterms: {anchor: 0.5, pq_diagonal: 3}\n"), {"terms.anchor=1"});
  const nlohmann::json terms = s.builder->SettingsJson()["terms"];
  EXPECT_DOUBLE_EQ(terms["anchor"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(terms["pq_diagonal"].get<double>(), 3.0);
}

}  // namespace
}  // namespace archgeo
