// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/commands/run.h"
#include "core/clock.h"
#include "problems/runtime/mesh_inputs.h"
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
#include "core/no_result.h"
#include "io/io.h"
#include "analysis/metrics.h"
#include "io/output_files.h"
#include "geometry/reference.h"
#include "mesh/similarity.h"
#include "mesh/topology.h"
#include "analysis/validity.h"
#include "problems/report/analysis.h"
#include "problems/report/colors.h"
#include "problems/report/fabrication.h"
#include "problems/declarations/hnet_net.h"
#include "problems/report/picture.h"
#include "problems/runtime/model.h"
#include "problems/report/report.h"
#include "problems/runtime/session.h"
#include "problems/runtime/solve.h"

namespace archgeo {
namespace {

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
    const std::string change = ChangeText(before, it->second);
    char line[200];
    std::snprintf(line, sizeof line, "  %s %.6g -> %.6g%s\n", name.c_str(), before, it->second,
                  change.empty() ? "" : (" (" + change + ")").c_str());
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

// The per-face planarity of every measure report (δ_PQ, δ_PQ,n and warp of
// analysis/metrics.h, the values whose max and mean the report's metrics
// are) into `face` as "pq", "pq_normalized" and "warp", when `mesh` has a
// face of 4 or more sides (triangles: 0). `mesh` is in a frame of unit
// `scale` file units; δ_PQ is reported in file units.
void PlanarityArrays(const Mesh& mesh, double scale, nlohmann::json& face) {
  bool polygons = false;
  for (FaceIndex f : mesh.faces()) polygons = polygons || mesh.degree(f) >= 4;
  if (!polygons) return;
  const PlanarityMeasure planarity = MeasureFacePlanarity(mesh);
  const std::pair<const char*, const std::vector<double>*> arrays[] = {
      {"pq", &planarity.distance}, {"pq_normalized", &planarity.normalized},
      {"warp", &planarity.warp}};
  for (const auto& [name, values] : arrays) {
    if (face.contains(name)) continue;
    const double unit = std::string(name) == "pq" ? scale : 1.0;
    nlohmann::json& out = face[name] = nlohmann::json::array();
    for (FaceIndex f : mesh.faces()) out.push_back(unit * (*values)[f.idx()]);
  }
}

// The per-vertex distance from `original` (file units; both meshes in a
// frame of unit `scale`), when it has the mesh's vertices, into `vertex` as
// "displacement".
void DisplacementArray(const Mesh& mesh, const Mesh& original, double scale,
                       nlohmann::json& vertex) {
  if (mesh.number_of_vertices() != original.number_of_vertices()) return;
  nlohmann::json displacement = nlohmann::json::array();
  for (VertexIndex v : mesh.vertices()) {
    displacement.push_back(scale *
                           std::sqrt(CGAL::squared_distance(mesh.point(v), original.point(v))));
  }
  vertex["displacement"] = displacement;
}

// Per-face values (file order of the output's faces: the colours' value and
// the planarity) and per-vertex displacement (when the output has the
// input's vertices), for output.arrays; meshes in a frame of unit `scale`.
nlohmann::json ArraysJson(const FaceValues& values, const Mesh& output, const Mesh& input,
                          double scale) {
  nlohmann::json face = nlohmann::json::object();
  nlohmann::json& shown = face[values.name] = nlohmann::json::array();
  for (FaceIndex f : output.faces()) shown.push_back(values.values[f.idx()]);
  PlanarityArrays(output, scale, face);
  nlohmann::json arrays = {{"face", face}, {"vertex", nlohmann::json::object()}};
  DisplacementArray(output, input, scale, arrays["vertex"]);
  return arrays;
}

// Outputs written in one format only: another name would hide the content
// (a PLY patchwork named .stl), so it is refused before any work.
void CheckOutputName(const Settings& s, const std::string& key) {
  const std::string& path = s.String(key);
  if (key == "output.mesh" || key == "output.layout" || key == "output.grid") {
    try {
      CheckMeshExtension(path);
    } catch (const InputError& e) {
      throw s.Error(key, "'" + path + "': " + e.message());
    }
  }
  static const std::map<std::string, std::vector<std::string>> kFormats = {
      {"output.image", {".png", ".html"}},
      {"output.patchwork", {".ply"}},
      {"output.rulings", {".obj"}},
      {"output.field", {".ply", ".rawfield"}},
      {"output.panels", {".csv"}},
      {"output.nodes", {".csv"}},
      {"output.beams", {".csv"}},
      {"output.cutting", {".dxf"}}};
  const auto format = kFormats.find(key);
  if (format == kFormats.end()) return;
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  const std::vector<std::string>& allowed = format->second;
  if (std::find(allowed.begin(), allowed.end(), extension) != allowed.end()) return;
  std::string names;
  for (const std::string& a : allowed) names += (names.empty() ? "" : " or ") + a;
  throw s.Error(key, "'" + path + "': this output is written as " + names + " only: use a " +
                         names + " name");
}

ReadLimits LimitsOfSpec(const Settings& s) {
  ReadLimits limits;
  limits.max_vertices = size_t(s.Integer("limits.max_vertices"));
  limits.max_faces = size_t(s.Integer("limits.max_faces"));
  limits.max_face_degree = size_t(s.Integer("limits.max_face_degree"));
  limits.max_file_bytes = std::uint64_t(s.Integer("limits.max_file_bytes"));
  limits.weld_distance = s.Number("limits.weld_distance");
  return limits;
}

// The report's units section.
nlohmann::json UnitsJson(bool derived, double scale) {
  return {{"lengths", "file units"},
          {"relative", derived ? "file units / bounding-box diagonal of the net "
                                 "solved (before solving)"
                               : "file units / bounding-box diagonal of the input"},
          {"bbox_diagonal", scale},
          {"angles", "degrees"},
          {"rounds", "measures and max_move in the canonical frame (input mean edge "
                     "length = 1); round 0 = the input"},
          {"objective", "0.5 * sum_terms w * sum r^2, in the canonical frame (unit mean "
                        "edge length), at the last linearisation"}};
}

// The per-vertex displacement from the input as a PLY property, when the
// output has the input's vertices (meshes in a frame of unit `scale` file
// units, displacements in file units).
std::vector<PlyValues> DisplacementValues(const Mesh& output, const Mesh& input, double scale) {
  std::vector<PlyValues> values;
  if (output.number_of_vertices() != input.number_of_vertices()) return values;
  PlyValues& d = values.emplace_back();
  d.name = "displacement";
  d.values.assign(output.num_vertices(), 0.0);
  for (VertexIndex v : output.vertices()) {
    d.values[v.idx()] = scale * std::sqrt(CGAL::squared_distance(output.point(v), input.point(v)));
  }
  return values;
}

// The validity checks of `archgeo measure MESH --reference REF` (MESH and
// REF in file units; REF may be null), in MESH's local frame
// (mesh/similarity.h LocalFrame): against REF when it has MESH's vertex and
// face counts (an output and its input), else of MESH alone (every defect
// counts: no flips, creases or shortened edges compared). `archgeo solve`
// judges a net it made from the design surface by this same call, so the
// two verdicts are one.
struct MeasuredValidity {
  Validity validity;
  bool paired = false;  // checked against REF
};

MeasuredValidity ValidityAsMeasured(const Mesh& mesh, const Mesh* reference,
                                    const ValidityLimits& limits) {
  const Similarity local = LocalFrame(mesh);
  MeasuredValidity out;
  out.paired = reference && SameConnectivity(*reference, mesh);
  const Mesh in_frame = InFrame(local, mesh);
  if (!out.paired) {
    out.validity = CheckValidity(in_frame, nullptr, limits, true);
  } else {
    const Mesh reference_in_frame = InFrame(local, *reference);
    out.validity = CheckValidity(in_frame, &reference_in_frame, limits, true);
  }
  return out;
}

// One `archgeo solve` run, stage by stage: stage the outputs, read the
// inputs, solve, measure the input, report the solve, check validity, write
// and measure the output, summarise. Each stage's wall time goes to the
// report's `seconds`.
class SpecRun {
 public:
  // `session` (may be null): solves it (SolveSession::Run) instead of
  // Solve; its start is the mesh and its reference (or first mesh, once it
  // has solved) the reference.
  SpecRun(const ProblemSpec& spec, const ProgressSink& progress, const MeshInputs& meshes,
          const std::atomic<bool>* stop, SolveSession* session = nullptr)
      : spec_(spec), s_(spec.settings), d_(*spec.declaration), progress_(progress),
        meshes_(meshes), stop_(stop), session_(session) {}

