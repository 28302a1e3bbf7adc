// archgeo — the YAML problem spec: parse, validate, apply --set overrides.
//
// Common keys (every problem; every key optional unless marked):
//
//   mesh: PATH                  required. OBJ, OFF or PLY; polygonal faces.
//   reference: PATH             proximity target surface (default: the input
//                               mesh itself, triangulated).
//   problem: planar_quads       the builder: see problems/builders.h for the
//                               list and each builder's header for its keys.
//   fixed: none                 hard-fixed vertices: none, corners, boundary,
//                               or a list of vertex indices (0-based).
//   multiresolution:            [Pellis 2019, §6] solve, subdivide, solve again
//     levels: 0                 number of subdivisions after the first solve
//     scheme: loop              loop | sqrt3 (triangle meshes), catmull_clark |
//                               doo_sabin (any polygon mesh). Loop and
//                               Catmull–Clark keep vertex ids, and fixed
//                               vertices keep their positions through them.
//   solver:                     mapped onto ceres::Solver::Options
//     linear_solver: sparse_normal_cholesky   | dense_qr | dense_normal_cholesky
//                                             | cgnr | iterative_schur
//     sparse_library: suite_sparse            | eigen_sparse
//     trust_region: levenberg_marquardt       | dogleg
//     preconditioner: jacobi                  | identity (cgnr, iterative_schur)
//     max_iterations: 50        Ceres iterations per outer iteration
//     outer_iterations: 12      re-projection / reweighting rounds, at most
//     function_tolerance: 1e-10
//     gradient_tolerance: 1e-14
//     parameter_tolerance: 1e-10
//     threads: 2
//   output:
//     mesh: PATH                optimised mesh (.obj/.off/.ply; PLY gets face
//                               colours: δ_PQ,n green 0 → red ≥ color_max, or
//                               the builder's own colouring)
//     color_max: 0.01
//     ascii_ply: false
//     report: PATH              JSON run report
//     ...                       builder-specific files (e.g. hnet's patchwork)
//                               (an empty value writes no file)
//
// Builder keys (e.g. planar_quads: tolerance, terms, continuation) are read
// by the builder; lengths are unit-free there: relative to the input's mean
// edge length, so millimetres and metres give the same result up to scale.
//
// Relative paths inside the YAML file are relative to the YAML file's folder;
// paths given with --set are relative to the current directory.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "problems/builder.h"
#include "problems/solver_options.h"

namespace archgeo {

struct ProblemSpec {
  std::string spec_path;  // the YAML file as given
  std::string mesh;       // resolved paths
  std::string reference;  // empty: the input mesh
  std::string problem = "planar_quads";
  std::shared_ptr<const Builder> builder;  // `problem` with its keys read
  std::string fixed = "none";  // none | corners | boundary | ids
  std::vector<int> fixed_ids;
  std::string fixed_file;  // where `fixed` was given (the spec or "--set"), for errors
  int fixed_line = 0;
  SolverSettings solver;
  int multiresolution_levels = 0;
  std::string multiresolution_scheme = "loop";
  std::string output_mesh, output_report;  // empty: not written
  std::map<std::string, std::string> extra_outputs;  // builder's output key -> path
  double color_max = 0.01;
  bool ascii_ply = false;
};

// Reads and validates `path`, after applying `overrides` ("dotted.key=value",
// the value parsed as YAML). Throws InputError naming the file and line (or
// "--set" for an overridden key) and the key.
ProblemSpec ReadSpec(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace archgeo
