// The total_absolute_curvature builder: the weight iteration of [Pellis 2019,
// §5.3] (problems/total_absolute_curvature.h documents it and the keys) and
// its adapter to the generic run (problems/builder.h).
#include "problems/total_absolute_curvature.h"

#include <ceres/problem.h>
#include <ceres/solver.h>
#include <glog/logging.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "energies/anchor.h"
#include "energies/fairness.h"
#include "energies/proximity.h"
#include "energies/total_absolute_curvature.h"
#include "mesh/input_error.h"
#include "mesh/reference.h"
#include "mesh/smoothness_metrics.h"
#include "mesh/topology.h"
#include "problems/builders.h"
#include "problems/common_terms.h"

namespace archgeo {
namespace {

using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The one-ring of v in the order of energies/total_absolute_curvature.h:
// counter-clockwise (CGAL face orientation) around v; for a boundary vertex
// the open fan from one boundary neighbour to the other.
struct Star {
  VertexIndex v;
  std::vector<VertexIndex> ring;
  bool closed = true;
};

// Returns false for isolated vertices, vertices with more than
// one boundary gap, and stars without an interior edge.
bool MakeStar(const Mesh& mesh, VertexIndex v, Star* star) {
  if (mesh.is_isolated(v)) return false;
  star->v = v;
  star->ring.clear();
  // Out-halfedges v → w are opposite(h) for h around the target v.
  HalfedgeIndex start = Mesh::null_halfedge();
  int gaps = 0;
  for (HalfedgeIndex h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh)) {
    const HalfedgeIndex out = mesh.opposite(h);
    if (mesh.is_border(mesh.opposite(out))) {  // border to the right of v → w
      start = out;
      ++gaps;
    }
  }
  if (gaps > 1) return false;
  star->closed = gaps == 0;
  if (star->closed) start = mesh.opposite(mesh.halfedge(v));
  HalfedgeIndex h = start;
  const size_t limit = mesh.number_of_halfedges();
  do {
    star->ring.push_back(mesh.target(h));
    if (mesh.is_border(h)) break;                  // last spoke of an open fan
    h = mesh.opposite(mesh.prev(h));               // next spoke counter-clockwise
    CHECK_LE(star->ring.size(), limit);
  } while (h != start);
  return star->ring.size() >= 3;  // closed: ≥ 3 faces; open: ≥ 1 interior edge
}

std::vector<Star> Stars(const Mesh& mesh) {
  std::vector<Star> stars;
  Star s;
  for (VertexIndex v : mesh.vertices()) {
    if (MakeStar(mesh, v, &s)) stars.push_back(s);
  }
  return stars;
}

VertexShapeOperator Evaluate(const Mesh& mesh, const Star& s) {
  std::vector<const double*> ring;
  for (VertexIndex w : s.ring) ring.push_back(PositionBlock(mesh, w));
  return EvaluateVertexShapeOperator(PositionBlock(mesh, s.v), ring, s.closed);
}

double SumAbsLambda(const Mesh& mesh, const std::vector<Star>& stars) {
  double c = 0;
  for (const Star& s : stars) {
    const VertexShapeOperator op = Evaluate(mesh, s);
    c += std::abs(op.lambda1) + std::abs(op.lambda2);
  }
  return c;
}

// Umbrella triples (w_i, v, w_{i+⌊k/2⌋}) of the interior vertices and the
// boundary triples of free boundary vertices (see the header).
std::vector<std::array<VertexIndex, 3>> FairnessTriples(const std::vector<Star>& stars,
                                                        const std::vector<bool>& fixed) {
  std::vector<std::array<VertexIndex, 3>> triples;
  auto is_fixed = [&](VertexIndex v) { return fixed[v.idx()]; };
  for (const Star& s : stars) {
    const int k = int(s.ring.size());
    if (s.closed) {
      const int half = k / 2;
      const int count = k % 2 == 0 ? half : k;
      for (int i = 0; i < count; ++i) {
        const VertexIndex u = s.ring[i], w = s.ring[(i + half) % k];
        if (is_fixed(u) && is_fixed(s.v) && is_fixed(w)) continue;
        triples.push_back({u, s.v, w});
      }
    } else if (!is_fixed(s.v)) {
      triples.push_back({s.ring.front(), s.v, s.ring.back()});
    }
  }
  return triples;
}


// The tangent planes of the input at its boundary vertices: one (second-ring
// vertex w, boundary point b, normal n_b) per such pair.
struct TangentPlane {
  VertexIndex w;
  Vec3 point, normal;
};

struct Setup {
  std::vector<Star> stars;  // every vertex with an interior edge
  std::vector<bool> fixed;
  std::vector<std::array<VertexIndex, 3>> triples;
  std::vector<TangentPlane> planes;
};

Setup MakeSetup(const Mesh& mesh, const TotalAbsoluteCurvatureSettings& s) {
  Setup setup;
  setup.stars = Stars(mesh);
  const size_t n = mesh.number_of_vertices();
  setup.fixed = s.fixed.empty() ? std::vector<bool>(n, false) : s.fixed;
  CHECK_EQ(setup.fixed.size(), n) << "SolveTotalAbsoluteCurvature: one fixed flag per vertex";
  const std::vector<bool> boundary = BoundaryVertices(mesh);
  const bool fix_ring = s.tangent_planes == TangentPlanes::kFixSecondRing ||
                        s.tangent_planes == TangentPlanes::kBoth;
  const bool term = s.tangent_planes == TangentPlanes::kTerm ||
                    s.tangent_planes == TangentPlanes::kBoth;
  if (fix_ring || term) {
    const std::vector<Vec3> normals = FaceNormals(mesh);
    for (VertexIndex b : mesh.vertices()) {
      if (!boundary[b.idx()]) continue;
      const Vec3 nb = VertexNormal(mesh, normals, b);
      for (VertexIndex w : CGAL::vertices_around_target(mesh.halfedge(b), mesh)) {
        if (boundary[w.idx()]) continue;
        if (fix_ring) setup.fixed[w.idx()] = true;
        if (term && (nb[0] != 0 || nb[1] != 0 || nb[2] != 0)) {
          setup.planes.push_back({w, ToVec3(mesh.point(b)), nb});
        }
      }
    }
  }
  if (s.terms.fairness > 0) setup.triples = FairnessTriples(setup.stars, setup.fixed);
  return setup;
}

bool HasFreeVertex(const Star& s, const std::vector<bool>& fixed) {
  if (!fixed[s.v.idx()]) return true;
  for (VertexIndex w : s.ring) {
    if (!fixed[w.idx()]) return true;
  }
  return false;
}

// Round data that must outlive the problem (the energies copy their targets,
// but the proximity projections are referenced by AddProximityTerms).
struct RoundData {
  std::vector<Vec3> previous;  // positions at the start of the round
  Projection projection;
};

struct Built {
  std::unique_ptr<ceres::Problem> problem;
  TermBlocks terms;
};

Built Build(Mesh& mesh, const Setup& setup, const TotalAbsoluteCurvatureSettings& s,
            RoundData& data) {
  Built b;
  ceres::Problem::Options options;
  options.enable_fast_removal = false;
  b.problem = std::make_unique<ceres::Problem>(options);
  ceres::Problem& problem = *b.problem;
  const TacWeights& w = s.terms;
  auto pos = [&](VertexIndex v) { return PositionBlock(mesh, v); };

  if (w.target > 0) {
    for (const Star& star : setup.stars) {
      if (!HasFreeVertex(star, setup.fixed)) continue;
      const VertexShapeOperator op = Evaluate(mesh, star);
      const double omega1 = TotalAbsoluteCurvatureIrlsWeight(op.lambda1, 1.0, s.irls_epsilon);
      const double omega2 = TotalAbsoluteCurvatureIrlsWeight(op.lambda2, 1.0, s.irls_epsilon);
      std::vector<double*> blocks{pos(star.v)};
      for (VertexIndex v : star.ring) blocks.push_back(pos(v));
      b.terms["target"].push_back(problem.AddResidualBlock(
          MakeTotalAbsoluteCurvature(int(star.ring.size()), star.closed, 1.0, omega1, omega2),
          Weight(w.target), blocks));
    }
  }
  if (w.fairness > 0 && !setup.triples.empty()) {
    std::vector<Vec3> normal;
    if (w.fairness_normal_free) {
      const std::vector<Vec3> face_normals = FaceNormals(mesh);
      normal.resize(mesh.number_of_vertices());
      for (VertexIndex v : mesh.vertices()) normal[v.idx()] = VertexNormal(mesh, face_normals, v);
    }
    for (const auto& t : setup.triples) {
      Vec3 target{0, 0, 0};
      if (w.fairness_normal_free) {
        const Vec3& n = normal[t[1].idx()];
        const Vec3& u = data.previous[t[0].idx()];
        const Vec3& v = data.previous[t[1].idx()];
        const Vec3& x = data.previous[t[2].idx()];
        double dn = 0;
        for (int k = 0; k < 3; ++k) dn += n[k] * (u[k] - 2 * v[k] + x[k]);
        for (int k = 0; k < 3; ++k) target[k] = dn * n[k];
      }
      b.terms["fairness"].push_back(problem.AddResidualBlock(
          MakeFairness(target.data(), 1.0), Weight(w.fairness), pos(t[0]), pos(t[1]),
          pos(t[2])));
    }
  }
  for (const TangentPlane& p : setup.planes) {
    b.terms["tangent_planes"].push_back(
        problem.AddResidualBlock(MakeProximity(p.point.data(), p.normal.data(), 1.0),
                                 Weight(s.tangent_plane_weight), pos(p.w)));
  }
  if (w.proximity > 0 || w.proximity_point > 0) {
    ProximityWeights pw;
    pw.proximity = w.proximity;
    pw.proximity_point = w.proximity_point;
    AddProximityTerms(problem, mesh, &data.projection, data.previous, pw, b.terms);
  }
  if (w.regularizer > 0) {
    for (VertexIndex v : mesh.vertices()) {
      if (setup.fixed[v.idx()] || !problem.HasParameterBlock(pos(v))) continue;
      b.terms["regularizer"].push_back(problem.AddResidualBlock(
          MakeAnchor(data.previous[v.idx()].data(), 1.0), Weight(w.regularizer), pos(v)));
    }
  }
  FixVertices(problem, mesh, setup.fixed);
  return b;
}

// One progress line per Ceres iteration.
class IterationLine : public ceres::IterationCallback {
 public:
  IterationLine(const ProgressSink& sink, int round) : sink_(sink), round_(round) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    char line[200];
    std::snprintf(line, sizeof line,
                  "round %2d  iter %3d  cost %.6e  |gradient| %.2e  |step| %.2e  %.3f s", round_,
                  s.iteration, s.cost, s.gradient_max_norm, s.step_norm,
                  s.cumulative_time_in_seconds);
    sink_(line);
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const ProgressSink& sink_;
  int round_;
};

}  // namespace