  RunResult Run() {
    StageOutputs();
    ReadInputs();
    try {
      SolveAndMeasureInput();
    } catch (const NoResult& e) {
      return NothingMade(e.what());
    }
    ReportSolve();
    if (!solution_->loop.usable) return NotUsable();
    if (!Valid()) return run_;
    WriteAndMeasureOutput();
    // Panels as defective as the input's, or as the layout's the problem made.
    if (!validity_.valid() || !design_.valid()) run_.exit_code = 5;
    run_.summary = Summary();
    if (run_.stopped) run_.summary += "stopped by request: the outputs were not written\n";
    return run_;
  }

 private:
  // Outputs are checked and staged before any work; no output may name an
  // input (the spec, the mesh, the reference, files the problem reads).
  void StageOutputs() {
    CheckFabricationSettings(s_);
    for (const Key& k : s_.schema().keys()) {
      if (k.type != Type::kOutputPath || s_.String(k.name).empty()) continue;
      CheckOutputName(s_, k.name);
      temporaries_[k.name] = staged_.Stage(s_.String(k.name), k.name);
    }
  }

  static std::vector<std::string> Inputs(const ProblemSpec& spec) {
    std::vector<std::string> inputs = spec.InputFiles();
    inputs.push_back(spec.spec_path);
    return inputs;
  }

  // Calls `write`; an error a writer reports about a temporary names the
  // user's path.
  void Writing(const std::function<void()>& write) const {
    try {
      write();
    } catch (const InputError& e) {
      for (const auto& [key, temporary] : temporaries_) {
        if (e.file() == temporary) throw InputError(s_.String(key), e.line(), key, e.message());
      }
      throw;
    }
  }

