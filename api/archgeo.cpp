// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the public API (api/archgeo/archgeo.h) over problems/ and mesh/.
#include "archgeo/archgeo.h"

#include <glog/logging.h>
#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>

#include "core/input_error.h"
#include "io/io.h"
#include "problems/commands/generate.h"
#include "problems/declarations/custom.h"
#include "problems/declarations/registry.h"
#include "problems/commands/run.h"
#include "problems/runtime/mesh_inputs.h"
#include "problems/runtime/session.h"
#include "problems/spec/schema.h"
#include "problems/spec/spec.h"

namespace archgeo {
namespace {

namespace fs = std::filesystem;

// InputError → Error with the same message the CLI prints.
template <typename F>
auto Translated(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const InputError& e) {
    throw Error(e.what(), e.file(), e.line(), e.key());
  }
}

// Where line `line` of ToMesh's OFF text is in `data`: "vertex i" or "face j".
std::string RowOf(const MeshData& data, int line) {
  const long row = long(line) - 3;  // line 1: OFF, line 2: the counts
  if (row < 0) return "";
  const long vertices = long(data.vertices.size());
  return row < vertices ? "vertex " + std::to_string(row) : "face " + std::to_string(row - vertices);
}

Mesh ToMesh(const MeshData& data, const std::string& name) {
  // Through the readers' own checks (indices, degenerate faces, manifold,
  // orientation): an OFF text in memory. Its errors name `name` and the
  // vertex or face, not the text's lines.
  std::string off = "OFF\n" + std::to_string(data.vertices.size()) + " " +
                    std::to_string(data.faces.size()) + " 0\n";
  char buf[96];
  for (const auto& p : data.vertices) {
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
    off += buf;
  }
  for (const auto& f : data.faces) {
    off += std::to_string(f.size());
    for (int v : f) off += " " + std::to_string(v);
    off += "\n";
  }
  try {
    return ReadMeshFromMemory(name + ".off", off);
  } catch (const InputError& e) {
    if (e.file() != name + ".off") throw;
    const std::string row = RowOf(data, e.line());
    throw InputError(name, 0, e.key(), (row.empty() ? "" : row + ": ") + e.message());
  }
}

MeshData ToData(const Mesh& mesh) {
  MeshData data;
  std::vector<int> index(mesh.num_vertices(), -1);
  for (VertexIndex v : mesh.vertices()) {
    index[v.idx()] = int(data.vertices.size());
    const Point& p = mesh.point(v);
    data.vertices.push_back({p.x(), p.y(), p.z()});
  }
  for (FaceIndex f : mesh.faces()) {
    auto& face = data.faces.emplace_back();
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      face.push_back(index[v.idx()]);
    }
  }
  return data;
}

void QuietLogging() {
  static bool done = false;
  if (done) return;
  done = true;
  if (!google::IsGoogleLoggingInitialized()) google::InitGoogleLogging("archgeo");
  FLAGS_minloglevel = google::GLOG_ERROR;
  FLAGS_logtostderr = true;
}

// The engine's progress events as the API's.
ProgressSink SinkOf(const SolveControl& control) {
  if (!control.progress) return {};
  return [progress = control.progress](const ProgressEvent& e) {
    SolveProgress p;
    p.kind = e.kind == ProgressEvent::Kind::kIteration ? "iteration"
             : e.kind == ProgressEvent::Kind::kRound   ? "round"
                                                       : "note";
    p.line = e.line;
    p.stage = e.stage;
    p.round = e.round;
    p.stage_round = e.stage_round;
    p.stage_rounds = e.stage_rounds;
    p.iteration = e.iteration;
    p.measure = e.measure;
    p.value = e.value;
    p.target = e.target;
    p.elapsed = e.elapsed;
    progress(p);
  };
}

SolveResult FromRun(const RunResult& run, const Mesh& output) {
  SolveResult r;
  r.status = run.exit_code;
  if (run.exit_code == 0 || run.exit_code == 4 || run.exit_code == 5) r.mesh = ToData(output);
  r.report = run.report.dump(2);
  r.summary = run.summary;
  r.stopped = run.stopped;
  return r;
}

}  // namespace

