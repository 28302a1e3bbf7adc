// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/run.h"
#include "problems/mesh_inputs.h"
#include "energies/registry.h"

#include <glog/logging.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <cstdio>
#include <functional>
#include <future>
#include <map>
#include <optional>
#include <set>

#include "core/solver_options.h"
#include "core/input_error.h"
#include "io/io.h"
#include "analysis/metrics.h"
#include "io/output_files.h"
#include "geometry/reference.h"
#include "mesh/similarity.h"
#include "analysis/validity.h"
#include "problems/analysis.h"
#include "problems/colors.h"
#include "problems/hnet_net.h"
#include "problems/picture.h"
#include "problems/model.h"
#include "problems/report.h"
#include "problems/solve.h"

namespace archgeo {
namespace {

using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// "before -> after (change %)" of every measure of the first stage's log.
std::string MeasureHeadline(const LoopResult& r) {
  if (r.log.empty()) return "";
  const RoundLog& first = r.log.front();
  const RoundLog* out = &r.log.back();
  for (const RoundLog& row : r.log) {
    if (row.round == r.output_round) out = &row;
  }
  std::string text;
  for (const auto& [name, before] : first.measures) {
    const auto it = out->measures.find(name);
    if (it == out->measures.end()) continue;
    char line[200];
    std::snprintf(line, sizeof line, "  %s %.6g -> %.6g%s\n", name.c_str(), before, it->second,
                  before != 0 ? (" (" + std::to_string(int(std::lround(
                                            100.0 * (it->second - before) / std::abs(before)))) +
                                 "%)").c_str()
                              : "");
    text += line;
  }
  return text.empty() ? "" : "measures (canonical frame: input mean edge length 1), input -> output:\n" + text;
}

// The problem's output blocks, per element, in file units.
nlohmann::json BlocksJson(const Store& store, const Similarity& frame) {
  nlohmann::json blocks = nlohmann::json::object();
  for (const std::string& name : store.Names()) {
    const BlockDecl& decl = store.Decl(name);
    if (!decl.output) continue;
    const char* on = store.IsGlobal(name)       ? "global"
                     : decl.on == Site::kVertex ? "vertex"
                     : decl.on == Site::kFace   ? "face"
                                                : "edge";
    blocks[name] = {{"on", on},
                    {"width", decl.width},
                    {"doc", decl.doc},
                    {"values", store.InFileUnits(name, frame)}};
  }
  return blocks;
}

// Measures that count things (written as JSON integers in the round log).
bool IsCountMeasure(const std::string& name) {
  return name == "self_intersecting_pyramids" || name == "bad_saddles" ||
         name == "saddle_violations";
}

// The round log with counts as integers (RoundLog keeps every measure as a
// double).
nlohmann::json RoundsJson(const nlohmann::json& rounds) {
  nlohmann::json out = rounds;
  for (nlohmann::json& row : out) {
    if (!row.contains("measures")) continue;
    for (auto& [name, value] : row["measures"].items()) {
      if (IsCountMeasure(name) && value.is_number() && std::isfinite(value.get<double>())) {
        value = std::llround(value.get<double>());
      }
    }
  }
  return out;
}

// Per-face values (file order of the output's faces) and per-vertex
// displacement (when the output has the input's vertices), for output.arrays.
nlohmann::json ArraysJson(const FaceValues& values, const Mesh& output, const Mesh& input) {
  nlohmann::json face = nlohmann::json::array();
  for (FaceIndex f : output.faces()) face.push_back(values.values[f.idx()]);
  nlohmann::json arrays = {{"face", {{values.name, face}}}, {"vertex", nlohmann::json::object()}};
  if (output.number_of_vertices() == input.number_of_vertices()) {
    nlohmann::json displacement = nlohmann::json::array();
    for (VertexIndex v : output.vertices()) {
      displacement.push_back(std::sqrt(CGAL::squared_distance(output.point(v), input.point(v))));
    }
    arrays["vertex"]["displacement"] = displacement;
  }
  return arrays;
}

}  // namespace

RunResult RunSpec(const ProblemSpec& spec, const ProgressSink& progress) {
  return RunSpec(spec, progress, MeshInputs{});
}

RunResult RunSpec(const ProblemSpec& spec, const ProgressSink& progress, const MeshInputs& meshes) {
  const auto start = Clock::now();
  ConfigureThreading();
  CHECK(spec.declaration) << "RunSpec: the spec has no problem (use ReadSpec)";
  const ProblemDecl& d = *spec.declaration;
  const Settings& s = spec.settings;
  SolverOptions(s);  // a combination Ceres rejects fails before any work

  // Outputs are checked and staged before any work; no output may name an
  // input (the spec, the mesh, the reference, files the problem reads).
  std::vector<std::string> inputs = spec.InputFiles();
  inputs.push_back(spec.spec_path);
  StagedOutputs staged(inputs);
  std::map<std::string, std::string> temporaries;  // output key -> staged file
  for (const Key& k : s.schema().keys()) {
    if (k.type != Type::kOutputPath || s.String(k.name).empty()) continue;
    const std::string& path = s.String(k.name);
    if (k.name == "output.mesh" || k.name == "output.layout" || k.name == "output.grid") {
      try {
        CheckMeshExtension(path);
      } catch (const InputError& e) {
        throw s.Error(k.name, "'" + path + "': " + e.message());
      }
    }
    // Outputs written in one format only: another name would hide the
    // content (a PLY patchwork named .stl), so it is refused before any work.
    static const std::map<std::string, std::vector<std::string>> kFormats = {
        {"output.image", {".png", ".html"}},
        {"output.patchwork", {".ply"}},
        {"output.rulings", {".obj"}},
        {"output.field", {".ply"}}};
    if (const auto format = kFormats.find(k.name); format != kFormats.end()) {
      std::string extension = std::filesystem::path(path).extension().string();
      for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
      const std::vector<std::string>& allowed = format->second;
      if (std::find(allowed.begin(), allowed.end(), extension) == allowed.end()) {
        std::string names;
        for (const std::string& a : allowed) names += (names.empty() ? "" : " or ") + a;
        throw s.Error(k.name, "'" + path + "': this output is written as " + names +
                                  " only: use a " + names + " name");
      }
    }
    temporaries[k.name] = staged.Stage(s.String(k.name), k.name);
  }
  // An error a writer reports about a temporary names the user's path.
  auto writing = [&](const std::function<void()>& write) {
    try {
      write();
    } catch (const InputError& e) {
      for (const auto& [key, temporary] : temporaries) {
        if (e.file() == temporary) throw InputError(s.String(key), e.line(), key, e.message());
      }
      throw;
    }
  };

  ReadInfo info;
  ReadLimits limits;
  limits.max_vertices = size_t(s.Integer("limits.max_vertices"));
  limits.max_faces = size_t(s.Integer("limits.max_faces"));
  limits.max_face_degree = size_t(s.Integer("limits.max_face_degree"));
  limits.max_file_bytes = std::uint64_t(s.Integer("limits.max_file_bytes"));
  const Mesh read = d.makes_input ? Mesh()
                    : meshes.mesh ? *meshes.mesh
                                  : ReadMesh(spec.mesh(), &info, limits);
  if (meshes.mesh) info.format = "memory";
  std::unique_ptr<Mesh> reference_mesh;
  if (meshes.reference) {
    reference_mesh = std::make_unique<Mesh>(*meshes.reference);
  } else if (!spec.reference().empty()) {
    reference_mesh = std::make_unique<Mesh>(ReadMesh(spec.reference(), nullptr, limits));
  }
  const double read_seconds = Since(start);

  const auto solve_start = Clock::now();
  const std::unique_ptr<Solution> solution = Solve(spec, read, reference_mesh.get(), progress);
  const double solve_seconds = Since(solve_start);
  const LoopResult& solved = solution->loop;
  const WorkingNet& net = solution->net;
  const Mesh& input = solution->input;
  // The result's validity against the net it came from (analysis/validity.h)
  // needs no reference: it is checked on a second thread while the
  // reference's trees are built and the input is measured (mostly serial).
  std::future<Validity> validity_check;
  if (solved.usable) {
    validity_check = std::async(std::launch::async, [&] {
      return CheckValidity(solution->output, &input, LimitsOf(s), true);
    });
  }

  const auto setup_start = Clock::now();
  const ReferenceSurface reference(reference_mesh ? *reference_mesh : input);
  // Without a separate reference the input is its own reference surface:
  // every vertex lies on it, so its distances to it are 0 and need not be
  // measured.
  Metrics before = ComputeMetrics(input, reference_mesh ? &reference : nullptr, &input);
  if (!reference_mesh) {
    before.prox_max = before.surface_distance_max = before.surface_distance_mean = 0;
    before.boundary_prox_max = reference.HasBoundary() ? 0 : -1;
    before.hausdorff = 0;
  }
  const double scale = before.bbox_diagonal;
  const AnalysisRows extra_before = Analyse(input, d.analyses, HNetOptionsOf(s));
  const double setup_seconds = Since(setup_start);
  const int levels = int(s.Integer("multiresolution.levels"));

  RunResult run;
  nlohmann::json& rep = run.report;
  rep["schema_version"] = kReportSchemaVersion;
  rep["archgeo"] = "solve";
  rep["spec"] = spec.spec_path;
  rep["mesh"] = spec.mesh();
  rep["reference"] = spec.reference().empty() ? spec.mesh() : spec.reference();
  rep["problem"] = d.name;
  rep["input"] = {{"format", info.format}, {"reoriented_faces", info.reoriented_faces}};
  rep["units"] = {{"lengths", "file units"},
                  {"relative", net.derived ? "file units / bounding-box diagonal of the net "
                                             "solved (before solving)"
                                           : "file units / bounding-box diagonal of the input"},
                  {"bbox_diagonal", scale},
                  {"angles", "degrees"},
                  {"rounds", "measures and max_move in the canonical frame (input mean edge "
                             "length = 1); round 0 = the input"},
                  {"objective", "0.5 * sum_terms w * sum r^2, in the canonical frame (unit mean "
                                "edge length), at the last linearisation"}};
  rep["settings"] = s.ToJson();
  rep["blas"] = BlasLibrary();
  rep["details"] = solution->details;
  if (!net.details.empty()) rep["details"]["net"] = net.details;  // a net the problem made
  if (s.Bool("output.blocks")) rep["blocks"] = BlocksJson(*solution->store, solution->frame);
  if (levels > 0) {
    rep["multiresolution"] = {{"scheme", s.String("multiresolution.scheme")},
                              {"levels", solution->levels}};
  }
  rep["rounds"] = RoundsJson(solution->rounds);
  rep["output_round"] = solved.output_round;
  rep["stop"] = solved.stop;
  rep["usable"] = solved.usable;
  rep["variables"] = solved.variables;
  rep["residuals"] = solved.residuals;
  rep["pcg"] = {{"rounds", solved.pcg_rounds}, {"cg_iterations", solved.cg_iterations}};
  rep["iterations"] = {{"outer", solved.rounds}, {"inner", solved.iterations}};
  rep["objective"] = solved.objective;
  nlohmann::json tolerances = nlohmann::json::object();
  std::string tolerance_lines;
  for (const auto& [key, met] : solved.tolerances) {
    tolerances[key] = {{"bound", s.Number(key)}, {"met", met}};
    char line[200];
    std::snprintf(line, sizeof line, "tolerance %s <= %g: %s\n", key.c_str(), s.Number(key),
                  s.Number(key) <= 0 ? "off" : met ? "met" : "NOT met");
    tolerance_lines += line;
  }
  rep["tolerances"] = tolerances;
  rep["before"] = MetricsToJson(before, scale);
  AnalysisToJson(extra_before, scale, rep["before"]);

  if (!solved.usable) {
    run.exit_code = 3;
    rep["message"] = solved.message;
    run.summary = "archgeo: the solver found no usable solution: " + solved.message +
                  "\nnothing was written.\n";
    return run;
  }

  const Mesh& output = solution->output;
  const Validity validity = validity_check.get();
  rep["validity"] = validity.ToJson();
  rep["validity"]["restored_round"] =
      solved.restored_valid ? nlohmann::json(solved.output_round) : nlohmann::json(nullptr);
  // The problem's own checks (ProblemDecl::invalid), on the state written.
  const std::string own = d.invalid ? d.invalid(solution->hooks) : std::string();
  rep["validity"]["problem"] = own.empty() ? nlohmann::json(nullptr) : nlohmann::json(own);
  if (!own.empty()) rep["validity"]["valid"] = false;
  if (!validity.valid() || !own.empty()) {
    run.exit_code = 3;
    rep["message"] = "the result is not valid";
    run.summary = "archgeo: the result is not valid (nothing was written):\n" + validity.Reason() +
                  own +
                  "(limits: validity.* keys; the report's validity section lists every check)\n";
    const nlohmann::json& details = solution->details;
    if (details.contains("suitability") && details["suitability"].contains("warning")) {
      run.summary += "WARNING (input suitability): " +
                     details["suitability"]["warning"].get<std::string>() + "\n";
    }
    return run;
  }
  bool tolerances_met = true;
  for (const auto& [key, met] : solved.tolerances) tolerances_met = tolerances_met && met;
  run.exit_code = tolerances_met ? 0 : 4;
  // The per-face value of the colours, the PLY properties and the picture;
  // the input gives the scale where the problem has no tolerance for it.
  const auto write_start = Clock::now();
  const FaceValues face_values = ComputeFaceValues(d.colors, output, &input, &s);
  // The mesh file is written on a second thread while the output is
  // measured (its staged temporary is committed only at the end).
  const bool ascii_ply = s.Bool("output.ascii_ply");
  double mesh_write_seconds = 0;
  std::future<void> mesh_written;
  if (temporaries.count("output.mesh")) {
    mesh_written = std::async(std::launch::async, [&] {
      const auto mesh_start = Clock::now();
      const FaceColors colors = ColorsOf(face_values);
      const std::vector<PlyValues> properties = {{face_values.name, face_values.values}};
      // Per vertex: the displacement from the input (file units), when the
      // output has the input's vertices.
      std::vector<PlyValues> vertex_values;
      if (output.number_of_vertices() == input.number_of_vertices()) {
        PlyValues& d = vertex_values.emplace_back();
        d.name = "displacement";
        d.values.assign(output.num_vertices(), 0.0);
        for (VertexIndex v : output.vertices()) {
          d.values[v.idx()] = std::sqrt(CGAL::squared_distance(output.point(v), input.point(v)));
        }
      }
      writing([&] {
        WriteMesh(temporaries.at("output.mesh"), output, &colors, ascii_ply, &properties,
                  &vertex_values);
      });
      mesh_write_seconds = Since(mesh_start);
    });
  }
  double write_seconds = Since(write_start);

  const auto metrics_start = Clock::now();
  const bool same_vertices = output.number_of_vertices() == input.number_of_vertices();
  const Metrics after = ComputeMetrics(output, &reference, same_vertices ? &input : nullptr);
  const AnalysisRows extra_after = Analyse(output, d.analyses, HNetOptionsOf(s));
  rep["after"] = MetricsToJson(after, scale);
  AnalysisToJson(extra_after, scale, rep["after"]);
  const double metrics_seconds = Since(metrics_start);

  const auto rest_start = Clock::now();
  rep["colors"] = {{"value", face_values.name},  {"label", face_values.label},
                   {"units", face_values.units}, {"red_at", face_values.red_at},
                   {"red_from", face_values.red_from}};
  if (s.Bool("output.arrays")) rep["arrays"] = ArraysJson(face_values, output, input);
  if (temporaries.count("output.image")) {
    const FaceValues before = ComputeFaceValues(d.colors, input, &input, &s);
    std::vector<PicturePanel> panels = {PanelOf(input, before.values, "input"),
                                        PanelOf(output, face_values.values, "output")};
    writing([&] {
      WriteView(temporaries.at("output.image"), panels, ScaleOf(face_values), {},
                "output.image");
    });
  }
  HookContext& hooks = solution->hooks;
  for (const auto& [key, temporary] : temporaries) {
    if (key != "output.mesh" && key != "output.report" && key != "output.image") {
      hooks.temporaries[key.substr(std::string("output.").size())] = temporary;
    }
  }
  if (d.write && !hooks.temporaries.empty()) writing([&] { d.write(hooks); });
  if (mesh_written.valid()) mesh_written.get();
  rep["details"] = hooks.details;
  if (!net.details.empty()) rep["details"]["net"] = net.details;  // a net the problem made
  nlohmann::json seconds = {{"read", read_seconds},
                            {"reference_and_metrics_before", setup_seconds},
                            {"solve", solve_seconds},
                            {"metrics_after", metrics_seconds},
                            {"write", write_seconds + Since(rest_start)},
                            {"write_mesh", mesh_write_seconds},
                            {"total", Since(start)}};
  for (const auto& [k, v] : solved.seconds) seconds[k] = v;
  rep["seconds"] = seconds;
  if (temporaries.count("output.report")) {
    writing([&] { WriteTextFile(temporaries.at("output.report"), rep.dump(2) + "\n", "output.report"); });
  }
  staged.Commit();
  if (meshes.output) *meshes.output = output;

  char head[512];
  std::snprintf(head, sizeof head,
                "%s: %d variables, %d residuals, %d rounds / %d iterations%s, %.2f s (solve "
                "%.2f s); stop: %s\n",
                d.name.c_str(), solved.variables, solved.residuals, solved.rounds,
                solved.iterations,
                solved.pcg_rounds > 0
                    ? (" (" + std::to_string(solved.pcg_rounds) + " rounds by PCG, " +
                       std::to_string(solved.cg_iterations) + " CG steps)").c_str()
                    : "",
                Since(start), solve_seconds, solved.stop.c_str());
  char objective[128];
  std::snprintf(objective, sizeof objective, "objective (canonical frame): %.6e\n",
                solved.objective.count("total") ? solved.objective.at("total") : 0.0);
  std::string validity_lines = "validity: every check passed\n";
  if (!validity.Warnings().empty()) validity_lines = "validity: valid; warnings:\n" + validity.Warnings();
  if (solved.restored_valid) {
    validity_lines += "the last round was not valid: the output is round " +
                      std::to_string(solved.output_round) + ", the last valid one\n";
  }
  if (run.exit_code == 4) {
    validity_lines += "WARNING: a tolerance was not met (exit 4): the result is valid and written\n";
  }
  if (!ZeroedTerm().empty()) {
    validity_lines += "WARNING: ARCHGEO_ZERO_TERM=" + ZeroedTerm() +
                      ": that term's residuals were zeroed (mutation testing)\n";
  }
  run.summary = head + net.headline + tolerance_lines + validity_lines + solution->headline +
                MeasureHeadline(solved) +
                objective + FormatMetrics(before, &after, scale) +
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
  // The validity checks of `archgeo solve` (default limits): against the
  // reference when it has the mesh's topology (an output and its input),
  // else those of the mesh alone (panels, short edges, self-intersections).
  std::string validity_text;
  nlohmann::json validity_json;
  {
    std::optional<Mesh> input;
    if (!reference_path.empty()) input = ReadMesh(reference_path);
    const bool paired = input && input->number_of_vertices() == mesh.number_of_vertices() &&
                        input->number_of_faces() == mesh.number_of_faces();
    const Validity v = CheckValidity(mesh, paired ? &*input : nullptr, ValidityLimits{}, true);
    validity_json = v.ToJson();
    validity_json["against_reference"] = paired;
    const std::string what =
        paired ? "validity against the reference"
               : input ? "validity of the mesh alone (the reference has another topology: no "
                         "flips, creases or shortened edges compared)"
                       : "validity of the mesh alone";
    validity_text = what + (v.valid() ? ": every hard check passed\n" : ": NOT valid\n" + v.Reason());
    if (!v.Warnings().empty()) validity_text += "warnings:\n" + v.Warnings();
  }
  run.report = {{"schema_version", kReportSchemaVersion},
                {"archgeo", "measure"},
                {"mesh", mesh_path},
                {"reference", reference_path},
                {"units", {{"lengths", "file units"},
                           {"relative", "file units / bounding-box diagonal of the mesh"},
                           {"angles", "degrees"}}},
                {"metrics", MetricsToJson(metrics, metrics.bbox_diagonal)}};
  AnalysisToJson(analysis, metrics.bbox_diagonal, run.report["metrics"]);
  if (!validity_json.is_null()) run.report["validity"] = validity_json;
  run.summary = FormatMetrics(metrics, nullptr, metrics.bbox_diagonal) +
                FormatAnalysis(analysis, nullptr, metrics.bbox_diagonal) + validity_text;
  return run;
}

}  // namespace archgeo