  void ReadInputs() {
    const ReadLimits limits = LimitsOfSpec(s_);
    if (session_) {
      read_ = session_->start();
      info_.format = "memory";
      const Mesh* reference = session_->reference();
      if (reference) {
        reference_mesh_ = std::make_unique<Mesh>(*reference);
      } else if (session_->solved()) {
        reference_mesh_ = std::make_unique<Mesh>(session_->first());
      }
      seconds_["read"] = SecondsSince(start_);
      return;
    }
    read_ = d_.makes_input ? Mesh()
            : meshes_.mesh ? *meshes_.mesh
                           : ReadMesh(spec_.mesh(), &info_, limits);
    if (meshes_.mesh) info_.format = "memory";
    if (meshes_.reference) {
      reference_mesh_ = std::make_unique<Mesh>(*meshes_.reference);
    } else if (!spec_.reference().empty()) {
      reference_mesh_ = std::make_unique<Mesh>(ReadMesh(spec_.reference(), nullptr, limits));
    }
    seconds_["read"] = SecondsSince(start_);
  }

  // The result's validity against the net it came from (analysis/validity.h)
  // needs no reference: it is checked on a second thread while the
  // reference's trees are built and the input is measured (mostly serial).
  // Everything is measured in the input's local frame (mesh/similarity.h
  // LocalFrame) and its lengths reported in file units.
  void SolveAndMeasureInput() {
    const auto solve_start = Clock::now();
    if (session_) {
      solution_ = &session_->Run(progress_, stop_);
    } else {
      owned_ = Solve(spec_, read_, reference_mesh_.get(), progress_, stop_);
      solution_ = owned_.get();
    }
    solve_seconds_ = SecondsSince(solve_start);
    seconds_["solve"] = solve_seconds_;
    local_ = LocalFrame(solution_->input);
    input_ = InFrame(local_, solution_->input);
    if (solution_->loop.usable) {
      output_ = InFrame(local_, solution_->output);
      validity_check_ = std::async(std::launch::async, [this] {
        return CheckValidity(output_, &input_, LimitsOf(s_), true);
      });
      if (MadeNet()) {
        // As `archgeo measure OUTPUT --reference DESIGN` checks the output
        // written, with the spec's validity.* limits.
        design_check_ = std::async(std::launch::async, [this] {
          return ValidityAsMeasured(solution_->output, &read_, LimitsOf(s_));
        });
      }
    }
    const auto setup_start = Clock::now();
    // The reference: `reference`, else the design surface for a net the
    // problem made from it (Solve's reference too), else the input itself.
    reference_ = std::make_unique<ReferenceSurface>(
        reference_mesh_ ? InFrame(local_, *reference_mesh_)
        : DesignReference() ? InFrame(local_, read_)
                            : input_);
    // Without a separate reference the input is its own reference surface:
    // every vertex lies on it, so its distances to it are 0 and need not be
    // measured.
    const bool own_reference = !reference_mesh_ && !DesignReference();
    before_ = ScaleLengths(
        ComputeMetrics(input_, own_reference ? nullptr : reference_.get(), &input_),
        local_.scale);
    if (own_reference) {
      before_.prox_max = before_.surface_distance_max = before_.surface_distance_mean = 0;
      before_.boundary_prox_max = reference_->HasBoundary() ? 0 : -1;
      before_.hausdorff = 0;
    }
    scale_ = before_.bbox_diagonal;
    extra_before_ = Analyse(input_, d_.analyses, HNetOptionsOf(s_));
    ScaleLengths(extra_before_, local_.scale);
    seconds_["reference_and_metrics_before"] = SecondsSince(setup_start);
  }

  void ReportSolve() {
    const LoopResult& solved = solution_->loop;
    const WorkingNet& net = solution_->net;
    nlohmann::json& rep = run_.report;
    rep["schema_version"] = kReportSchemaVersion;
    rep["archgeo"] = "solve";
    rep["spec"] = spec_.spec_path;
    rep["mesh"] = spec_.mesh();
    rep["reference"] = spec_.reference().empty() ? spec_.mesh() : spec_.reference();
    rep["problem"] = d_.name;
    rep["input"] = {{"format", info_.format},
                    {"reoriented_faces", info_.reoriented_faces},
                    {"welded_vertices", info_.welded_vertices}};
    rep["units"] = UnitsJson(net.derived, scale_);
    rep["settings"] = s_.ToJson();
    rep["blas"] = BlasLibrary();
    rep["blas_kernels"] = BlasKernels();
    rep["details"] = solution_->details;
    if (!net.details.empty()) rep["details"]["net"] = net.details;  // a net the problem made
    if (s_.Bool("output.blocks")) rep["blocks"] = BlocksJson(*solution_->store, solution_->frame);
    if (s_.Integer("multiresolution.levels") > 0) {
      rep["multiresolution"] = {{"scheme", s_.String("multiresolution.scheme")},
                                {"levels", solution_->levels}};
    }
    rep["rounds"] = RoundsJson(solution_->rounds);
    rep["output_round"] = solved.output_round;
    rep["stop"] = solved.stop;
    rep["usable"] = solved.usable;
    rep["variables"] = solved.variables;
    rep["residuals"] = solved.residuals;
    rep["cholesky_rounds"] = solved.cholesky_rounds;
    rep["cholesky_analyses"] = solved.cholesky_analyses;
    rep["cholesky_factorisations"] = {{"count", solved.cholesky_factorisations},
                                      {"gflop", solved.cholesky_flops * 1e-9},
                                      {"largest_factor_nonzeros", solved.cholesky_factor_nonzeros}};
    rep["pcg"] = {{"rounds", solved.pcg_rounds}, {"cg_iterations", solved.cg_iterations}};
    rep["iterations"] = {{"outer", solved.rounds}, {"inner", solved.iterations}};
    rep["objective"] = solved.objective;
    nlohmann::json tolerances = nlohmann::json::object();
    for (const auto& [key, met] : solved.tolerances) {
      tolerances[key] = {{"bound", s_.Number(key)}, {"met", met}};
    }
    rep["tolerances"] = tolerances;
    rep["before"] = MetricsToJson(before_, scale_);
    AnalysisToJson(extra_before_, scale_, rep["before"]);
  }

