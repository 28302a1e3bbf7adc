// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// `archgeo bench` end to end (bench/bench.h), through the binary:
//  - a sweep of 4 settings × 2 meshes × 2 repeats gives 8 rows in the table,
//    the CSV and the JSON; the combination Ceres rejects (cgnr with dogleg)
//    is a row with exit code 2 and Ceres' reason, the sweep goes on; wall
//    min ≤ median ≤ max; every other row meets planar_quads' tolerance;
//  - a run that misses its tolerance is a row with exit 4 naming it;
//  - --emit-jobs, the jobs run with `xargs -P 2`, then --collect gives the
//    same rows (times and memory aside);
//  - a --vary key the problem does not have is refused (exit 2, the key
//    named) before any run, and nothing is written.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "generators/generators.h"
#include "io/io.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

namespace fs = std::filesystem;
using json = nlohmann::json;

struct Outcome {
  int code;
  std::string output;
};

Outcome Shell(const std::string& command) {
  Outcome o{0, ""};
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) o.output.append(buf.data(), n);
  const int status = pclose(pipe);
  o.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return o;
}

json ReadJson(const std::string& path) {
  std::ifstream in(path);
  return json::parse(in);
}

class BenchTest : public ScratchDirTest {
 protected:
  void SetUp() override {
    ScratchDirTest::SetUp();
    WriteMesh(Path("a.obj"), QuadGrid(6, 6, RoofSurface, 0.05, 1));
    WriteMesh(Path("b.obj"), QuadGrid(8, 5, RoofSurface, 0.05, 2));
    spec_ = std::string(ARCHGEO_SOURCE_DIR) + "/examples/planar_quads.yaml";
    sweep_ = " --mesh " + Path("a.obj") + " --mesh " + Path("b.obj") +
             " --vary 'solver.linear_solver_type=[sparse_normal_cholesky,cgnr]'"
             " --vary 'solver.trust_region_strategy_type=[levenberg_marquardt,dogleg]'"
             " --repeat 2";
  }
  std::string spec_, sweep_;
};

// The rows' settings and outcomes, without times and memory.
json Outcomes(const json& rows) {
  json out = json::array();
  for (const json& r : rows) {
    out.push_back({r["mesh"], r["settings"], r["repeats"], r["exit_code"], r["message"],
                   r["iterations"], r["objective"], r["tolerance_met"], r["measures"]});
  }
  return out;
}

TEST_F(BenchTest, SweepGivesOneRowPerSettingAndMeshWithFailuresAsRows) {
  const Outcome o = Shell(std::string(ARCHGEO_BINARY) + " bench " + spec_ + sweep_ + " --out " +
                        Path("results.csv"));
  ASSERT_EQ(o.code, 0) << o.output;
  const json rows = ReadJson(Path("results.json"));
  ASSERT_EQ(rows.size(), 8u) << o.output;
  std::ifstream csv(Path("results.csv"));
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 9);  // header + 8 rows
  int failed = 0;
  for (const json& r : rows) {
    EXPECT_EQ(r["repeats"], 2);
    EXPECT_LE(r["wall_min_s"].get<double>(), r["wall_median_s"].get<double>());
    EXPECT_LE(r["wall_median_s"].get<double>(), r["wall_max_s"].get<double>());
    EXPECT_GT(r["peak_memory_mb"].get<double>(), 1.0);
    const bool rejected = r["settings"]["solver.linear_solver_type"] == "cgnr" &&
                          r["settings"]["solver.trust_region_strategy_type"] == "dogleg";
    if (rejected) {
      ++failed;
      EXPECT_EQ(r["exit_code"], 2);
      EXPECT_NE(r["message"].get<std::string>().find("DOGLEG only supports exact factorization"),
                std::string::npos)
          << r["message"];
      EXPECT_TRUE(r["iterations"].is_null());
    } else {
      EXPECT_EQ(r["exit_code"], 0) << r["message"];
      EXPECT_TRUE(r["tolerance_met"].get<bool>());
      EXPECT_LE(r["measures"]["pq_normalized_max"].get<double>(), 1e-3);
      EXPECT_GT(r["iterations"].get<int>(), 0);
      EXPECT_GE(r["solver_s"].get<double>(),
                r["linear_solver_s"].get<double>() + r["evaluation_s"].get<double>() - 1e-3);
    }
  }
  EXPECT_EQ(failed, 2);
  // The printed table names every run's failure.
  EXPECT_NE(o.output.find("DOGLEG only supports"), std::string::npos) << o.output;
}

// A run that misses its tolerance (exit 4: valid, written) is a row that
// names the tolerance.
TEST_F(BenchTest, AMissedToleranceIsARowThatNamesIt) {
  const Outcome o = Shell(std::string(ARCHGEO_BINARY) + " bench " + spec_ + " --mesh " + Path("a.obj") +
                      " --vary 'solver.max_num_iterations=[1]' --vary 'schedule.outer_iterations=[1]'"
                      " --out " + Path("r.csv"));
  ASSERT_EQ(o.code, 0) << o.output;
  const json rows = ReadJson(Path("r.json"));
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0]["exit_code"], 4);
  EXPECT_FALSE(rows[0]["tolerance_met"].get<bool>());
  EXPECT_GT(rows[0]["measures"]["pq_normalized_max"].get<double>(), 1e-3);
  EXPECT_NE(rows[0]["message"].get<std::string>().find("pq_normalized_max <= 0.001: NOT met"),
            std::string::npos)
      << rows[0]["message"];
}

TEST_F(BenchTest, EmittedJobsCollectedGiveTheSameRows) {
  Outcome o = Shell(std::string(ARCHGEO_BINARY) + " bench " + spec_ + sweep_ + " --out " +
                  Path("direct.csv"));
  ASSERT_EQ(o.code, 0) << o.output;
  o = Shell(std::string(ARCHGEO_BINARY) + " bench " + spec_ + sweep_ + " --emit-jobs " +
          Path("jobs.txt"));
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_FALSE(fs::exists(Path("jobs_runs")));  // nothing ran yet
  o = Shell("xargs -P 2 -I{} sh -c {} < " + Path("jobs.txt"));
  ASSERT_EQ(o.code, 0) << o.output;
  int records = 0;
  for (const auto& e : fs::directory_iterator(Path("jobs_runs"))) records += e.path().extension() == ".json";
  EXPECT_EQ(records, 16);
  o = Shell(std::string(ARCHGEO_BINARY) + " bench --collect " + Path("jobs_runs") + " --out " +
          Path("collected.csv"));
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_EQ(Outcomes(ReadJson(Path("collected.json"))), Outcomes(ReadJson(Path("direct.json"))));
}

TEST_F(BenchTest, AKeyTheProblemDoesNotHaveIsRefusedBeforeAnyRun) {
  const Outcome o = Shell(std::string(ARCHGEO_BINARY) + " bench " + spec_ + " --mesh " +
                        Path("a.obj") + " --vary 'solver.linear_solver_typo=[cgnr]' --out " +
                        Path("r.csv"));
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find("solver.linear_solver_typo"), std::string::npos) << o.output;
  EXPECT_FALSE(fs::exists(Path("r.csv")));
  EXPECT_FALSE(fs::exists(Path("r.json")));
  const Outcome missing = Shell(std::string(ARCHGEO_BINARY) + " bench " + spec_ + " --mesh " +
                              Path("nope.obj"));
  EXPECT_EQ(missing.code, 2) << missing.output;
  EXPECT_NE(missing.output.find("nope.obj"), std::string::npos) << missing.output;
}

}  // namespace
}  // namespace archgeo
