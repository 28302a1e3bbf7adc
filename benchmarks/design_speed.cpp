// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 47's acceptance at design size: examples/planar_quads.yaml, unchanged
// but for its output paths (mesh, image and report go to the scratch folder),
// as whole `archgeo solve` processes on the shared Conjugate mesh (1,633
// quads) and on generated noisy roofs (`archgeo generate --nu n --nv n
// --noise 0.05`) of 100² (10k quads), 173² (30k) and 316² (100k);
// --include-1m adds 1000² (1M quads, long: about 90 s and 6 GB a run).
// Each size runs --runs times (5); its row gives the median wall time beside
// the target, the CPU time, iterations, factorisations or CG steps,
// peak memory, δ_PQ,n max, E beside the input's, the largest displacement,
// validity, the exit codes and whether the target is met.
// A second column of runs, for ratios on a noisy machine: --other PATH (an
// archgeo binary built from another commit) and/or --other-set KEY=VALUE
// (settings of that side only; with this build, e.g. solver.back_end=ceres).
// Its runs are interleaved with this build's, alternating which goes first,
// on the same input, and a third row per size gives the ratios of medians.
//
//   cmake --build build --target archgeo archgeo_benchmarks
//   build/benchmarks/design_speed [--sizes conjugate,10k,30k,100k,1m] [--include-1m]
//       [--runs N] [--other PATH] [--other-set KEY=VALUE]... [--timeout SECONDS]
//       [--set KEY=VALUE]...          (--help: what each flag does)
//
// --set applies to both sides. Prints a Markdown table; writes only to the
// scratch folder (bench::Scratch(): the roofs, cached, and each run's
// outputs, removed after it; a failed run's log is kept).
#include "benchmarks/bench_util.h"
#include "bench/bench.h"
#include "benchmarks/program.h"

#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace ARCHGEO_UNITY_ID {

using bench::Fmt;
using bench::Get;
using bench::Json;

struct Size {
  std::string name;
  int n;               // roof of n x n quads; 0: the Conjugate mesh
  double target_s;     // issue 47's wall-time target
  double target_mb;    // its peak-memory bound (MiB), 0 if none
};

const std::vector<Size> kSizes = {{"conjugate", 0, 0.3, 0},   {"10k", 100, 1.5, 0},
                                  {"30k", 173, 4, 0},         {"100k", 316, 10, 1024},
                                  {"1m", 1000, 120, 6 * 1024}};

struct Side {
  std::string label, binary;
  std::vector<std::string> sets;  // after the --set of both sides
};

struct Run {
  bench::ProcessResult process;
  Json report;  // null when none was written (exit 1, 2, 3, a timeout)
};

// The input of a size: the shared Conjugate mesh, or the roof (generated
// once by this build, cached under the name benchmarks/scaling uses).
std::string DesignMesh(const Size& s) {
  if (s.n == 0) return bench::Data("libigl_inspired_mesh_quads_Conjugate.off");
  const std::string path = (bench::Scratch() / Fmt("grid_%dx%d.ply", s.n, s.n)).string();
  if (!bench::fs::exists(path)) {
    const std::string n = std::to_string(s.n);
    if (bench::RunProcess({ARCHGEO_BINARY, "generate", path, "--nu", n, "--nv", n, "--noise",
                           "0.05"}).exit_code != 0) {
      throw std::runtime_error("archgeo generate failed for " + path);
    }
  }
  return path;
}

// One `archgeo solve` of examples/planar_quads.yaml on `mesh` by `side`.
Run SolveOnce(const Side& side, const std::string& mesh, double timeout) {
  const std::string out = (bench::Scratch() / Fmt("design_speed_%d", int(getpid()))).string();
  const std::string report = out + ".json", log = out + ".log";
  std::vector<std::string> argv = {side.binary, "solve", bench::Source("examples/planar_quads.yaml"),
                                   "--quiet", "--set", "mesh=" + mesh, "--set",
                                   "output={mesh: " + out + ".ply, image: " + out +
                                       ".png, report: " + report + "}"};
  std::vector<std::string> sets = bench::ExtraSets();
  sets.insert(sets.end(), side.sets.begin(), side.sets.end());
  for (const std::string& s : sets) argv.insert(argv.end(), {"--set", s});
  bench::fs::remove(report);
  Run r;
  r.process = bench::RunProcess(argv, timeout, log);
  if (r.process.exit_code == 2) {  // bad input: archgeo's message, and the same exit code
    std::cout << std::flush;
    std::cerr << side.label << ": " << std::ifstream(log).rdbuf();
    bench::fs::remove(log);
    std::exit(2);
  }
  if (bench::fs::exists(report)) r.report = Json::parse(std::ifstream(report));
  for (const char* ext : {".json", ".ply", ".png"}) bench::fs::remove(out + ext);
  if (!r.report.is_null()) bench::fs::remove(log);
  return r;
}