  // Exit 3, nothing written: `why` (e.g. "the solver found no usable
  // solution") and the message in the summary, the message in the report.
  RunResult NothingWritten(const std::string& why, const std::string& message) {
    run_.exit_code = 3;
    run_.report["message"] = message;
    run_.summary = "archgeo: " + why + ": " + message + "\nnothing was written.\n";
    return run_;
  }

  // A step found nothing to solve or write for an input that is fine
  // (core/no_result.h).
  RunResult NothingMade(const std::string& message) {
    return NothingWritten("no valid result", message);
  }

  RunResult NotUsable() {
    return NothingWritten("the solver found no usable solution", solution_->loop.message);
  }

  // A net the problem made from the input (a layout: its vertices are not
  // the input's) is archgeo's own work, not the user's input: a defect it
  // has is not one to excuse. The output is then also checked alone (every
  // defect counts, as `archgeo measure OUTPUT --reference DESIGN` checks it)
  // and measured against the design surface, the input as read.
  bool MadeNet() const { return solution_->on_design; }

  // The design surface is the reference (of the solve and of the metrics):
  // a net made from it, and no `reference` given.
  bool DesignReference() const { return MadeNet() && !reference_mesh_; }

  // The output's vertices' largest distance from the design surface (file
  // units; the report's after.surface_distance_max, and `archgeo measure
  // OUTPUT --reference DESIGN`'s, where the design is the reference), and
  // whether it lies within the deviation band, where the problem has one;
  // the report's validity.design_surface.
  void MeasureAgainstDesign(nlohmann::json& entry) {
    std::unique_ptr<ReferenceSurface> own;
    if (!DesignReference()) own = std::make_unique<ReferenceSurface>(InFrame(local_, read_));
    const ReferenceSurface& design = own ? *own : *reference_;
    double worst = 0;
    for (VertexIndex v : output_.vertices()) {
      const Vec3 p = ToVec3(output_.point(v));
      const Vec3 q = design.Closest(p).point;
      worst = std::max(worst, std::hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]));
    }
    worst *= local_.scale;
    design_distance_ = worst;
    entry["distance_max"] = worst;
    entry["distance_max_relative"] = worst / scale_;
    if (s_.schema().Find("tolerance.surface_distance_max") == nullptr) return;
    const double band = s_.Number("tolerance.surface_distance") > 0
                            ? s_.Number("tolerance.surface_distance")
                            : s_.Number("tolerance.surface_distance_max") * scale_;
    if (band <= 0) return;
    design_band_ = band;
    entry["band"] = band;
    design_band_met_ = worst <= band;
    entry["within_band"] = design_band_met_;
  }

  // The checks of analysis/validity.h and the problem's own
  // (ProblemDecl::invalid), on the state written. False: exit 3, with the
  // reasons in the summary.
  bool Valid() {
    validity_ = validity_check_.get();
    nlohmann::json& v = run_.report["validity"];
    v = validity_.ToJson();
    if (design_check_.valid()) {
      const MeasuredValidity measured = design_check_.get();
      design_ = measured.validity;
      nlohmann::json& d = v["design_surface"] = design_.ToJson();
      d["against_reference"] = measured.paired;
      MeasureAgainstDesign(d);
      if (!design_.valid()) v["valid"] = false;
    }
    v["restored_round"] = solution_->loop.restored_valid
                              ? nlohmann::json(solution_->loop.output_round)
                              : nlohmann::json(nullptr);
    const std::string own = d_.invalid ? d_.invalid(solution_->hooks) : std::string();
    v["problem"] = own.empty() ? nlohmann::json(nullptr) : nlohmann::json(own);
    if (!own.empty()) v["valid"] = false;
    if (validity_.valid() && own.empty()) return true;
    // Panels the input had so too: the result is written (exit 5) for the
    // user to repair them; ValidityLines names them.
    if (validity_.OnlyInherited() && own.empty()) return true;
    run_.exit_code = 3;
    run_.report["message"] = "the result is not valid";
    run_.summary = "archgeo: the result is not valid (nothing was written):\n" +
                   validity_.Reason() + own +
                   (validity_.valid() ? ""
                                      : "(limits: validity.* keys; the report's validity section "
                                        "lists every check)\n");
    const nlohmann::json& details = solution_->details;
    if (details.contains("suitability") && details["suitability"].contains("warning")) {
      run_.summary += "WARNING (input suitability): " +
                      details["suitability"]["warning"].get<std::string>() + "\n";
    }
    return false;
  }

