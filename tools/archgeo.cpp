// archgeo — command-line tool. Parses arguments and prints; all work is in
// problems/ and mesh/.
//
//   archgeo solve SPEC.yaml [--set KEY=VALUE ...] [--quiet]
//   archgeo measure MESH [--reference REF] [--json]
//   archgeo generate OUT [--nu N] [--nv N] [--noise X] [--scale S] [--seed K]
//
// Exit codes: 0 success, 2 bad input (file, YAML, argument), 3 the solver
// found no usable solution, 1 an internal error.
#include <CLI/CLI.hpp>
#include <glog/logging.h>

#include <iomanip>
#include <iostream>

#include "mesh/input_error.h"
#include "problems/run.h"
#include "problems/spec.h"

namespace {

constexpr int kBadInput = 2;

int Solve(const std::string& spec_path, const std::vector<std::string>& overrides, bool quiet) {
  const archgeo::ProblemSpec spec = archgeo::ReadSpec(spec_path, overrides);
  archgeo::ProgressSink progress;
  if (!quiet) progress = [](const std::string& line) { std::cerr << line << "\n"; };
  const archgeo::RunResult run = archgeo::RunSpec(spec, progress);
  std::cout << run.summary;
  if (run.exit_code == 0) {
    if (!spec.output_mesh.empty()) std::cout << "wrote " << spec.output_mesh << "\n";
    if (!spec.output_report.empty()) std::cout << "wrote " << spec.output_report << "\n";
  }
  return run.exit_code;
}

int Measure(const std::string& mesh, const std::string& reference, bool json) {
  const archgeo::RunResult run = archgeo::MeasureFiles(mesh, reference);
  if (json) {
    std::cout << std::setw(2) << run.report << "\n";
  } else {
    std::cout << run.summary;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  google::InitGoogleLogging(argv[0]);
  FLAGS_minloglevel = google::GLOG_ERROR;
  FLAGS_logtostderr = true;

  CLI::App app{"archgeo: optimisation of freeform-architecture meshes (planar quads, ...)"};
  app.require_subcommand(1);

  std::string spec_path;
  std::vector<std::string> overrides;
  bool quiet = false;
  CLI::App* solve = app.add_subcommand(
      "solve", "Solve the problem declared in a YAML spec; writes output.mesh and output.report");
  solve->add_option("spec", spec_path, "YAML problem spec (keys: see examples/ and README)")
      ->required();
  solve->add_option("--set", overrides,
                    "Override a spec key by dotted path, e.g. --set mesh=roof.obj "
                    "--set solver.threads=1 (repeatable; paths relative to the current folder)")
      ->allow_extra_args(false);
  solve->add_flag("-q,--quiet", quiet, "No progress lines (one per Ceres iteration otherwise)");

  std::string mesh_path, reference_path;
  bool json = false;
  CLI::App* measure = app.add_subcommand(
      "measure", "Print planarity, proximity and displacement metrics of a mesh");
  measure->add_option("mesh", mesh_path, "Mesh to measure (OBJ, OFF, PLY)")->required();
  measure->add_option("--reference", reference_path,
                      "Reference surface: adds δ_prox, δ∂_prox, distances, Hausdorff, and "
                      "displacement if the vertex counts agree");
  measure->add_flag("--json", json, "Print the metrics as JSON");

  std::string grid_path;
  int nu = 20, nv = 15;
  double noise = 0.1, grid_scale = 1.0;
  unsigned seed = 1;
  CLI::App* generate = app.add_subcommand(
      "generate", "Write a non-planar quad grid on a doubly curved roof (demos, tests, scaling)");
  generate->add_option("out", grid_path, "Output mesh (.obj, .off, .ply)")->required();
  generate->add_option("--nu", nu, "Quads along u (x in [0, 2])")->capture_default_str();
  generate->add_option("--nv", nv, "Quads along v (y in [0, 1.5])")->capture_default_str();
  generate->add_option("--noise", noise, "Random vertex offsets, in mean edge lengths")
      ->capture_default_str();
  generate->add_option("--scale", grid_scale, "Uniform scale (file units)")->capture_default_str();
  generate->add_option("--seed", seed, "Random seed")->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kBadInput;
  }

  try {
    if (*solve) return Solve(spec_path, overrides, quiet);
    if (*generate) {
      std::cout << archgeo::GenerateRoofGrid(grid_path, nu, nv, noise, grid_scale, seed).summary;
      return 0;
    }
    return Measure(mesh_path, reference_path, json);
  } catch (const archgeo::InputError& e) {
    std::cerr << "archgeo: error: " << e.what() << "\n";
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "archgeo: internal error: " << e.what() << "\n";
    return 1;
  }
}
