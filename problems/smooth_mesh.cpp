// The smooth_mesh optimisation (SolveSmoothMesh) and its builder adapter
// (problems/builder.h); problems/smooth_mesh.h documents the objective and keys.
#include "problems/smooth_mesh.h"

#include <ceres/problem.h>
#include <ceres/solver.h>
#include <ceres/sphere_manifold.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include <glog/logging.h>

#include "energies/anchor.h"
#include "energies/dihedral_energy.h"
#include "energies/face_planarity.h"
#include "energies/fairness.h"
#include "mesh/input_error.h"
#include "mesh/metrics.h"
#include "mesh/reference.h"
#include "mesh/similarity.h"
#include "mesh/smoothness_metrics.h"
#include "mesh/topology.h"
#include "mesh/vec3.h"
#include "problems/builders.h"
#include "problems/common_terms.h"

namespace archgeo {
namespace {

using Clock = std::chrono::steady_clock;

// Displacement guard (see smooth_mesh.h): starts at this fraction of the
// bound, with this anchor weight, growing by this factor per round.
// Rounds without a gain in E (tolerance.energy_relative) before stopping.
constexpr int kPatience = 3;
constexpr double kGuardStart = 0.5;
constexpr double kGuardFirst = 1.0;
constexpr double kGuardGrowth = 10.0;
// A clamped vertex goes just inside the bound, so that rounding in the
// conversion back to file units cannot put it outside.
constexpr double kClampMargin = 0.999;


// One interior edge: the halfedge v→w with face f on its left, f′ on its right.
struct EdgeTerm {
  VertexIndex v, w;
  FaceIndex left, right;
  VertexIndex a, b;  // third vertices of the left / right face when triangles
};

struct Setup {
  std::vector<EdgeTerm> edges;
  std::vector<FaceIndex> polygons;  // faces with more than 3 sides
  Mesh::Property_map<FaceIndex, Block<3>> normal;
  Mesh::Property_map<FaceIndex, Block<1>> offset;
  std::vector<bool> boundary, fixed;
  std::vector<Vec3> original;
  std::vector<std::array<VertexIndex, 3>> triples;
  std::vector<Vec3> triple_target;
  std::vector<double> guard;  // per vertex: weight of the displacement guard
};

Vec3 NewellNormal(const Mesh& mesh, FaceIndex f) {
  Vec3 n{0, 0, 0};
  std::vector<Vec3> p;
  for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
    p.push_back(ToVec3(mesh.point(v)));
  }
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec3 c = Cross(p[i], p[(i + 1) % p.size()]);
    for (int k = 0; k < 3; ++k) n[k] += c[k];
  }
  return Unit(n);
}

Setup MakeSetup(Mesh& mesh, const SmoothMeshSettings& s) {
  Setup setup;
  setup.normal = AddBlocks<FaceIndex, 3>(mesh, "f:smooth_normal");
  setup.offset = AddBlocks<FaceIndex, 1>(mesh, "f:smooth_offset");
  for (FaceIndex f : mesh.faces()) {
    if (mesh.degree(f) > 3) {
      setup.polygons.push_back(f);
      const Vec3 n = NewellNormal(mesh, f);
      setup.normal[f] = Norm(n) > 0 ? n : Vec3{0, 0, 1};
      setup.offset[f] = {0.0};
    }
  }
  for (EdgeIndex e : mesh.edges()) {
    if (mesh.is_border(e)) continue;
    const HalfedgeIndex h = mesh.halfedge(e, 0);
    const HalfedgeIndex o = mesh.opposite(h);
    EdgeTerm t;
    t.v = mesh.source(h);
    t.w = mesh.target(h);
    t.left = mesh.face(h);
    t.right = mesh.face(o);
    t.a = mesh.target(mesh.next(h));
    t.b = mesh.target(mesh.next(o));
    setup.edges.push_back(t);
  }
  setup.boundary = BoundaryVertices(mesh);
  setup.fixed = s.fixed.empty() ? std::vector<bool>(mesh.number_of_vertices(), false) : s.fixed;
  setup.original = Positions(mesh);
  setup.guard.assign(mesh.number_of_vertices(), 0.0);
  if (s.terms.fairness > 0) {
    setup.triples = SmoothFairnessTriples(mesh);
    setup.triple_target = FairnessTargets(setup.triples, setup.original, s.terms.fairness_relative);
  }
  return setup;
}

