// archgeo — the YAML problem spec: parse, validate, apply --set overrides.
//
// Keys (every one optional unless marked; lengths are unit-free: relative to
// the input's mean edge length, so millimetres and metres give the same
// result up to scale):
//
//   mesh: PATH                  required. OBJ, OFF or PLY; polygonal faces.
//   reference: PATH             proximity target surface (default: the input
//                               mesh itself, triangulated).
//   problem: planar_quads       the builder (only planar_quads so far).
//   tolerance:
//     pq_normalized_max: 1e-3   stop as soon as every quad has δ_PQ,n (diagonal
//                               distance / mean diagonal length) ≤ this; 0 turns
//                               the tolerance off: fixed weights, all outer
//                               iterations.
//   terms:                      weights w: the objective is ½ Σ_terms w Σ r².
//                               If `terms` is given, a term not listed is off.
//     pq_diagonal: 10           starting planarity weight (× continuation.factor
//                               after every round short of the tolerance).
//     face_planarity: 10        the same for faces with more than 4 sides.
//     fairness: {weight: 0, relative_to_original: true}   (or a number):
//                               second differences along mesh polylines.
//     proximity: {weight: 2, point_weight: 0.01}   distance to the reference's
//                               tangent plane; the point part pulls towards the
//                               closest point itself.
//     boundary_proximity: 2     distance to the reference's boundary tangent.
//     anchor: 0.1               pull towards each vertex's original position
//                               (keeps vertices from sliding along the surface).
//   continuation:
//     band: 0                   a face whose δ_PQ,n is within band × tolerance
//                               costs nothing (only the excess is penalised):
//                               less movement for a loose tolerance, slower for a
//                               tight one. 0 pulls every face towards planarity.
//     factor: 10                planarity weight growth per round short of
//                               the tolerance.
//   fixed: none                 hard-fixed vertices: none, corners, boundary,
//                               or a list of vertex indices (0-based).
//   solver:                     mapped onto ceres::Solver::Options
//     linear_solver: sparse_normal_cholesky   | dense_qr | dense_normal_cholesky
//                                             | cgnr | iterative_schur
//     sparse_library: suite_sparse            | eigen_sparse
//     trust_region: levenberg_marquardt       | dogleg
//     preconditioner: jacobi                  | identity (cgnr, iterative_schur)
//     max_iterations: 50        Ceres iterations per outer iteration
//     outer_iterations: 12      re-projection / continuation rounds, at most
//     function_tolerance: 1e-10
//     gradient_tolerance: 1e-14
//     parameter_tolerance: 1e-10
//     threads: 2
//   output:
//     mesh: PATH                optimised mesh (.obj/.off/.ply; PLY gets face
//                               colours by δ_PQ,n: green 0 → red ≥ color_max)
//     color_max: 0.01
//     ascii_ply: false
//     report: PATH              JSON run report
//                               (an empty mesh: or report: writes no file)
//
// Relative paths inside the YAML file are relative to the YAML file's folder;
// paths given with --set are relative to the current directory.
#pragma once

#include <string>
#include <vector>

#include "problems/solver_options.h"

namespace archgeo {

struct TermWeights {
  double pq_diagonal = 10.0;
  double face_planarity = 10.0;
  double fairness = 0.0;
  bool fairness_relative = true;
  double proximity = 2.0;
  double proximity_point = 0.01;
  double boundary_proximity = 2.0;
  double anchor = 0.1;
};

struct ProblemSpec {
  std::string spec_path;  // the YAML file as given
  std::string mesh;       // resolved paths
  std::string reference;  // empty: the input mesh
  std::string problem = "planar_quads";
  double pq_normalized_max = 1e-3;
  TermWeights terms;
  double continuation_band = 0.0;
  double continuation_factor = 10.0;
  std::string fixed = "none";  // none | corners | boundary | ids
  std::vector<int> fixed_ids;
  std::string fixed_file;  // where `fixed` was given (the spec or "--set"), for errors
  int fixed_line = 0;
  SolverSettings solver;
  std::string output_mesh, output_report;  // empty: not written
  double color_max = 0.01;
  bool ascii_ply = false;
};

// Reads and validates `path`, after applying `overrides` ("dotted.key=value",
// the value parsed as YAML). Throws InputError naming the file and line (or
// "--set" for an overridden key) and the key.
ProblemSpec ReadSpec(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace archgeo
