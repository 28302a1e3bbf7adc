// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The deviation / planarity trade-off (issue 49, item 4): how flat the panels
// get, and what it costs in smoothness and time, for each deviation band a
// designer may allow (docs/methods/design_band.md).
//
//   cmake --build <build> --target deviation_tradeoff archgeo
//   <build>/benchmarks/deviation_tradeoff [--mesh PATH] [--bands 0.05,0.1,...]
//       [--svg PATH] [--timeout S] [--set KEY=VALUE ...]
//
// One `archgeo solve examples/planar_quads.yaml` subprocess per band, with
// tolerance.surface_distance_max set to the band (--bands: percent of the
// input's bounding-box diagonal; default 0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1
// and the example's own 1.5%) and one without a band (0). Default mesh: the
// shared Conjugate net. --set is added to every run (not the band's own
// keys: the sweep sets those).
//
// Per run it prints: the exit code; δ_PQ,n max reached; the output's
// deviation (after.surface_distance_max_relative: the report's metrics
// measure every output vertex against the input surface, apart from the
// band's own bookkeeping) and the largest deviation of any round
// (details.surface_band.deviation_reached_relative: the output is the best
// valid round, not always the last); E before and after; panels not convex; whether
// the band binds (details.surface_band.binds) and, where a rejected round met
// planarity, the deviation it needed, or else, where the band binds, the
// deviation of the same run without the band (details.surface_band.unbounded,
// "unbounded"); rounds; wall and CPU seconds.
// It writes an SVG (--svg; default deviation_tradeoff_<mesh>.svg here) of
// δ_PQ,n max, the deviation reached, E and wall seconds against the band
// (log x), with the tolerance 1e-3, the input's E and the unbounded run's
// deviation marked.
//
// Exits 1 when a run gave no report, a banded output lies beyond its band,
// or a run exits 0 with δ_PQ,n max above 1e-3 or a panel not convex.
#include <unistd.h>

#include <sstream>

#include "benchmarks/bench_util.h"
#include "benchmarks/svg_chart.h"
#include "benchmarks/program.h"

namespace ARCHGEO_UNITY_ID {

using bench::Fmt;
using bench::Get;

constexpr double kPlanarity = 1e-3;  // examples/planar_quads.yaml's tolerance.pq_normalized_max
constexpr double kBandSlack = 1e-9;  // relative: the band is exact (design_band.md, step 3)

struct Run {
  double band = 0;  // fraction of the diagonal; 0 = none
  bench::ProcessResult process;
  bench::Json report;  // null if the run wrote none
};

Run SolveWithBand(const std::string& mesh, double band, double timeout) {
  const bench::fs::path out = bench::Scratch() / ("tradeoff_" + std::to_string(getpid()));
  const std::string report = out.string() + ".json", log = out.string() + ".log";
  bench::fs::remove(report);
  std::vector<std::string> argv = {ARCHGEO_BINARY, "solve",
                                   bench::Source("examples/planar_quads.yaml"), "--quiet"};
  std::vector<std::string> sets = {"mesh=" + mesh,
                                   Fmt("tolerance.surface_distance_max=%.17g", band),
                                   "output={report: " + report + "}"};
  sets.insert(sets.end(), bench::ExtraSets().begin(), bench::ExtraSets().end());
  for (const std::string& s : sets) argv.insert(argv.end(), {"--set", s});
  Run run;
  run.band = band;
  run.process = bench::RunProcess(argv, timeout, log);
  if (run.process.exit_code == 2) {  // bad input: archgeo's message, and the same exit code
    std::cout << std::flush;
    std::cerr << std::ifstream(log).rdbuf();
    std::exit(2);
  }
  if (bench::fs::exists(report)) {
    run.report = bench::Json::parse(std::ifstream(report));
    bench::fs::remove(log);
  }
  bench::fs::remove(report);
  return run;
}

// "0.05,0.1,1" (percent) as fractions, ascending; anything else is refused.
std::vector<double> ParseBands(const char* argv0, const std::string& text) {
  std::vector<double> bands;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    char* end = nullptr;
    const double percent = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !(percent > 0) || percent > 100) {
      bench::RefuseValue(argv0, "--bands", text,
                         "percentages of the diagonal in (0, 100], separated by commas");
    }
    bands.push_back(percent / 100);
  }
  if (bands.empty()) {
    bench::RefuseValue(argv0, "--bands", text, "at least one percentage of the diagonal");
  }
  std::sort(bands.begin(), bands.end());
  bands.erase(std::unique(bands.begin(), bands.end()), bands.end());
  return bands;
}