SolveResult Solve(const std::string& spec_yaml, const MeshData& mesh, const MeshData* reference,
                  const std::vector<std::string>& overrides, const std::string& spec_name,
                  const SolveControl& control) {
  QuietLogging();
  return Translated([&] {
    const ProblemSpec spec = ParseSpec(spec_yaml, spec_name, overrides);
    // No mesh: a problem that makes its own (grid), or the spec's `mesh` file.
    const bool none = mesh.vertices.empty() && mesh.faces.empty();
    const Mesh input = none ? Mesh() : ToMesh(mesh, "<mesh>");
    std::unique_ptr<Mesh> ref;
    if (reference) ref = std::make_unique<Mesh>(ToMesh(*reference, "<reference>"));
    Mesh output;
    const RunResult run =
        RunSpec(spec, SinkOf(control), MeshInputs{none ? nullptr : &input, ref.get(), &output}, control.stop);
    return FromRun(run, output);
  });
}

SolveResult SolveFile(const std::string& spec_path, const std::vector<std::string>& overrides,
                      const SolveControl& control) {
  QuietLogging();
  return Translated([&] {
    const ProblemSpec spec = ReadSpec(spec_path, overrides);
    Mesh output;
    const RunResult run =
        RunSpec(spec, SinkOf(control), MeshInputs{nullptr, nullptr, &output}, control.stop);
    return FromRun(run, output);
  });
}

struct Session::Impl {
  std::unique_ptr<SolveSession> session;
};

Session::Session(const std::string& spec_yaml, const MeshData& mesh, const MeshData* reference,
                 const std::vector<std::string>& overrides, const std::string& spec_name) {
  QuietLogging();
  Translated([&] {
    ProblemSpec spec = ParseSpec(spec_yaml, spec_name, overrides);
    std::unique_ptr<archgeo::Mesh> ref;
    if (reference) ref = std::make_unique<archgeo::Mesh>(ToMesh(*reference, "<reference>"));
    // No mesh: the spec's `mesh` file.
    const bool none = mesh.vertices.empty() && mesh.faces.empty();
    archgeo::Mesh input = none ? ReadMesh(spec.mesh()) : ToMesh(mesh, "<mesh>");
    impl_ = std::make_unique<Impl>();
    impl_->session =
        std::make_unique<SolveSession>(std::move(spec), std::move(input), std::move(ref));
  });
}

Session::~Session() = default;
Session::Session(Session&&) noexcept = default;
Session& Session::operator=(Session&&) noexcept = default;

SolveResult Session::Solve(const SolveControl& control) {
  return Translated([&] {
    SolveSession& session = *impl_->session;
    const RunResult run = RunSession(session, SinkOf(control), control.stop);
    return FromRun(run, session.start());  // a result written is the next start
  });
}

void Session::MoveVertices(const std::vector<int>& ids,
                           const std::vector<std::array<double, 3>>& positions) {
  if (ids.size() != positions.size()) {
    throw std::invalid_argument("Session::MoveVertices: " + std::to_string(ids.size()) +
                                " vertex ids for " + std::to_string(positions.size()) +
                                " positions");
  }
  Translated([&] {
    const std::vector<long long> vertices(ids.begin(), ids.end());
    const std::vector<Vec3> points(positions.begin(), positions.end());
    impl_->session->Move(vertices, points);
  });
}

void Session::SetWeight(const std::string& term, double weight) {
  Translated([&] { impl_->session->SetWeight(term, weight); });
}

double Session::Weight(const std::string& term) const {
  return Translated([&] { return impl_->session->Weight(term); });
}

MeshData Session::Current() const { return ToData(impl_->session->start()); }

