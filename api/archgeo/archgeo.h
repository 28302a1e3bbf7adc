// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the public C++ API (installed as <archgeo/archgeo.h>, target
// archgeo::archgeo). No CGAL, Ceres or YAML in this header: meshes are plain
// arrays in file units (any unit: the library moves them into its canonical
// frame — centred, principal axes, mean edge length 1 — and back itself);
// specs are YAML text with the keys of `archgeo spec PROBLEM`.
//
//   archgeo::MeshData roof = archgeo::Generate({"roof", 20, 15});
//   archgeo::SolveResult r = archgeo::Solve("problem: planar_quads\n", roof);
//   // r.mesh: the optimised vertices (same order and faces), r.report: JSON
//
// Errors in the user's input (a spec key, a mesh) throw archgeo::Error with
// exactly the message the command-line tool prints after "archgeo: error: ".
#pragma once

#include <array>
#include <atomic>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace archgeo {

// A polygon mesh: vertex positions and faces as 0-based vertex indices
// (counter-clockwise seen from outside; 3 or more vertices each).
struct MeshData {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::vector<int>> faces;
};

// An input error (file, line and key as far as known; what() = the message).
class Error : public std::runtime_error {
 public:
  Error(const std::string& message, std::string file, int line, std::string key)
      : std::runtime_error(message), file_(std::move(file)), line_(line), key_(std::move(key)) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& key() const { return key_; }

 private:
  std::string file_;
  int line_;
  std::string key_;
};

struct SolveResult {
  // 0: valid, every tolerance met; 4: valid, a tolerance missed; 5: written,
  // with panels that cannot be built as in the input; 3: no usable or valid
  // result (`mesh` is then empty). As the CLI's exit codes.
  int status = 0;
  MeshData mesh;        // the result in file units (same vertex order and faces)
  std::string report;   // the JSON report (docs/report.schema.json)
  std::string summary;  // the text the CLI prints
  bool stopped = false;  // SolveControl::stop ended the solve (the spec's outputs not written)
};

// One progress event of a solve: a note (a stage's line), a solver
// iteration or the end of a round.
struct SolveProgress {
  std::string kind;         // "note", "iteration" or "round"
  std::string line;         // the log line (`archgeo solve --log`; no newline)
  std::string stage;        // the stage's name ("" for a problem's main stage)
  int round = 0;            // rounds so far over the run (this one included)
  int stage_round = 0;      // k of the stage's rounds (1-based)
  int stage_rounds = 0;     // the stage's most rounds (0: not known)
  int iteration = -1;       // the solver iteration within the round ("iteration" only)
  std::string measure;      // the stage's goal tolerance, e.g. "pq_normalized_max" ("": none)
  double value = std::numeric_limits<double>::quiet_NaN();   // its value at this event
  double target = std::numeric_limits<double>::quiet_NaN();  // the tolerance it must reach
  double elapsed = 0;       // seconds since the solve loop began
};

// How a caller follows and stops a solve.
struct SolveControl {
  // Called with each progress event on the thread that called Solve.
  // Empty: none.
  std::function<void(const SolveProgress& event)> progress;
  // When it turns true (from any thread, a signal handler or `progress`),
  // the solve ends after the current solver iteration: no further round,
  // stage or multiresolution level runs, the result is the last valid state
  // (measured and reported as usual, report "stop": "stopped by request",
  // SolveResult::stopped), and the spec's output files are not written.
  // Null: never stops.
  const std::atomic<bool>* stop = nullptr;
};

// Solves the problem of the YAML spec `spec_yaml` on `mesh` (its `mesh` key
// may be omitted). `reference`: the surface to stay close to (null: the mesh
// itself). `overrides`: "dotted.key=value" as `archgeo solve --set`. Output
// keys in the spec (output.mesh, output.report, ...) are written as by the
// CLI, relative to the current folder. Throws Error.
// `spec_name` names the spec in messages and anchors its relative paths
// (e.g. the path of the YAML file the text came from).
// An empty `mesh` (no vertices, no faces): the spec's `mesh` file, or none
// for a problem that makes its own (grid). Errors in `mesh` or `reference` name them "<mesh>" / "<reference>" and the
// vertex or face (e.g. "<mesh>: face 12: ..."), not a file.
SolveResult Solve(const std::string& spec_yaml, const MeshData& mesh,
                  const MeshData* reference = nullptr,
                  const std::vector<std::string>& overrides = {},
                  const std::string& spec_name = "<spec>", const SolveControl& control = {});

