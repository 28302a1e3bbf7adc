// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// How the planar-quad solve scales with mesh size (STYLE.md, "Direct solves
// grow ~n^1.5"): examples/planar_quads.yaml on generated non-planar roof grids
// (`archgeo generate --noise 0.05`) of 100x100 (10k quads) and 316x316 (~100k
// quads), and 1000x1000 (1M quads) only with --include-1m (long: about 90 s
// and 5.65 GiB with the defaults, docs/performance.md; add --defaults-only,
// Ceres' Cholesky would need more memory than this machine has). Every size is
// solved twice, by Ceres with one sparse Cholesky per
// step (solver.pcg_above=0) and with the spec's defaults (Levenberg-Marquardt
// with conjugate gradients on the assembled normal equations for large
// rounds, core/lean_solve.h), unless --defaults-only. Prints time to
// tolerance, iterations, peak memory, the time of one linear solve and the
// fitted exponents of time and memory.
// Each solve is an `archgeo solve` subprocess, so the peak memory is per run.
// The time to tolerance depends on the roof, not only on its size: with
// --seeds K the defaults solve K roofs of each size (noise seeds 1..K; Ceres'
// Cholesky only the first), a row each, and the exponents are fitted to the
// median time and memory of each size.
//
//   cmake --build <build> --target scaling archgeo   # runs the archgeo tool
//   <build>/benchmarks/scaling [--include-1m] [--defaults-only] [--seeds K]
//                              [--timeout SECONDS] [--set KEY=VALUE]...
//
// Times are wall-clock on the machine that runs it. Grids are cached in the
// scratch folder (see bench::Scratch()).
#include "benchmarks/bench_util.h"
#include "bench/bench.h"
#include "benchmarks/program.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace ARCHGEO_UNITY_ID {

using bench::Fmt;
using bench::Get;
using archgeo::Median;

// Generates (once) an n x n quad grid with noise seed `seed` and returns its path.
std::string Grid(int n, int seed) {
  const std::string name =
      seed == 1 ? Fmt("grid_%dx%d.ply", n, n) : Fmt("grid_%dx%d_seed%d.ply", n, n, seed);
  const std::string path = (bench::Scratch() / name).string();
  if (!bench::fs::exists(path)) {
    const std::string size = std::to_string(n);
    const bench::ProcessResult p = bench::RunProcess({ARCHGEO_BINARY, "generate", path, "--nu", size,
                                                      "--nv", size, "--noise", "0.05", "--seed",
                                                      std::to_string(seed)});
    if (p.exit_code != 0) throw std::runtime_error("archgeo generate failed for " + path);
  }
  return path;
}

// Fitted exponent b of y = a x^b between two sizes.
double Exponent(double x1, double y1, double x2, double y2) {
  return std::log(y2 / y1) / std::log(x2 / x1);
}