// The normal the dihedral energy uses for face f: exact for triangles, the
// normal block for polygons.
Vec3 EnergyNormal(const Mesh& mesh, const Setup& setup, FaceIndex f) {
  if (mesh.degree(f) > 3) return setup.normal[f];
  const HalfedgeIndex h = mesh.halfedge(f);
  const Vec3 p0 = ToVec3(mesh.point(mesh.source(h)));
  const Vec3 p1 = ToVec3(mesh.point(mesh.target(h)));
  const Vec3 p2 = ToVec3(mesh.point(mesh.target(mesh.next(h))));
  return Unit(Cross(Sub(p1, p0), Sub(p2, p0)));
}

struct Built {
  std::unique_ptr<ceres::Problem> problem;
  TermBlocks terms;
  // Storage the cost functions point to (constant for the round).
  std::vector<Vec3> previous;
  std::vector<Vec3> centers;
};

Built Build(Mesh& mesh, Setup& setup, const Projection* proj, const SmoothMeshSettings& s) {
  Built b;
  ceres::Problem::Options options;
  options.enable_fast_removal = false;
  b.problem = std::make_unique<ceres::Problem>(options);
  ceres::Problem& problem = *b.problem;
  const SmoothTermWeights& w = s.terms;
  auto pos = [&](VertexIndex v) { return PositionBlock(mesh, v); };

  // Polygons: re-centre the plane of each face at its current centroid.
  b.centers.resize(setup.polygons.size());
  if (w.face_planarity > 0) {
    for (size_t i = 0; i < setup.polygons.size(); ++i) {
      const FaceIndex f = setup.polygons[i];
      Vec3 c{0, 0, 0};
      double k = 0;
      double diagonal = 0;
      std::vector<VertexIndex> vs;
      for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) vs.push_back(v);
      for (VertexIndex v : vs) {
        for (int j = 0; j < 3; ++j) c[j] += mesh.point(v)[j];
        k += 1;
      }
      for (int j = 0; j < 3; ++j) c[j] /= k;
      for (size_t j = 0; j < vs.size(); ++j) {
        diagonal += Norm(Sub(ToVec3(mesh.point(vs[(j + 2) % vs.size()])), ToVec3(mesh.point(vs[j]))));
      }
      b.centers[i] = c;
      const Vec3& n = setup.normal[f];
      double d = 0;
      for (VertexIndex v : vs) d += Dot(n, Sub(ToVec3(mesh.point(v)), c)) / k;
      setup.offset[f] = {d};
      const double inv_length = diagonal > 0 ? double(vs.size()) / diagonal : 1.0;
      for (VertexIndex v : vs) {
        b.terms["face_planarity"].push_back(problem.AddResidualBlock(
            MakeFacePlanarity(b.centers[i].data(), inv_length), Weight(w.face_planarity),
            setup.normal[f].data(), setup.offset[f].data(), pos(v)));
      }
    }
  }

  if (w.dihedral_energy > 0) {
    for (const EdgeTerm& e : setup.edges) {
      const Vec3 nl = EnergyNormal(mesh, setup, e.left);
      const Vec3 nr = EnergyNormal(mesh, setup, e.right);
      const double length = Norm(Sub(ToVec3(mesh.point(e.w)), ToVec3(mesh.point(e.v))));
      const double omega = DihedralIrlsWeight(length, Norm(Sub(nl, nr)), 1.0);
      const bool poly_l = mesh.degree(e.left) > 3, poly_r = mesh.degree(e.right) > 3;
      ceres::ResidualBlockId id;
      if (!poly_l && !poly_r) {
        id = problem.AddResidualBlock(MakeDihedralTriTri(1.0, omega), Weight(w.dihedral_energy),
                                      pos(e.v), pos(e.w), pos(e.a), pos(e.b));
      } else if (!poly_l && poly_r) {
        id = problem.AddResidualBlock(MakeDihedralTriPoly(1.0, omega), Weight(w.dihedral_energy),
                                      pos(e.v), pos(e.w), pos(e.a), setup.normal[e.right].data());
      } else if (poly_l && !poly_r) {
        // The triangle (w, v, b) is on the left of w→v.
        id = problem.AddResidualBlock(MakeDihedralTriPoly(1.0, omega), Weight(w.dihedral_energy),
                                      pos(e.w), pos(e.v), pos(e.b), setup.normal[e.left].data());
      } else {
        id = problem.AddResidualBlock(MakeDihedralPolyPoly(1.0, omega), Weight(w.dihedral_energy),
                                      pos(e.v), pos(e.w), setup.normal[e.left].data(),
                                      setup.normal[e.right].data());
      }
      b.terms["dihedral_energy"].push_back(id);
    }
  }
  for (FaceIndex f : setup.polygons) {
    double* n = setup.normal[f].data();
    if (problem.HasParameterBlock(n)) problem.SetManifold(n, new ceres::SphereManifold<3>());
  }

  AddProximityTerms(problem, mesh, proj, setup.original, ProximityWeightsOf(w), b.terms);
  if (w.handles > 0) {
    for (const CanonicalHandle& h : s.handles) {
      b.terms["handles"].push_back(problem.AddResidualBlock(
          MakeAnchor(h.target.data(), 1.0), Weight(w.handles), pos(VertexIndex(h.vertex))));
    }
  }
  if (w.fairness > 0) {
    for (size_t t = 0; t < setup.triples.size(); ++t) {
      const auto& tr = setup.triples[t];
      b.terms["fairness"].push_back(problem.AddResidualBlock(
          MakeFairness(setup.triple_target[t].data(), 1.0), Weight(w.fairness), pos(tr[0]),
          pos(tr[1]), pos(tr[2])));
    }
  }
  for (VertexIndex v : mesh.vertices()) {
    if (setup.guard[v.idx()] > 0 && !mesh.is_isolated(v)) {
      b.terms["displacement_guard"].push_back(problem.AddResidualBlock(
          MakeAnchor(setup.original[v.idx()].data(), 1.0), Weight(setup.guard[v.idx()]), pos(v)));
    }
  }
  if (w.step > 0) {
    b.previous = Positions(mesh);
    for (VertexIndex v : mesh.vertices()) {
      if (mesh.is_isolated(v)) continue;
      b.terms["step"].push_back(problem.AddResidualBlock(
          MakeAnchor(b.previous[v.idx()].data(), 1.0), Weight(w.step), pos(v)));
    }
  }
  FixVertices(problem, mesh, setup.fixed);
  return b;
}

