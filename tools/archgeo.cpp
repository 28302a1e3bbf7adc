// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — command-line tool. Parses arguments and prints; all work is in
// problems/ and mesh/.
//
//   archgeo solve SPEC.yaml [--set KEY=VALUE ...] [--quiet | --log]
//   archgeo spec PROBLEM [--keys]
//   archgeo measure MESH [--reference REF] [--json] [--all]
//   archgeo spectral MESH --list [--count K] [--laplacian cotangent|normalised]
//                        [--charts N | --edge-length L]
//   archgeo spectral MESH --complex OUT.obj [--quasi-dual OUT2.obj] --eigenfunction K
//                        [--cancel-to N | --persistence P]
//   archgeo generate OUT [--surface NAME] [--nu N] [--nv N] [--noise X] [--scale S]
//                        [--seed K] [--refinement K] [--reference REF_OUT]
//   archgeo darboux NET OUT.ply [--c C] [--minus] [--projective 16 numbers]
//                        [--samples N] [--isophotes DEG] [--direction X Y Z] [--rulings R.obj]
//   archgeo render MESH... --out VIEW.png|VIEW.html [--value NAME] [--color-max X] [--titles A,B]
//   archgeo bench SPEC --mesh M... [--vary 'KEY=[A,B]']... [--repeat N] [--out R.csv]
//                        [--emit-jobs JOBS.txt [--records DIR]]
//   archgeo bench --run-jobs JOBS.txt --job K
//   archgeo bench --collect DIR [--out R.csv]
//   archgeo help [COMMAND]      (the same text as --help)
//   archgeo --version
//
// Exit codes: 0 a valid result with every tolerance met, 4 a valid result
// written with a tolerance missed, 3 no usable or no valid result (nothing
// written), 2 bad input (file, YAML, argument), 1 an internal error.
#include <CLI/CLI.hpp>
#include <ceres/version.h>
#include <CGAL/config.h>
#include <CGAL/version.h>
#include <glog/logging.h>

#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench.h"
#include "bench/child.h"
#include "core/closest_name.h"
#include "core/input_error.h"
#include "core/solver_options.h"
#include "io/output_files.h"
#include "problems/commands/darboux.h"
#include "problems/commands/generate.h"
#include "problems/declarations/custom.h"
#include "problems/report/picture.h"
#include "energies/registry.h"
#include "problems/declarations/registry.h"
#include "problems/commands/run.h"
#include "problems/commands/spectral.h"
#include "problems/spec/schema.h"
#include "problems/spec/spec.h"
#include "tools/progress_line.h"

namespace {

constexpr int kBadInput = 2;
constexpr int kGoalMissed = 4;  // the command's result misses its goal (written for inspection)

// Where progress goes: nothing (--quiet); one line rewritten in place when
// stderr is a terminal (unless --log); otherwise every event's log line.
archgeo::ProgressSink Progress(bool quiet, bool log, std::unique_ptr<archgeo::ProgressLine>* line) {
  if (quiet) return {};
  if (!log && isatty(STDERR_FILENO)) {
    *line = std::make_unique<archgeo::ProgressLine>(stderr);
    archgeo::ProgressLine* display = line->get();
    return [display](const archgeo::ProgressEvent& event) { display->Show(event); };
  }
  return [](const archgeo::ProgressEvent& event) { std::cerr << event.line << "\n"; };
}

int Solve(const std::string& spec_path, const std::vector<std::string>& overrides, bool quiet,
          bool log) {
  const archgeo::ProblemSpec spec = archgeo::ReadSpec(spec_path, overrides);
  std::unique_ptr<archgeo::ProgressLine> line;
  const archgeo::RunResult run = archgeo::RunSpec(spec, Progress(quiet, log, &line));
  if (line) line->Clear();
  std::cout << run.summary;
  if (run.exit_code == 0 || run.exit_code == 4 || run.exit_code == 5) {
    for (const archgeo::Key& k : spec.settings.schema().keys()) {
      if (k.type == archgeo::Type::kOutputPath && !spec.settings.String(k.name).empty()) {
        std::cout << "wrote " << spec.settings.String(k.name) << "\n";
      }
    }
  }
  return run.exit_code;
}

// Every registered term: what `terms:` of a spec (and `problem: custom`) can name.
int Terms() {
  for (const archgeo::TermSpec* t : archgeo::RegisteredTerms()) {
    std::cout << t->name << "  (energies/" << t->name << ".h)\n  " << t->summary << "\n  "
              << t->paper << "\n  acts on: " << t->elements;
    for (const std::string& e : t->element_choices) std::cout << " | " << e;
    std::cout << "\n";
    for (const archgeo::Key& k : t->options) {
      std::cout << "  option " << k.name << " (default " << archgeo::ToText(k.fallback)
                << "): " << k.doc << "\n";
    }
    std::cout << "\n";
  }
  return 0;
}

int Spec(const std::string& name, bool keys, bool common) {
  archgeo::ProblemDecl custom;
  if (name == "custom") custom = archgeo::CustomExample();
  const archgeo::ProblemDecl* problem =
      name == "custom" ? &custom : archgeo::FindProblem(name);
  if (!problem) {
    std::string list;
    for (const std::string& n : archgeo::ProblemNames()) list += (list.empty() ? "" : ", ") + n;
    throw archgeo::InputError("", 0, "PROBLEM", "'" + name + "' is not a problem (" + list + ")");
  }
  if (keys) {
    std::cout << archgeo::KeyTable(*problem, common);
  } else {
    std::cout << archgeo::SpecTemplate(*problem);
  }
  return 0;
}

int Measure(const std::string& mesh, const std::string& reference, bool json, bool all) {
  const archgeo::RunResult run = archgeo::MeasureFiles(mesh, reference, all);
  if (json) {
    std::cout << std::setw(2) << run.report << "\n";
  } else {
    std::cout << run.summary;
  }
  return 0;
}

}  // namespace

