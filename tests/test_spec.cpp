// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The YAML problem spec: defaults, overrides and every class of bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/input_error.h"
#include "problems/declarations/registry.h"
#include "problems/spec/schema.h"
#include "problems/spec/spec.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

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
  EXPECT_EQ(s.mesh(), (dir_ / "roof.obj").string());
  EXPECT_EQ(s.settings.String("output.mesh"), (dir_ / "out/r.ply").string());
  EXPECT_EQ(s.problem(), "planar_quads");
  EXPECT_DOUBLE_EQ(s.settings.Number("tolerance.pq_normalized_max"), 1e-3);
  EXPECT_GT(s.settings.Number("terms.proximity.weight"), 0);
  EXPECT_EQ(s.settings.String("solver.linear_solver_type"), "sparse_normal_cholesky");
  EXPECT_EQ(s.settings.String("fixed"), "none");
}

TEST_F(SpecTest, ListedTermsTurnTheOthersOff) {
  const ProblemSpec s =
      ReadSpec(Write("mesh: a.obj\nterms:\n  pq_diagonal: 2\n  fairness: {weight: 0.5}\n"));
  EXPECT_DOUBLE_EQ(s.settings.Number("terms.pq_diagonal.weight"), 2);
  EXPECT_DOUBLE_EQ(s.settings.Number("terms.fairness.weight"), 0.5);
  EXPECT_TRUE(s.settings.Bool("terms.fairness.relative_to_original"));
  EXPECT_DOUBLE_EQ(s.settings.Number("terms.proximity.weight"), 0);
  EXPECT_DOUBLE_EQ(s.settings.Number("terms.anchor.weight"), 0);
}

TEST_F(SpecTest, SetOverridesByDottedPath) {
  const ProblemSpec s = ReadSpec(Write("mesh: a.obj\nsolver: {num_threads: 2}\n"),
                                 {"solver.num_threads=1", "mesh=/data/b.off",
                                  "tolerance.pq_normalized_max=5e-3", "fixed=[0, 3]"});
  EXPECT_EQ(s.settings.Integer("solver.num_threads"), 1);
  EXPECT_EQ(s.mesh(), "/data/b.off");
  EXPECT_DOUBLE_EQ(s.settings.Number("tolerance.pq_normalized_max"), 5e-3);
  EXPECT_EQ(s.settings.Integers("fixed"), (std::vector<long long>{0, 3}));
  EXPECT_EQ(s.settings.Where("fixed").file, "--set");
}

TEST_F(SpecTest, SetAnOptionOfATermGivenAsAWeight) {
  // `terms.fairness: 0.5` is short for {weight: 0.5}: --set of one of its
  // options keeps the weight; --set of its weight replaces it.
  const ProblemSpec s = ReadSpec(Write("mesh: a.obj\nterms:\n  fairness: 0.5\n  anchor: 2\n"),
                                 {"terms.fairness.relative_to_original=false",
                                  "terms.anchor.weight=0"});
  EXPECT_DOUBLE_EQ(s.settings.Number("terms.fairness.weight"), 0.5);
  EXPECT_FALSE(s.settings.Bool("terms.fairness.relative_to_original"));
  EXPECT_DOUBLE_EQ(s.settings.Number("terms.anchor.weight"), 0);
}

TEST_F(SpecTest, EmptyOutputsAreNotWritten) {
  const ProblemSpec s = ReadSpec(Write("mesh: a.obj\noutput: {mesh: out.ply, report: r.json}\n"),
                                 {"output.mesh=", "output.report="});
  EXPECT_TRUE(s.settings.String("output.mesh").empty());
  EXPECT_TRUE(s.settings.String("output.report").empty());
}

// An optional input file an example gives is dropped by an empty --set
// (e.g. examples/conjugate_field.yaml's constraints, one row per face of
// its own mesh, on another mesh); `mesh` itself cannot be emptied.
TEST_F(SpecTest, AnEmptySetDropsAnOptionalInputFile) {
  const std::string text =
      "mesh: a.obj\nproblem: conjugate_field\nfield: {constraints: c.dmat}\n";
  const ProblemSpec s = ReadSpec(Write(text), {"field.constraints="});
  EXPECT_TRUE(s.settings.String("field.constraints").empty());
  EXPECT_NE(ReadSpec(Write(text), {}).settings.String("field.constraints"), "");
  EXPECT_EQ(Error(text, {"mesh="}).key(), "mesh");
}

TEST_F(SpecTest, SetPathsAreRelativeToTheCurrentFolder) {
  const ProblemSpec s = ReadSpec(Write("mesh: a.obj\n"), {"output.mesh=x/y.obj"});
  EXPECT_EQ(s.settings.String("output.mesh"), (fs::current_path() / "x/y.obj").string());
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
  const InputError e = Error("mesh: a.obj\nsolver: {num_threads: 2\nterms: [\n");
  EXPECT_GE(e.line(), 2);
  EXPECT_NE(std::string(e.what()).find("malformed YAML"), std::string::npos);
}

