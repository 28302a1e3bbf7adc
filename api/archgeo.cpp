// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the public API (api/archgeo/archgeo.h) over problems/ and mesh/.
#include "archgeo/archgeo.h"

#include <glog/logging.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>

#include "core/input_error.h"
#include "io/io.h"
#include "problems/commands/generate.h"
#include "problems/declarations/registry.h"
#include "problems/commands/run.h"
#include "problems/runtime/mesh_inputs.h"
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

Mesh ToMesh(const MeshData& data, const std::string& name) {
  // Through the readers' own checks (indices, degenerate faces, manifold,
  // orientation): an OFF text in memory.
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
  return ReadMeshFromMemory(name + ".off", off);
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

SolveResult FromRun(const RunResult& run, const Mesh& output) {
  SolveResult r;
  r.status = run.exit_code;
  if (run.exit_code == 0 || run.exit_code == 4 || run.exit_code == 5) r.mesh = ToData(output);
  r.report = run.report.dump(2);
  r.summary = run.summary;
  return r;
}

}  // namespace

SolveResult Solve(const std::string& spec_yaml, const MeshData& mesh, const MeshData* reference,
                  const std::vector<std::string>& overrides, const std::string& spec_name) {
  QuietLogging();
  return Translated([&] {
    const ProblemSpec spec = ParseSpec(spec_yaml, spec_name, overrides);
    const Mesh input = ToMesh(mesh, "<mesh>");
    std::unique_ptr<Mesh> ref;
    if (reference) ref = std::make_unique<Mesh>(ToMesh(*reference, "<reference>"));
    Mesh output;
    const RunResult run = RunSpec(spec, nullptr, MeshInputs{&input, ref.get(), &output});
    return FromRun(run, output);
  });
}

SolveResult SolveFile(const std::string& spec_path, const std::vector<std::string>& overrides) {
  QuietLogging();
  return Translated([&] {
    const ProblemSpec spec = ReadSpec(spec_path, overrides);
    Mesh output;
    const RunResult run = RunSpec(spec, nullptr, MeshInputs{nullptr, nullptr, &output});
    return FromRun(run, output);
  });
}

std::string Measure(const MeshData& mesh, const MeshData* reference) {
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
    nlohmann::json report = MeasureFiles(mesh_path, reference_path).report;
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
    g.noise = o.noise;
    g.scale = o.scale;
    g.seed = o.seed;
    g.refinement = o.refinement;
    const std::string path = (dir / "generated.off").string();
    GenerateSurface(path, g);
    return ToData(ReadMesh(path));
  });
}

std::vector<std::string> Problems() { return ProblemNames(); }

std::string ProblemKeys(const std::string& problem) {
  const ProblemDecl* d = FindProblem(problem);
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