namespace {

bool IsCommand(CLI::App& app, const std::string& name) {
  for (const CLI::App* command : app.get_subcommands({})) {
    if (command->get_name() == name) return true;
  }
  return false;
}

// "'NAME' is not a command; did you mean 'X'? (archgeo help lists them)", the
// suggestion only for a command within two edits.
std::string NotACommand(CLI::App& app, const std::string& name) {
  std::vector<std::string> commands;
  for (const CLI::App* command : app.get_subcommands({})) commands.push_back(command->get_name());
  const std::string best = archgeo::ClosestName(name, commands);
  return "'" + name + "' is not a command" + (best.empty() ? "" : "; did you mean '" + best + "'?") +
         " (archgeo help lists them)";
}

}  // namespace

int main(int argc, char** argv) {
  archgeo::StartWithPassiveOpenMpWaits(argv);
  // The loop rebuilds lists of hundreds of MB every round (core/residuals.h).
  // glibc maps every block above 32 MB afresh and unmaps it when freed, so
  // each growth step and each round would fault its pages in again (a large
  // share of the time spent building the rounds). Blocks up to 1 GiB come
  // from the heap instead, and the heap keeps what is freed.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  google::InitGoogleLogging(argv[0]);
  // A signal removes the staged temporaries and leaves existing outputs as
  // they were (io/output_files.h).
  archgeo::InstallOutputSignalCleanup();
  FLAGS_minloglevel = google::GLOG_ERROR;
  FLAGS_logtostderr = true;

  CLI::App app{"archgeo: optimisation of freeform-architecture meshes (planar quads, ...)"};
  app.require_subcommand(1);
  app.set_version_flag("--version",
                       std::string("archgeo ") + ARCHGEO_VERSION + " (report schema_version " +
                           std::to_string(archgeo::kReportSchemaVersion) + "; Ceres " +
                           CERES_VERSION_STRING + ", CGAL " + CGAL_STRINGIZE(CGAL_VERSION) + ")",
                       "Print the version and exit");

  std::string help_topic;
  CLI::App* help = app.add_subcommand("help", "Print the help of archgeo or of one command");
  help->add_option("command", help_topic, "A command (solve, spec, terms, measure, spectral, "
                                          "generate, darboux, render, bench)");

  std::string spec_path;
  std::vector<std::string> overrides;
  bool quiet = false;
  CLI::App* solve = app.add_subcommand(
      "solve", "Solve the problem declared in a YAML spec; writes output.mesh and output.report");
  solve->add_option("spec", spec_path, "YAML problem spec (keys: `archgeo spec PROBLEM --keys`, docs/keys.md)")
      ->required();
  solve->add_option("--set", overrides,
                    "Override a spec key by dotted path, e.g. --set mesh=roof.obj "
                    "--set solver.num_threads=1 (repeatable; paths relative to the current folder)")
      ->allow_extra_args(false);
  bool log = false;
  solve->add_flag("-q,--quiet", quiet, "No progress (one line updated in place on a terminal, "
                                      "the log otherwise)");
  solve->add_flag("--log", log, "Progress as the log: a line per solver iteration and round, "
                                "also on a terminal");

  std::string problem_name;
  bool keys_only = false;
  CLI::App* spec = app.add_subcommand(
      "spec", "Print a problem's spec with every key, its default and doc (valid YAML to "
              "start from: set `mesh`)");
  std::string problem_list;  // custom: its template composes the terms of examples/planar_smooth.yaml
  for (const std::string& n : archgeo::ProblemNames()) {
    problem_list += (problem_list.empty() ? "" : ", ") + n;
  }
  spec->add_option("problem", problem_name, problem_list)->required();
  spec->add_flag("--keys", keys_only, "Print the problem's own keys as a Markdown table instead");
  bool common_keys = false;
  spec->add_flag("--common", common_keys,
                 "With --keys: the keys every problem has (mesh, outputs, schedule, solver, "
                 "validity, limits) with this problem's defaults");

  CLI::App* terms = app.add_subcommand(
      "terms", "List every registered term (energy): what a spec's `terms:` can name");

  std::string mesh_path, reference_path;
  bool json = false;
  CLI::App* measure = app.add_subcommand(
      "measure", "Print planarity, proximity and displacement metrics of a mesh");
  measure->add_option("mesh", mesh_path, "Mesh to measure (OBJ, OFF, PLY)")->required();
  measure->add_option("--reference", reference_path,
                      "Reference surface: adds δ_prox, δ∂_prox, distances, Hausdorff, and "
                      "displacement if the vertex counts agree");
  measure->add_flag("--json", json, "Print the metrics as JSON (every metric)");
  bool all_metrics = false;
  measure->add_flag("--all", all_metrics,
                    "Print every metric, also those that do not describe this mesh (A-net, "
                    "H-net and conical rows of a net that is none of these; saddles of a quad "
                    "mesh)");

  archgeo::SpectralRequest spectral_request;
  bool spectral_list = false;
  CLI::App* spectral = app.add_subcommand(
      "spectral", "The lowest Laplacian eigenfunctions of a triangle mesh with their critical "
                  "points: the candidates of spectral quad meshing");
  spectral->add_option("mesh", spectral_request.mesh, "Design surface (OBJ, OFF, PLY; polygons "
                                                      "are triangulated)")
      ->required();
  spectral->add_flag("--list", spectral_list, "Print every candidate eigenfunction");
  spectral->add_option("--count", spectral_request.count,
                       "Eigenpairs to compute, the constant one included")
      ->capture_default_str();
  spectral->add_option("--laplacian", spectral_request.laplacian,
                       "cotangent (area-weighted, thesis §4.1.5) or normalised (§6.1.3)")
      ->capture_default_str();
  spectral->add_option("--charts", spectral_request.charts,
                       "Mark the eigenfunction whose complex has the nearest number of charts");
  spectral->add_option("--edge-length", spectral_request.edge_length,
                       "Mark the one whose charts are nearest this size (file units)");
  spectral->add_option("--complex", spectral_request.complex_out,
                       "Write the Morse-Smale complex of --eigenfunction as OBJ polylines (an open "
                       "mesh: of its double across the boundary)");
  spectral->add_option("--quasi-dual", spectral_request.quasi_dual_out,
                       "Write its quasi-dual quad base complex as an OBJ mesh");
  spectral->add_option("--eigenfunction", spectral_request.eigenfunction,
                       "Eigenfunction k of the complex (k >= 1)");
  spectral->add_option("--cancel-to", spectral_request.cancel_to,
                       "Cancel saddle-extremum pairs down to this many extrema");
  spectral->add_option("--persistence", spectral_request.persistence,
                       "Or cancel the pairs up to this persistence (a fraction of max |phi_k|)");

  std::string grid_path;
  archgeo::GenerateOptions gen;
  CLI::App* generate = app.add_subcommand(
      "generate", "Write an analytic test mesh (demos, tests, paper reproductions)");
  generate->add_option("out", grid_path, "Output mesh (.obj, .off, .ply)")->required();
  generate->add_option("--surface", gen.surface, "Surface:\n" + archgeo::GenerateSurfaceNames())
      ->capture_default_str();
  generate->add_option("--nu", gen.nu, "Resolution along u (roof: x in [0, 2])")
      ->capture_default_str();
  generate->add_option("--nv", gen.nv, "Resolution along v (roof: y in [0, 1.5])")
      ->capture_default_str();
  generate->add_option("--noise", gen.noise,
                       "roof, torus: random vertex offsets, in mean edge lengths (default: roof "
                       "0.1, torus 0)");
  generate->add_option("--scale", gen.scale, "Uniform scale (file units)")->capture_default_str();
  generate->add_option("--seed", gen.seed, "roof, torus: random seed of the noise")
      ->capture_default_str();
  generate->add_option("--refinement", gen.refinement,
                       "Asymptotic nets: subdivide each parameter step K times")
      ->capture_default_str();
  generate->add_option("--reference", gen.reference,
                       "Asymptotic nets: also write the analytic surface (a fine triangle mesh) "
                       "here, for proximity");

  std::string net_path, patchwork_path;
  archgeo::DarbouxOptions darboux_options;
  std::vector<double> direction;
  CLI::App* darboux = app.add_subcommand(
      "darboux",
      "Map an H-net's patchwork by a Darboux transformation (Shi 2014, eq. 12): smooth "
      "Darboux-cyclide patches, sampled as a PLY mesh");
  darboux->add_option("net", net_path, "Quad net (e.g. an hnet output), OBJ/OFF/PLY")->required();
  darboux->add_option("out", patchwork_path, "Output patchwork (.ply)")->required();
  darboux->add_option("--c", darboux_options.c, "Centre (0,0,0,c) of the projection; c != 1")
      ->capture_default_str();
  darboux->add_flag("--minus", darboux_options.minus_branch,
                    "Take the other root of eq. 12 (the image inverted in the sphere Λ)");
  darboux->add_option("--projective", darboux_options.projective,
                      "A projective map applied first: 16 numbers, the 4x4 matrix row by row, "
                      "acting on (x, y, z, 1)")
      ->expected(16);
  darboux->add_option("--samples", darboux_options.samples, "n x n quads per patch")
      ->capture_default_str();
  darboux->add_option("--isophotes", darboux_options.isophote_band,
                      "Colour isophote bands of this width (degrees; 0 = no colours)")
      ->capture_default_str();
  darboux->add_option("--direction", direction, "Isophote direction (3 numbers)")->expected(3);
  darboux->add_flag("--ascii", darboux_options.ascii, "ASCII PLY");
  darboux->add_option("--rulings", darboux_options.rulings,
                      "Also write the mapped rulings (circular arcs) as OBJ polylines");

  archgeo::RenderRequest render_request;
  CLI::App* render = app.add_subcommand(
      "render", "Draw meshes side by side as a PNG, faces coloured by a per-face value with a "
                "colour bar (e.g. input and output of a solve)");
  render->add_option("meshes", render_request.meshes,
                     "Meshes (OBJ, OFF, PLY); the first sets the camera and the colour scale")
      ->required();
  render->add_option("--out,-o", render_request.out,
                     "Output picture (.png) or self-contained page to rotate (.html)")
      ->required();
  std::string value_names = "auto, none";
  for (const std::string& n : archgeo::FaceValueNames()) value_names += ", " + n;
  render->add_option("--value", render_request.value,
                     "Per-face value shown (" + value_names +
                         "); auto: planarity if the first mesh has quads, else bending")
      ->capture_default_str();
  render->add_option("--color-max", render_request.color_max,
                     "The value drawn red (default: planarity 1e-3 = planar_quads' default "
                     "tolerance; bending the first mesh's largest value; kinks 1 degree)");
  render->add_option("--titles", render_request.titles, "One title per mesh (default: file names)")
      ->delimiter(',');
  render->add_option("--lines", render_request.lines,
                     "OBJ polylines (e.g. output.streamlines) drawn over the mesh of the same "
                     "position (repeatable; PNG): group v red, w blue, separatrices black");
  render->add_option("--width", render_request.options.panel_width,
                     "Pixels per panel, across (PNG; the HTML page fills the window)")
      ->capture_default_str()
      ->check(CLI::Range(200, 4000));
  render->add_option("--height", render_request.options.panel_height, "Pixels per panel, down (PNG)")
      ->capture_default_str()
      ->check(CLI::Range(200, 4000));
  render->add_option("--tilt", render_request.options.tilt_degrees,
                     "View tilt from the surface's normal, degrees")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 90.0));

  archgeo::BenchRequest bench_request;
  CLI::App* bench = app.add_subcommand(
      "bench", "Sweep solver settings over meshes: each run in its own process; a table, CSV and "
               "JSON of times, memory and quality (docs/bench.md)");
  bench->add_option("spec", bench_request.spec, "YAML problem spec every run solves");
  bench->add_option("--mesh", bench_request.meshes, "An input mesh (repeatable)");
  bench->add_option("--vary", bench_request.vary,
                    "A key and its values, e.g. 'solver.linear_solver_type=[sparse_normal_cholesky,"
                    "cgnr]' (repeatable; the runs are the cross product × the meshes)");
  bench->add_option("--repeat", bench_request.repeat, "Runs of each setting and mesh (wall time: "
                                                      "median, min, max)")
      ->capture_default_str();
  bench->add_option("--out", bench_request.out, "CSV of the rows (a name ending in .csv); the same "
                                                "rows as JSON beside it (.json)");
  bench->add_option("--emit-jobs", bench_request.emit_jobs,
                    "Write one job per run (a line of data, not a command) to this file instead "
                    "of running them; --run-jobs runs them");
  bench->add_option("--run-jobs", bench_request.run_jobs,
                    "Run one job of this file from --emit-jobs (the one --job names) and write "
                    "its record");
  bench->add_option("--job", bench_request.job, "The job of --run-jobs to run, from 1")
      ->check(CLI::PositiveNumber);
  bench->add_option("--records", bench_request.records,
                    "Folder the emitted jobs write their records into (default: JOBS_runs)");
  bench->add_option("--collect", bench_request.collect,
                    "Merge the records of this folder (from --emit-jobs) into the table");
  bench->add_option("--set", bench_request.sets, "One run's setting KEY=VALUE (with --record)");
  bench->add_option("--record", bench_request.record,
                    "Run once (the --set settings; --repeat is the repeat's number) and write its "
                    "record here (what an emitted job does)");

  if (argc > 1 && argv[1][0] != '-' && !IsCommand(app, argv[1])) {
    std::cerr << "archgeo: error: " << NotACommand(app, argv[1]) << "\n";
    return kBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kBadInput;
  }

  if (*help) {
    if (help_topic.empty()) {  // the tool's help: every command (not help's own)
      std::cout << app.get_formatter()->make_help(&app, "archgeo", CLI::AppFormatMode::Normal);
      return 0;
    }
    for (CLI::App* command : app.get_subcommands({})) {
      if (command->get_name() == help_topic && command != help) {
        std::cout << command->help();
        return 0;
      }
    }
    std::cerr << "archgeo: error: " << NotACommand(app, help_topic) << "\n";
    return kBadInput;
  }

  try {
    if (*solve) return Solve(spec_path, overrides, quiet, log);
    if (*spec) return Spec(problem_name, keys_only, common_keys);
    if (*terms) return Terms();
    if (*bench) {
      bench_request.self = "/proc/self/exe";
      char resolved[4096];
      const ssize_t n = readlink("/proc/self/exe", resolved, sizeof resolved - 1);
      if (n > 0) bench_request.self.assign(resolved, size_t(n));
      // A signal also stops the running child and removes its scratch folder.
      archgeo::InstallBenchSignalHandling();
      std::unique_ptr<archgeo::ProgressLine> line;
      bench_request.progress = Progress(false, false, &line);
      const std::string table = archgeo::RunBench(bench_request);
      if (line) line->Clear();
      std::cout << table;
      return 0;
    }
    if (*render) {
      std::cout << archgeo::RenderFiles(render_request);
      return 0;
    }
    if (*generate) {
      std::cout << archgeo::GenerateSurface(grid_path, gen).summary;
      return 0;
    }
    if (*spectral) {
      const bool complex = !spectral_request.complex_out.empty() ||
                           !spectral_request.quasi_dual_out.empty();
      if (spectral_list == complex) {
        std::cerr << "archgeo spectral: give --list, or --complex and/or --quasi-dual\n";
        return kBadInput;
      }
      if (!complex) {
        std::cout << archgeo::SpectralList(spectral_request);
        return 0;
      }
      const archgeo::SpectralComplexResult result = archgeo::SpectralComplex(spectral_request);
      std::cout << result.text;
      if (result.valid) return 0;
      std::cout << "WARNING: the goal was missed (exit 4): " << result.why << "\n";
      return kGoalMissed;
    }
    if (*darboux) {
      if (direction.size() == 3) {
        darboux_options.isophote_direction = {direction[0], direction[1], direction[2]};
      }
      std::cout << archgeo::RunDarboux(net_path, patchwork_path, darboux_options).summary;
      return 0;
    }
    return Measure(mesh_path, reference_path, json, all_metrics);
  } catch (const archgeo::InputError& e) {
    std::cerr << "archgeo: error: " << e.what() << "\n";
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "archgeo: internal error: " << e.what() << "\n";
    return 1;
  }
}
