// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// `archgeo bench` end to end (bench/bench.h), through the binary:
//  - a sweep of 4 settings × 2 meshes × 2 repeats gives 8 rows in the table,
//    the CSV and the JSON; the combination Ceres rejects (cgnr with dogleg)
//    is a row with exit code 2 and Ceres' reason, the sweep goes on; wall
//    min ≤ median ≤ max; every other row meets planar_quads' tolerance;
//  - a run that misses its tolerance is a row with exit 4 naming it;
//  - --emit-jobs, the jobs run with `xargs -P 2 -n 1 archgeo bench --run-jobs`,
//    then --collect gives the same rows (times and memory aside);
//  - a --vary key the problem does not have is refused (exit 2, the key
//    named) before any run, and nothing is written;
//  - outputs as safe as solve's (issue 48, item 4): an output naming an input
//    (the spec, a mesh, a record being collected), a FIFO or a device, an
//    --out not ending in .csv are refused (exit 2, path and option named,
//    nothing changed); a full disk leaves the previous results; SIGTERM and
//    SIGINT stop the running solve and remove the scratch folder;
//  - job files run no file name through a shell (item 6): a mesh named
//    `q $(touch PWN).obj` runs and touches nothing; a path with a space, a
//    quote and " #" runs through the Slurm script.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

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
  o = Shell("seq 16 | xargs -P 2 -n 1 " + std::string(ARCHGEO_BINARY) + " bench --run-jobs " +
            Path("jobs.txt") + " --job");
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

// --- outputs as safe as solve's (issue 48, item 4) -----------------------------

std::string Text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Files of `folder` whose name contains `part`.
int FilesNamed(const fs::path& folder, const std::string& part) {
  int n = 0;
  for (const auto& e : fs::recursive_directory_iterator(folder)) {
    n += e.path().filename().string().find(part) != std::string::npos;
  }
  return n;
}

// Exit 2 (not 1, not a signal) with a message naming the path and option.
void ExpectRefused(const Outcome& o, const std::string& path, const std::string& option,
                   const std::string& reason) {
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find("archgeo: error: " + path + ": key '" + option + "': "), std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find(reason), std::string::npos) << o.output;
}

// A record as --record writes it, with a message of `message_length` characters.
std::string RecordText(size_t message_length) {
  const json record = {{"mesh", "/data/a.obj"}, {"settings", json::object()}, {"repeat", 1},
                       {"exit_code", 2},        {"wall_s", 0.5},             {"peak_memory_mb", 20.0},
                       {"message", std::string(message_length, 'x')}};
  return record.dump(2) + "\n";
}

TEST_F(BenchTest, OutputsThatNameAnInputAreRefusedBeforeAnyRun) {
  fs::copy_file(spec_, Path("pq.yaml"));
  const std::string spec = Path("pq.yaml"), mesh = Path("a.obj");
  const std::string spec_text = Text(spec), mesh_text = Text(mesh);
  const std::string run = std::string(ARCHGEO_BINARY) + " bench " + spec + " --mesh " + mesh;
  const std::string input = "refusing to overwrite the input file";
  ExpectRefused(Shell(run + " --emit-jobs " + mesh), mesh, "--emit-jobs", input);
  ExpectRefused(Shell(run + " --emit-jobs " + spec), spec, "--emit-jobs", input);
  ExpectRefused(Shell(run + " --record " + spec), spec, "--record", input);
  ExpectRefused(Shell(run + " --record " + mesh), mesh, "--record", input);
  // --out the mesh through a symbolic link; --out the spec.
  fs::create_symlink(mesh, Path("m.csv"));
  ExpectRefused(Shell(run + " --out " + Path("m.csv")), Path("m.csv"), "--out", input);
  ExpectRefused(Shell(run + " --out " + spec), spec, "--out", "must end in .csv");
  EXPECT_EQ(Text(spec), spec_text);
  EXPECT_EQ(Text(mesh), mesh_text);
  EXPECT_TRUE(fs::is_symlink(Path("m.csv")));
  // The JSON beside --out naming a record being collected.
  fs::create_directory(Path("runs"));
  const std::string record = WriteFile("runs/run-0001-r1.json", RecordText(10));
  const Outcome o = Shell(std::string(ARCHGEO_BINARY) + " bench --collect " + Path("runs") +
                          " --out " + Path("runs/run-0001-r1.csv"));
  ExpectRefused(o, Path("runs/run-0001-r1.json"), "--out", input);
  EXPECT_EQ(Text(record), RecordText(10));
  EXPECT_FALSE(fs::exists(Path("runs/run-0001-r1.csv")));
  EXPECT_EQ(FilesNamed(dir_, ".tmp-"), 0);
}