  // The mesh file is written on a second thread while the output is
  // measured (its staged temporary is committed only at the end).
  std::future<void> StartMeshWrite(const FaceValues& face_values) {
    if (!temporaries_.count("output.mesh")) return {};
    return std::async(std::launch::async, [this, &face_values] {
      const auto mesh_start = Clock::now();
      const bool shown = face_values.name != "none";  // else no colours, no face property
      const FaceColors colors = ColorsOf(face_values);
      const std::vector<PlyValues> properties = {{face_values.name, face_values.values}};
      const std::vector<PlyValues> vertex_values = DisplacementValues(output_, input_, local_.scale);
      Writing([&] {
        WriteMesh(temporaries_.at("output.mesh"), solution_->output, shown ? &colors : nullptr,
                  s_.Bool("output.ascii_ply"), shown ? &properties : nullptr, &vertex_values);
      });
      mesh_write_seconds_ = SecondsSince(mesh_start);
    });
  }

  // Whether `a` and `b` have the same points and faces (a problem that
  // optimises no position, e.g. wave_quads, gives back its input).
  static bool SameMesh(const Mesh& a, const Mesh& b) {
    if (a.number_of_vertices() != b.number_of_vertices() ||
        a.number_of_faces() != b.number_of_faces() || !a.is_valid(false) || !b.is_valid(false) ||
        a.has_garbage() || b.has_garbage()) {
      return false;
    }
    for (VertexIndex v : a.vertices()) {
      if (a.point(v) != b.point(v)) return false;
    }
    for (FaceIndex f : a.faces()) {
      auto ra = a.vertices_around_face(a.halfedge(f)), rb = b.vertices_around_face(b.halfedge(f));
      if (!std::equal(ra.begin(), ra.end(), rb.begin(), rb.end())) return false;
    }
    return true;
  }

  void MeasureOutput() {
    const auto metrics_start = Clock::now();
    const bool same_vertices = output_.number_of_vertices() == input_.number_of_vertices();
    // An output that is the input, with the input as its own reference, lies
    // on it: its distances are 0 and need not be measured (as before).
    const bool unchanged = !reference_mesh_ && !DesignReference() && SameMesh(output_, input_);
    after_ = ScaleLengths(ComputeMetrics(output_, unchanged ? nullptr : reference_.get(),
                                         same_vertices ? &input_ : nullptr),
                          local_.scale);
    if (unchanged) {
      after_.prox_max = after_.surface_distance_max = after_.surface_distance_mean = 0;
      after_.boundary_prox_max = before_.boundary_prox_max;
      after_.hausdorff = 0;
    }
    extra_after_ = Analyse(output_, d_.analyses, HNetOptionsOf(s_));
    ScaleLengths(extra_after_, local_.scale);
    run_.report["after"] = MetricsToJson(after_, scale_);
    AnalysisToJson(extra_after_, scale_, run_.report["after"]);
    seconds_["metrics_after"] = SecondsSince(metrics_start);
  }

  // tolerance.energy_not_above_input: the output's E at most the input's
  // (both measured on the meshes as written, at the input's scale). Only for
  // a net the user gave: a net archgeo laid out (conjugate_layout, relayout:
  // auto) is not the design whose fairness the bound keeps.
  void CheckEnergyNotAboveInput() {
    if (!s_.schema().Find("tolerance.energy_not_above_input") ||
        !s_.Bool("tolerance.energy_not_above_input") || solution_->net.derived) {
      return;
    }
    const double* before = RowValue(extra_before_, "E");
    const double* after = RowValue(extra_after_, "E");
    if (!before || !after) return;
    energy_checked_ = true;
    energy_input_ = *before;
    energy_output_ = *after;
    energy_met_ = *after <= *before;
    run_.report["tolerances"]["tolerance.energy_not_above_input"] = {{"bound", *before}, {"met", energy_met_}};
    if (!energy_met_) run_.exit_code = 4;
  }

  // The mean of the finite values (0 for none).
  static double Mean(const std::vector<double>& values) {
    double sum = 0;
    int n = 0;
    for (double x : values) {
      if (std::isfinite(x)) sum += x, ++n;
    }
    return n > 0 ? sum / n : 0.0;
  }

  // The per-face quantity the problem lowers, on the input or the output
  // (in the local frame), at the input's scale.
  FaceValues ColorValues(const Mesh& mesh, bool input) {
    const ProblemDecl::StateColors& own = d_.state_colors;
    if (!own.values) return ComputeFaceValues(d_.colors, mesh, &input_, &s_);
    HookContext& hooks = solution_->hooks;
    const std::vector<double> before = own.values(hooks, true);
    return StateFaceValues(own.name, own.label, own.units,
                           input ? before : own.values(hooks, false), before, &s_);
  }

