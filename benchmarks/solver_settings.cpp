// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Compares Ceres settings for the planar-quad solve (examples/planar_quads.yaml
// on the Conjugate mesh): sparse Cholesky with SuiteSparse vs Eigen, CGNR,
// Levenberg-Marquardt vs dogleg, 1 vs 2 threads, OpenMP dynamic threads on vs
// off (STYLE.md: Debian's CHOLMOD hard-codes 4 OpenMP threads), then dense_qr
// on a small generated grid and one cost-functor evaluation with Google
// Benchmark.
//
//   cmake --build <build> --target solver_settings
//   <build>/benchmarks/solver_settings [--benchmark_filter=...]
//
// Times are wall-clock on the machine that runs it.
#include <benchmark/benchmark.h>
#include <ceres/cost_function.h>
#include <omp.h>

#include <fstream>

#include "benchmarks/bench_util.h"
#include "energies/pq_diagonal.h"
#include "problems/commands/generate.h"
#include "benchmarks/program.h"

namespace ARCHGEO_UNITY_ID {

using bench::Fmt;
using bench::Get;

const std::string kSpec = bench::Source("examples/planar_quads.yaml");

struct Setting {
  std::string label;
  std::vector<std::string> overrides;
  archgeo::ProgressSink progress = {};  // called per Ceres iteration
};

constexpr int kRounds = 3;

std::vector<std::string> Row(const std::string& label, const bench::Json& r) {
  const double iters = Get(r, "/iterations/inner"), ceres = Get(r, "/seconds/solver"),
               linear = Get(r, "/seconds/linear_solver");
  if (r.value("exit_code", 0) != 0) return {label, "no usable solution: " + r.value("message", "")};
  return {label,
          Fmt("%.2f", Get(r, "/wall_seconds")),
          Fmt("%.0f / %.0f", iters, Get(r, "/iterations/outer")),
          Fmt("%.3f", linear),
          Fmt("%.0f%%", 100 * linear / ceres),
          Fmt("%.1f", 1000 * ceres / iters),
          Fmt("%.6e", Get(r, "/objective/total")),
          Fmt("%.2e", Get(r, "/after/pq_normalized_max")),
          bench::Met(r)};
}

const std::vector<std::string> kHeader = {"setting",   "wall s",       "iter (Ceres/outer)",
                                          "linear s",  "linear share", "ms/iter",
                                          "objective", "δ_PQ,n max",   "met"};

bench::Json SolveOrError(const std::string& mesh, const std::vector<std::string>& overrides,
                         const archgeo::ProgressSink& progress = {}) {
  std::vector<std::string> all = {"mesh=" + mesh};
  all.insert(all.end(), overrides.begin(), overrides.end());
  try {
    return bench::Solve(kSpec, all, progress);
  } catch (const std::exception& e) {
    return {{"exit_code", 1}, {"message", e.what()}};
  }
}

int ProcessThreads() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("Threads:", 0) == 0) return std::stoi(line.substr(8));
  }
  return -1;
}

// Best of kRounds per setting by wall time; the rounds run the settings in
// turn, so a burst of load elsewhere on the machine hits them all alike. Each
// report gets "process_threads": this process's thread count after its first run.
std::vector<bench::Json> RunSettings(const std::string& mesh,
                                     const std::vector<Setting>& settings) {
  std::vector<bench::Json> best(settings.size());
  for (int round = 0; round < kRounds; ++round) {
    for (size_t i = 0; i < settings.size(); ++i) {
      bench::Json r = SolveOrError(mesh, settings[i].overrides, settings[i].progress);
      if (round == 0) {
        r["process_threads"] = ProcessThreads();
        best[i] = std::move(r);
      } else if (Get(r, "/wall_seconds") < Get(best[i], "/wall_seconds")) {
        r["process_threads"] = best[i]["process_threads"];
        best[i] = std::move(r);
      }
    }
  }
  return best;
}

void PrintTable(const std::vector<Setting>& settings, const std::vector<bench::Json>& reports) {
  bench::Table t(kHeader);
  for (size_t i = 0; i < settings.size(); ++i) t.Add(Row(settings[i].label, reports[i]));
  t.Print();
}

