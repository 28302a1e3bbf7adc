// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The engine: the one loop's schedule rules on a model whose rounds are
// scripted, the term registry, per-face variable blocks end to end
// (solved, written to the report in file units and read back), and
// problem: custom.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/loop.h"
#include "core/problem.h"
#include "core/solver_options.h"
#include "energies/registry.h"
#include "generators/generators.h"
#include "core/input_error.h"
#include "io/io.h"
#include "mesh/similarity.h"
#include "problems/runtime/model.h"
#include "problems/declarations/registry.h"
#include "problems/commands/run.h"
#include "problems/spec/schema.h"
#include "problems/report/report.h"
#include "problems/spec/spec.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

// The scripted model's state, kept in its hooks' state.
struct Script : ProblemState {
  std::vector<double> values;  // one "measure" per round
  size_t next = 0;             // the next round's value
  double state = 0;            // the current value of the measure
};

namespace fs = std::filesystem;

// A model without a mesh: every round (a Stage::step) sets the state to the
// next scripted value; the measure "m" is the state.
class ScriptedModel : public Model {
 public:
  explicit ScriptedModel(std::vector<double> script) {
    hooks_.State<Script>().values = std::move(script);
  }
  Script& script() { return hooks_.State<Script>(); }
  void BeginRound(bool) override {}
  void Build(const std::vector<ActiveTerm>&, int, Residuals&) override {}
  int Guard(double) override { return 0; }
  double Measure(const std::string& name) override {
    EXPECT_EQ(name, "m");
    return script().state;
  }
  void StateChanged() override {}
  std::vector<double> SaveState() const override {
    return {hooks_.State<Script>().state};
  }
  void RestoreState(const std::vector<double>& s) override { script().state = s.at(0); }
  double MaxMove(const std::vector<double>& a, const std::vector<double>& b) const override {
    return std::abs(a.at(0) - b.at(0));
  }
  bool Finite() const override { return std::isfinite(SaveState()[0]); }
  // A negative state stands for an invalid one (e.g. a folded panel).
  std::string Invalid() override {
    return !Finite() ? "finite" : SaveState()[0] < 0 ? "negative" : "";
  }
  HookContext& hooks() override { return hooks_; }

 private:
  HookContext hooks_;
};

Settings LoopSettings(const std::vector<Key>& extra) {
  Schema schema;
  schema.Add(IntegerKey("schedule.outer_iterations", 20, 1, 1000, ""));
  schema.Add(NumberKey("schedule.max_seconds", 0, 0, 1e9, ""));
  schema.Add(SolverKeys());
  schema.Add(extra);
  return Settings(schema);
}

// Runs `stage` for at most as many rounds as the script has values.
LoopResult RunScript(const Stage& stage, const std::vector<double>& script, Settings settings,
                     double start = 10) {
  settings.Set("schedule.outer_iterations", (long long)script.size(), Origin{"test", 1});
  ProblemDecl d;
  d.name = "scripted";
  Stage s = stage;
  s.rounds_key = "schedule.outer_iterations";
  s.logged = {"m"};
  s.step = [](HookContext& c) {
    Script& script = c.State<Script>();
    script.state = script.values.at(script.next++);
    StepResult r;
    r.iterations = 1;
    return r;
  };
  d.stages = [s](const Settings&) { return std::vector<Stage>{s}; };
  ScriptedModel model(script);
  model.script().state = start;
  LoopOptions options;
  options.settings = &settings;
  return RunLoop(d, options, model);
}

TEST(Loop, StopsWhenTheToleranceHolds) {
  const Settings s = LoopSettings({NumberKey("tol", 1, 0, 100, "")});
  Stage st;
  st.tolerances = {{"m", "tol"}};
  const LoopResult r = RunScript(st, {5, 3, 0.5, 0.2, 0.1}, s);
  EXPECT_EQ(r.rounds, 3);
  EXPECT_TRUE(r.tolerances.at("tol"));
  EXPECT_EQ(r.stop, "tolerances met");
}