  // The picture and the problem's own outputs (ProblemDecl::write).
  void WriteOtherOutputs(const FaceValues& face_values, const FaceValues& before) {
    if (temporaries_.count("output.image")) {
      const bool shown = face_values.name != "none";  // else grey faces
      std::vector<PicturePanel> panels = {
          PanelOf(input_, shown ? before.values : std::vector<double>{}, "input"),
          PanelOf(output_, shown ? face_values.values : std::vector<double>{}, "output")};
      Writing([&] {
        WriteView(temporaries_.at("output.image"), panels, ScaleOf(face_values), {},
                  "output.image");
      });
    }
    HookContext& hooks = solution_->hooks;
    for (const auto& [key, temporary] : temporaries_) {
      if (key != "output.mesh" && key != "output.report" && key != "output.image" &&
          !IsFabricationOutput(key)) {
        hooks.temporaries[key.substr(std::string("output.").size())] = temporary;
      }
    }
    if (d_.write && !hooks.temporaries.empty()) Writing([&] { d_.write(hooks); });
    Writing([&] {
      const nlohmann::json fabrication =
          WriteFabrication(solution_->output, s_, temporaries_, &fabrication_headline_);
      if (!fabrication.is_null()) run_.report["fabrication"] = fabrication;
    });
  }

  // The per-face value of the colours, the PLY properties and the picture;
  // the input gives the scale where the problem has no tolerance for it.
  void WriteAndMeasureOutput() {
    bool tolerances_met = true;
    for (const auto& [key, met] : solution_->loop.tolerances) tolerances_met &= met;
    const bool goal_met = solution_->hooks.missed.empty();  // the problem's own goal
    run_.exit_code = tolerances_met && design_band_met_ && goal_met ? 0 : 4;
    if (!goal_met) run_.report["missed"] = solution_->hooks.missed;
    const Mesh& output = solution_->output;
    const auto write_start = Clock::now();
    const FaceValues face_values = ColorValues(output_, false);
    std::future<void> mesh_written = StartMeshWrite(face_values);
    const double write_seconds = SecondsSince(write_start);
    MeasureOutput();

    const auto rest_start = Clock::now();
    nlohmann::json& rep = run_.report;
    CheckEnergyNotAboveInput();
    const FaceValues before = ColorValues(input_, true);
    rep["colors"] = {{"value", face_values.name},   {"label", face_values.label},
                     {"units", face_values.units},  {"red_at", face_values.red_at},
                     {"red_from", face_values.red_from},
                     {"mean_before", Mean(before.values)}, {"mean_after", Mean(face_values.values)}};
    if (s_.Bool("output.arrays")) {
      rep["arrays"] = ArraysJson(face_values, output_, input_, local_.scale);
    }
    WriteOtherOutputs(face_values, before);
    if (mesh_written.valid()) mesh_written.get();
    rep["details"] = solution_->hooks.details;
    const WorkingNet& net = solution_->net;
    if (!net.details.empty()) rep["details"]["net"] = net.details;  // a net the problem made
    seconds_["write"] = write_seconds + SecondsSince(rest_start);
    seconds_["write_mesh"] = mesh_write_seconds_;
    seconds_["total"] = SecondsSince(start_);
    for (const auto& [k, v] : solution_->loop.seconds) seconds_[k] = v;
    rep["seconds"] = seconds_;
    if (temporaries_.count("output.report")) {
      Writing([&] {
        WriteTextFile(temporaries_.at("output.report"), rep.dump(2) + "\n", "output.report");
      });
    }
    run_.stopped = solution_->loop.stopped;
    if (!run_.stopped) staged_.Commit();  // else the temporaries go with staged_
    if (meshes_.output) *meshes_.output = output;
  }

  // How LeanSolve solved the rounds it solved, e.g. " (5 rounds by PCG, 23
  // CG steps)"; "" when Ceres solved them all.
  static std::string SolverNote(const LoopResult& solved) {
    std::string note;
    if (solved.cholesky_rounds > 0) {
      note = std::to_string(solved.cholesky_rounds) + " rounds by LeanSolve's Cholesky";
    }
    if (solved.pcg_rounds > 0) {
      note += (note.empty() ? "" : ", ") + std::to_string(solved.pcg_rounds) + " rounds by PCG, " +
              std::to_string(solved.cg_iterations) + " CG steps";
    }
    return note.empty() ? "" : " (" + note + ")";
  }

  std::string Summary() const {
    const LoopResult& solved = solution_->loop;
    char head[512];
    std::snprintf(head, sizeof head,
                  "%s: %d variables, %d residuals, %d rounds / %d iterations%s, %.2f s (solve "
                  "%.2f s); stop: %s\n",
                  d_.name.c_str(), solved.variables, solved.residuals, solved.rounds,
                  solved.iterations,
                  SolverNote(solved).c_str(),
                  SecondsSince(start_), solve_seconds_, solved.stop.c_str());
    char objective[128];
    std::snprintf(objective, sizeof objective, "objective (canonical frame): %.6e\n",
                  solved.objective.count("total") ? solved.objective.at("total") : 0.0);
    // Without a solve (remesh, subdivide, extract: the net made is the
    // result) "before" would repeat "after": one column.
    const bool solved_any = solved.variables > 0;
    return head + solution_->net.headline + ToleranceLines() + ValidityLines() +
           fabrication_headline_ +
           solution_->headline + MeasureHeadline(solved) + objective +
           (solved_any ? FormatMetrics(before_, &after_, scale_)
                       : FormatMetrics(after_, nullptr, scale_)) +
           (solved_any ? FormatAnalysis(extra_before_, &extra_after_, scale_)
                       : FormatAnalysis(extra_after_, nullptr, scale_));
  }

