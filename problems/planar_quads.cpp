#include "problems/planar_quads.h"

#include <ceres/loss_function.h>
#include <ceres/sphere_manifold.h>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "energies/face_planarity.h"
#include "energies/fairness.h"
#include "energies/pq_diagonal.h"
#include "mesh/metrics.h"
#include "mesh/reference.h"
#include "mesh/topology.h"
#include "mesh/vec3.h"
#include "problems/common_terms.h"
#include "problems/tolerance_band.h"

namespace archgeo {
namespace {

constexpr double kStillMove = 1e-6;  // outer loop at rest (fixed weights), mean edge lengths

struct Quad {
  FaceIndex face;
  std::array<VertexIndex, 4> v;
  double inv_length;  // 1 / initial mean diagonal length
};

struct Polygon {
  FaceIndex face;
  std::vector<VertexIndex> v;
  Vec3 center;
  double inv_length;  // 1 / initial mean length of the diagonals (i, i+2)
};

// Everything fixed for the whole run: topology, targets, per-face weights.
struct Setup {
  std::vector<Quad> quads;
  std::vector<Polygon> polygons;
  std::vector<double> weight;  // per face index: base planarity weight
  std::vector<bool> boundary, fixed;
  std::vector<Vec3> original;
  std::vector<std::array<VertexIndex, 3>> triples;
  std::vector<Vec3> triple_target;
  Mesh::Property_map<FaceIndex, Block<3>> normal;
  Mesh::Property_map<FaceIndex, Block<1>> offset;
};


double MaxNormalizedPlanarity(const Mesh& mesh) {
  const PlanarityMeasure p = MeasureFacePlanarity(mesh);
  return p.normalized.empty() ? 0.0 : *std::max_element(p.normalized.begin(), p.normalized.end());
}

Setup MakeSetup(Mesh& mesh, const PlanarQuadsSettings& s) {
  Setup setup;
  setup.weight.assign(mesh.number_of_faces(), 0.0);
  setup.normal = AddBlocks<FaceIndex, 3>(mesh, "f:normal");
  setup.offset = AddBlocks<FaceIndex, 1>(mesh, "f:offset");
  for (FaceIndex f : mesh.faces()) {
    std::vector<VertexIndex> vs;
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) vs.push_back(v);
    if (vs.size() == 4) {
      const double d0 = Norm(Sub(ToVec3(mesh.point(vs[2])), ToVec3(mesh.point(vs[0]))));
      const double d1 = Norm(Sub(ToVec3(mesh.point(vs[3])), ToVec3(mesh.point(vs[1]))));
      setup.quads.push_back({f, {vs[0], vs[1], vs[2], vs[3]}, 2.0 / (d0 + d1)});
      setup.weight[f.idx()] = s.terms.pq_diagonal;
    } else if (vs.size() > 4) {
      // Newell normal through the centroid: the start of the plane variables.
      Vec3 c{0, 0, 0}, n{0, 0, 0};
      for (size_t i = 0; i < vs.size(); ++i) {
        const Point& a = mesh.point(vs[i]);
        const Point& b = mesh.point(vs[(i + 1) % vs.size()]);
        n[0] += (a.y() - b.y()) * (a.z() + b.z());
        n[1] += (a.z() - b.z()) * (a.x() + b.x());
        n[2] += (a.x() - b.x()) * (a.y() + b.y());
        for (int k = 0; k < 3; ++k) c[k] += ToVec3(a)[k] / double(vs.size());
      }
      const double len = Norm(n);
      setup.normal[f] = len > 0 ? Vec3{n[0] / len, n[1] / len, n[2] / len} : Vec3{0, 0, 1};
      setup.offset[f] = {0.0};
      double diagonals = 0;
      for (size_t i = 0; i < vs.size(); ++i) {
        diagonals += Norm(Sub(ToVec3(mesh.point(vs[(i + 2) % vs.size()])), ToVec3(mesh.point(vs[i]))));
      }
      setup.polygons.push_back({f, vs, c, double(vs.size()) / diagonals});
      setup.weight[f.idx()] = s.terms.face_planarity;
    }
  }
  setup.boundary = BoundaryVertices(mesh);
  setup.fixed = s.fixed.empty() ? std::vector<bool>(mesh.number_of_vertices(), false) : s.fixed;
  setup.original = Positions(mesh);
  if (s.terms.fairness > 0) {
    setup.triples = PolylineTriples(MeshPolylines(mesh));
    setup.triple_target = FairnessTargets(setup.triples, setup.original, s.terms.fairness_relative);
  }
  return setup;
}

// One Ceres problem for the current linearisation; residual ids per term.
struct Built {
  std::unique_ptr<ceres::Problem> problem;
  TermBlocks terms;
  double weight_max = 0;
};

// Planarity residuals get weight base × `planarity_scale` and the tolerance
// band `band` (in δ_PQ,n units; 0 = none).
Built Build(Mesh& mesh, Setup& setup, const Projection& proj, const TermWeights& w,
            double planarity_scale, double band) {
  Built b;
  ceres::Problem::Options options;
  options.enable_fast_removal = false;
  b.problem = std::make_unique<ceres::Problem>(options);
  ceres::Problem& problem = *b.problem;
  auto pos = [&](VertexIndex v) { return PositionBlock(mesh, v); };

  for (const Quad& q : setup.quads) {
    const double wf = setup.weight[q.face.idx()] * planarity_scale;
    if (wf <= 0) continue;
    b.weight_max = std::max(b.weight_max, wf);
    b.terms["pq_diagonal"].push_back(problem.AddResidualBlock(
        new ToleranceBand(MakePqDiagonal(q.inv_length), band), Weight(wf), pos(q.v[0]),
        pos(q.v[1]), pos(q.v[2]), pos(q.v[3])));
  }
  for (Polygon& poly : setup.polygons) {
    const double wf = setup.weight[poly.face.idx()] * planarity_scale;
    if (wf <= 0) continue;
    b.weight_max = std::max(b.weight_max, wf);
    double* n = setup.normal[poly.face].data();
    double* d = setup.offset[poly.face].data();
    for (VertexIndex v : poly.v) {
      b.terms["face_planarity"].push_back(problem.AddResidualBlock(
          new ToleranceBand(MakeFacePlanarity(poly.center.data(), poly.inv_length), band),
          Weight(wf), n, d, pos(v)));
    }
    problem.SetManifold(n, new ceres::SphereManifold<3>());
  }
  AddProximityTerms(problem, mesh, &proj, setup.original, ProximityWeightsOf(w), b.terms);
  for (size_t t = 0; t < setup.triples.size(); ++t) {
    const auto& tr = setup.triples[t];
    b.terms["fairness"].push_back(problem.AddResidualBlock(
        MakeFairness(setup.triple_target[t].data(), 1.0), Weight(w.fairness), pos(tr[0]),
        pos(tr[1]), pos(tr[2])));
  }
  FixVertices(problem, mesh, setup.fixed);
  return b;
}

// Per Ceres iteration: measures max δ_PQ,n on the current positions, prints
// the progress line, and ends the solve as soon as the tolerance holds.
class IterationWatch : public ceres::IterationCallback {
 public:
  IterationWatch(const Mesh& mesh, double tolerance, const ProgressSink& sink, int outer)
      : mesh_(mesh), tolerance_(tolerance), sink_(sink), outer_(outer) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    const double pq = MaxNormalizedPlanarity(mesh_);
    if (sink_) {
      char line[200];
      std::snprintf(line, sizeof line,
                    "outer %2d  iter %3d  cost %.6e  max δ_PQ,n %.3e  |gradient| %.2e  |step| "
                    "%.2e  %.3f s",
                    outer_, s.iteration, s.cost, pq, s.gradient_max_norm, s.step_norm,
                    s.cumulative_time_in_seconds);
      sink_(line);
    }
    if (tolerance_ > 0 && pq <= tolerance_) return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const Mesh& mesh_;
  double tolerance_;
  const ProgressSink& sink_;
  int outer_;
};

}  // namespace