TEST(Loop, ContinuationGrowsTheScaleWhileTheToleranceIsMissed) {
  const Settings s =
      LoopSettings({NumberKey("tol", 1, 0, 100, ""), NumberKey("factor", 10, 1, 100, "")});
  Stage st;
  st.tolerances = {{"m", "tol"}};
  st.factor_key = "factor";
  const LoopResult r = RunScript(st, {5, 3, 0.5}, s);
  ASSERT_EQ(r.log.size(), 4u);  // round 0 = the start
  EXPECT_DOUBLE_EQ(r.log[1].weight_scale, 1);
  EXPECT_DOUBLE_EQ(r.log[2].weight_scale, 10);
  EXPECT_DOUBLE_EQ(r.log[3].weight_scale, 100);
}

TEST(Loop, KeepsTheBestRound) {
  const Settings s = LoopSettings({});
  Stage st;
  st.keep_best = "m";
  const LoopResult r = RunScript(st, {8, 2, 6, 7, 9}, s);
  EXPECT_EQ(r.rounds, 5);
  EXPECT_EQ(r.output_round, 2);
  EXPECT_EQ(r.log[2].measures.at("m"), 2);
}

TEST(Loop, TheInputIsKeptWhenNoRoundBeatsIt) {
  const Settings s = LoopSettings({});
  Stage st;
  st.keep_best = "m";
  const LoopResult r = RunScript(st, {12, 11, 13}, s, /*start=*/10);
  EXPECT_EQ(r.output_round, 0);
}

TEST(Loop, PatienceEndsTheStage) {
  const Settings s = LoopSettings({NumberKey("gain", 0.01, 0, 1, "")});
  Stage st;
  st.patience_measure = "m";
  st.patience_key = "gain";
  st.patience_rounds = 3;
  // 9.99 and 9.95 are gains below 1% of 10: rounds 1..3 bring no real gain.
  const LoopResult r = RunScript(st, {9.99, 9.95, 9.96, 1, 1, 1}, s);
  EXPECT_EQ(r.rounds, 3);
  EXPECT_NE(r.stop.find("no gain"), std::string::npos) << r.stop;
  EXPECT_TRUE(r.stalled);
}

TEST(Loop, TheStallRoundsComeFromAKey) {
  const Settings s = LoopSettings({NumberKey("gain", 0.01, 0, 1, ""),
                                   IntegerKey("stall_rounds", 2, 1, 100, "")});
  Stage st;
  st.patience_measure = "m";
  st.patience_key = "gain";
  st.patience_rounds = 5;  // the key wins
  st.patience_rounds_key = "stall_rounds";
  const LoopResult r = RunScript(st, {9, 8.95, 8.99, 1, 1}, s);
  EXPECT_EQ(r.rounds, 3);  // round 1 gains 10%; rounds 2 and 3 less than 1% of 9
  EXPECT_TRUE(r.stalled);
  EXPECT_NE(r.stop.find("in 2 rounds"), std::string::npos) << r.stop;
}

// With patience_valid, an invalid round's lower value is no gain: the stage
// stalls although the measure fell, and runs on where only valid rounds gain.
TEST(Loop, OnlyValidRoundsGainWhenTheStageSaysSo) {
  const Settings s = LoopSettings({NumberKey("gain", 0.01, 0, 1, "")});
  Stage st;
  st.patience_measure = "m";
  st.patience_key = "gain";
  st.patience_rounds = 2;
  st.patience_valid = true;
  const LoopResult stalls = RunScript(st, {-1, -2, 5, 4}, s);
  EXPECT_EQ(stalls.rounds, 2);
  EXPECT_TRUE(stalls.stalled);
  EXPECT_NE(stalls.stop.find("best valid m (10)"), std::string::npos) << stalls.stop;
  st.patience_valid = false;
  const LoopResult counts_all = RunScript(st, {-1, -2, -2, -2}, s);
  EXPECT_EQ(counts_all.rounds, 4);  // rounds 1 and 2 gain; 3 and 4 do not
  EXPECT_TRUE(counts_all.stalled);
}