  // Hard-check defects the input had too (accepted or not).
  int Inherited() const {
    int n = 0;
    for (const ValidityCheck& c : validity_.checks) n += c.hard ? c.inherited : 0;
    return n;
  }

  std::string ToleranceLines() const {
    std::string lines;
    for (const auto& [key, met] : solution_->loop.tolerances) {
      char line[200];
      std::snprintf(line, sizeof line, "tolerance %s <= %g: %s\n", key.c_str(), s_.Number(key),
                    s_.Number(key) <= 0 ? "off" : met ? "met" : "NOT met");
      lines += line;
    }
    if (energy_checked_) {
      char line[200];
      std::snprintf(line, sizeof line,
                    "tolerance tolerance.energy_not_above_input: E %.6g <= %.6g (the input's): %s\n",
                    energy_output_, energy_input_, energy_met_ ? "met" : "NOT met");
      lines += line;
    }
    return lines;
  }

  // The output as `archgeo measure OUTPUT --reference DESIGN` judges it, and
  // its distance from the design surface (a net the problem made).
  std::string DesignLine() const {
    char line[400];
    std::snprintf(line, sizeof line,
                  "validity against the design surface (as archgeo measure OUTPUT --reference "
                  "DESIGN checks it): %s; vertices at most %.4g file units (%.3g%% of the "
                  "diagonal) from it",
                  design_.valid() ? "every hard check passed" : "NOT valid",
                  design_distance_, 100 * design_distance_ / scale_);
    std::string text = line;
    if (design_band_ > 0) {
      std::snprintf(line, sizeof line, ", band %.4g: %s", design_band_,
                    design_band_met_ ? "within" : "BEYOND");
      text += line;
    }
    return text + "\n";
  }

  std::string ValidityLines() const {
    const LoopResult& solved = solution_->loop;
    const std::string warnings = validity_.Warnings();
    std::string lines;
    if (!validity_.valid() && !MadeNet()) {
      lines = "validity: NOT valid (exit 5): panels that cannot be built, as they were in the "
              "input (the result is written for you to repair them; "
              "validity.allow_input_defects: true accepts them):\n" +
              validity_.Reason() + (warnings.empty() ? "" : "warnings:\n" + warnings);
    } else if (!validity_.valid() || !design_.valid()) {
      // Not the user's input: allow_input_defects does not accept them.
      lines = "validity: NOT valid (exit 5): panels that cannot be built, as they were in the "
              "net this problem made from the design surface (the result is written for you "
              "to repair them; the report's validity and validity.design_surface name them):\n" +
              (design_.valid() ? validity_.Reason() : design_.Reason()) +
              (warnings.empty() ? "" : "warnings:\n" + warnings);
    } else {
      const std::string what = MadeNet() ? "validity against the net solved (the layout)" : "validity";
      lines = warnings.empty() ? what + ": every check passed\n"
                               : what + ": valid; warnings:\n" + warnings;
      if (validity_.allow_input_defects && Inherited() > 0) {
        lines += "validity.allow_input_defects: " + std::to_string(Inherited()) +
                 " defects as in the input were accepted\n";
      }
    }
    if (MadeNet()) lines += DesignLine();
    if (info_.welded_vertices > 0) {
      lines += "WARNING: the input had coincident vertices: " +
               std::to_string(info_.welded_vertices) +
               " were welded on reading (limits.weld_distance; the report's input section)\n";
    }
    if (!solution_->hooks.missed.empty()) {
      lines += std::string("WARNING: the problem's goal was missed") +
               (run_.exit_code == 4 ? " (exit 4)" : "") + ": " + solution_->hooks.missed + "\n";
    }
    if (!design_band_met_) {
      char line[240];
      std::snprintf(line, sizeof line,
                    "WARNING: the result leaves the deviation band around the design surface"
                    "%s: %.4g > %.4g file units (the loop keeps the band around the net "
                    "it solved)\n",
                    run_.exit_code == 4 ? " (exit 4)" : "", design_distance_, design_band_);
      lines += line;
    }
    if (solved.restored_valid) {
      lines += "the last round was not valid: the output is round " +
               std::to_string(solved.output_round) + ", the last valid one\n";
    }
    bool tolerance_missed = false;
    for (const auto& [key, met] : solved.tolerances) tolerance_missed |= !met;
    tolerance_missed |= !energy_met_;
    if (run_.exit_code == 4 && tolerance_missed) {
      lines += "WARNING: a tolerance was not met (exit 4): the result is valid and written\n";
    }
    if (!ZeroedTerm().empty()) {
      lines += "WARNING: ARCHGEO_ZERO_TERM=" + ZeroedTerm() +
               ": that term's residuals were zeroed (mutation testing)\n";
    }
    return lines;
  }