double DiscreteTotalAbsoluteCurvature(const Mesh& mesh) {
  for (FaceIndex f : mesh.faces()) {
    CHECK_EQ(mesh.degree(f), 3u) << "DiscreteTotalAbsoluteCurvature: triangle meshes only";
  }
  return SumAbsLambda(mesh, Stars(mesh));
}

TotalAbsoluteCurvatureResult SolveTotalAbsoluteCurvature(
    Mesh& mesh, const ReferenceSurface* reference,
    const TotalAbsoluteCurvatureSettings& settings, const ProgressSink& progress) {
  for (FaceIndex f : mesh.faces()) {
    CHECK_EQ(mesh.degree(f), 3u) << "SolveTotalAbsoluteCurvature: triangle meshes only";
  }
  const bool proximity = settings.terms.proximity > 0 || settings.terms.proximity_point > 0;
  CHECK(!proximity || reference != nullptr)
      << "SolveTotalAbsoluteCurvature: proximity needs a reference";
  TotalAbsoluteCurvatureResult result;
  const Setup setup = MakeSetup(mesh, settings);
  result.C_start = SumAbsLambda(mesh, setup.stars);
  const ceres::Solver::Options base_options = ToCeresOptions(settings.solver);
  const std::vector<bool> boundary = proximity ? BoundaryVertices(mesh) : std::vector<bool>{};
  Built built;
  RoundData data;

  for (int round = 1; round <= settings.solver.outer_iterations; ++round) {
    const auto start = Clock::now();
    data.previous = Positions(mesh);
    if (proximity) data.projection = Project(mesh, *reference, boundary);
    built = Build(mesh, setup, settings, data);

    ceres::Solver::Options options = base_options;
    IterationLine line(progress, round);
    if (progress) {
      options.callbacks.push_back(&line);
      options.update_state_every_iteration = true;
    }
    ceres::Solver::Summary summary;
    ceres::Solve(options, built.problem.get(), &summary);

    result.outer_iterations = round;
    if (!RecordSolve(summary, *built.problem, mesh, result)) return result;
    TacRoundLog log;
    log.round = round;
    log.iterations = std::max(0, int(summary.iterations.size()) - 1);
    log.cost = summary.final_cost;
    log.C = SumAbsLambda(mesh, setup.stars);
    log.max_move = MaxMove(data.previous, Positions(mesh));
    log.seconds = Since(start);
    result.log.push_back(log);
    if (progress) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "round %2d  done: %d iterations  cost %.6e  C %.6f  max move %.2e  %.3f s",
                    round, log.iterations, log.cost, log.C, log.max_move, log.seconds);
      progress(text);
    }
    const double previous_c = result.log.size() > 1 ? result.log[result.log.size() - 2].C
                                                    : result.C_start;
    if (log.max_move < settings.rest_move ||
        std::abs(log.C - previous_c) <= settings.rest_change * std::abs(previous_c)) {
      break;
    }
  }
  if (built.problem) result.objective = TermObjective(*built.problem, built.terms);
  return result;
}