int Main(int argc, char** argv) {
  std::vector<int> sizes = {100, 316};
  double timeout = 600;
  int seeds = 1;
  bool compare = true;
  // bench::Init takes the --set arguments and refuses any other it is not given here.
  const std::vector<std::string> rest = bench::Init(
      argc, argv, {{"--include-1m"}, {"--defaults-only"}, {"--seeds", true}, {"--timeout", true}});
  for (size_t i = 0; i < rest.size(); ++i) {
    if (rest[i] == "--include-1m") {
      sizes.push_back(1000);
    } else if (rest[i] == "--defaults-only") {
      compare = false;
    } else if (rest[i] == "--seeds") {
      seeds = bench::CountArgument(argv[0], rest[i], rest[i + 1]);
      ++i;
    } else {  // --timeout SECONDS
      timeout = bench::SecondsArgument(argv[0], rest[i], rest[i + 1]);
      ++i;
    }
  }
  const std::string spec = bench::Source("examples/planar_quads.yaml");
  std::cout << "spec: " << spec
            << " (mesh overridden)\ntimes: wall-clock on this machine (2 cores, shared); "
               "timeout "
            << timeout << " s per run\n\n";

  // Each size: Ceres with one sparse Cholesky per step (solver.pcg_above=0)
  // and the spec's default, which solves large rounds by PCG (core/lean_solve.h).
  struct Mode {
    std::string name;
    std::vector<std::string> sets;
    int seeds;  // roofs of each size
  };
  std::vector<Mode> modes;
  if (compare) modes.push_back({"cholesky", {"solver.pcg_above=0"}, 1});
  modes.push_back({"default", {}, seeds});
  bench::Table t({"grid", "seed", "quads", "solve", "PCG rounds", "variables",
                  "iter (inner/outer)", "CG steps", "s / linear solve", "solver s", "total s",
                  "peak MB", "δ_PQ,n max", "max move % diag", "met"});
  std::string blas;  // as reported by the archgeo subprocess
  // Per mode and size: the total s and peak MB of the runs that met the tolerance.
  std::map<std::string, std::map<int, std::array<std::vector<double>, 2>>> curve;
  for (int n : sizes) {
    for (const Mode& mode : modes) {
      for (int seed = 1; seed <= mode.seeds; ++seed) {
        bench::Json r;
        std::vector<std::string> sets = {"mesh=" + Grid(n, seed)};
        sets.insert(sets.end(), mode.sets.begin(), mode.sets.end());
        const bench::ProcessResult p = bench::SolveCommand(spec, sets, &r, /*write_mesh=*/false, timeout);
        const std::string grid = Fmt("%dx%d", n, n), quads = Fmt("%d", n * n);
        if (p.timed_out || r.is_null()) {
          t.Add({grid, Fmt("%d", seed), quads, mode.name, "-", "-", "-", "-", "-", "-",
                 Fmt("%.0f", p.seconds), Fmt("%.0f", p.max_rss_mb), "-", "-",
                 p.timed_out ? Fmt("timed out after %.0f s", p.seconds)
                             : Fmt("failed: exit code %d", p.exit_code)});
        } else {
          const double iters = Get(r, "/iterations/inner"), ceres = Get(r, "/seconds/solver");
          t.Add({grid, Fmt("%d", seed), quads, mode.name, Fmt("%.0f", Get(r, "/pcg/rounds")),
                 Fmt("%.0f", Get(r, "/variables")),
                 Fmt("%.0f / %.0f", iters, Get(r, "/iterations/outer")),
                 Fmt("%.0f", Get(r, "/pcg/cg_iterations")),
                 Fmt("%.2f", Get(r, "/seconds/linear_solver") / iters), Fmt("%.1f", ceres),
                 Fmt("%.1f", p.seconds), Fmt("%.0f", p.max_rss_mb),
                 Fmt("%.2e", Get(r, "/after/pq_normalized_max")),
                 Fmt("%.3f", 100 * Get(r, "/after/displacement_max") / Get(r, "/before/bbox_diagonal")),
                 bench::Met(r)});
          if (bench::Met(r) == "yes") {
            curve[mode.name][n * n][0].push_back(p.seconds);
            curve[mode.name][n * n][1].push_back(p.max_rss_mb);
          }
        }
        if (blas.empty() && !r.is_null()) blas = r.value("blas", "");
        std::cout << "done " << grid << " seed " << seed << " " << mode.name << " ("
                  << Fmt("%.1f", p.seconds) << " s)\n"
                  << std::flush;
      }
    }
  }
  std::cout << "\nBLAS (archgeo's report): " << (blas.empty() ? "unknown" : blas) << "\n\n";
  t.Print();
  if (seeds > 1) {
    std::cout << "\ndefault, per size (" << seeds << " roofs; those that met the tolerance):\n";
    for (const auto& [quads, runs] : curve["default"]) {
      const auto [low, high] = std::minmax_element(runs[0].begin(), runs[0].end());
      std::cout << Fmt("  %9d quads: %zu met, total %.1f-%.1f s (median %.1f), "
                       "peak %.0f MB (median)\n",
                       quads, runs[0].size(), *low, *high, Median(runs[0]), Median(runs[1]));
    }
  }
  std::cout << "\nfitted exponents (time ~ quads^b, memory ~ quads^c, between consecutive sizes"
            << (seeds > 1 ? "; medians" : "") << "):\n";
  for (const auto& [mode, sizes_met] : curve) {
    std::vector<std::array<double, 3>> points;  // (quads, median total s, median peak MB)
    for (const auto& [quads, runs] : sizes_met) {
      points.push_back({double(quads), Median(runs[0]), Median(runs[1])});
    }
    for (size_t k = 1; k < points.size(); ++k) {
      const auto& a = points[k - 1];
      const auto& b = points[k];
      std::cout << Fmt("  %-8s", mode.c_str()) << Fmt("%.0f -> %.0f quads: ", a[0], b[0])
                << Fmt("b = %.2f, ", Exponent(a[0], a[1], b[0], b[1]))
                << Fmt("c = %.2f\n", Exponent(a[0], a[2], b[0], b[2]));
    }
  }
  std::cout
      << "\nsolve: cholesky = Ceres, one sparse Cholesky of the whole problem per step\n"
         "(solver.pcg_above=0); default = the spec's settings, which solve a round of more\n"
         "than solver.pcg_above variables by Levenberg-Marquardt with block-Jacobi conjugate\n"
         "gradients on the assembled normal equations (core/lean_solve.h).\n"
         "s / linear solve: linear-solver seconds / iterations (Ceres: forming J^T J, the\n"
         "factorisation, the back-substitution; PCG: the CG steps); solver s: time in the\n"
         "solver (ceres::Solve or LeanSolve), all rounds;\n"
         "total s: the whole `archgeo solve --quiet` subprocess (read, reference, solve,\n"
         "metrics, report), the time to tolerance; peak MB: its maximum resident set (wait4\n"
         "ru_maxrss); max move: the largest vertex displacement, % of the bounding-box diagonal;\n"
         "seed: the roof's noise seed (archgeo generate --seed); CG steps: all PCG rounds'.\n";
  return 0;
}

}  // namespace ARCHGEO_UNITY_ID

ARCHGEO_BENCHMARK_PROGRAM(scaling, ARCHGEO_UNITY_ID::Main);