// A --set of the keys the sweep sets would replace the band in every run.
void RefuseBandOverrides(const char* argv0) {
  for (const std::string& s : bench::ExtraSets()) {
    const std::string key = s.substr(0, s.find('='));
    if (key == "tolerance" || key == "tolerance.surface_distance_max" ||
        key == "tolerance.surface_distance") {
      bench::RefuseValue(argv0, "--set", s, "a key the sweep does not set (it sets the band)");
    }
  }
}

std::string Sci(double x) { return std::isnan(x) ? "-" : Fmt("%.2e", x); }
std::string Percent(double relative) {
  return std::isnan(relative) ? "-" : Fmt("%.3f%%", 100 * relative);
}
std::string BandName(double band) { return band > 0 ? Fmt("%g%%", 100 * band) : "none"; }

void PrintTable(const std::vector<Run>& runs) {
  bench::Table t({"band", "exit", "δ_PQ,n max", "deviation", "rounds' max", "E before → after",
                  "not convex", "binds", "needed", "rounds", "wall s", "CPU s"});
  for (const Run& run : runs) {
    const bench::Json& r = run.report;
    const bool banded = run.band > 0 && !r.is_null();
    std::string binds = "-", needed = "-";
    if (banded && r.contains(bench::Json::json_pointer("/details/surface_band/binds"))) {
      binds = r["details"]["surface_band"]["binds"].get<bool>() ? "yes" : "no";
      needed = Percent(Get(r, "/details/surface_band/goals_needed_relative"));
      const bench::Json::json_pointer unbounded("/details/surface_band/unbounded");
      if (r.contains(unbounded)) {  // no round met planarity: the run without the band
        needed = Percent(r.at(unbounded)["deviation_relative"].get<double>()) +
                 (r.at(unbounded)["goals_met"].get<bool>() ? " unbounded" : " unbounded, missed");
      }
    }
    t.Add({BandName(run.band), Fmt("%d", run.process.exit_code),
           Sci(Get(r, "/after/pq_normalized_max")),
           Percent(Get(r, "/after/surface_distance_max_relative")),
           Percent(Get(r, "/details/surface_band/deviation_reached_relative")),
           Fmt("%.2f → %.2f", Get(r, "/before/E"), Get(r, "/after/E")),
           Fmt("%.0f", Get(r, "/after/nonconvex_panels")), binds, needed,
           Fmt("%.0f", Get(r, "/iterations/outer")), Fmt("%.1f", run.process.seconds),
           Fmt("%.1f", run.process.cpu_seconds)});
  }
  t.Print();
}

// What a run broke of the band's and the exit code's promises ("" if none).
std::string Failure(const Run& run) {
  const bench::Json& r = run.report;
  const std::string name = "band " + BandName(run.band) + ": ";
  if (r.is_null()) {
    return name + (run.process.timed_out ? "timed out" : Fmt("no report (exit %d)", run.process.exit_code));
  }
  const double deviation = Get(r, "/after/surface_distance_max_relative");
  if (run.band > 0 && !(deviation <= run.band * (1 + kBandSlack))) {
    return name + "the output lies " + Percent(deviation) + " from the surface";
  }
  if (run.process.exit_code == 0 && !(Get(r, "/after/pq_normalized_max") <= kPlanarity &&
                                      Get(r, "/after/nonconvex_panels") == 0)) {
    return name + "exit 0 with δ_PQ,n max " + Sci(Get(r, "/after/pq_normalized_max")) + " and " +
           Fmt("%.0f", Get(r, "/after/nonconvex_panels")) + " panels not convex";
  }
  return "";
}