namespace {

const char* TangentPlanesName(TangentPlanes t) {
  switch (t) {
    case TangentPlanes::kFree: return "free";
    case TangentPlanes::kFixSecondRing: return "fix_second_ring";
    case TangentPlanes::kTerm: return "term";
    case TangentPlanes::kBoth: return "both";
  }
  return "free";
}

class TotalAbsoluteCurvatureBuilder : public Builder {
 public:
  std::set<std::string> Keys() const override { return {"terms", "boundary", "irls"}; }

  void Read(const SpecReader& r, const YAML::Node& root) override {
    if (root["terms"]) ReadTerms(r, root["terms"]);
    if (const YAML::Node b = root["boundary"]) {
      r.CheckKeys(b, "boundary", {"tangent_planes", "weight"});
      if (b["tangent_planes"]) {
        const std::string t = r.String(b["tangent_planes"], "boundary.tangent_planes",
                                       {"free", "fix_second_ring", "term", "both"});
        s_.tangent_planes = t == "fix_second_ring" ? TangentPlanes::kFixSecondRing
                            : t == "term"          ? TangentPlanes::kTerm
                            : t == "both"          ? TangentPlanes::kBoth
                                                   : TangentPlanes::kFree;
      }
      if (b["weight"]) s_.tangent_plane_weight = r.Number(b["weight"], "boundary.weight", 0, 1e12);
    }
    if (const YAML::Node i = root["irls"]) {
      r.CheckKeys(i, "irls", {"epsilon", "rest_move", "rest_change"});
      if (i["epsilon"]) s_.irls_epsilon = r.Number(i["epsilon"], "irls.epsilon", 1e-12, 1e3);
      if (i["rest_move"]) s_.rest_move = r.Number(i["rest_move"], "irls.rest_move", 0, 1e6);
      if (i["rest_change"]) {
        s_.rest_change = r.Number(i["rest_change"], "irls.rest_change", 0, 1);
      }
    }
  }

