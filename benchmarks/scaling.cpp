// How the planar-quad solve scales with mesh size (STYLE.md, "Direct solves
// grow ~n^1.5"): examples/planar_quads.yaml on generated non-planar roof grids
// (`archgeo generate --noise 0.05`) of 100x100 (10k quads) and 316x316 (~100k
// quads), and 1000x1000 (1M quads) only with --include-1m (long: 120–131 s,
// depending on the hour, and 5.70 GiB with the defaults on 2026-11-28; add
// --defaults-only, Ceres' Cholesky would need more memory than this machine
// has). Every size is solved twice, by Ceres with one sparse Cholesky per
// step (solver.pcg_above=0) and with the spec's defaults (Levenberg-Marquardt
// with conjugate gradients on the assembled normal equations for large
// rounds, core/lean_solve.h), unless --defaults-only. Prints time to
// tolerance, iterations, peak memory, the time of one linear solve and the
// fitted exponents of time and memory.
// Each solve is an `archgeo solve` subprocess, so the peak memory is per run.
//
//   cmake --build <build> --target scaling archgeo   # runs the archgeo tool
//   <build>/benchmarks/scaling [--include-1m] [--defaults-only] [--timeout SECONDS]
//                              [--set KEY=VALUE]...
//
// Times are wall-clock on the machine that runs it. Grids are cached in the
// scratch folder (see bench::Scratch()).
#include "benchmarks/bench_util.h"

#include <array>
#include <cmath>
#include <map>

namespace {

using bench::Fmt;
using bench::Get;

// Generates (once) an n x n quad grid and returns its path.
std::string Grid(int n) {
  const std::string path = (bench::Scratch() / Fmt("grid_%dx%d.ply", n, n)).string();
  if (!bench::fs::exists(path)) {
    const std::string size = std::to_string(n);
    const bench::ProcessResult p = bench::RunProcess(
        {ARCHGEO_BINARY, "generate", path, "--nu", size, "--nv", size, "--noise", "0.05"});
    if (p.exit_code != 0) throw std::runtime_error("archgeo generate failed for " + path);
  }
  return path;
}

// Fitted exponent b of y = a x^b between two sizes.
double Exponent(double x1, double y1, double x2, double y2) {
  return std::log(y2 / y1) / std::log(x2 / x1);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes = {100, 316};
  double timeout = 600;
  bool compare = true;
  // bench::Init takes the --set arguments and refuses any other it is not given here.
  const std::vector<std::string> rest = bench::Init(
      argc, argv, {{"--include-1m"}, {"--defaults-only"}, {"--timeout", true}});
  for (size_t i = 0; i < rest.size(); ++i) {
    if (rest[i] == "--include-1m") {
      sizes.push_back(1000);
    } else if (rest[i] == "--defaults-only") {
      compare = false;
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
  };
  std::vector<Mode> modes;
  if (compare) modes.push_back({"cholesky", {"solver.pcg_above=0"}});
  modes.push_back({"default", {}});
  bench::Table t({"grid", "quads", "solve", "PCG rounds", "variables", "iter (inner/outer)",
                  "s / linear solve", "solver s", "total s", "peak MB", "δ_PQ,n max",
                  "max move % diag", "met"});
  std::string blas;  // as reported by the archgeo subprocess
  // Per mode: (quads, total s, peak MB) of the runs that met the tolerance.
  std::map<std::string, std::vector<std::array<double, 3>>> curve;
  for (int n : sizes) {
    const std::string mesh = Grid(n);
    for (const Mode& mode : modes) {
      bench::Json r;
      std::vector<std::string> sets = {"mesh=" + mesh};
      sets.insert(sets.end(), mode.sets.begin(), mode.sets.end());
      const bench::ProcessResult p = bench::SolveCommand(spec, sets, &r, /*write_mesh=*/false, timeout);
      const std::string grid = Fmt("%dx%d", n, n), quads = Fmt("%d", n * n);
      if (p.timed_out || r.is_null()) {
        t.Add({grid, quads, mode.name, "-", "-", "-", "-", "-", Fmt("%.0f", p.seconds),
               Fmt("%.0f", p.max_rss_mb), "-", "-",
               p.timed_out ? Fmt("timed out after %.0f s", p.seconds)
                           : Fmt("failed: exit code %d", p.exit_code)});
      } else {
        const double iters = Get(r, "/iterations/inner"), ceres = Get(r, "/seconds/solver");
        t.Add({grid, quads, mode.name, Fmt("%.0f", Get(r, "/pcg/rounds")),
               Fmt("%.0f", Get(r, "/variables")),
               Fmt("%.0f / %.0f", iters, Get(r, "/iterations/outer")),
               Fmt("%.2f", Get(r, "/seconds/linear_solver") / iters), Fmt("%.1f", ceres),
               Fmt("%.1f", p.seconds), Fmt("%.0f", p.max_rss_mb),
               Fmt("%.2e", Get(r, "/after/pq_normalized_max")),
               Fmt("%.3f", 100 * Get(r, "/after/displacement_max") / Get(r, "/before/bbox_diagonal")),
               bench::Met(r)});
        if (bench::Met(r) == "yes") curve[mode.name].push_back({double(n * n), p.seconds, p.max_rss_mb});
      }
      if (blas.empty() && !r.is_null()) blas = r.value("blas", "");
      std::cout << "done " << grid << " " << mode.name << " (" << Fmt("%.1f", p.seconds) << " s)\n"
                << std::flush;
    }
  }
  std::cout << "\nBLAS (archgeo's report): " << (blas.empty() ? "unknown" : blas) << "\n\n";
  t.Print();
  std::cout << "\nfitted exponents (time ~ quads^b, memory ~ quads^c, between consecutive sizes):\n";
  for (const auto& [mode, points] : curve) {
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
         "ru_maxrss); max move: the largest vertex displacement, % of the bounding-box diagonal.\n";
}