PlanarQuadsResult SolvePlanarQuads(Mesh& mesh, const ReferenceSurface& reference,
                                   const PlanarQuadsSettings& settings,
                                   const ProgressSink& progress) {
  using Clock = std::chrono::steady_clock;
  PlanarQuadsResult result;
  Setup setup = MakeSetup(mesh, settings);
  const ceres::Solver::Options base_options = ToCeresOptions(settings.solver);
  const double tol = settings.tolerance;
  const double band = settings.continuation_band * tol;
  double planarity_scale = 1.0;
  Built built;

  for (int outer = 1; outer <= settings.solver.outer_iterations; ++outer) {
    const auto start = Clock::now();
    const Projection proj = Project(mesh, reference, setup.boundary);
    result.seconds["projection"] += std::chrono::duration<double>(Clock::now() - start).count();
    built = Build(mesh, setup, proj, settings.terms, planarity_scale, band);

    std::vector<Vec3> before;
    for (VertexIndex v : mesh.vertices()) before.push_back(ToVec3(mesh.point(v)));

    ceres::Solver::Options options = base_options;
    IterationWatch watch(mesh, tol, progress, outer);
    options.callbacks.push_back(&watch);
    options.update_state_every_iteration = true;
    ceres::Solver::Summary summary;
    ceres::Solve(options, built.problem.get(), &summary);

    result.outer_iterations = outer;
    if (!RecordSolve(summary, *built.problem, mesh, result)) return result;

    OuterIterationLog log;
    log.outer = outer;
    log.inner_iterations = int(summary.iterations.size()) - 1;
    log.cost = summary.final_cost;
    log.weight_max = built.weight_max;
    for (VertexIndex v : mesh.vertices()) {
      log.max_move = std::max(log.max_move, Norm(Sub(ToVec3(mesh.point(v)), before[v.idx()])));
    }
    const PlanarityMeasure planarity = MeasureFacePlanarity(mesh);
    for (FaceIndex f : mesh.faces()) {
      const double d = planarity.normalized[f.idx()];
      log.pq_normalized_max = std::max(log.pq_normalized_max, d);
      if (tol > 0 && d > tol) ++log.faces_above_tolerance;
    }
    log.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.log.push_back(log);
    if (progress) {
      char line[200];
      std::snprintf(line, sizeof line,
                    "outer %2d  done: %d iterations  cost %.6e  max δ_PQ,n %.3e  faces above "
                    "tolerance %d  max weight %.3g  max move %.2e",
                    outer, log.inner_iterations, log.cost, log.pq_normalized_max,
                    log.faces_above_tolerance, log.weight_max, log.max_move);
      progress(line);
    }

    if (tol > 0) {
      if (log.pq_normalized_max <= tol) {
        result.tolerance_met = true;
        break;
      }
      planarity_scale *= settings.continuation_factor;  // short of the tolerance
    } else if (log.max_move < kStillMove) {
      break;
    }
  }

  if (built.problem) result.objective = TermObjective(*built.problem, built.terms);
  return result;
}

}  // namespace archgeo