  nlohmann::json SettingsJson() const override {
    const TacWeights& w = s_.terms;
    return {{"terms",
             {{"target", w.target},
              {"regularizer", w.regularizer},
              {"fairness",
               {{"weight", w.fairness},
                {"normal_part", w.fairness_normal_free ? "free" : "penalised"}}},
              {"proximity", {{"weight", w.proximity}, {"point_weight", w.proximity_point}}}}},
            {"boundary",
             {{"tangent_planes", TangentPlanesName(s_.tangent_planes)},
              {"weight", s_.tangent_plane_weight}}},
            {"irls",
             {{"epsilon", s_.irls_epsilon},
              {"rest_move", s_.rest_move},
              {"rest_change", s_.rest_change}}}};
  }

  void CheckInput(const Mesh& input, const std::string& path) const override {
    for (FaceIndex f : input.faces()) {
      if (input.degree(f) != 3) {
        throw InputError(path, 0, "mesh",
                         "total_absolute_curvature needs a triangle mesh; face " +
                             std::to_string(f.idx()) + " has " +
                             std::to_string(input.degree(f)) + " sides");
      }
    }
  }

  SolveOutcome Solve(Mesh& mesh, const SolveContext& context) const override {
    TotalAbsoluteCurvatureSettings settings = s_;
    settings.fixed = context.fixed;
    settings.solver = context.solver;
    const auto start = Clock::now();
    const TotalAbsoluteCurvatureResult r =
        SolveTotalAbsoluteCurvature(mesh, context.reference, settings, context.progress);
    SolveOutcome out = r;
    nlohmann::json log = nlohmann::json::array();
    for (const TacRoundLog& l : r.log) {
      log.push_back({{"round", l.round}, {"iterations", l.iterations}, {"cost", l.cost},
                     {"C_canonical", l.C}, {"max_move_mean_edges", l.max_move},
                     {"seconds", l.seconds}});
    }
    out.details["rounds"] = log;
    const double c_end = r.log.empty() ? r.C_start : r.log.back().C;
    out.details["total_absolute_curvature"] = {
        {"C_start_canonical", r.C_start}, {"C_end_canonical", c_end},
        {"units", "canonical frame (mean edge length of the input = 1)"},
        {"seconds", Since(start)}};
    char line[256];
    std::snprintf(line, sizeof line,
                  "total absolute curvature (canonical frame): C %.4f -> %.4f in %d rounds\n",
                  r.C_start, c_end, r.outer_iterations);
    out.headline = line;
    return out;
  }