TEST(Loop, NoStallWhileEveryRoundGains) {
  const Settings s = LoopSettings({NumberKey("gain", 0.01, 0, 1, "")});
  Stage st;
  st.patience_measure = "m";
  st.patience_key = "gain";
  st.patience_rounds = 1;
  const LoopResult r = RunScript(st, {9, 8, 7, 6}, s);
  EXPECT_EQ(r.rounds, 4);
  EXPECT_FALSE(r.stalled);
}

TEST(Loop, ARoundThatMakesTheMeasureWorseIsUndone) {
  const Settings s = LoopSettings({});
  Stage st;
  st.undo_if_worse = "m";
  const LoopResult r = RunScript(st, {9, 8, 12, 1}, s);
  EXPECT_EQ(r.rounds, 3);
  EXPECT_TRUE(r.log.back().undone);
  EXPECT_DOUBLE_EQ(r.log.back().measures.at("m"), 12);  // measured, then undone
}

TEST(Loop, RestRules) {
  const Settings s = LoopSettings({NumberKey("change", 0.05, 0, 1, "")});
  Stage moving;
  moving.rest_move = 0.5;
  EXPECT_EQ(RunScript(moving, {5, 2, 1.8, 0}, s).rounds, 3);  // |1.8 − 2| < 0.5
  Stage settling;
  settling.rest_change_measure = "m";
  settling.rest_change_key = "change";
  EXPECT_EQ(RunScript(settling, {5, 2, 1.95, 0}, s).rounds, 3);  // 2.5% change
}

TEST(Loop, ANonFiniteStateIsUnusable) {
  const Settings s = LoopSettings({});
  const LoopResult r = RunScript(Stage{}, {1, std::nan(""), 2}, s);
  EXPECT_FALSE(r.usable);
  EXPECT_EQ(r.rounds, 2);
}

// Every registered term is the energy of the same name in energies/, with
// its paper, elements and summary declared.
TEST(Registry, EveryTermIsItsEnergyFile) {
  for (const TermSpec* t : RegisteredTerms()) {
    const fs::path header = fs::path(ARCHGEO_SOURCE_DIR) / "energies" / (std::string(t->name) + ".h");
    EXPECT_TRUE(fs::exists(header)) << t->name;
    EXPECT_GT(std::string(t->summary).size(), 10u) << t->name;
    EXPECT_NE(std::string(t->paper).find('['), std::string::npos) << t->name;
    EXPECT_NE(t->add, nullptr) << t->name;
    EXPECT_EQ(FindTerm(t->name), t);
  }
}

// Every problem's declaration is consistent: each term it uses is
// registered and each option default it gives a term is one of that term's
// declared options; each of its own defaults overrides a key its schema has
// (a misspelt default would silently not apply); it has stages and a key
// table (docs/keys.md).
TEST(Registry, EveryProblemDeclarationIsComplete) {
  for (const std::string& name : ProblemNames()) {
    if (name == "custom") continue;
    const ProblemDecl* d = FindProblem(name);
    ASSERT_NE(d, nullptr);
    const Schema schema = ProblemSchema(*d);
    for (const TermUse& use : d->terms) {
      const TermSpec* term = FindTerm(use.term);
      ASSERT_NE(term, nullptr) << name << ": " << use.term;
      for (const auto& [option, value] : use.options) {
        bool declared = false;
        for (const Key& k : term->options) declared |= k.name == option;
        EXPECT_TRUE(declared) << name << ": " << use.term << " has no option " << option;
      }
    }
    for (const auto& [key, value] : d->defaults) {
      EXPECT_NE(schema.Find(key), nullptr) << name << ": default for unknown key " << key;
    }
    EXPECT_FALSE(d->stages(Settings(schema)).empty()) << name;
    EXPECT_NE(KeyTable(*d, false).find("| `"), std::string::npos) << name;
  }
}

class EngineTest : public ScratchDirTest {};