// --- Google Benchmark: small grid (dense_qr fits) and one functor evaluation.

std::string SmallGrid() {
  static const std::string path = [] {
    const std::string p = (bench::Scratch() / "grid_20x15.obj").string();
    archgeo::GenerateOptions grid;
    grid.nu = 20;
    grid.nv = 15;
    grid.noise = 0.05;
    archgeo::GenerateSurface(p, grid);
    return p;
  }();
  return path;
}

void BM_SmallGridSolve(benchmark::State& state, std::vector<std::string> overrides) {
  bench::Json r;
  for (auto _ : state) r = SolveOrError(SmallGrid(), overrides);
  if (r.value("exit_code", 0) != 0) {
    state.SkipWithError(r.value("message", "failed").c_str());
    return;
  }
  state.counters["ceres_iter"] = Get(r, "/iterations/inner");
  state.counters["linear_ms"] = 1000 * Get(r, "/seconds/linear_solver");
  state.counters["objective"] = Get(r, "/objective/total");
  state.counters["pq_n_max"] = Get(r, "/after/pq_normalized_max");
  state.counters["met"] = bench::Met(r) == "yes";
}

void BM_PqDiagonalEvaluate(benchmark::State& state) {
  std::unique_ptr<ceres::CostFunction> cost(archgeo::MakeAutoDiff(archgeo::PqDiagonal(1.0)));
  double b[4][3] = {{0, 0, 0}, {1, 0, 0.01}, {1, 1, 0}, {0, 1, -0.02}};
  double residual, jac[4][3];
  const double* params[] = {b[0], b[1], b[2], b[3]};
  double* jacobians[] = {jac[0], jac[1], jac[2], jac[3]};
  for (auto _ : state) {
    cost->Evaluate(params, &residual, state.range(0) ? jacobians : nullptr);
    benchmark::DoNotOptimize(residual);
    benchmark::ClobberMemory();
  }
}