  const Clock::time_point start_ = Clock::now();
  const ProblemSpec& spec_;
  const Settings& s_;
  const ProblemDecl& d_;
  const ProgressSink& progress_;
  const MeshInputs& meshes_;
  const std::atomic<bool>* stop_;
  StagedOutputs staged_{Inputs(spec_)};
  std::map<std::string, std::string> temporaries_;  // output key -> staged file
  ReadInfo info_;
  Mesh read_;
  std::unique_ptr<Mesh> reference_mesh_;
  SolveSession* session_;
  std::unique_ptr<Solution> owned_;  // Solve's (no session)
  Solution* solution_ = nullptr;
  Similarity local_;    // the frame input_ and output_ are measured in
  Mesh input_, output_;  // the solution's input and output in local_
  std::future<Validity> validity_check_;
  Validity validity_;
  std::future<MeasuredValidity> design_check_;  // as measured, for a net the problem made
  Validity design_;                     // valid when not checked
  bool design_band_met_ = true;
  bool energy_checked_ = false, energy_met_ = true;  // tolerance.energy_not_above_input
  double energy_input_ = 0, energy_output_ = 0;
  double design_distance_ = 0, design_band_ = 0;  // file units
  std::unique_ptr<ReferenceSurface> reference_;
  Metrics before_, after_;
  AnalysisRows extra_before_, extra_after_;
  double scale_ = 0;
  double solve_seconds_ = 0;
  double mesh_write_seconds_ = 0;
  std::string fabrication_headline_;  // output.cutting's warning, if any
  nlohmann::json seconds_ = nlohmann::json::object();
  RunResult run_;
};

}  // namespace

RunResult RunSpec(const ProblemSpec& spec, const ProgressSink& progress) {
  return RunSpec(spec, progress, MeshInputs{});
}

RunResult RunSpec(const ProblemSpec& spec, const ProgressSink& progress, const MeshInputs& meshes,
                  const std::atomic<bool>* stop) {
  ConfigureThreading();
  CHECK(spec.declaration) << "RunSpec: the spec has no problem (use ReadSpec)";
  SolverOptions(spec.settings);  // a combination Ceres rejects fails before any work
  return SpecRun(spec, progress, meshes, stop).Run();
}

RunResult RunSession(SolveSession& session, const ProgressSink& progress,
                     const std::atomic<bool>* stop) {
  ConfigureThreading();
  RunResult run;
  try {
    run = SpecRun(session.spec(), progress, MeshInputs{}, stop, &session).Run();
  } catch (...) {
    if (session.solved()) session.Keep(false);
    throw;
  }
  session.Keep(run.exit_code == 0 || run.exit_code == 4 || run.exit_code == 5);
  return run;
}

RunResult MeasureFiles(const std::string& mesh_path, const std::string& reference_path,
                       bool all, bool arrays) {
  // Measured in the mesh's local frame (mesh/similarity.h LocalFrame), the
  // reference in the same frame; lengths reported in file units.
  const Mesh read = ReadMesh(mesh_path);
  const Similarity local = LocalFrame(read);
  const Mesh mesh = InFrame(local, read);
  std::optional<Mesh> reference_read, input;  // the reference as read, and in the mesh's frame
  if (!reference_path.empty()) {
    reference_read = ReadMesh(reference_path);
    input = InFrame(local, *reference_read);
  }
  RunResult run;
  Metrics metrics;
  if (!input) {
    metrics = ComputeMetrics(mesh, nullptr, nullptr);
  } else {
    const ReferenceSurface reference(*input);
    const bool same = input->number_of_vertices() == mesh.number_of_vertices();
    metrics = ComputeMetrics(mesh, &reference, same ? &*input : nullptr);
  }
  metrics = ScaleLengths(metrics, local.scale);
  AnalysisRows analysis = Analyse(mesh, ApplicableAnalyses(mesh));
  ScaleLengths(analysis, local.scale);
  // The validity checks of `archgeo solve` (default limits): against the
  // reference when it has the mesh's topology (an output and its input),
  // else those of the mesh alone (panels, short edges, self-intersections).
  std::string validity_text;
  nlohmann::json validity_json;
  {
    const MeasuredValidity measured = ValidityAsMeasured(
        read, reference_read ? &*reference_read : nullptr, ValidityLimits{});
    const bool paired = measured.paired;
    const Validity& v = measured.validity;
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
  // Relative figures: to the reference's diagonal when there is one (the
  // design's, as `solve` gives them for an output and its input), else to
  // the mesh's own.
  const double diagonal = reference_read ? PrincipalBoxDiagonal(*reference_read) : metrics.bbox_diagonal;
  run.report = {{"schema_version", kReportSchemaVersion},
                {"archgeo", "measure"},
                {"mesh", mesh_path},
                {"reference", reference_path},
                {"units", {{"lengths", "file units"},
                           {"relative", reference_read
                                            ? "file units / bounding-box diagonal of the reference"
                                            : "file units / bounding-box diagonal of the mesh"},
                           {"bbox_diagonal", diagonal},
                           {"angles", "degrees"}}},
                {"metrics", MetricsToJson(metrics, diagonal)}};
  AnalysisToJson(analysis, diagonal, run.report["metrics"]);
  if (!validity_json.is_null()) run.report["validity"] = validity_json;
  if (arrays) {
    nlohmann::json& a = run.report["arrays"] = {{"face", nlohmann::json::object()},
                                                {"vertex", nlohmann::json::object()}};
    PlanarityArrays(mesh, local.scale, a["face"]);
    if (input) DisplacementArray(mesh, *input, local.scale, a["vertex"]);
  }
  run.summary = FormatMetrics(metrics, nullptr, diagonal) +
                FormatAnalysis(all ? analysis : RowsThatApply(mesh, analysis), nullptr, diagonal) +
                validity_text;
  return run;
}

}  // namespace archgeo