// A per-face variable block end to end: the unit direction of every face,
// smoothed by the Dirichlet term to one direction, written to the report in
// file units and read back; the input rotated by R gives directions rotated
// by R (the block maps as a direction between file units and the solve's
// frame).
TEST_F(EngineTest, PerFaceDirectionsAreSolvedWrittenAndReadBack) {
  Mesh grid = QuadGrid(8, 6, RoofSurface, 0.02, 5);
  Mesh turned = grid;
  const double c = std::cos(0.7), s = std::sin(0.7);
  for (VertexIndex v : turned.vertices()) {
    const Point p = turned.point(v);
    turned.point(v) = Point(c * p.x() - s * p.z() + 3, p.y() - 1, s * p.x() + c * p.z());
  }
  WriteMesh(Path("grid.obj"), grid);
  WriteMesh(Path("turned.obj"), turned);
  const std::string spec = WriteFile(
      "spec.yaml",
      "problem: custom\nterms: {direction_dirichlet: 1}\nschedule: {outer_iterations: 3}\n"
      "output: {report: r.json, blocks: true}\n");
  std::vector<std::vector<double>> directions;
  for (const std::string mesh : {"grid.obj", "turned.obj"}) {
    const RunResult run = RunSpec(ReadSpec(spec, {"mesh=" + Path(mesh)}), {});
    ASSERT_EQ(run.exit_code, 0);
    std::ifstream in(Path("r.json"));
    const nlohmann::json report = nlohmann::json::parse(in);
    const nlohmann::json& block = report.at("blocks").at("face_direction");
    EXPECT_EQ(block.at("on"), "face");
    EXPECT_EQ(block.at("width"), 3);
    const std::vector<double> values = block.at("values").get<std::vector<double>>();
    ASSERT_EQ(values.size(), 3 * grid.number_of_faces());
    // One unit direction on every face (the Dirichlet energy's minimum).
    for (size_t f = 0; f < grid.number_of_faces(); ++f) {
      const double* d = &values[3 * f];
      EXPECT_NEAR(std::hypot(d[0], d[1], d[2]), 1.0, 1e-9);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(d[k], values[k], 1e-6) << "face " << f;
    }
    EXPECT_LT(report.at("objective").at("total").get<double>(), 1e-12);
    directions.push_back({values[0], values[1], values[2]});
  }
  const std::vector<double>& a = directions[0];
  const std::vector<double> turned_a = {c * a[0] - s * a[2], a[1], s * a[0] + c * a[2]};
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(directions[1][k], turned_a[k], 1e-6);
}

// A term that acts on elements the mesh does not have is an input error
// naming it.
TEST_F(EngineTest, CustomTermsMustFitTheMesh) {
  WriteFile("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
  const std::string spec = WriteFile(
      "spec.yaml", "mesh: tri.obj\nproblem: custom\nterms: {pq_diagonal: 1, proximity: 1}\n");
  try {
    RunSpec(ReadSpec(spec), {});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "terms.pq_diagonal");
    EXPECT_NE(e.message().find("quads"), std::string::npos) << e.what();
  }
}

// Summary changes: whole percents; from or to zero the absolute change (a
// percentage of nothing means nothing); beyond +1000% the factor, so no
// percent string exceeds ±1000%.
TEST(ChangeText, PercentsAbsoluteChangesAndFactors) {
  EXPECT_EQ(ChangeText(2.0, 2.5), "+25%");
  EXPECT_EQ(ChangeText(2.0, 1.0), "-50%");
  EXPECT_EQ(ChangeText(-2.0, -1.0), "+50%");
  EXPECT_EQ(ChangeText(0.0, 0.0123), "+0.0123");
  EXPECT_EQ(ChangeText(4e-18, 0.00296), "+0.00296");  // rounding-level start: zero
  EXPECT_EQ(ChangeText(4.5e-5, 0.0), "-4.5e-05");
  EXPECT_EQ(ChangeText(1.0, 11.0), "+1000%");
  EXPECT_EQ(ChangeText(1.0, 15.2), "x15.2");
  EXPECT_EQ(ChangeText(3.0, 3.0), "");
  for (double after : {1e-9, 0.5, 1.0 + 1e-9, 9.0, 10.99, 11.01, 1e6}) {
    const std::string text = ChangeText(1.0, after);
    if (text.back() != '%') continue;
    EXPECT_LE(std::abs(std::stod(text)), 1000.0) << text;
  }
}

}  // namespace
}  // namespace archgeo