// --out r.json would give the CSV and the JSON one name: refused, the CSV kept.
TEST_F(BenchTest, AnOutNotEndingInCsvIsRefusedAndTheCsvKept) {
  WriteFile("r.csv", "old rows\n");
  const Outcome o = Shell(std::string(ARCHGEO_BINARY) + " bench " + spec_ + " --mesh " +
                          Path("a.obj") + " --out " + Path("r.json"));
  ExpectRefused(o, Path("r.json"), "--out", "must end in .csv");
  EXPECT_EQ(Text(Path("r.csv")), "old rows\n");
  EXPECT_FALSE(fs::exists(Path("r.json")));
}

TEST_F(BenchTest, FifosAndDevicesAreRefusedWithoutHanging) {
  const std::string run = "timeout 10 " + std::string(ARCHGEO_BINARY) + " bench " + spec_ +
                          " --mesh " + Path("a.obj");
  ASSERT_EQ(mkfifo(Path("r.csv").c_str(), 0600), 0);
  ExpectRefused(Shell(run + " --out " + Path("r.csv")), Path("r.csv"), "--out", "(a FIFO)");
  ASSERT_EQ(mkfifo(Path("s.json").c_str(), 0600), 0);  // the JSON beside s.csv
  ExpectRefused(Shell(run + " --out " + Path("s.csv")), Path("s.json"), "--out", "(a FIFO)");
  EXPECT_FALSE(fs::exists(Path("s.csv")));
  ASSERT_EQ(mkfifo(Path("jobs.txt").c_str(), 0600), 0);
  ExpectRefused(Shell(run + " --emit-jobs " + Path("jobs.txt")), Path("jobs.txt"), "--emit-jobs",
                "(a FIFO)");
  ExpectRefused(Shell(run + " --record /dev/null"), "/dev/null", "--record", "(a character device)");
}

// A write that fails part-way (a file size limit standing in for a full
// disk): exit 2, the previous results as they were, no temporary left.
TEST_F(BenchTest, AFailedWriteLeavesThePreviousResults) {
  fs::create_directory(Path("runs"));
  WriteFile("runs/run-0001-r1.json", RecordText(8000));
  WriteFile("results.csv", "old rows\n");
  WriteFile("results.json", "[]\n");
  const std::string collect = std::string(ARCHGEO_BINARY) + " bench --collect " + Path("runs") +
                              " --out " + Path("results.csv");
  Outcome o = Shell("ulimit -f 4; trap '' XFSZ; " + collect);  // 2 or 4 KB: under the 8 KB rows
  ExpectRefused(o, Path("results.csv"), "--out", "File too large");
  EXPECT_EQ(Text(Path("results.csv")), "old rows\n");
  EXPECT_EQ(Text(Path("results.json")), "[]\n");
  EXPECT_EQ(FilesNamed(dir_, ".tmp-"), 0);
  // The limit is what failed: without it the same command writes both.
  o = Shell(collect);
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_NE(Text(Path("results.csv")).find(std::string(8000, 'x')), std::string::npos);
  EXPECT_EQ(ReadJson(Path("results.json")).size(), 1u);
}