using bench::PrintMarkdown;
using bench::Rows;

double MedianOf(const std::vector<Run>& runs, double (*f)(const Run&)) {
  std::vector<double> v;
  for (const Run& r : runs) v.push_back(f(r));
  return archgeo::Median(v);
}
double Wall(const Run& r) { return r.process.seconds; }
double Cpu(const Run& r) { return r.process.cpu_seconds; }
double PeakMb(const Run& r) { return r.process.max_rss_mb; }
double MovePercent(const Run& r) {
  return 100 * Get(r.report, "/after/displacement_max") / Get(r.report, "/before/bbox_diagonal");
}

// Linear solves of a run: factorisations (the iterations of rounds solved
// with one sparse Cholesky per step, by LeanSolve or Ceres) or CG steps.
std::string LinearSolves(const Json& r) {
  const double pcg = Get(r, "/pcg/rounds"), iters = Get(r, "/iterations/inner");
  if (!(pcg > 0)) {
    // The report's count and flops (an archgeo that writes them); else one
    // factorisation per iteration.
    const Json factored = r.value("cholesky_factorisations", Json());
    if (!factored.is_object() || factored.value("count", 0) == 0) {
      return Fmt("%.0f factorisations", iters);
    }
    const int count = factored.value("count", 0);
    return Fmt("%d factorisations of %.0f Mflop", count, 1e3 * factored.value("gflop", 0.0) / count);
  }
  const double rounds = Get(r, "/iterations/outer");
  return Fmt("%.0f CG steps", Get(r, "/pcg/cg_iterations")) +
         (pcg < rounds ? Fmt(" (%.0f of %.0f rounds)", pcg, rounds) : "");
}

// What a run misses of the quality ("" if nothing): exit 0 (valid,
// every tolerance met), δ_PQ,n ≤ 1e-3, E not above the input's, every panel convex.
std::string QualityMissed(const Run& r) {
  if (r.process.exit_code != 0 || r.report.is_null()) return "exit";
  if (!(Get(r.report, "/after/pq_normalized_max") <= 1e-3)) return "δ_PQ,n";
  if (!(Get(r.report, "/after/E") <= Get(r.report, "/before/E"))) return "E";
  if (Get(r.report, "/after/nonconvex_panels") != 0) return "convexity";
  return "";
}

// Why the size's target is not met by these runs ("" if it is): the median
// wall time, the median peak memory against its bound, every run's quality.
std::string Missed(const Size& size, const std::vector<Run>& runs) {
  std::vector<std::string> why;
  if (MedianOf(runs, Wall) > size.target_s) why.push_back("time");
  if (size.target_mb > 0 && MedianOf(runs, PeakMb) > size.target_mb) why.push_back("memory");
  for (const Run& r : runs) {
    const std::string q = QualityMissed(r);
    if (!q.empty()) {
      why.push_back(q);
      break;
    }
  }
  std::string text;
  for (const std::string& w : why) text += (text.empty() ? "" : ", ") + w;
  return text;
}