  std::set<std::string> Analyses() const override { return {"smoothness"}; }

  // Faces coloured by the largest ℓ|α| of their edges (green 0 → red at the
  // mesh's maximum), where the curvature concentrates.
  FaceColors Colors(const Mesh& output, double /*color_max*/) const override {
    return SmoothnessColors(output, MeasureEdgeSmoothness(output, FaceNormals(output)));
  }

 private:
  void ReadTerms(const SpecReader& r, const YAML::Node& terms) {
    r.CheckKeys(terms, "terms", {"target", "regularizer", "fairness", "proximity"});
    TacWeights& w = s_.terms;
    w = TacWeights{0, 0, 0, true, 0, 0};
    if (terms["target"]) r.Weight(terms["target"], "terms.target", &w.target);
    if (terms["regularizer"]) r.Weight(terms["regularizer"], "terms.regularizer", &w.regularizer);
    if (const YAML::Node fair = terms["fairness"]) {
      const YAML::Node extra = r.Weight(fair, "terms.fairness", &w.fairness, {"normal_part"});
      if (extra && extra["normal_part"]) {
        w.fairness_normal_free = r.String(extra["normal_part"], "terms.fairness.normal_part",
                                          {"free", "penalised"}) == "free";
      }
    }
    if (const YAML::Node prox = terms["proximity"]) {
      r.ProximityTerm(prox, &w.proximity, &w.proximity_point);
    }
  }

  TotalAbsoluteCurvatureSettings s_;
};

}  // namespace

std::unique_ptr<Builder> MakeTotalAbsoluteCurvatureBuilder() {
  return std::make_unique<TotalAbsoluteCurvatureBuilder>();
}

}  // namespace archgeo