// A problem kept for solving again, for interaction: drag a few vertices or
// change a term weight, solve to tolerance from the last solution.
//
//   archgeo::Session session("problem: planar_quads\nfixed: boundary\n", mesh);
//   archgeo::SolveResult r = session.Solve();          // as Solve
//   session.MoveVertices({17}, {{1.0, 2.0, 0.3}});      // a boundary vertex, file units
//   r = session.Solve();                               // from the last solution
//
// The first Solve is Solve(spec_yaml, mesh, reference, overrides, spec_name).
// After it the session keeps the problem: the spec, the mesh's variables and
// element sets, the reference surface (`reference`, else `mesh` itself), and
// the pattern of the normal equations with its sparse Cholesky analysis; a
// later Solve reads and builds none of them again and, while the same
// vertices are fixed and the same terms on, analyses no new structure. Each
// later Solve starts from the last result written (status 0, 4 or 5; after a
// status 3 from where that solve started) with the vertices moved since,
// and is the solve of that mesh against the session's reference: the same
// terms (anchor and fairness relative to that start), schedule, tolerance
// stops, validity checks, SolveResult, report and the spec's outputs as
// Solve(spec_yaml, start, reference or mesh) with two settings where the
// last solve left them (the report's settings give both): `continuation.start`,
// the weight scale it ended with (planar_quads, custom: the planarity
// weights and barriers start where they made the last result planar,
// instead of growing from 1 again over several rounds), and
// `solver.initial_trust_region_radius`, Levenberg–Marquardt's trust region
// at the end of its last round (LeanSolve's: no steps rejected again to find
// its size). Only its frame (the canonical frame of the first mesh,
// mesh/similarity.h) is the session's.
// A session takes a problem that solves the mesh it is given (not hnet's
// derived net, relayout: auto or a problem that makes its own net) without
// multiresolution; others throw Error. Not thread-safe: one call at a time.
class Session {
 public:
  // Parses and checks the spec and the meshes as Solve does (throws Error);
  // solves nothing yet. An empty `mesh`: the spec's `mesh` file (read with
  // the readers' default limits).
  Session(const std::string& spec_yaml, const MeshData& mesh, const MeshData* reference = nullptr,
          const std::vector<std::string>& overrides = {},
          const std::string& spec_name = "<spec>");
  ~Session();
  Session(Session&&) noexcept;
  Session& operator=(Session&&) noexcept;

  // Solves (see above). `control` as Solve's.
  SolveResult Solve(const SolveControl& control = {});
  // Vertex ids[i] (0-based, the mesh's order) to positions[i] (file units)
  // for the next Solve: a fixed vertex (the spec's `fixed`) stays there, a
  // free one starts there. Throws Error (key "vertex": an index out of range,
  // a non-finite position; nothing moves then) or std::invalid_argument when
  // the two lists differ in length.
  void MoveVertices(const std::vector<int>& ids,
                    const std::vector<std::array<double, 3>>& positions);
  // terms.<term>.weight for the next Solves. Throws Error (key "terms": not a
  // term of the problem; the key itself: out of its range).
  void SetWeight(const std::string& term, double weight);
  // The weight terms.<term>.weight has now. Throws Error as SetWeight.
  double Weight(const std::string& term) const;
  // The mesh the next Solve starts from (file units): the last result
  // written with the moves since (before the first Solve: `mesh`, moved).
  MeshData Current() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// `archgeo solve SPEC.yaml --set ...`: the spec's files, the result read back.
SolveResult SolveFile(const std::string& spec_path, const std::vector<std::string>& overrides = {},
                      const SolveControl& control = {});

// `archgeo measure --json`: the metrics report (JSON) of `mesh`, against
// `reference` if given. `arrays`: the report gets "arrays" (per-face "pq",
// "pq_normalized", "warp" when the mesh has faces of 4 or more sides; the
// per-vertex "displacement" from a reference with the mesh's vertex count),
// the values whose max and mean its metrics are. Throws Error.
std::string Measure(const MeshData& mesh, const MeshData* reference = nullptr,
                    bool arrays = false);

// A mesh file (.obj, .off, .ply) read by the CLI's readers with their
// default limits (the `limits.*` keys' defaults): same checks, same repairs
// (faces re-oriented, coincident vertices welded), file order of vertices
// and faces. Throws Error naming the file and line.
MeshData ReadMeshFile(const std::string& path);

// A scalar per face or per vertex (indexed as MeshData's faces / vertices).
struct NamedValues {
  std::string name;  // a PLY property name: letters, digits, '_'
  std::vector<double> values;
};

// Writes `mesh` as the CLI writes its output meshes (format from the
// extension; full double precision; PLY binary). `face_values` and
// `vertex_values` become float properties of a PLY's faces and vertices;
// they need a .ply path. Throws Error (a bad extension, a count that is not
// the mesh's, an unwritable path; nothing is written then).
void WriteMeshFile(const std::string& path, const MeshData& mesh,
                   const std::vector<NamedValues>& face_values = {},
                   const std::vector<NamedValues>& vertex_values = {});

// `archgeo generate`: an analytic test mesh (see `archgeo generate --help`).
struct SurfaceOptions {
  std::string surface = "roof";
  int nu = 20, nv = 15;
  double noise = -1;  // < 0: the surface's default (roof 0.1, torus 0, the nets none)
  double scale = 1.0;
  unsigned seed = 1;
  int refinement = 1;
};
MeshData Generate(const SurfaceOptions& options);

// Problem names and a problem's keys (JSON array of {name, type, default,
// doc}), as `archgeo spec PROBLEM --keys`.
std::vector<std::string> Problems();
std::string ProblemKeys(const std::string& problem);

// The library version ("0.1.0").
std::string Version();

}  // namespace archgeo