// Starts argv with `environment` added to this process's; output discarded.
pid_t StartQuietly(const std::vector<std::string>& argv, const std::string& environment) {
  std::vector<std::string> env;
  for (char** e = ::environ; *e; ++e) env.push_back(*e);
  env.push_back(environment);
  std::vector<char*> args, envp;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  for (const std::string& e : env) envp.push_back(const_cast<char*>(e.c_str()));
  args.push_back(nullptr);
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0].c_str(), &actions, nullptr, args.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  return spawned == 0 ? pid : -1;
}

// The processes whose command line contains `text` (their pids).
std::vector<int> ProcessesMentioning(const std::string& text) {
  std::vector<int> pids;
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::string line = Text((e.path() / "cmdline").string());
    for (char& c : line) c = c == '\0' ? ' ' : c;
    if (line.find(text) != std::string::npos) pids.push_back(std::stoi(name));
  }
  return pids;
}

// SIGTERM and SIGINT to a running sweep: the bench ends by the signal, its
// solve is stopped with it, the scratch folder ($TMPDIR/archgeo_bench.*) is
// gone, the previous results are untouched and no temporary is left.
TEST_F(BenchTest, ASignalStopsTheRunningSolveAndRemovesTheScratchFolder) {
  WriteMesh(Path("big.obj"), QuadGrid(40, 40, RoofSurface, 0.05, 3));
  fs::create_directory(Path("tmp"));
  WriteFile("results.csv", "old rows\n");
  WriteFile("results.json", "[]\n");
  for (const int sig : {SIGTERM, SIGINT}) {
    const pid_t bench = StartQuietly({ARCHGEO_BINARY, "bench", spec_, "--mesh", Path("big.obj"),
                                      "--repeat", "20", "--out", Path("results.csv")},
                                     "TMPDIR=" + Path("tmp"));
    ASSERT_GT(bench, 0);
    // A solve is running (its command names the scratch folder in tmp/).
    const auto start = std::chrono::steady_clock::now();
    while (ProcessesMentioning(Path("tmp") + "/archgeo_bench.").empty() &&
           std::chrono::steady_clock::now() - start < std::chrono::seconds(10)) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_FALSE(ProcessesMentioning(Path("tmp") + "/archgeo_bench.").empty());
    ASSERT_FALSE(fs::is_empty(Path("tmp")));
    ASSERT_EQ(kill(bench, sig), 0);
    int status = 0;
    ASSERT_EQ(waitpid(bench, &status, 0), bench);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << "status " << status;
    const std::vector<int> left = ProcessesMentioning(Path("tmp") + "/archgeo_bench.");
    EXPECT_TRUE(left.empty()) << "a solve outlived the bench";
    for (int pid : left) kill(pid, SIGKILL);
    EXPECT_TRUE(fs::is_empty(Path("tmp"))) << fs::directory_iterator(Path("tmp"))->path();
    EXPECT_EQ(Text(Path("results.csv")), "old rows\n");
    EXPECT_EQ(Text(Path("results.json")), "[]\n");
    EXPECT_EQ(FilesNamed(dir_, ".tmp-"), 0);
  }
}

// --- job files that never run a file name (issue 48, item 6) -------------------

