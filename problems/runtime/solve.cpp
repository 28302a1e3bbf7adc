// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/runtime/solve.h"

#include <algorithm>
#include <glog/logging.h>

#include <chrono>

#include "core/clock.h"
#include "core/solver_options.h"
#include "core/input_error.h"
#include "mesh/similarity.h"
#include "mesh/subdivision.h"
#include "mesh/topology.h"

namespace archgeo {
namespace {

// The `fixed` setting on `mesh`. Throws InputError for an index out of range.
std::vector<bool> FixedVertices(const Settings& s, const Mesh& mesh, const std::string& mesh_path) {
  std::vector<bool> fixed(mesh.number_of_vertices(), false);
  const Value& value = s.Get("fixed");
  if (const auto* ids = std::get_if<std::vector<long long>>(&value)) {
    for (long long id : *ids) {
      if (id >= (long long)mesh.number_of_vertices()) {
        throw s.Error("fixed", "vertex index " + std::to_string(id) + " out of range: " +
                                   mesh_path + " has " +
                                   std::to_string(mesh.number_of_vertices()) + " vertices");
      }
      fixed[size_t(id)] = true;
    }
  } else if (s.String("fixed") == "corners") {
    for (VertexIndex v : Corners(mesh)) fixed[v.idx()] = true;
  } else if (s.String("fixed") == "boundary") {
    fixed = BoundaryVertices(mesh);
  }
  return fixed;
}

bool FixedByIds(const Settings& s) {
  return std::holds_alternative<std::vector<long long>>(s.Get("fixed"));
}

// Fixed input vertices as vertices of a derived net; every one must be on it.
std::vector<bool> OnNet(const Settings& s, const std::vector<bool>& fixed_input,
                        const WorkingNet& net, const std::string& mesh_path) {
  std::vector<bool> on_net(fixed_input.size(), false);
  std::vector<bool> fixed(net.source.size(), false);
  for (size_t i = 0; i < net.source.size(); ++i) {
    fixed[i] = fixed_input[net.source[i]];
    on_net[net.source[i]] = true;
  }
  for (size_t v = 0; v < fixed_input.size(); ++v) {
    if (fixed_input[v] && !on_net[v]) {
      throw s.Error("fixed", "vertex " + std::to_string(v) + " of " + mesh_path +
                                 " is not a vertex of the net solved (" +
                                 net.details.value("net", std::string("derived net")) + ")");
    }
  }
  return fixed;
}

void CheckInput(const ProblemDecl& d, const Mesh& mesh, const std::string& path) {
  int triangles = 0, quads = 0, others = 0;
  for (FaceIndex f : mesh.faces()) {
    const size_t k = mesh.degree(f);
    (k == 3 ? triangles : k == 4 ? quads : others)++;
  }
  const std::string faces = std::to_string(mesh.number_of_faces());
  switch (d.input) {
    case InputKind::kAny:
      return;
    case InputKind::kTriangles:
      if (quads + others > 0) {
        throw InputError(path, 0, "mesh",
                         d.name + " needs a triangle mesh; " + std::to_string(quads + others) +
                             " of " + faces + " faces have more than 3 sides");
      }
      return;
    case InputKind::kHasPolygons:
      if (quads + others == 0) {
        throw InputError(path, 0, "mesh",
                         d.name + " needs quads (or larger polygons); this mesh has only "
                                  "triangles");
      }
      return;
    case InputKind::kQuads:
      if (triangles + others > 0 || quads == 0) {
        throw InputError(path, 0, "mesh",
                         d.name + " needs a pure quad mesh; " +
                             std::to_string(triangles + others) + " of " + faces +
                             " faces are not quads");
      }
      return;
    case InputKind::kInteriorEdge:
      for (EdgeIndex e : mesh.edges()) {
        if (!mesh.is_border(e)) return;
      }
      throw InputError(path, 0, "mesh", d.name + " needs a mesh with an interior edge");
  }
}

// Adds the counts and times of the levels before (`earlier`) to a level's
// result: the report's totals are those of every level.
void AddEarlierLevels(const LoopResult& earlier, LoopResult* level) {
  level->rounds += earlier.rounds;
  level->iterations += earlier.iterations;
  level->pcg_rounds += earlier.pcg_rounds;
  level->cg_iterations += earlier.cg_iterations;
  level->cholesky_rounds += earlier.cholesky_rounds;
  level->cholesky_analyses += earlier.cholesky_analyses;
  level->cholesky_factorisations += earlier.cholesky_factorisations;
  level->cholesky_flops += earlier.cholesky_flops;
  level->cholesky_factor_nonzeros =
      std::max(level->cholesky_factor_nonzeros, earlier.cholesky_factor_nonzeros);
  for (const auto& [k, v] : earlier.seconds) level->seconds[k] += v;
}

}  // namespace

double ContinuationStart(const Settings& s) {
  return s.schema().Find("continuation.start") ? s.Number("continuation.start") : 1.0;
}

Mesh InFileFrame(const Mesh& input, const Mesh& solved, const Mesh& start,
                 const Similarity& frame) {
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
    const bool unmoved = v.idx() < start.number_of_vertices() &&
                         v.idx() < input.number_of_vertices() &&
                         solved.point(v) == start.point(v);
    out.point(v) = unmoved ? input.point(v)
                           : ToPoint(frame.FromCanonical(ToVec3(solved.point(v))));
  }
  return out;
}