std::vector<std::string> Row(const Size& size, const Side& side, const std::vector<Run>& runs) {
  std::set<int> codes;
  for (const Run& r : runs) codes.insert(r.process.timed_out ? -2 : r.process.exit_code);
  std::string exits;
  for (int c : codes) exits += (exits.empty() ? "" : ",") + (c == -2 ? "timeout" : std::to_string(c));
  auto [low, high] = std::minmax_element(runs.begin(), runs.end(),
                                         [](const Run& a, const Run& b) { return Wall(a) < Wall(b); });
  const std::string target = Fmt("%.1f s", size.target_s) +
                             (size.target_mb > 0 ? Fmt(", %.0f MB", size.target_mb) : "");
  // Iterations and quality: the first run that wrote a report.
  const auto first = std::find_if(runs.begin(), runs.end(), [](const Run& x) { return !x.report.is_null(); });
  const bool reported = first != runs.end();
  const std::string quads = reported ? Fmt("%.0f", Get(first->report, "/before/quads"))
                                     : Fmt("%d", size.n * size.n);
  std::vector<std::string> row = {size.name, quads, side.label,
                                  Fmt("%.2f (%.2f–%.2f)", MedianOf(runs, Wall), Wall(*low), Wall(*high)),
                                  target, Fmt("%.2f", MedianOf(runs, Cpu)),
                                  Fmt("%.0f", MedianOf(runs, PeakMb))};
  if (!reported) {
    row.insert(row.end(), {"-", "-", "-", "-", "-", "-", exits, "no: exit"});
    return row;
  }
  const Json& rep = first->report;
  const std::string missed = Missed(size, runs);
  row.insert(row.end(),
             {Fmt("%.0f / %.0f", Get(rep, "/iterations/outer"), Get(rep, "/iterations/inner")),
              LinearSolves(rep), Fmt("%.3e", Get(rep, "/after/pq_normalized_max")),
              Fmt("%.3f (%.3f)", Get(rep, "/after/E"), Get(rep, "/before/E")),
              Fmt("%.3f", MovePercent(*first)),
              Fmt("%.0f non-convex, %s", Get(rep, "/after/nonconvex_panels"),
                  rep.value("validity", Json::object()).value("valid", false) ? "valid" : "invalid"),
              exits, missed.empty() ? "met" : "no: " + missed});
  return row;
}

std::vector<std::string> RatioRow(const Size& size, const std::vector<Run>& a, const std::vector<Run>& b) {
  const auto ratio = [&](double (*f)(const Run&)) { return Fmt("×%.2f", MedianOf(a, f) / MedianOf(b, f)); };
  const bool moved = !a.front().report.is_null() && !b.front().report.is_null();
  return {size.name, "", "ratio", ratio(Wall), "", ratio(Cpu), ratio(PeakMb), "", "", "", "",
          moved ? Fmt("×%.3f", MovePercent(a.front()) / MovePercent(b.front())) : "-", "", "", ""};
}

const char kUsage[] =
    "usage: design_speed [--sizes LIST] [--include-1m] [--runs N] [--other PATH]\n"
    "                    [--other-set KEY=VALUE]... [--timeout SECONDS] [--set KEY=VALUE]...\n"
    "  --sizes LIST           comma-separated of conjugate, 10k, 30k, 100k, 1m\n"
    "                         (default conjugate,10k,30k,100k)\n"
    "  --include-1m           adds 1m (1000x1000 quads; about 90 s and 6 GB a run)\n"
    "  --runs N               runs of each side per size (5); medians are reported\n"
    "  --other PATH           a second archgeo binary, its runs interleaved with this build's\n"
    "  --other-set KEY=VALUE  a setting of the second side only (without --other: this build)\n"
    "  --timeout SECONDS      a run is killed after this long (600)\n"
    "  --set KEY=VALUE        a setting of every run\n";