// Single-quoted for the shell these tests type commands into.
std::string Quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// A mesh named like a command substitution: the sweep and the jobs (run by
// the very line --emit-jobs prints) solve it and nothing else runs.
TEST_F(BenchTest, AMeshNamedLikeACommandRunsAndRunsNothing) {
  const std::string name = "q $(touch PWN).obj";
  WriteMesh(Path(name), QuadGrid(6, 6, RoofSurface, 0.05, 1));
  const std::string in_dir = "cd " + Quoted(dir_.string()) + " && ";
  const std::string bench = std::string(ARCHGEO_BINARY) + " bench " + spec_ + " --mesh " +
                            Quoted(name) + " --vary 'solver.linear_solver_type=[sparse_normal_cholesky,cgnr]'";
  Outcome o = Shell(in_dir + bench + " --out direct.csv");
  ASSERT_EQ(o.code, 0) << o.output;
  o = Shell(in_dir + bench + " --emit-jobs jobs.txt");
  ASSERT_EQ(o.code, 0) << o.output;
  const size_t at = o.output.find("e.g.:\n");
  ASSERT_NE(at, std::string::npos) << o.output;
  const std::string runner = o.output.substr(at + 6, o.output.find('\n', at + 6) - at - 6);
  EXPECT_NE(runner.find("xargs -P 2 -n 1"), std::string::npos) << runner;
  o = Shell(in_dir + runner);
  ASSERT_EQ(o.code, 0) << runner << "\n" << o.output;
  EXPECT_FALSE(fs::exists(Path("PWN")));
  o = Shell(in_dir + std::string(ARCHGEO_BINARY) + " bench --collect jobs_runs --out collected.csv");
  ASSERT_EQ(o.code, 0) << o.output;
  const json rows = ReadJson(Path("collected.json"));
  ASSERT_EQ(rows.size(), 2u);
  for (const json& r : rows) {
    EXPECT_EQ(r["mesh"], Path(name));
    EXPECT_EQ(r["exit_code"], 0) << r["message"];
    EXPECT_TRUE(r["tolerance_met"].get<bool>());
  }
  EXPECT_EQ(Outcomes(rows), Outcomes(ReadJson(Path("direct.json"))));
  EXPECT_FALSE(fs::exists(Path("PWN")));
}

// A space and a quote in every path (folder, spec, mesh, job file), and a
// " #" in the mesh's (a comment in a YAML value, were it not quoted): the
// jobs run through docs/bench_sbatch.sh as a Slurm array task would.
TEST_F(BenchTest, APathWithASpaceAndAQuoteRunsThroughTheSlurmScript) {
  const fs::path folder = dir_ / "it's a dir";
  fs::create_directory(folder);
  const std::string spec = (folder / "pq spec.yaml").string(), mesh = (folder / "a b'c #1.obj").string();
  fs::copy_file(spec_, spec);
  WriteMesh(mesh, QuadGrid(6, 6, RoofSurface, 0.05, 1));
  const std::string jobs = (folder / "my jobs.txt").string();
  Outcome o = Shell(std::string(ARCHGEO_BINARY) + " bench " + Quoted(spec) + " --mesh " +
                    Quoted(mesh) + " --repeat 2 --emit-jobs " + Quoted(jobs));
  ASSERT_EQ(o.code, 0) << o.output;
  for (const char* task : {"1", "2"}) {
    o = Shell("SLURM_ARRAY_TASK_ID=" + std::string(task) + " ARCHGEO=" + ARCHGEO_BINARY + " bash " +
              ARCHGEO_SOURCE_DIR + "/docs/bench_sbatch.sh " + Quoted(jobs));
    ASSERT_EQ(o.code, 0) << o.output;
  }
  // A task beyond the file: exit 2 naming the job.
  o = Shell("SLURM_ARRAY_TASK_ID=3 ARCHGEO=" + std::string(ARCHGEO_BINARY) + " bash " +
            ARCHGEO_SOURCE_DIR + "/docs/bench_sbatch.sh " + Quoted(jobs));
  ExpectRefused(o, jobs, "--job", "no job 3 (the file has 2)");
  const std::string runs = (folder / "my jobs_runs").string();
  for (const char* record : {"run-0001-r1.json", "run-0001-r2.json"}) {
    const json r = ReadJson(runs + "/" + record);
    EXPECT_EQ(r["mesh"], mesh);
    EXPECT_EQ(r["exit_code"], 0) << r["message"];
  }
  o = Shell(std::string(ARCHGEO_BINARY) + " bench --collect " + Quoted(runs) + " --out " +
            Quoted((folder / "r.csv").string()));
  ASSERT_EQ(o.code, 0) << o.output;
  const json rows = ReadJson((folder / "r.json").string());
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0]["repeats"], 2);
  EXPECT_TRUE(rows[0]["tolerance_met"].get<bool>());
}

}  // namespace
}  // namespace archgeo
