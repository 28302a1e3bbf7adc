#include "problems/run.h"

#include <chrono>
#include <cstdio>
#include <map>
#include <set>

#include <glog/logging.h>
#include <functional>

#include "mesh/input_error.h"
#include "mesh/io.h"
#include "mesh/metrics.h"
#include "mesh/output_files.h"
#include "mesh/reference.h"
#include "mesh/similarity.h"
#include "mesh/subdivision.h"
#include "mesh/topology.h"
#include "problems/analysis.h"
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

// Fixed input vertices (`fixed: ids`) as net vertices; every one must be on the net.
std::vector<bool> OnNet(const ProblemSpec& spec, const std::vector<bool>& fixed_input,
                        const WorkingNet& net) {
  std::vector<bool> on_net(fixed_input.size(), false);
  std::vector<bool> fixed(net.source.size(), false);
  for (size_t i = 0; i < net.source.size(); ++i) {
    fixed[i] = fixed_input[net.source[i]];
    on_net[net.source[i]] = true;
  }
  for (size_t v = 0; v < fixed_input.size(); ++v) {
    if (fixed_input[v] && !on_net[v]) {
      throw InputError(spec.fixed_file, spec.fixed_line, "fixed",
                       "vertex " + std::to_string(v) + " of " + spec.mesh +
                           " is not a vertex of the net solved (" +
                           net.details.value("net", std::string("derived net")) + ")");
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

// `solved` (canonical frame) moved back to file units, without any solver
// property: on a copy of the input when the topology is the input's, else
// rebuilt from positions and faces (after subdivision).
Mesh InFileFrame(const Mesh& input, const Mesh& solved, const Similarity& frame) {
  Mesh out;
  if (solved.number_of_vertices() == input.number_of_vertices() &&
      solved.number_of_faces() == input.number_of_faces()) {
    out = input;
  } else {
    for (VertexIndex v : solved.vertices()) out.add_vertex(solved.point(v));
    for (FaceIndex f : solved.faces()) {
      std::vector<VertexIndex> vs;
      for (VertexIndex v : CGAL::vertices_around_face(solved.halfedge(f), solved)) vs.push_back(v);
      out.add_face(vs);
    }
  }
  for (VertexIndex v : out.vertices()) {
    out.point(v) = ToPoint(frame.FromCanonical(ToVec3(solved.point(v))));
  }
  return out;
}

// Adds `level` to the running totals in `total`.
void Accumulate(const SolveOutcome& level, SolveOutcome& total) {
  total.usable = level.usable;
  total.message = level.message;
  total.variables = level.variables;
  total.residuals = level.residuals;
  total.outer_iterations += level.outer_iterations;
  total.inner_iterations += level.inner_iterations;
  total.objective = level.objective;
  for (const auto& [k, v] : level.seconds) total.seconds[k] += v;
  total.headline = level.headline;
}

}  // namespace

RunResult RunSpec(const ProblemSpec& spec, const ProgressSink& progress) {
  const auto start = Clock::now();
  ConfigureThreading();
  CHECK(spec.builder) << "RunSpec: the spec has no builder (use ReadSpec)";
  const Builder& builder = *spec.builder;

  // Outputs are checked and staged before any work: a bad output name or an
  // output that would overwrite an input fails at once.
  // Every input (the spec, the mesh, the reference, files a builder reads)
  // is protected: no output may name it.
  std::vector<std::string> inputs = {spec.spec_path, spec.mesh};
  if (!spec.reference.empty()) inputs.push_back(spec.reference);
  for (const std::string& path : builder.InputFiles()) inputs.push_back(path);
  StagedOutputs staged(inputs);
  std::string mesh_temporary, report_temporary;
  if (!spec.output_mesh.empty()) {
    try {
      CheckMeshExtension(spec.output_mesh);
    } catch (const InputError& e) {
      throw InputError(spec.output_mesh, 0, "output.mesh", e.message());
    }
    mesh_temporary = staged.Stage(spec.output_mesh, "output.mesh");
  }
  if (!spec.output_report.empty()) {
    report_temporary = staged.Stage(spec.output_report, "output.report");
  }
  std::map<std::string, std::string> extra_temporary;
  for (const auto& [key, path] : spec.extra_outputs) {
    extra_temporary[key] = staged.Stage(path, "output." + key);
  }
  // An error a writer reports about a temporary names the user's path.
  auto writing = [&](const std::function<void()>& write) {
    try {
      write();
    } catch (const InputError& e) {
      if (e.file() == mesh_temporary && !mesh_temporary.empty()) {
        throw InputError(spec.output_mesh, e.line(), "output.mesh", e.message());
      }
      for (const auto& [key, temporary] : extra_temporary) {
        if (e.file() == temporary) {
          throw InputError(spec.extra_outputs.at(key), e.line(), "output." + key, e.message());
        }
      }
      throw;
    }
  };

  ReadInfo info;
  const Mesh read = ReadMesh(spec.mesh, &info);
  builder.CheckInput(read, spec.mesh);
  const WorkingNet net = builder.Net(read, spec.mesh);
  const Mesh& input = net.derived ? net.mesh : read;
  const Mesh reference_mesh = spec.reference.empty() ? input : ReadMesh(spec.reference);
  if (spec.multiresolution_levels > 0 && !CanSubdivide(input, spec.multiresolution_scheme)) {
    throw InputError(spec.spec_path, 0, "multiresolution.scheme",
                     spec.multiresolution_scheme + " subdivision needs a triangle mesh; " +
                         spec.mesh + " has other faces (use catmull_clark or doo_sabin)");
  }
  std::vector<bool> fixed = FixedVertices(spec, net.derived && spec.fixed == "ids" ? read : input);
  if (net.derived && spec.fixed == "ids") fixed = OnNet(spec, fixed, net);
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
  const std::set<std::string> analyses = builder.Analyses();
  const AnalysisRows extra_before = Analyse(input, analyses);
  const double setup_seconds = Since(setup_start);

  const auto solve_start = Clock::now();
  const Similarity frame = CanonicalFrame(input);
  Mesh work = input;
  ToCanonical(frame, work);
  Mesh reference_canonical = reference_mesh;
  ToCanonical(frame, reference_canonical);
  const ReferenceSurface reference_in_frame(reference_canonical);
  SolveContext context;
  context.input = &input;
  context.frame = frame;
  context.reference = &reference_in_frame;
  context.solver = spec.solver;
  context.progress = progress;
  SolveOutcome solved;
  nlohmann::json levels = nlohmann::json::array();
  for (int level = 0; level <= spec.multiresolution_levels; ++level) {
    if (level > 0) {
      const Mesh coarse = work;
      work = Subdivide(work, spec.multiresolution_scheme);
      // Boundary and corners are recomputed on the finer mesh; listed ids
      // keep their vertex (Loop and Catmull–Clark keep the old indices).
      const bool keeps_ids =
          spec.multiresolution_scheme == "loop" || spec.multiresolution_scheme == "catmull_clark";
      if (spec.fixed == "ids" && !keeps_ids) {
        throw InputError(spec.fixed_file, spec.fixed_line, "fixed",
                         "vertex ids cannot be kept through " + spec.multiresolution_scheme +
                             " subdivision (it renumbers vertices); use loop or catmull_clark");
      }
      std::vector<bool> finer = FixedVertices(spec, work);
      if (spec.fixed == "ids") {
        finer.assign(work.number_of_vertices(), false);
        for (size_t i = 0; i < fixed.size(); ++i) finer[i] = fixed[i];
      }
      // Fixed vertices keep their positions: the smoothing masks of the
      // subdivision would move them (e.g. Loop shrinks a fixed boundary
      // circle by (6 + 2 cos(2π/n))/8).
      if (keeps_ids) {
        for (VertexIndex v : coarse.vertices()) {
          if (fixed[v.idx()]) work.point(v) = coarse.point(v);
        }
      }
      fixed = finer;
      if (progress) {
        progress("multiresolution level " + std::to_string(level) + ": " +
                 spec.multiresolution_scheme + " subdivision -> " +
                 std::to_string(work.number_of_vertices()) + " vertices, " +
                 std::to_string(work.number_of_faces()) + " faces");
      }
    }
    context.fixed = fixed;
    const auto level_start = Clock::now();
    const SolveOutcome outcome = builder.Solve(work, context);
    Accumulate(outcome, solved);
    levels.push_back({{"level", level},
                      {"vertices", work.number_of_vertices()},
                      {"faces", work.number_of_faces()},
                      {"variables", outcome.variables},
                      {"residuals", outcome.residuals},
                      {"outer_iterations", outcome.outer_iterations},
                      {"inner_iterations", outcome.inner_iterations},
                      {"objective", outcome.objective},
                      {"details", outcome.details},
                      {"seconds", Since(level_start)}});
    if (!outcome.usable) break;
  }
  const double solve_seconds = Since(solve_start);

  RunResult run;
  nlohmann::json& rep = run.report;
  rep["archgeo"] = "solve";
  rep["spec"] = spec.spec_path;
  rep["mesh"] = spec.mesh;
  rep["reference"] = spec.reference.empty() ? spec.mesh : spec.reference;
  rep["problem"] = spec.problem;
  rep["input"] = {{"format", info.format}, {"reoriented_faces", info.reoriented_faces}};
  if (!net.details.empty()) rep["net"] = net.details;
  rep["units"] = {{"lengths", "file units"},
                  {"relative", net.derived ? "file units / bounding-box diagonal of the net "
                                             "solved (before solving)"
                                           : "file units / bounding-box diagonal of the input"},
                  {"bbox_diagonal", scale},
                  {"angles", "degrees"},
                  {"objective", "0.5 * sum_terms w * sum r^2, in the canonical frame (unit mean "
                                "edge length), at the last linearisation"}};
  rep["settings"] = builder.SettingsJson();
  if (rep["settings"].contains("terms")) rep["terms"] = rep["settings"]["terms"];
  rep["fixed"] = spec.fixed;
  rep["solver"] = SolverJson(spec.solver);
  rep["blas"] = BlasLibrary();
  if (!levels.empty()) {
    for (const auto& [key, value] : levels.back()["details"].items()) rep[key] = value;
  }
  if (spec.multiresolution_levels > 0) {
    rep["multiresolution"] = {{"scheme", spec.multiresolution_scheme}, {"levels", levels}};
  }
  rep["usable"] = solved.usable;
  rep["variables"] = solved.variables;
  rep["residuals"] = solved.residuals;
  rep["iterations"] = {{"outer", solved.outer_iterations}, {"inner", solved.inner_iterations}};
  rep["objective"] = solved.objective;
  rep["before"] = MetricsToJson(before, scale);
  AnalysisToJson(extra_before, scale, rep["before"]);

  if (!solved.usable) {
    run.exit_code = 3;
    rep["message"] = solved.message;
    run.summary = "archgeo: the solver found no usable solution: " + solved.message +
                  "\nnothing was written.\n";
    return run;
  }

  const Mesh output = InFileFrame(input, work, frame);
  const auto metrics_start = Clock::now();
  const bool same_vertices = output.number_of_vertices() == input.number_of_vertices();
  const Metrics after = ComputeMetrics(output, &reference, same_vertices ? &input : nullptr);
  const AnalysisRows extra_after = Analyse(output, analyses);
  rep["after"] = MetricsToJson(after, scale);
  AnalysisToJson(extra_after, scale, rep["after"]);
  const double metrics_seconds = Since(metrics_start);

  const auto write_start = Clock::now();
  if (!spec.output_mesh.empty()) {
    FaceColors colors = builder.Colors(output, spec.color_max);
    if (colors.empty()) colors = PlanarityColors(MeasureFacePlanarity(output), spec.color_max);
    writing([&] { WriteMesh(mesh_temporary, output, &colors, spec.ascii_ply); });
    rep["output_mesh"] = spec.output_mesh;
  }
  writing([&] { builder.WriteOutputs(output, extra_temporary, rep); });
  for (const auto& [key, path] : spec.extra_outputs) rep["output_" + key] = path;
  nlohmann::json seconds = {{"read", read_seconds},
                            {"reference_and_metrics_before", setup_seconds},
                            {"solve", solve_seconds},
                            {"metrics_after", metrics_seconds},
                            {"write", Since(write_start)},
                            {"total", Since(start)}};
  for (const auto& [k, v] : solved.seconds) seconds[k] = v;
  rep["seconds"] = seconds;
  if (!spec.output_report.empty()) {
    rep["output_report"] = spec.output_report;
    try {
      WriteTextFile(report_temporary, rep.dump(2) + "\n", "output.report");
    } catch (const InputError& e) {
      throw InputError(spec.output_report, 0, "output.report", e.message());
    }
  }
  staged.Commit();

  char head[512];
  std::snprintf(head, sizeof head,
                "%s: %d variables, %d residuals, %d outer / %d Ceres iterations, %.2f s (solve "
                "%.2f s)\n",
                spec.problem.c_str(), solved.variables, solved.residuals,
                solved.outer_iterations, solved.inner_iterations, Since(start), solve_seconds);
  char objective[128];
  std::snprintf(objective, sizeof objective, "objective (canonical frame): %.6e\n",
                solved.objective.count("total") ? solved.objective.at("total") : 0.0);
  run.summary = head + net.headline + solved.headline + objective + FormatMetrics(before, &after, scale) +
                FormatAnalysis(extra_before, &extra_after, scale);
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
  const AnalysisRows analysis = Analyse(mesh, ApplicableAnalyses(mesh));
  run.report = {{"archgeo", "measure"},
                {"mesh", mesh_path},
                {"reference", reference_path},
                {"units", {{"lengths", "file units"},
                           {"relative", "file units / bounding-box diagonal of the mesh"},
                           {"angles", "degrees"}}},
                {"metrics", MetricsToJson(metrics, metrics.bbox_diagonal)}};
  AnalysisToJson(analysis, metrics.bbox_diagonal, run.report["metrics"]);
  run.summary = FormatMetrics(metrics, nullptr, metrics.bbox_diagonal) +
                FormatAnalysis(analysis, nullptr, metrics.bbox_diagonal);
  return run;
}

}  // namespace archgeo
