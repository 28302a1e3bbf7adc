// archgeo — the interface every problem builder implements.
//
// `archgeo solve` is the same for every problem (problems/run.cpp): stage the
// outputs, read the mesh and the reference, measure, move to the canonical
// frame (mesh/similarity.h), solve, measure again, write. A builder supplies
// the parts that differ: its own spec keys (terms and options), the check that
// the input suits it, the optimisation itself, and any extra output files.
// Builders know nothing of file formats: they get meshes and paths to write.
//
// To add a problem: implement Builder in problems/<name>.cpp, declare its
// factory in problems/builders.h and add it to the table in builders.cpp.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include "mesh/similarity.h"
#include "mesh/surface_mesh.h"
#include "problems/progress.h"
#include "problems/solve_outcome.h"
#include "problems/solver_options.h"
#include "problems/spec_reader.h"

namespace archgeo {

class ReferenceSurface;

// What a builder's Solve gets besides the mesh.
struct SolveContext {
  const Mesh* input = nullptr;                  // the net as read (file units, see Net)
  Similarity frame;                             // file units -> the canonical frame solved in
  const ReferenceSurface* reference = nullptr;  // in the canonical frame of the mesh
  std::vector<bool> fixed;                      // per vertex index: hard-fixed
  SolverSettings solver;
  ProgressSink progress;  // may be empty
};

using FaceColors = std::vector<std::array<unsigned char, 3>>;

// The net a builder optimises when that is not the input mesh itself (hnet:
// a diagonal net of the input, mesh/diagonal_net.h). The run then measures,
// solves and writes this net; displacements are measured from its vertices'
// input positions, and without a `reference` the net (as derived) is its own
// reference surface, as the input is otherwise (its boundary is the one the
// boundary terms keep).
struct WorkingNet {
  bool derived = false;      // false: the builder works on the input itself
  Mesh mesh;                 // the net, in file units (when derived)
  std::vector<int> source;   // per net vertex: its input vertex index (when derived)
  nlohmann::json details = nlohmann::json::object();  // the report's "net" entry (if not empty)
  std::string headline;      // for the terminal ("" or lines ending in '\n')
};

class Builder {
 public:
  virtual ~Builder() = default;

  // Top-level spec keys this builder reads besides the common ones (mesh,
  // reference, problem, fixed, solver, output, multiresolution).
  virtual std::set<std::string> Keys() const = 0;
  // Extra `output.<key>: PATH` entries this builder writes.
  virtual std::set<std::string> OutputKeys() const { return {}; }
  // Files the builder reads besides the mesh and the reference (after Read):
  // no output may name them.
  virtual std::vector<std::string> InputFiles() const { return {}; }
  // Reads the builder's keys from the spec's root mapping (all optional;
  // absent keys keep the documented defaults). Throws InputError.
  virtual void Read(const SpecReader& reader, const YAML::Node& root) = 0;
  // The settings in effect, for the report.
  virtual nlohmann::json SettingsJson() const = 0;
  // Throws InputError(path, 0, "mesh", ...) if the builder cannot work on `input`.
  virtual void CheckInput(const Mesh& input, const std::string& path) const = 0;
  // The net to optimise, from the input read from `path` (after CheckInput).
  // Throws InputError. Default: the input itself.
  virtual WorkingNet Net(const Mesh& input, const std::string& path) const { return {}; }
  // Optimises `mesh` in place; `mesh` is in the canonical frame (unit mean
  // edge length) and may carry nothing but positions.
  virtual SolveOutcome Solve(Mesh& mesh, const SolveContext& context) const = 0;
  // Analyses the report shows before and after (see problems/analysis.h):
  // "planarity" (always), "smoothness", "hnet".
  virtual std::set<std::string> Analyses() const { return {}; }
  // Per-face colours of the output mesh (PLY); empty: the planarity colours.
  virtual FaceColors Colors(const Mesh& output, double color_max) const { return {}; }
  // Writes the extra outputs: `temporary` maps each OutputKeys() entry the
  // spec set to the staged file to write (committed by the caller). `output`
  // is in file units. May add entries to `report`.
  virtual void WriteOutputs(const Mesh& output, const std::map<std::string, std::string>& temporary,
                            nlohmann::json& report) const {}
};

}  // namespace archgeo