int Main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--help") {
    std::cout << kUsage;
    return 0;
  }
  const std::vector<std::string> rest = bench::Init(
      argc, argv, {{"--sizes", true}, {"--include-1m"}, {"--runs", true}, {"--other", true},
                   {"--other-set", true}, {"--timeout", true}});
  std::vector<std::string> names = {"conjugate", "10k", "30k", "100k"};
  int runs = 5;
  double timeout = 600;
  Side self{"this build", ARCHGEO_BINARY, {}}, other{"other", "", {}};
  for (size_t i = 0; i < rest.size(); ++i) {
    const std::string& flag = rest[i];
    if (flag == "--include-1m") {
      names.push_back("1m");
      continue;
    }
    const std::string& value = rest[++i];
    if (flag == "--sizes") {
      names.clear();
      std::stringstream list(value);
      for (std::string name; std::getline(list, name, ',');) {
        if (std::none_of(kSizes.begin(), kSizes.end(), [&](const Size& s) { return s.name == name; })) {
          bench::RefuseValue(argv[0], flag, value, "a comma-separated list of conjugate, 10k, 30k, 100k, 1m");
        }
        names.push_back(name);
      }
    } else if (flag == "--runs") {
      runs = bench::CountArgument(argv[0], flag, value);
    } else if (flag == "--other") {
      if (access(value.c_str(), X_OK) != 0) bench::RefuseValue(argv[0], flag, value, "an executable archgeo");
      other.binary = value;
    } else if (flag == "--other-set") {
      other.sets.push_back(value);
    } else {  // --timeout
      timeout = bench::SecondsArgument(argv[0], flag, value);
    }
  }
  const bool compare = !other.binary.empty() || !other.sets.empty();
  if (compare && other.binary.empty()) other.binary = ARCHGEO_BINARY;
  if (compare) {
    other.label = other.binary == ARCHGEO_BINARY ? "this build" : "other";
    for (const std::string& s : other.sets) other.label += " " + s;
  }
  double load[3] = {0, 0, 0};
  getloadavg(load, 3);
  std::cout << "spec: examples/planar_quads.yaml (mesh and output paths set); runs per size and side: "
            << runs << "; timeout " << timeout << " s a run\nthis build: " << ARCHGEO_BINARY << "\n";
  if (compare) std::cout << "other: " << other.binary << "\n";
  std::cout << Fmt("load average at the start: %.2f\n\n", load[0]) << std::flush;

  Rows table = {{"size", "quads", "binary", "wall s median (min–max)", "target", "CPU s",
                      "peak MB", "rounds / iterations", "linear solves", "δ_PQ,n max", "E (input)",
                      "max move %", "panels", "exit", "target met"}};
  for (const std::string& name : names) {
    const Size& size = *std::find_if(kSizes.begin(), kSizes.end(), [&](const Size& s) { return s.name == name; });
    const std::string mesh = DesignMesh(size);
    std::vector<Run> mine, theirs;
    for (int k = 0; k < runs; ++k) {  // interleaved, alternating which side goes first
      if (compare && k % 2 == 1) theirs.push_back(SolveOnce(other, mesh, timeout));
      mine.push_back(SolveOnce(self, mesh, timeout));
      if (compare && k % 2 == 0) theirs.push_back(SolveOnce(other, mesh, timeout));
    }
    table.push_back(Row(size, self, mine));
    if (compare) {
      table.push_back(Row(size, other, theirs));
      table.push_back(RatioRow(size, mine, theirs));
    }
    std::cout << "done " << name << Fmt(" (%.1f s median)\n", MedianOf(mine, Wall)) << std::flush;
  }
  getloadavg(load, 3);
  std::cout << Fmt("load average at the end: %.2f\n\n", load[0]);
  PrintMarkdown(table);
  std::cout
      << "\nwall: the whole `archgeo solve` process (read, solve, metrics, writing the mesh, image\n"
         "and report), median of the runs (fastest–slowest); target: issue 47's wall time (and\n"
         "peak memory) for the size; CPU: user + system seconds of the process; peak MB: its\n"
         "maximum resident set (wait4 ru_maxrss, MiB); iterations: rounds (outer) / iterations\n"
         "(inner, accepted and rejected steps); linear solves: factorisations when every round\n"
         "was solved with one sparse Cholesky per step (with CHOLMOD's flops of one, on average),\n"
         "else the CG steps of the PCG rounds;\n"
         "E (input): the output's E = Σ ℓ ℓ* and the input's; max move: the largest vertex\n"
         "displacement, % of the bounding-box diagonal; panels: non-convex panels of the output\n"
         "and the report's validity; these figures are the first run's. exit: every run's exit\n"
         "code; target met: the median wall time (and memory) within the target and every run\n"
         "exits 0 with δ_PQ,n ≤ 1e-3, E not above the input's and no non-convex panel.\n"
         "ratio: this build's median over the other's (max move: first runs).\n";
  return 0;
}

}  // namespace ARCHGEO_UNITY_ID

ARCHGEO_BENCHMARK_PROGRAM(design_speed, ARCHGEO_UNITY_ID::Main);