std::unique_ptr<Solution> Solve(const ProblemSpec& spec, const Mesh& mesh, const Mesh* reference,
                                const ProgressSink& progress, const std::atomic<bool>* stop,
                                NormalPattern* pattern) {
  CHECK(spec.declaration) << "Solve: the spec has no problem (use ReadSpec)";
  const ProblemDecl& d = *spec.declaration;
  const Settings& s = spec.settings;
  SolverOptions(s);  // a combination Ceres rejects fails before any work
  auto sol = std::make_unique<Solution>();
  HookContext& hooks = sol->hooks;

  if (!d.makes_input) CheckInput(d, mesh, spec.mesh());
  hooks.settings = &s;
  hooks.progress = progress;
  hooks.input = &mesh;
  if (d.net) d.net(hooks);
  CHECK(!d.makes_input || hooks.net.derived) << d.name << ": makes_input without a net";
  sol->net = hooks.net;
  sol->on_design = hooks.net.derived && hooks.net.source.empty() && !d.makes_input &&
                   mesh.number_of_faces() > 0;
  sol->input = hooks.net.derived ? hooks.net.mesh : mesh;
  hooks.input = &sol->input;
  const Mesh& input = sol->input;
  const std::string scheme = s.String("multiresolution.scheme");
  const int levels = int(s.Integer("multiresolution.levels"));
  if (levels > 0 && !CanSubdivide(input, scheme)) {
    throw s.Error("multiresolution.scheme",
                  scheme + " subdivision needs a triangle mesh; " + spec.mesh() +
                      " has other faces (use catmull_clark or doo_sabin)");
  }
  // Subdivision rules are defined on the faces around a vertex: a vertex on
  // no face has none (CGAL's subdivision crashed on one).
  if (levels > 0) {
    for (VertexIndex v : input.vertices()) {
      if (input.is_isolated(v)) {
        throw s.Error("multiresolution.levels",
                      spec.mesh() + " has a vertex on no face (vertex " +
                          std::to_string(v.idx()) + "): subdivision needs every vertex on a "
                          "face; remove it or solve without multiresolution");
      }
    }
  }
  // Each multiresolution level multiplies the faces (3× for sqrt3, about 4×
  // for the others): refuse levels beyond limits.max_subdivided_faces before
  // any work.
  double faces = double(input.number_of_faces());
  for (int level = 1; level <= levels; ++level) {
    faces *= scheme == "sqrt3" ? 3 : 4;
    if (faces > double(s.Integer("limits.max_subdivided_faces"))) {
      throw s.Error("multiresolution.levels",
                    "level " + std::to_string(level) + " would have about " +
                        std::to_string((long long)faces) +
                        " faces, more than limits.max_subdivided_faces (" +
                        std::to_string(s.Integer("limits.max_subdivided_faces")) + ")");
    }
  }
  // Fixed vertex ids name input vertices, or the net's when the problem
  // makes its own input (there is no input mesh then).
  const bool ids_of_input = sol->net.derived && FixedByIds(s) && !d.makes_input;
  std::vector<bool> fixed = FixedVertices(s, ids_of_input ? mesh : input,
                                          d.makes_input ? std::string("the net") : spec.mesh());
  if (ids_of_input) fixed = OnNet(s, fixed, sol->net, spec.mesh());

  // The canonical frame: every length below is in input mean edge lengths.
  hooks.frame = sol->frame = CanonicalFrame(input);
  Mesh work = input;
  ToCanonical(hooks.frame, work);
  const Mesh start = work;
  // A net made from the input surface (a layout) stays on that surface, the
  // design the user gave, not on the net it started as: the band, the
  // projections and the distances are measured from the design.
  Mesh reference_canonical = reference ? *reference : sol->on_design ? mesh : input;
  ToCanonical(hooks.frame, reference_canonical);
  sol->reference = std::make_unique<ReferenceSurface>(reference_canonical);
  hooks.reference = sol->reference.get();
  const std::vector<const TermSpec*> terms = TermsOf(d);
  LoopResult& solved = sol->loop;
  for (int level = 0; level <= levels; ++level) {
    if (level > 0) {
      const Mesh coarse = work;
      work = Subdivide(work, scheme);
      const bool keeps_ids = scheme == "loop" || scheme == "catmull_clark";
      if (FixedByIds(s) && !keeps_ids) {
        throw s.Error("fixed", "vertex ids cannot be kept through " + scheme +
                                   " subdivision (it renumbers vertices); use loop or "
                                   "catmull_clark");
      }
      std::vector<bool> finer = FixedVertices(s, work, spec.mesh());
      if (FixedByIds(s)) {
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
        progress("multiresolution level " + std::to_string(level) + ": " + scheme +
                 " subdivision -> " + std::to_string(work.number_of_vertices()) + " vertices, " +
                 std::to_string(work.number_of_faces()) + " faces");
      }
    }
    sol->store = std::make_unique<Store>(work);
    hooks.store = sol->store.get();
    hooks.level = level;
    hooks.fixed = fixed;
    const auto level_start = Clock::now();
    sol->model = std::make_unique<MeshModel>(d, terms, hooks);
    LoopOptions options;
    options.settings = &s;
    options.terms = terms;
    options.progress = progress;
    options.stop = stop;
    if (level == levels) options.pattern = pattern;
    options.weight_scale = ContinuationStart(s);
    const LoopResult earlier = solved;
    solved = RunLoop(d, options, *sol->model);
    fixed = hooks.fixed;
    work = sol->store->mesh();
    for (const RoundLog& row : solved.log) {
      nlohmann::json j = RoundJson(row);
      j["level"] = level;
      sol->rounds.push_back(j);
    }
    sol->levels.push_back({{"level", level},
                           {"vertices", work.number_of_vertices()},
                           {"faces", work.number_of_faces()},
                           {"variables", solved.variables},
                           {"residuals", solved.residuals},
                           {"rounds", solved.rounds},
                           {"iterations", solved.iterations},
                           {"objective", solved.objective},
                           {"stop", solved.stop},
                           {"seconds", SecondsSince(level_start)}});
    AddEarlierLevels(earlier, &solved);
    if (!solved.usable || solved.stopped) break;
  }
  hooks.RecordChecks(true);
  sol->input_details = hooks.details;
  sol->input_headline = hooks.headline;
  hooks.loop = &solved;
  if (solved.usable && d.finish) d.finish(hooks);
  sol->details = hooks.details;
  sol->headline = hooks.headline;
  sol->output = InFileFrame(input, work, start, hooks.frame);
  hooks.output = &sol->output;
  return sol;
}

}  // namespace archgeo