// A number written non-zero that double precision reads as 0 is refused: a
// tolerance of 1e-400 would otherwise be "off" (issue 48, item 8); a zero
// written as such is accepted.
TEST_F(SpecTest, ANumberThatUnderflowsToZeroIsRefused) {
  const InputError e =
      Error("mesh: a.obj\nproblem: planar_quads\ntolerance:\n  pq_normalized_max: 1e-400\n");
  EXPECT_EQ(e.line(), 4);
  EXPECT_EQ(e.key(), "tolerance.pq_normalized_max");
  EXPECT_NE(std::string(e.what()).find("underflows to 0"), std::string::npos) << e.what();
  EXPECT_EQ(Error("mesh: a.obj\n", {"schedule.max_seconds=-0.5e-999"}).key(), "schedule.max_seconds");
  const std::string zero = Write("mesh: a.obj\nproblem: planar_quads\ntolerance:\n  pq_normalized_max: 0.0e-5\n");
  EXPECT_EQ(ReadSpec(zero).settings.Number("tolerance.pq_normalized_max"), 0.0);
}

TEST_F(SpecTest, UnknownKeyNamesLineAndKey) {
  const InputError e = Error("mesh: a.obj\nsolver:\n  treads: 2\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.key(), "solver.treads");
  EXPECT_NE(std::string(e.what()).find("unknown key"), std::string::npos);
}

// A mistyped key or choice gets the nearest one (issue 46, item 6): within
// two edits of the name or of a tail after '_' ("treads" → num_threads).
TEST_F(SpecTest, AMistypedKeyOrChoiceGetsTheNearestOne) {
  EXPECT_NE(std::string(Error("mesh: a.obj\nsolver:\n  treads: 2\n").what())
                .find("unknown key; did you mean 'num_threads'?"),
            std::string::npos);
  EXPECT_NE(std::string(Error("mesh: a.obj\nproblem: planar_quads\nterms: {fairnes: 1}\n").what())
                .find("did you mean 'fairness'?"),
            std::string::npos);
  EXPECT_NE(std::string(Error("mesh: a.obj\nsolver: {linear_solver_type: sparse_normal_cholesk}\n").what())
                .find("did you mean 'sparse_normal_cholesky'?"),
            std::string::npos);
  EXPECT_EQ(std::string(Error("mesh: a.obj\nsolver: {frobnicate: 1}\n").what()).find("did you mean"),
            std::string::npos);
}

TEST_F(SpecTest, UnknownTopLevelAndTermKeys) {
  EXPECT_EQ(Error("mesh: a.obj\nmesch: b\n").key(), "mesch");
  EXPECT_EQ(Error("mesh: a.obj\nterms: {planarity: 1}\n").key(), "terms.planarity");
}

TEST_F(SpecTest, WrongTypesNameLineAndKey) {
  InputError e = Error("mesh: a.obj\nsolver:\n  num_threads: two\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.key(), "solver.num_threads");
  EXPECT_NE(std::string(e.what()).find("expected an integer"), std::string::npos);
  EXPECT_EQ(Error("mesh: a.obj\nterms: {proximity: [1]}\n").key(), "terms.proximity");
  EXPECT_EQ(Error("mesh: [a.obj]\n").key(), "mesh");
  EXPECT_EQ(Error("mesh: a.obj\noutput: {ascii_ply: maybe}\n").key(), "output.ascii_ply");
  EXPECT_EQ(Error("mesh: a.obj\nsolver: {linear_solver_type: lu}\n").key(),
            "solver.linear_solver_type");
  EXPECT_EQ(Error("mesh: a.obj\nfixed: some\n").key(), "fixed");
}

TEST_F(SpecTest, OutOfRangeValues) {
  EXPECT_EQ(Error("mesh: a.obj\nterms: {anchor: -1}\n").key(), "terms.anchor");
  EXPECT_EQ(Error("mesh: a.obj\nsolver: {num_threads: 0}\n").key(), "solver.num_threads");
  EXPECT_EQ(Error("mesh: a.obj\ntolerance: {pq_normalized_max: .nan}\n").key(),
            "tolerance.pq_normalized_max");
}

TEST_F(SpecTest, MissingMeshKey) {
  const InputError e = Error("problem: planar_quads\n");
  EXPECT_EQ(e.key(), "mesh");
}

TEST_F(SpecTest, NotAMapping) { EXPECT_NE(Error("- a\n- b\n").line(), -1); }

TEST_F(SpecTest, BadOverridesNameTheOption) {
  InputError e = Error("mesh: a.obj\n", {"solver.num_threads=zwei"});
  EXPECT_EQ(e.file(), "--set");
  EXPECT_EQ(e.key(), "solver.num_threads");
  EXPECT_EQ(Error("mesh: a.obj\n", {"noequals"}).file(), "--set");
  EXPECT_EQ(Error("mesh: a.obj\n", {"solver.bogus=1"}).key(), "solver.bogus");
  EXPECT_EQ(Error("mesh: a.obj\n", {"mesh.x=1"}).file(), "--set");
}

}  // namespace
}  // namespace archgeo

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

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
  EXPECT_DOUBLE_EQ(s.settings.Number("terms.anchor.weight"), 1.0);
  EXPECT_DOUBLE_EQ(s.settings.Number("terms.pq_diagonal.weight"), 3.0);
}