std::string Measure(const MeshData& mesh, const MeshData* reference, bool arrays) {
  QuietLogging();
  return Translated([&] {
    // MeasureFiles reads files: the meshes go through a private folder.
    const fs::path dir = fs::temp_directory_path() /
                         ("archgeo_measure_" + std::to_string(getpid()) + "_" +
                          std::to_string(reinterpret_cast<std::uintptr_t>(&mesh)));
    fs::create_directories(dir);
    struct Cleanup {
      fs::path dir;
      ~Cleanup() {
        std::error_code ignored;
        fs::remove_all(dir, ignored);
      }
    } cleanup{dir};
    const std::string mesh_path = (dir / "mesh.off").string();
    WriteMesh(mesh_path, ToMesh(mesh, "<mesh>"));
    std::string reference_path;
    if (reference) {
      reference_path = (dir / "reference.off").string();
      WriteMesh(reference_path, ToMesh(*reference, "<reference>"));
    }
    nlohmann::json report = MeasureFiles(mesh_path, reference_path, false, arrays).report;
    report["mesh"] = "<memory>";
    report["reference"] = reference ? "<memory>" : "";
    return report.dump(2);
  });
}

MeshData Generate(const SurfaceOptions& o) {
  QuietLogging();
  return Translated([&] {
    const fs::path dir = fs::temp_directory_path() /
                         ("archgeo_generate_" + std::to_string(getpid()) + "_" +
                          std::to_string(reinterpret_cast<std::uintptr_t>(&o)));
    fs::create_directories(dir);
    struct Cleanup {
      fs::path dir;
      ~Cleanup() {
        std::error_code ignored;
        fs::remove_all(dir, ignored);
      }
    } cleanup{dir};
    archgeo::GenerateOptions g;
    g.surface = o.surface;
    g.nu = o.nu;
    g.nv = o.nv;
    if (o.noise >= 0) g.noise = o.noise;
    g.scale = o.scale;
    g.seed = o.seed;
    g.refinement = o.refinement;
    const std::string path = (dir / "generated.off").string();
    GenerateSurface(path, g);
    return ToData(ReadMesh(path));
  });
}

MeshData ReadMeshFile(const std::string& path) {
  QuietLogging();
  return Translated([&] { return ToData(ReadMesh(path)); });
}

namespace {

// `named` as PLY properties of `count` elements (faces or vertices).
std::vector<PlyValues> PlyValuesOf(const std::vector<NamedValues>& named, size_t count,
                                   const std::string& path, const char* what) {
  std::vector<PlyValues> values;
  for (const NamedValues& n : named) {
    if (n.values.size() != count) {
      throw InputError(path, 0, n.name,
                       std::to_string(n.values.size()) + " values for " +
                           std::to_string(count) + " " + what);
    }
    values.push_back({n.name, n.values});
  }
  return values;
}

}  // namespace

void WriteMeshFile(const std::string& path, const MeshData& mesh,
                   const std::vector<NamedValues>& face_values,
                   const std::vector<NamedValues>& vertex_values) {
  QuietLogging();
  Translated([&] {
    CheckMeshExtension(path);
    std::string extension = fs::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if ((!face_values.empty() || !vertex_values.empty()) && extension != ".ply") {
      throw InputError(path, 0, "", "per-face and per-vertex values are written to .ply only");
    }
    const Mesh m = ToMesh(mesh, "<mesh>");
    const std::vector<PlyValues> faces = PlyValuesOf(face_values, mesh.faces.size(), path, "faces");
    const std::vector<PlyValues> vertices =
        PlyValuesOf(vertex_values, mesh.vertices.size(), path, "vertices");
    WriteMesh(path, m, nullptr, false, faces.empty() ? nullptr : &faces,
              vertices.empty() ? nullptr : &vertices);
  });
}

std::vector<std::string> Problems() { return ProblemNames(); }

std::string ProblemKeys(const std::string& problem) {
  // custom: the keys of `archgeo spec custom` (the example composition's terms).
  const ProblemDecl custom = problem == "custom" ? CustomExample() : ProblemDecl();
  const ProblemDecl* d = problem == "custom" ? &custom : FindProblem(problem);
  if (!d) throw Error("'" + problem + "' is not a problem", "", 0, "problem");
  nlohmann::json keys = nlohmann::json::array();
  const Schema schema = ProblemSchema(*d);  // alive while its keys are read
  for (const Key& k : schema.keys()) {
    keys.push_back({{"name", k.name}, {"default", ToJson(k.fallback)}, {"doc", k.doc}});
  }
  return keys.dump(2);
}

std::string Version() { return ARCHGEO_VERSION; }

}  // namespace archgeo