void Measure(const Mesh& mesh, const std::vector<Vec3>& original, SmoothRoundLog& log) {
  const SmoothnessMetrics m = ComputeSmoothnessMetrics(mesh);
  log.E = m.E;
  log.E_prime = m.E_prime;
  log.self_intersecting_pyramids = m.self_intersecting_pyramids;
  log.bad_saddles = m.bad_saddles;
  log.displacement = MaxMove(Positions(mesh), original);
}

}  // namespace

std::vector<std::array<VertexIndex, 3>> SmoothFairnessTriples(const Mesh& mesh) {
  std::vector<std::array<VertexIndex, 3>> triples;
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_isolated(v)) continue;
    if (mesh.is_border(v, /*check_all_incident_halfedges=*/true)) {
      // The two boundary neighbours: targets of the border halfedge out of v
      // and source of the border halfedge into v.
      for (HalfedgeIndex h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh)) {
        if (mesh.is_border(h)) {
          const VertexIndex prev = mesh.source(h);
          const VertexIndex next = mesh.target(mesh.next(h));
          if (prev != next && prev != v && next != v) triples.push_back({prev, v, next});
          break;
        }
      }
      continue;
    }
    std::vector<VertexIndex> ring;
    for (VertexIndex w : CGAL::vertices_around_target(mesh.halfedge(v), mesh)) ring.push_back(w);
    const size_t k = ring.size();
    if (k < 4 || k % 2 != 0) continue;
    for (size_t j = 0; j < k / 2; ++j) triples.push_back({ring[j], v, ring[j + k / 2]});
  }
  return triples;
}

