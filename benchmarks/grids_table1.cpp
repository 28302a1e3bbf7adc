// Force-directed orthogonal grids, Table 1 — one command:
//   build-xxx/grids_table1 [--quick] [--history] [--scene NAME]
// For every scene of Table 1 of "An iterative force-directed algorithm for
// orthogonal, locally equilateral grids on parametric surfaces" (text in
// ../shared/papers/force-directed-orthogonal-grids.md) it lays the uniform
// grid of the scene's type on our stand-in surface (surfaces/surface_factory.h;
// the paper does not give its surfaces, grid sizes or factors), runs the
// force-directed method (surfaces/force_directed.h, Listing 1, the defaults
// d_o = d_b = d_l = 5%, ideal length = mean initial edge length, stop on
// stall) and prints MDO, ADO (degrees, on the interpolating splines) and MDE,
// ADE (percent, quad sides) before and after, with iterations and time,
// beside the paper's rows. A last run times a 100 × 100 grid.
// The least-squares method of issue 12 is declared on the new engine in
// phase 2; its column is added to this table then (nothing is printed for it
// here).
// --quick: halves the grid sizes; --history: prints every run's history;
// --scene NAME: only that surface name.
#include <chrono>
#include <cmath>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "bench_util.h"
#include "surfaces/force_directed.h"
#include "surfaces/grid.h"
#include "surfaces/grid_quality.h"
#include "surfaces/surface_factory.h"

namespace {

using archgeo::ForceDirectedOptions;
using archgeo::ForceDirectedResult;
using archgeo::GridType;
using archgeo::QualityMeasures;
using bench::Fmt;

// Table 1 of the paper: MDO, ADO (degrees), MDE, ADE (percent). The open
// scenes have a single row; the table's caption marks before/after rows by
// subscripts, which only the two closed scenes carry, so their single rows
// are results after the algorithm.
struct PaperRow {
  const char* label;
  double mdo, ado, mde, ade;
};

struct Scene {
  const char* table1_name;  // the scene of Table 1
  const char* surface;      // our stand-in (factory name, default parameters)
  GridType type;
  int nu, nv;
  std::vector<PaperRow> paper;
};

std::vector<Scene> Scenes() {
  return {
      {"Klein Bottle", "klein_bottle", GridType::kClosedBoth, 60, 24,
       {{"before", 33.78, 11.75, 404, 90}, {"after", 5.43, 0.48, 152, 28}}},
      {"Tower", "tower", GridType::kClosedU, 48, 30,
       {{"before", 40.47, 10.55, 134, 29}, {"after", 1.43, 0.28, 15, 9}}},
      {"Tower (Rings)", "tower_rings", GridType::kOpen, 24, 30, {{"after", 5.84, 1.73, 8, 4}}},
      {"Bridge", "dupin_bridge", GridType::kOpen, 40, 16, {{"after", 5.37, 2.28, 12, 4}}},
      {"Function Graph", "function_graph", GridType::kOpen, 30, 30, {{"after", 4.30, 1.09, 9, 3}}},
  };
}

std::string Cells(const QualityMeasures& q) {
  return Fmt("%7.2f° %6.2f° %7.1f%% %6.1f%%", q.mdo, q.ado, q.mde, q.ade);
}

std::string Parameters(const archgeo::Surface& surface) {
  std::string s;
  for (const auto& [name, value] : archgeo::SurfaceParameterValues(surface)) {
    s += (s.empty() ? "" : ", ") + name + "=" + Fmt("%g", value);
  }
  return s;
}

void PrintHistory(const ForceDirectedResult& r) {
  const size_t step = std::max<size_t>(1, r.history.size() / 12);
  for (size_t k = 0; k < r.history.size(); k += step) {
    const auto& h = r.history[k];
    std::cout << Fmt("    iteration %6d  ", h.iteration) << Cells(h.quality.Table1())
              << Fmt("   max move %.2e L\n", h.max_move);
  }
  const auto& h = r.history.back();
  std::cout << Fmt("    iteration %6d  ", h.iteration) << Cells(h.quality.Table1())
            << Fmt("   max move %.2e L\n", h.max_move);
}

}  // namespace

