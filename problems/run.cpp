#include "problems/run.h"

#include <chrono>
#include <fstream>
#include <iomanip>

#include "mesh/generators.h"
#include "mesh/input_error.h"
#include "mesh/io.h"
#include "mesh/metrics.h"
#include "mesh/output_files.h"
#include "mesh/reference.h"
#include "mesh/similarity.h"
#include "mesh/topology.h"
#include "problems/planar_quads.h"
#include "problems/report.h"
#include "problems/solver_options.h"

namespace archgeo {
namespace {

using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::vector<bool> FixedVertices(const ProblemSpec& spec, const Mesh& mesh) {
  std::vector<bool> fixed(mesh.number_of_vertices(), false);
  if (spec.fixed == "corners") {
    for (VertexIndex v : Corners(mesh)) fixed[v.idx()] = true;
  } else if (spec.fixed == "boundary") {
    fixed = BoundaryVertices(mesh);
  } else if (spec.fixed == "ids") {
    for (int id : spec.fixed_ids) {
      if (id >= int(mesh.number_of_vertices())) {
        throw InputError(spec.fixed_file, spec.fixed_line, "fixed",
                         "vertex index " + std::to_string(id) + " out of range: " + spec.mesh +
                             " has " + std::to_string(mesh.number_of_vertices()) + " vertices");
      }
      fixed[id] = true;
    }
  }
  return fixed;
}

nlohmann::json SolverJson(const SolverSettings& s) {
  return {{"linear_solver", s.linear_solver},   {"sparse_library", s.sparse_library},
          {"trust_region", s.trust_region},     {"preconditioner", s.preconditioner},
          {"max_iterations", s.max_iterations}, {"outer_iterations", s.outer_iterations},
          {"function_tolerance", s.function_tolerance},
          {"gradient_tolerance", s.gradient_tolerance},
          {"parameter_tolerance", s.parameter_tolerance}, {"threads", s.threads}};
}

nlohmann::json TermsJson(const TermWeights& w) {
  return {{"pq_diagonal", w.pq_diagonal},
          {"face_planarity", w.face_planarity},
          {"fairness", {{"weight", w.fairness}, {"relative_to_original", w.fairness_relative}}},
          {"proximity", {{"weight", w.proximity}, {"point_weight", w.proximity_point}}},
          {"boundary_proximity", w.boundary_proximity},
          {"anchor", w.anchor}};
}

// The optimised positions on a clean copy of the input (no solver properties).
Mesh WithPositions(const Mesh& input, const Mesh& solved, const Similarity& frame) {
  Mesh out = input;
  for (VertexIndex v : out.vertices()) {
    out.point(v) = ToPoint(frame.FromCanonical(ToVec3(solved.point(v))));
  }
  return out;
}

}  // namespace

RunResult RunSpec(const ProblemSpec& spec, const ProgressSink& progress) {
  const auto start = Clock::now();
  ConfigureThreading();

  // Outputs are checked and staged before any work: a bad output name or an
  // output that would overwrite an input fails at once.
  StagedOutputs staged(spec.reference.empty()
                           ? std::vector<std::string>{spec.spec_path, spec.mesh}
                           : std::vector<std::string>{spec.spec_path, spec.mesh, spec.reference});
  std::string mesh_temporary, report_temporary;
  if (!spec.output_mesh.empty()) {
    CheckMeshExtension(spec.output_mesh);
    mesh_temporary = staged.Stage(spec.output_mesh);
  }
  if (!spec.output_report.empty()) report_temporary = staged.Stage(spec.output_report);

  ReadInfo info;
  const Mesh input = ReadMesh(spec.mesh, &info);
  const Mesh reference_mesh = spec.reference.empty() ? input : ReadMesh(spec.reference);
  int planar_faces = 0;
  for (FaceIndex f : input.faces()) planar_faces += input.degree(f) >= 4;
  if (planar_faces == 0) {
    throw InputError(spec.mesh, 0, "mesh",
                     "planar_quads needs quads (or larger polygons); this mesh has only "
                     "triangles");
  }
  PlanarQuadsSettings settings;
  settings.terms = spec.terms;
  settings.tolerance = spec.pq_normalized_max;
  settings.continuation_band = spec.continuation_band;
  settings.continuation_factor = spec.continuation_factor;
  settings.fixed = FixedVertices(spec, input);
  settings.solver = spec.solver;
  const double read_seconds = Since(start);

  const auto setup_start = Clock::now();
  const ReferenceSurface reference(reference_mesh);
  // Without a separate reference the input is its own reference surface:
  // its Hausdorff distance to it is 0 and need not be sampled.
  MetricsOptions before_options;
  before_options.hausdorff = !spec.reference.empty();
  Metrics before = ComputeMetrics(input, &reference, &input, before_options);
  if (spec.reference.empty()) before.hausdorff = 0;
  const double scale = before.bbox_diagonal;

  const double setup_seconds = Since(setup_start);
  const auto solve_start = Clock::now();
  const Similarity frame = CanonicalFrame(input);
  Mesh work = input;
  ToCanonical(frame, work);
  Mesh reference_canonical = reference_mesh;
  ToCanonical(frame, reference_canonical);
  const ReferenceSurface reference_in_frame(reference_canonical);
  const PlanarQuadsResult solved = SolvePlanarQuads(work, reference_in_frame, settings, progress);
  const double solve_seconds = Since(solve_start);

  RunResult run;
  nlohmann::json& rep = run.report;
  rep["archgeo"] = "solve";
  rep["spec"] = spec.spec_path;
  rep["mesh"] = spec.mesh;
  rep["reference"] = spec.reference.empty() ? spec.mesh : spec.reference;
  rep["problem"] = spec.problem;
  rep["input"] = {{"format", info.format}, {"reoriented_faces", info.reoriented_faces}};
  rep["units"] = {{"lengths", "file units"},
                  {"relative", "file units / bounding-box diagonal of the input"},
                  {"bbox_diagonal", scale},
                  {"objective", "0.5 * sum_terms w * sum r^2, in the canonical frame (unit mean "
                                "edge length), at the last linearisation"}};
  rep["terms"] = TermsJson(spec.terms);
  rep["solver"] = SolverJson(spec.solver);
  rep["blas"] = BlasLibrary();
  rep["tolerance"] = {{"pq_normalized_max", spec.pq_normalized_max},
                      {"met", solved.tolerance_met}};
  rep["usable"] = solved.usable;
  rep["variables"] = solved.variables;
  rep["residuals"] = solved.residuals;
  rep["iterations"] = {{"outer", solved.outer_iterations}, {"inner", solved.inner_iterations}};
  rep["objective"] = solved.objective;
  nlohmann::json log = nlohmann::json::array();
  for (const OuterIterationLog& l : solved.log) {
    log.push_back({{"outer", l.outer}, {"iterations", l.inner_iterations}, {"cost", l.cost},
                   {"pq_normalized_max", l.pq_normalized_max},
                   {"faces_above_tolerance", l.faces_above_tolerance},
                   {"weight_max", l.weight_max}, {"max_move_mean_edges", l.max_move},
                   {"seconds", l.seconds}});
  }
  rep["outer_log"] = log;
  rep["before"] = MetricsToJson(before, scale);

  if (!solved.usable) {
    run.exit_code = 3;
    rep["message"] = solved.message;
    run.summary = "archgeo: the solver found no usable solution: " + solved.message +
                  "\nnothing was written.\n";
    return run;
  }

  const Mesh output = WithPositions(input, work, frame);
  const auto metrics_start = Clock::now();
  const Metrics after = ComputeMetrics(output, &reference, &input);
  rep["after"] = MetricsToJson(after, scale);
  const double metrics_seconds = Since(metrics_start);

  const auto write_start = Clock::now();
  if (!spec.output_mesh.empty()) {
    const auto colors = PlanarityColors(MeasureFacePlanarity(output), spec.color_max);
    WriteMesh(mesh_temporary, output, &colors, spec.ascii_ply);
    rep["output_mesh"] = spec.output_mesh;
  }
  rep["seconds"] = {{"read", read_seconds},
                    {"reference_and_metrics_before", setup_seconds},
                    {"solve", solve_seconds},
                    {"ceres", solved.seconds_solver},
                    {"linear_solver", solved.seconds_linear_solver},
                    {"jacobian", solved.seconds_jacobian},
                    {"projection", solved.seconds_projection},
                    {"metrics_after", metrics_seconds},
                    {"write", Since(write_start)},
                    {"total", Since(start)}};
  if (!spec.output_report.empty()) {
    rep["output_report"] = spec.output_report;
    std::ofstream out(report_temporary);
    out << std::setw(2) << rep << "\n";
    if (!out) throw InputError(spec.output_report, 0, "output.report", "cannot write the report");
  }
  staged.Commit();

  char head[512];
  std::snprintf(head, sizeof head,
                "planar_quads: %d variables, %d residuals, %d outer / %d Ceres iterations, "
                "%.2f s (solve %.2f s)\ntolerance δ_PQ,n max <= %g: %s\nobjective (canonical "
                "frame): %.6e\n",
                solved.variables, solved.residuals, solved.outer_iterations,
                solved.inner_iterations, Since(start), solve_seconds, spec.pq_normalized_max,
                spec.pq_normalized_max <= 0 ? "off"
                : solved.tolerance_met      ? "met"
                                            : "NOT met within solver.outer_iterations rounds "
                                              "(weaker anchor/proximity pulls let it move more)",
                solved.objective.count("total") ? solved.objective.at("total") : 0.0);
  run.summary = head + FormatMetrics(before, &after, scale);
  return run;
}

RunResult MeasureFiles(const std::string& mesh_path, const std::string& reference_path) {
  const Mesh mesh = ReadMesh(mesh_path);
  RunResult run;
  Metrics metrics;
  if (reference_path.empty()) {
    metrics = ComputeMetrics(mesh, nullptr, nullptr);
  } else {
    const Mesh reference_mesh = ReadMesh(reference_path);
    const ReferenceSurface reference(reference_mesh);
    const bool same = reference_mesh.number_of_vertices() == mesh.number_of_vertices();
    metrics = ComputeMetrics(mesh, &reference, same ? &reference_mesh : nullptr);
  }
  run.report = {{"archgeo", "measure"},
                {"mesh", mesh_path},
                {"reference", reference_path},
                {"units", {{"lengths", "file units"},
                           {"relative", "file units / bounding-box diagonal of the mesh"}}},
                {"metrics", MetricsToJson(metrics, metrics.bbox_diagonal)}};
  run.summary = FormatMetrics(metrics, nullptr, metrics.bbox_diagonal);
  return run;
}

RunResult GenerateRoofGrid(const std::string& path, int nu, int nv, double noise, double scale,
                           unsigned seed) {
  if (nu < 1 || nv < 1) throw InputError("--nu/--nv", 0, "", "grid sizes must be >= 1");
  if (!(noise >= 0) || !(scale > 0)) {
    throw InputError("--noise/--scale", 0, "", "noise must be >= 0 and scale > 0");
  }
  Mesh mesh = QuadGrid(nu, nv, RoofSurface, noise, seed);
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    mesh.point(v) = Point(scale * p.x(), scale * p.y(), scale * p.z());
  }
  StagedOutputs staged;
  WriteMesh(staged.Stage(path), mesh);
  staged.Commit();
  RunResult run;
  run.summary = "wrote " + path + ": " + std::to_string(mesh.number_of_vertices()) +
                " vertices, " + std::to_string(mesh.number_of_faces()) + " quads\n";
  return run;
}

}  // namespace archgeo