SmoothMeshResult SolveSmoothMesh(Mesh& mesh, const ReferenceSurface& reference,
                                 const SmoothMeshSettings& settings,
                                 const ProgressSink& progress) {
  SmoothMeshResult result;
  for (const CanonicalHandle& h : settings.handles) {
    CHECK(h.vertex >= 0 && h.vertex < int(mesh.number_of_vertices()))
        << "handle vertex " << h.vertex << " out of range";
  }
  Setup setup = MakeSetup(mesh, settings);
  const ceres::Solver::Options base_options = ToCeresOptions(settings.solver);
  const SmoothTermWeights& w = settings.terms;
  const bool project = w.proximity > 0 || w.proximity_point > 0 || w.boundary_proximity > 0;

  // The displacement bound in the canonical frame (the report's bounding-box
  // diagonal is PrincipalBoxDiagonal, invariant under the similarity).
  // No bound with handles (a design moves the mesh on purpose).
  const double bound = settings.handles.empty()
                           ? settings.displacement_relative * PrincipalBoxDiagonal(mesh)
                           : 0.0;
  std::vector<bool> on_polygon(mesh.number_of_vertices(), false);
  for (FaceIndex f : setup.polygons) {
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) on_polygon[v.idx()] = true;
  }
  SmoothRoundLog initial;
  Measure(mesh, setup.original, initial);
  result.log.push_back(initial);
  if (progress) {
    char line[200];
    std::snprintf(line, sizeof line, "round  0  E %.6e  E' %.6e  self-intersecting pyramids %d",
                  initial.E, initial.E_prime, initial.self_intersecting_pyramids);
    progress(line);
  }
  Built built;
  // The round with the lowest true E so far (the output).
  double best_E = initial.E;
  std::vector<Vec3> best_positions = Positions(mesh);
  std::vector<Vec3> best_normals;
  for (FaceIndex f : setup.polygons) best_normals.push_back(setup.normal[f]);
  int last_gain = 0;  // the last round that lowered the best E by > energy_relative
  for (int round = 1; round <= settings.solver.outer_iterations; ++round) {
    const auto start = Clock::now();
    Projection proj;
    if (project) {
      proj = Project(mesh, reference, setup.boundary);
      result.seconds["projection"] += std::chrono::duration<double>(Clock::now() - start).count();
    }
    built = Build(mesh, setup, project ? &proj : nullptr, settings);
    const std::vector<Vec3> before = Positions(mesh);

    ceres::Solver::Options options = base_options;
    ceres::Solver::Summary summary;
    ceres::Solve(options, built.problem.get(), &summary);

    result.outer_iterations = round;
    if (!RecordSolve(summary, *built.problem, mesh, result)) return result;

    SmoothRoundLog log;
    log.round = round;
    log.iterations = std::max(0, int(summary.iterations.size()) - 1);
    log.cost = summary.final_cost;
    if (w.dihedral_energy > 0 && built.terms.count("dihedral_energy")) {
      ceres::Problem::EvaluateOptions eval;
      eval.residual_blocks = built.terms.at("dihedral_energy");
      double c = 0;
      built.problem->Evaluate(eval, &c, nullptr, nullptr, nullptr);
      log.surrogate = c / w.dihedral_energy;
    }
    if (bound > 0) {
      // Guard: vertices past half the bound are anchored (×10 per round);
      // a vertex past the bound is put back onto the sphere of radius
      // `bound` around its input position.
      for (VertexIndex v : mesh.vertices()) {
        const Vec3& x0 = setup.original[v.idx()];
        const Vec3 d = Sub(ToVec3(mesh.point(v)), x0);
        const double length = Norm(d);
        if (length > kGuardStart * bound) {
          double& g = setup.guard[v.idx()];
          g = std::max(kGuardFirst, g * kGuardGrowth);
        }
        if (length > bound && !on_polygon[v.idx()]) {
          const double t = kClampMargin * bound / length;
          mesh.point(v) = Point(x0[0] + t * d[0], x0[1] + t * d[1], x0[2] + t * d[2]);
          ++log.clamped;
        }
      }
    }
    Measure(mesh, setup.original, log);
    log.max_move = MaxMove(Positions(mesh), before);
    log.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.log.push_back(log);
    if (progress) {
      char line[240];
      std::snprintf(line, sizeof line,
                    "round %2d  %3d iterations  cost %.6e  E %.6e  E' %.6e  self-intersecting "
                    "pyramids %d  max move %.2e  displacement %.3e  %.2f s",
                    round, log.iterations, log.cost, log.E, log.E_prime,
                    log.self_intersecting_pyramids, log.max_move, log.displacement, log.seconds);
      progress(line);
    }
    if (log.E < best_E - settings.energy_relative * best_E) last_gain = round;
    if (log.E < best_E || !settings.handles.empty()) {
      best_E = log.E;
      best_positions = Positions(mesh);
      best_normals.clear();
      for (FaceIndex f : setup.polygons) best_normals.push_back(setup.normal[f]);
      result.best_round = round;
    }
    if (settings.energy_relative > 0 && settings.handles.empty() &&
        round - last_gain >= kPatience) {
      break;
    }
    if (log.max_move < 1e-9) break;
  }
  if (result.best_round != result.outer_iterations) {
    for (VertexIndex v : mesh.vertices()) mesh.point(v) = ToPoint(best_positions[v.idx()]);
    for (size_t i = 0; i < setup.polygons.size(); ++i) setup.normal[setup.polygons[i]] = best_normals[i];
  }
  if (built.problem) result.objective = TermObjective(*built.problem, built.terms);
  return result;
}