void RegisterBenchmarks() {
  const std::pair<const char*, std::vector<std::string>> solves[] = {
      {"sparse_normal_cholesky/suite_sparse", {}},
      {"dense_qr", {"solver.linear_solver_type=dense_qr"}},
      {"dense_normal_cholesky", {"solver.linear_solver_type=dense_normal_cholesky"}},
      {"cgnr/jacobi", {"solver.linear_solver_type=cgnr"}},
  };
  for (const auto& [name, overrides] : solves) {
    benchmark::RegisterBenchmark((std::string("SmallGrid20x15/") + name).c_str(), BM_SmallGridSolve,
                                 overrides)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
  benchmark::RegisterBenchmark("PqDiagonal/Evaluate", BM_PqDiagonalEvaluate)
      ->ArgName("jacobians")
      ->Arg(0)
      ->Arg(1);
}


// The BLAS under CHOLMOD: archgeo links OpenBLAS; LD_PRELOAD puts another
// BLAS's dgemm_ & co. first (the report's "blas" names the one that served).
void PrintBlasTable(const std::string& mesh) {
  std::cout << "\nBLAS under CHOLMOD (archgeo solve as a subprocess, LD_PRELOAD), Conjugate mesh, "
               "best of "
            << kRounds << ":\n";
  const std::string lib = "/usr/lib/x86_64-linux-gnu/";
  const std::vector<std::pair<std::string, std::string>> blas = {
      {"OpenBLAS (default)", ""},
      {"ATLAS", lib + "atlas/libblas.so.3"},
      {"reference BLAS", lib + "blas/libblas.so.3"}};
  bench::Table table({"BLAS", "library", "wall s", "linear s", "ms/linear solve", "δ_PQ,n max"});
  for (const auto& [name, preload] : blas) {
    if (!preload.empty() && !bench::fs::exists(preload)) {
      table.Add({name, preload + " not installed"});
      continue;
    }
    if (!preload.empty()) setenv("LD_PRELOAD", preload.c_str(), 1);
    bench::Json best;
    double best_wall = 1e300;
    for (int round = 0; round < kRounds; ++round) {
      bench::Json report;
      const bench::ProcessResult r = bench::SolveCommand(kSpec, {"mesh=" + mesh}, &report);
      if (r.exit_code == 0 && r.seconds < best_wall) {
        best_wall = r.seconds;
        best = report;
      }
    }
    unsetenv("LD_PRELOAD");
    if (best.is_null()) {
      table.Add({name, "run failed"});
      continue;
    }
    const double linear = Get(best, "/seconds/linear_solver");
    table.Add({name, best.value("blas", ""), Fmt("%.2f", best_wall), Fmt("%.3f", linear),
               Fmt("%.1f", 1000 * linear / Get(best, "/iterations/inner")),
               Fmt("%.2e", Get(best, "/after/pq_normalized_max"))});
  }
  table.Print(std::cout);
}

int Main(int argc, char** argv) {
  bench::InitLogging(argv[0]);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  std::cout << "BLAS: " << archgeo::BlasLibrary() << "\n"
            << "spec: " << kSpec << " (weights as in the file; only solver keys overridden)\n"
            << "times: wall-clock on this machine (2 cores, shared with other work)\n\n";

  const std::string conjugate = bench::Data("libigl_inspired_mesh_quads_Conjugate.off");
  std::cout << "Conjugate mesh (1749 vertices, 1633 quads), in process, best of " << kRounds
            << ":\n";
  const std::vector<Setting> settings = {
      {"sparse_normal_cholesky + suite_sparse", {}},
      {"sparse_normal_cholesky + eigen_sparse", {"solver.sparse_linear_algebra_library_type=eigen_sparse"}},
      {"cgnr + jacobi", {"solver.linear_solver_type=cgnr", "solver.preconditioner_type=jacobi"}},
      {"dogleg (suite_sparse)", {"solver.trust_region_strategy_type=dogleg"}},
      {"threads 1 (suite_sparse)", {"solver.num_threads=1"}},
      {"threads 2 (suite_sparse)", {"solver.num_threads=2"}}};
  PrintTable(settings, RunSettings(conjugate, settings));
  std::cout
      << "wall s: whole RunSpec; linear share: linear-solver s / Ceres s; ms/iter: Ceres s /\n"
         "Ceres iterations; objective: ½Σ w r² at the last linearisation (canonical frame;\n"
         "it differs when the path differs). dense_qr does not fit here: its dense\n"
         "Jacobian has ~5k columns (see the small grid below).\n\n";

  // RunSpec calls ConfigureThreading() (omp_set_dynamic(1)) first; "OFF" undoes
  // it from the progress sink, which Ceres calls on the solving thread after
  // iteration 0, i.e. before the first linear solve. ON is listed first, so its
  // thread count is read before OFF grows the OpenMP pool (which stays).
  std::cout << "OpenMP dynamic threads (CHOLMOD's OpenMP teams), Conjugate mesh, suite_sparse, "
               "best of "
            << kRounds << ":\n";
  const std::vector<Setting> omp = {
      {"dynamic ON (ConfigureThreading)", {}},
      {"dynamic OFF (omp_set_dynamic(0))", {}, [](const archgeo::ProgressEvent&) { omp_set_dynamic(0); }}};
  const std::vector<bench::Json> omp_reports = RunSettings(conjugate, omp);
  omp_set_dynamic(1);
  PrintTable(omp, omp_reports);
  std::cout << "threads in this process after the first ON run: "
            << omp_reports[0].value("process_threads", -1)
            << ", after the first OFF run: " << omp_reports[1].value("process_threads", -1)
            << " (omp_get_num_procs() = " << omp_get_num_procs() << ")\n";
  PrintBlasTable(conjugate);
  std::cout << "\nSmall generated grid 20x15 quads (noise 0.05), Google Benchmark "
               "(Time = one whole RunSpec, wall clock):\n";
  RegisterBenchmarks();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace ARCHGEO_UNITY_ID

ARCHGEO_BENCHMARK_PROGRAM(solver_settings, ARCHGEO_UNITY_ID::Main);