// The spec fuzzer's findings: yaml-cpp's "bad conversion" on keys that are
// not scalars (e.g. `? :` or `[]:`) is an input error, not an internal one.
TEST_F(SpecTest, NonScalarKeysAreInputErrors) {
  for (const std::string text : {"? :\n", "[]: 1\n", "mesh: a.obj\n? [a]\n: 1\nproblem: x\n",
                                 "{? {a: 1} : 2, mesh: a.obj}\n"}) {
    EXPECT_THROW(ReadSpec(Write(text)), InputError) << text;
  }
}

TEST_F(SpecTest, DuplicateAndComplexKeysAreRefused) {
  InputError e = Error("mesh: a.obj\nsolver:\n  num_threads: 1\n  num_threads: 2\n");
  EXPECT_EQ(e.key(), "solver.num_threads");
  EXPECT_EQ(e.line(), 4);
  EXPECT_NE(e.message().find("duplicate"), std::string::npos) << e.what();
  EXPECT_EQ(Error("mesh: a.obj\n? [a, b]\n: 1\n").line(), 2);
  EXPECT_EQ(Error("mesh: a.obj\nsolver:\n  ? [a, b]\n  : 1\n").key(), "solver");
}

TEST_F(SpecTest, RenamedKeysSayTheirNewName) {
  const InputError e = Error("mesh: a.obj\nsolver: {threads: 2}\n");
  EXPECT_EQ(e.key(), "solver.threads");
  EXPECT_NE(e.message().find("solver.num_threads"), std::string::npos) << e.what();
}

TEST_F(SpecTest, AFolderIsNotASpec) {
  fs::create_directories(dir_ / "folder.yaml");
  try {
    ReadSpec((dir_ / "folder.yaml").string());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("regular files only"), std::string::npos) << e.what();
  }
}

// `archgeo spec PROBLEM` prints every key; the printed YAML reads back with
// the same defaults once `mesh` is set.
TEST_F(SpecTest, SpecTemplatesReadBackWithTheirDefaults) {
  for (const std::string& name : ProblemNames()) {
    if (name == "custom") continue;
    const ProblemDecl* d = FindProblem(name);
    ASSERT_NE(d, nullptr) << name;
    const std::string text = SpecTemplate(*d);
    const std::string path = WriteFile(name + ".yaml", text);
    ProblemSpec s = [&] {
      if (name == "principal_symmetric") {
        return ReadSpec(path, {"mesh=a.obj", "split.diagonal=first"});
      }
      return ReadSpec(path, {"mesh=a.obj"});
    }();
    EXPECT_EQ(s.problem(), name);
    const Schema schema = ProblemSchema(*d);
    for (const Key& k : schema.keys()) {
      if (k.type == Type::kCustom || k.name == "mesh" || k.name == "split.diagonal") continue;
      EXPECT_EQ(ToText(s.settings.Get(k.name)), ToText(k.fallback)) << name << ": " << k.name;
    }
  }
}

TEST_F(SpecTest, CustomProblemsComposeRegisteredTerms) {
  const ProblemSpec s = ReadSpec(Write(
      "mesh: a.obj\nproblem: custom\nterms:\n  pq_diagonal: 10\n  dihedral_energy: 1\n"
      "  proximity: {weight: 2, point_weight: 0.01}\ntolerance: {pq_normalized_max: 1e-3}\n"));
  EXPECT_EQ(s.problem(), "custom");
  EXPECT_DOUBLE_EQ(s.settings.Number("terms.dihedral_energy.weight"), 1);
  EXPECT_DOUBLE_EQ(s.settings.Number("tolerance.pq_normalized_max"), 1e-3);
  EXPECT_EQ(Error("mesh: a.obj\nproblem: custom\nterms: {planarity: 1}\n").key(), "terms.planarity");
  EXPECT_EQ(Error("mesh: a.obj\nproblem: custom\nterms: {co_spherical: 1}\n").key(),
            "terms.co_spherical");
  EXPECT_EQ(Error("mesh: a.obj\nproblem: custom\n").key(), "terms");
}

TEST_F(SpecTest, CeresRejectedCombinationsNameTheKeys) {
  // Dogleg needs an exact factorisation; Ceres would stop at run time.
  const InputError e =
      Error("mesh: a.obj\nsolver: {trust_region_strategy_type: dogleg, linear_solver_type: cgnr}\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_TRUE(e.key() == "solver.trust_region_strategy_type" ||
              e.key() == "solver.linear_solver_type")
      << e.what();
}

}  // namespace
}  // namespace archgeo