namespace {

struct HandleSpec {
  int vertex = 0;
  bool offset = false;  // `offset` (else `position`)
  Vec3 value{0, 0, 0};
  std::string file;
  int line = 0;
};

class SmoothMeshBuilder : public Builder {
 public:
  std::set<std::string> Keys() const override { return {"terms", "handles", "tolerance"}; }

  void Read(const SpecReader& r, const YAML::Node& root) override {
    if (root["terms"]) ReadTerms(r, root["terms"]);
    if (const YAML::Node t = root["tolerance"]) {
      r.CheckKeys(t, "tolerance", {"energy_relative", "displacement_relative"});
      if (t["energy_relative"]) {
        s_.energy_relative = r.Number(t["energy_relative"], "tolerance.energy_relative", 0, 1);
      }
      if (t["displacement_relative"]) {
        s_.displacement_relative =
            r.Number(t["displacement_relative"], "tolerance.displacement_relative", 0, 1);
      }
    }
    if (const YAML::Node h = root["handles"]) ReadHandles(r, h);
  }

  nlohmann::json SettingsJson() const override {
    const SmoothTermWeights& w = s_.terms;
    nlohmann::json handles = nlohmann::json::array();
    for (const HandleSpec& h : handles_) {
      handles.push_back({{"vertex", h.vertex}, {h.offset ? "offset" : "position", h.value}});
    }
    return {{"terms",
             {{"dihedral_energy", w.dihedral_energy},
              {"face_planarity", w.face_planarity},
              {"proximity", {{"weight", w.proximity}, {"point_weight", w.proximity_point}}},
              {"boundary_proximity", w.boundary_proximity},
              {"anchor", w.anchor},
              {"fairness", {{"weight", w.fairness}, {"relative_to_original", w.fairness_relative}}},
              {"step", w.step},
              {"handles", w.handles}}},
            {"handles", handles},
            {"tolerance",
             {{"energy_relative", s_.energy_relative},
              {"displacement_relative", s_.displacement_relative}}}};
  }

  void CheckInput(const Mesh& input, const std::string& path) const override {
    bool interior = false;
    for (EdgeIndex e : input.edges()) interior = interior || !input.is_border(e);
    if (!interior) {
      throw InputError(path, 0, "mesh", "smooth_mesh needs a mesh with an interior edge");
    }
    std::set<int> seen;
    for (const HandleSpec& h : handles_) {
      if (h.vertex >= int(input.number_of_vertices())) {
        throw InputError(h.file, h.line, "handles",
                         "vertex index " + std::to_string(h.vertex) + " out of range: " + path +
                             " has " + std::to_string(input.number_of_vertices()) + " vertices");
      }
      if (!seen.insert(h.vertex).second) {
        throw InputError(h.file, h.line, "handles",
                         "vertex " + std::to_string(h.vertex) + " is listed twice");
      }
    }
  }

  SolveOutcome Solve(Mesh& mesh, const SolveContext& context) const override {
    SmoothMeshSettings settings = s_;
    settings.fixed = context.fixed;
    settings.solver = context.solver;
    // Handle targets (file units; offsets from the input position) in the
    // canonical frame the run solves in.
    settings.handles.clear();
    for (const HandleSpec& h : handles_) {
      Vec3 target = h.value;
      if (h.offset) {
        const Vec3 p = ToVec3(context.input->point(VertexIndex(h.vertex)));
        for (int k = 0; k < 3; ++k) target[k] = p[k] + h.value[k];
      }
      settings.handles.push_back({h.vertex, context.frame.ToCanonical(target)});
    }
    const SmoothMeshResult r = SolveSmoothMesh(mesh, *context.reference, settings, context.progress);
    SolveOutcome out = r;
    nlohmann::json log = nlohmann::json::array();
    for (const SmoothRoundLog& l : r.log) {
      log.push_back({{"round", l.round},
                     {"iterations", l.iterations},
                     {"cost", l.cost},
                     {"E", l.E},
                     {"E_prime", l.E_prime},
                     {"irls_surrogate", l.surrogate},
                     {"self_intersecting_pyramids", l.self_intersecting_pyramids},
                     {"bad_saddles", l.bad_saddles},
                     {"max_move", l.max_move},
                     {"displacement_max", l.displacement},
                     {"clamped_vertices", l.clamped},
                     {"seconds", l.seconds}});
    }
    out.details["rounds"] = log;
    out.details["output_round"] = r.best_round;
    out.details["rounds_units"] =
        "lengths (E, E_prime, max_move, displacement_max) in input mean edge lengths; round 0 = "
        "input";
    if (!r.log.empty()) {
      const SmoothRoundLog& a = r.log.front();
      const SmoothRoundLog& b = r.log[r.best_round];
      char line[256];
      std::snprintf(line, sizeof line,
                    "E %.6e -> %.6e (%.1f%%), self-intersecting pyramids %d -> %d "
                    "(mean edge lengths)\n",
                    a.E, b.E, a.E > 0 ? 100.0 * (b.E - a.E) / a.E : 0.0,
                    a.self_intersecting_pyramids, b.self_intersecting_pyramids);
      out.headline = line;
      out.details["E_before"] = a.E;
      out.details["E_after"] = b.E;
    }
    return out;
  }