bench::Chart TradeoffChart(const std::vector<Run>& runs, const std::string& mesh_name) {
  const Run& none = runs.back();
  const double free_deviation = Get(none.report, "/after/surface_distance_max_relative");
  bench::Chart c;
  c.title = "Deviation band vs planarity: " + mesh_name;
  c.legend = "examples/planar_quads.yaml; filled: exit 0, hollow: exit 4; diamond: no band "
             "(at the deviation it reached)";
  c.x_label = "band tolerance.surface_distance_max (% of the bounding-box diagonal, log)";
  c.x_min = runs.front().band, c.x_max = runs[runs.size() - 2].band;
  if (free_deviation > 0) c.x_max = std::max(c.x_max, free_deviation);
  c.x_min /= 1.25, c.x_max *= 1.25;
  for (size_t i = 0; i + 1 < runs.size(); ++i) c.x_ticks.push_back(runs[i].band);
  c.x_tick_format = "%g%%";
  c.x_tick_scale = 100;
  if (free_deviation > 0) {
    c.lines.push_back({free_deviation, "no band: deviation " + Percent(free_deviation), "#c0392b"});
  }
  // One panel: value(run) against the band, the unbounded run as a diamond.
  const auto panel = [&](const std::string& label, bool log_y, const auto& value) {
    bench::ChartPanel p;
    p.y_label = label;
    p.log_y = log_y;
    bench::ChartSeries banded, free;
    free.diamond = true, free.joined = false, free.color = "#c0392b";
    for (const Run& run : runs) {
      bench::ChartSeries& s = run.band > 0 ? banded : free;
      s.x.push_back(run.band > 0 ? run.band : free_deviation);
      s.y.push_back(value(run));
      s.filled.push_back(run.process.exit_code == 0);
    }
    p.series = {banded, free};
    return p;
  };
  const auto from_report = [](const char* pointer) {
    return [pointer](const Run& run) { return Get(run.report, pointer); };
  };
  bench::ChartPanel planarity =
      panel("δ_PQ,n max reached", true, from_report("/after/pq_normalized_max"));
  planarity.lines.push_back({kPlanarity, "tolerance 1e-3", "#1e8449"});
  bench::ChartPanel deviation =
      panel("deviation of the output", true, from_report("/after/surface_distance_max_relative"));
  deviation.diagonal = true;
  deviation.y_tick_format = "%g%%";
  deviation.y_tick_scale = 100;
  bench::ChartPanel energy = panel("E (file units)", false, from_report("/after/E"));
  energy.lines.push_back({Get(runs.front().report, "/before/E"), "input's E", "#777"});
  bench::ChartPanel seconds = panel("seconds: wall (blue), CPU (grey)", false,
                                    [](const Run& run) { return run.process.seconds; });
  bench::ChartPanel cpu = panel("", false, [](const Run& run) { return run.process.cpu_seconds; });
  for (bench::ChartSeries& s : cpu.series) {
    s.color = "#888";
    seconds.series.push_back(s);
  }
  c.panels = {planarity, deviation, energy, seconds};
  return c;
}


int Main(int argc, char** argv) {
  const std::vector<std::string> args = bench::Init(
      argc, argv, {{"--mesh", true}, {"--bands", true}, {"--svg", true}, {"--timeout", true}});
  std::string mesh = bench::Data("libigl_inspired_mesh_quads_Conjugate.off"), svg;
  std::vector<double> bands = {0.0005, 0.001, 0.002, 0.003, 0.005, 0.0075, 0.01, 0.015};
  double timeout = 600;
  for (size_t i = 0; i + 1 < args.size(); i += 2) {
    if (args[i] == "--mesh") {
      mesh = bench::fs::absolute(args[i + 1]).lexically_normal().string();
      if (!bench::fs::is_regular_file(mesh)) bench::RefuseValue(argv[0], "--mesh", args[i + 1], "a mesh file");
    } else if (args[i] == "--bands") {
      bands = ParseBands(argv[0], args[i + 1]);
    } else if (args[i] == "--svg") {
      svg = args[i + 1];
    } else {  // --timeout SECONDS, per run
      timeout = bench::SecondsArgument(argv[0], args[i], args[i + 1]);
    }
  }
  RefuseBandOverrides(argv[0]);
  const std::string stem = bench::fs::path(mesh).stem().string();
  if (svg.empty()) svg = "deviation_tradeoff_" + stem + ".svg";

  std::printf("deviation band sweep: examples/planar_quads.yaml on %s\n(one archgeo solve "
              "subprocess per band; band, deviation: %% of the input's bounding-box diagonal; "
              "E in file units)\n\n",
              mesh.c_str());
  std::fflush(stdout);
  std::vector<Run> runs;
  for (double band : bands) runs.push_back(SolveWithBand(mesh, band, timeout));
  runs.push_back(SolveWithBand(mesh, 0, timeout));  // no band: last
  PrintTable(runs);
  std::printf("\ndeviation: of the output; rounds' max: the largest of any round "
              "(details.surface_band.\ndeviation_reached_relative); binds: "
              "details.surface_band.binds; needed: the deviation\nof a rejected round that met "
              "planarity (details.surface_band.goals_needed_relative) or, \"unbounded\",\nof the "
              "same run without the band (details.surface_band.unbounded)\n");

  std::vector<std::string> failures;
  for (const Run& run : runs) {
    const std::string f = Failure(run);
    if (!f.empty()) failures.push_back(f);
  }
  if (!runs.back().report.is_null()) {
    std::ofstream(svg) << bench::RenderSvg(TradeoffChart(runs, stem));
    std::printf("picture: %s\n", svg.c_str());
  }
  if (!failures.empty()) {
    std::printf("\nFAILED:\n");
    for (const std::string& f : failures) std::printf("  %s\n", f.c_str());
    return 1;
  }
  return 0;
}

}  // namespace ARCHGEO_UNITY_ID

ARCHGEO_BENCHMARK_PROGRAM(deviation_tradeoff, ARCHGEO_UNITY_ID::Main);