int main(int argc, char** argv) {
  bench::InitLogging(argv[0]);
  bool quick = false, history = false;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--history")) history = true;
    else if (!std::strcmp(argv[i], "--scene") && i + 1 < argc) only = argv[++i];
    else {
      std::cerr << "usage: " << argv[0] << " [--quick] [--history] [--scene NAME]\n";
      return 2;
    }
  }
  const ForceDirectedOptions options;  // the paper-faithful defaults
  std::cout << "Force-directed grids, Table 1 [force-directed grids paper, Table 1]\n"
            << "force method: d_o = " << options.d_o << ", d_b = " << options.d_b
            << ", d_l = " << options.d_l
            << ", L = mean initial edge length, one re-projection (eq. 3), stop on stall ("
            << options.stall_tolerance << " L) or " << options.max_iterations << " iterations\n"
            << "MDO, ADO on the interpolating splines; MDE, ADE on the quad sides\n\n";

  bench::Table table({"scene", "type", "grid", "row", "MDO     ADO     MDE      ADE", "iterations",
                      "stop", "time"});
  std::vector<std::string> stand_ins;
  for (const Scene& scene : Scenes()) {
    if (!only.empty() && only != scene.surface) continue;
    const archgeo::Surface surface = archgeo::MakeSurface(scene.surface);
    const int nu = quick ? scene.nu / 2 : scene.nu, nv = quick ? scene.nv / 2 : scene.nv;
    const archgeo::Grid grid = archgeo::MakeUniformGrid(surface, nu, nv, scene.type);
    const auto start = bench::Clock::now();
    const ForceDirectedResult r = archgeo::RunForceDirected(surface, grid, options);
    const double seconds = bench::Seconds(start);
    const std::string type = archgeo::GridTypePaperName(scene.type);
    const std::string size = Fmt("%d × %d", nu, nv);
    table.Add({scene.table1_name, type, size, "ours before", Cells(r.before.Table1()), "", "", ""});
    table.Add({"", "", "", "ours force", Cells(r.after.Table1()), std::to_string(r.iterations),
               archgeo::ForceStopName(r.stop), Fmt("%.2f s", seconds)});
    for (const PaperRow& row : scene.paper) {
      table.Add({"", "", "", std::string("paper ") + row.label,
                 Cells({row.mdo, row.ado, row.mde, row.ade}), "", "", ""});
    }
    stand_ins.push_back(std::string(scene.table1_name) + ": " + scene.surface + " (" +
                        Parameters(surface) + ")");
    if (history) {
      std::cout << scene.table1_name << " history (Table 1 measures):\n";
      PrintHistory(r);
    }
  }
  table.Print();
  std::cout << "\nstand-ins (surfaces/surface_factory.h, formulas in surfaces/*.h):\n";
  for (const std::string& s : stand_ins) std::cout << "  " << s << "\n";
  std::cout << "\nleast squares: declared on the new engine in phase 2 of issue 12; its rows are "
               "added to this table then.\n";

  if (only.empty()) {
    const int n = quick ? 50 : 100;
    const archgeo::Surface surface = archgeo::MakeSurface("function_graph");
    const archgeo::Grid grid = archgeo::MakeUniformGrid(surface, n, n, GridType::kOpen);
    const auto start = bench::Clock::now();
    const ForceDirectedResult r = archgeo::RunForceDirected(surface, grid, options);
    const double seconds = bench::Seconds(start);
    std::cout << Fmt("\n%d × %d function graph, force method: ", n, n) << Cells(r.before.Table1())
              << "  →  " << Cells(r.after.Table1())
              << Fmt(" in %d iterations (%s), %.2f s, %.2f ms per iteration\n", r.iterations,
                     archgeo::ForceStopName(r.stop), seconds, 1e3 * seconds / std::max(1, r.iterations));
  }
  return 0;
}