  std::set<std::string> Analyses() const override { return {"smoothness"}; }

  // Per face the largest ℓ_e|α_e| of its edges (Fig. 7), red at color_max ×
  // the mean edge length (an edge of mean length bent by color_max radians).
  FaceColors Colors(const Mesh& output, double color_max) const override {
    return BendingColors(output, color_max);
  }

 private:
  void ReadTerms(const SpecReader& r, const YAML::Node& terms) {
    r.CheckKeys(terms, "terms",
                {"dihedral_energy", "face_planarity", "proximity", "boundary_proximity", "anchor",
                 "fairness", "step", "handles"});
    SmoothTermWeights& w = s_.terms;
    const SmoothTermWeights defaults;
    w = SmoothTermWeights{0, 0, 0, 0, 0, 0, 0, false, 0, 0};
    auto weight = [&](const char* name, double& out) {
      if (terms[name]) r.Weight(terms[name], std::string("terms.") + name, &out);
    };
    weight("dihedral_energy", w.dihedral_energy);
    weight("face_planarity", w.face_planarity);
    weight("boundary_proximity", w.boundary_proximity);
    weight("anchor", w.anchor);
    weight("step", w.step);
    weight("handles", w.handles);
    if (const YAML::Node fair = terms["fairness"]) {
      w.fairness_relative = defaults.fairness_relative;
      r.FairnessTerm(fair, &w.fairness, &w.fairness_relative);
    }
    if (const YAML::Node prox = terms["proximity"]) {
      w.proximity_point = defaults.proximity_point;
      r.ProximityTerm(prox, &w.proximity, &w.proximity_point);
    }
  }

  void ReadHandles(const SpecReader& r, const YAML::Node& list) {
    if (!list.IsSequence()) r.Fail(list, "handles", "expected a list of {vertex, position|offset}");
    handles_.clear();
    for (size_t i = 0; i < list.size(); ++i) {
      const YAML::Node h = list[i];
      const std::string key = "handles[" + std::to_string(i) + "]";
      if (!h.IsMap()) r.Fail(h, key, "expected {vertex: i, position: [x, y, z]} or {vertex: i, offset: [dx, dy, dz]}");
      r.CheckKeys(h, key, {"vertex", "position", "offset"});
      if (!h["vertex"]) r.Fail(h, key, "missing 'vertex'");
      if (bool(h["position"]) == bool(h["offset"])) {
        r.Fail(h, key, "give exactly one of 'position' and 'offset'");
      }
      HandleSpec spec;
      spec.vertex = r.Integer(h["vertex"], key + ".vertex", 0, 1 << 30);
      spec.offset = bool(h["offset"]);
      const YAML::Node xyz = spec.offset ? h["offset"] : h["position"];
      const std::string xyz_key = key + (spec.offset ? ".offset" : ".position");
      if (!xyz.IsSequence() || xyz.size() != 3) r.Fail(xyz, xyz_key, "expected [x, y, z]");
      for (int k = 0; k < 3; ++k) {
        spec.value[k] = r.Number(xyz[k], xyz_key, -1e300, 1e300);
      }
      spec.file = r.Overridden("handles") ? "--set" : r.file();
      spec.line = r.Overridden("handles") ? 0 : h.Mark().line + 1;
      handles_.push_back(spec);
    }
  }

  SmoothMeshSettings s_;
  std::vector<HandleSpec> handles_;
  // Set by CheckInput (the run calls it on the input before Solve).
};

}  // namespace

std::unique_ptr<Builder> MakeSmoothMeshBuilder() { return std::make_unique<SmoothMeshBuilder>(); }

}  // namespace archgeo
