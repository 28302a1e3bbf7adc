// How the planar-quad solve scales with mesh size (STYLE.md, "Direct solves
// grow ~n^1.5"): examples/planar_quads.yaml on generated non-planar roof grids
// (`archgeo generate --noise 0.05`) of 100x100 (10k quads) and 316x316 (~100k
// quads), and 1000x1000 (1M quads) only with --include-1m (minutes, ~19 GB).
// Each solve is an `archgeo solve` subprocess, so the peak memory is per run.
//
//   cmake --build <build> --target scaling archgeo   # runs the archgeo tool
//   <build>/benchmarks/scaling [--include-1m] [--timeout SECONDS]
//
// Times are wall-clock on the machine that runs it. Grids are cached in the
// scratch folder (see bench::Scratch()).
#include "benchmarks/bench_util.h"

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

}  // namespace

int main(int argc, char** argv) {
  bench::InitLogging(argv[0]);
  std::vector<int> sizes = {100, 316};
  double timeout = 300;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--include-1m") {
      sizes.push_back(1000);
    } else if (arg == "--timeout" && i + 1 < argc) {
      timeout = std::stod(argv[++i]);
    } else {
      std::cerr << "usage: " << argv[0] << " [--include-1m] [--timeout SECONDS]\n";
      return 2;
    }
  }
  const std::string spec = bench::Source("examples/planar_quads.yaml");
  std::cout << "spec: " << spec
            << " (mesh overridden)\ntimes: wall-clock on this machine (2 cores, shared); "
               "timeout "
            << timeout << " s per run\n\n";

  bench::Table t({"grid", "quads", "variables", "iter (Ceres/outer)", "s/iter", "linear share",
                  "Ceres s", "total s", "peak MB", "δ_PQ,n max", "met"});
  std::string blas;  // as reported by the archgeo subprocess
  for (int n : sizes) {
    const std::string mesh = Grid(n);
    bench::Json r;
    const bench::ProcessResult p =
        bench::SolveCommand(spec, {"mesh=" + mesh}, &r, /*write_mesh=*/false, timeout);
    const std::string grid = Fmt("%dx%d", n, n), quads = Fmt("%d", n * n);
    if (p.timed_out || r.is_null()) {
      t.Add({grid, quads, "-", "-", "-", "-", "-", Fmt("%.0f", p.seconds),
             Fmt("%.0f", p.max_rss_mb), "-",
             p.timed_out ? Fmt("timed out after %.0f s", p.seconds)
                         : Fmt("failed: exit code %d", p.exit_code)});
    } else {
      const double iters = Get(r, "/iterations/inner"), ceres = Get(r, "/seconds/ceres");
      t.Add({grid, quads, Fmt("%.0f", Get(r, "/variables")),
             Fmt("%.0f / %.0f", iters, Get(r, "/iterations/outer")), Fmt("%.3f", ceres / iters),
             Fmt("%.0f%%", 100 * Get(r, "/seconds/linear_solver") / ceres), Fmt("%.1f", ceres),
             Fmt("%.1f", p.seconds), Fmt("%.0f", p.max_rss_mb),
             Fmt("%.2e", Get(r, "/after/pq_normalized_max")), bench::Met(r)});
    }
    if (blas.empty() && !r.is_null()) blas = r.value("blas", "");
    std::cout << "done " << grid << " (" << Fmt("%.1f", p.seconds) << " s)\n" << std::flush;
  }
  std::cout << "\nBLAS (archgeo's report): " << (blas.empty() ? "unknown" : blas) << "\n\n";
  t.Print();
  std::cout
      << "\ns/iter: Ceres seconds / Ceres iterations; linear share: linear-solver seconds /\n"
         "Ceres seconds; Ceres s: time in ceres::Solve, all outer rounds; total s: the whole\n"
         "`archgeo solve --quiet` subprocess (read, reference, solve, metrics, report);\n"
         "peak MB: its maximum resident set (wait4 ru_maxrss).\n";
}
