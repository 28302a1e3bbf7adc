#include "problems/common_terms.h"

#include <glog/logging.h>

#include <ceres/loss_function.h>

#include <algorithm>
#include <cmath>

#include "energies/anchor.h"
#include "energies/boundary_proximity.h"
#include "energies/proximity.h"
#include "mesh/reference.h"

namespace archgeo {

Projection Project(const Mesh& mesh, const ReferenceSurface& reference,
                   const std::vector<bool>& boundary) {
  Projection p;
  const size_t n = mesh.number_of_vertices();
  p.point.resize(n);
  p.direction.resize(n);
  p.on_boundary_curve.assign(n, false);
  const bool curves = reference.HasBoundary();
  for (VertexIndex v : mesh.vertices()) {
    const Vec3 x = ToVec3(mesh.point(v));
    if (curves && boundary[v.idx()]) {
      const auto c = reference.ClosestOnBoundary(x);
      p.point[v.idx()] = c->point;
      p.direction[v.idx()] = c->tangent;
      p.on_boundary_curve[v.idx()] = true;
    } else {
      const auto c = reference.Closest(x);
      p.point[v.idx()] = c.point;
      p.direction[v.idx()] = c.normal;
    }
  }
  return p;
}

ceres::LossFunction* Weight(double w) {
  return new ceres::ScaledLoss(nullptr, w, ceres::TAKE_OWNERSHIP);
}

void AddProximityTerms(ceres::Problem& problem, Mesh& mesh, const Projection* projection,
                       const std::vector<Vec3>& original, const ProximityWeights& w,
                       TermBlocks& terms) {
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_isolated(v)) continue;
    const size_t i = v.idx();
    double* x = PositionBlock(mesh, v);
    if (projection) {
      const Projection& proj = *projection;
      if (proj.on_boundary_curve[i]) {
        if (w.boundary_proximity > 0) {
          terms["boundary_proximity"].push_back(problem.AddResidualBlock(
              MakeBoundaryProximity(proj.point[i].data(), proj.direction[i].data(), 1.0),
              Weight(w.boundary_proximity), x));
        }
      } else if (w.proximity > 0) {
        terms["proximity"].push_back(problem.AddResidualBlock(
            MakeProximity(proj.point[i].data(), proj.direction[i].data(), 1.0),
            Weight(w.proximity), x));
      }
      if (w.proximity_point > 0 && (w.proximity > 0 || w.boundary_proximity > 0)) {
        terms["proximity_point"].push_back(problem.AddResidualBlock(
            MakeAnchor(proj.point[i].data(), 1.0), Weight(w.proximity_point), x));
      }
    }
    if (w.anchor > 0) {
      terms["anchor"].push_back(
          problem.AddResidualBlock(MakeAnchor(original[i].data(), 1.0), Weight(w.anchor), x));
    }
  }
}

void FixVertices(ceres::Problem& problem, Mesh& mesh, const std::vector<bool>& fixed) {
  for (VertexIndex v : mesh.vertices()) {
    if (v.idx() < fixed.size() && fixed[v.idx()] &&
        problem.HasParameterBlock(PositionBlock(mesh, v))) {
      problem.SetParameterBlockConstant(PositionBlock(mesh, v));
    }
  }
}

std::map<std::string, double> TermObjective(ceres::Problem& problem, const TermBlocks& terms) {
  std::map<std::string, double> objective;
  auto cost = [&](const std::vector<ceres::ResidualBlockId>* blocks) {
    ceres::Problem::EvaluateOptions options;
    if (blocks) options.residual_blocks = *blocks;
    double c = 0;
    problem.Evaluate(options, &c, nullptr, nullptr, nullptr);
    return c;
  };
  for (const auto& [name, ids] : terms) objective[name] = cost(&ids);
  objective["total"] = cost(nullptr);
  return objective;
}

bool RecordSolve(const ceres::Solver::Summary& summary, const ceres::Problem& problem,
                 const Mesh& mesh, SolveOutcome& outcome) {
  outcome.variables = problem.NumParameters();
  outcome.residuals = problem.NumResiduals();
  outcome.inner_iterations += std::max(0, int(summary.iterations.size()) - 1);
  outcome.seconds["ceres"] += summary.total_time_in_seconds;
  outcome.seconds["linear_solver"] += summary.linear_solver_time_in_seconds;
  outcome.seconds["jacobian"] += summary.jacobian_evaluation_time_in_seconds;
  bool finite = true;
  for (VertexIndex v : mesh.vertices()) {
    for (double c : ToVec3(mesh.point(v))) finite = finite && std::isfinite(c);
  }
  if (!summary.IsSolutionUsable() || !finite) {
    outcome.usable = false;
    outcome.message = finite ? summary.message : "the solver produced non-finite coordinates";
  }
  return outcome.usable;
}

std::vector<Vec3> FairnessTargets(const std::vector<std::vector<VertexIndex>>& tuples,
                                  const std::vector<Vec3>& original, bool relative) {
  std::vector<Vec3> targets(tuples.size(), Vec3{0, 0, 0});
  for (size_t i = 0; relative && i < tuples.size(); ++i) {
    const auto& t = tuples[i];
    CHECK(t.size() == 3 || t.size() == 4) << "fairness tuple of " << t.size() << " vertices";
    for (int c = 0; c < 3; ++c) {
      const auto o = [&](int j) { return original[t[j].idx()][c]; };
      targets[i][c] = t.size() == 3 ? o(0) - 2 * o(1) + o(2) : o(3) - 3 * o(2) + 3 * o(1) - o(0);
    }
  }
  return targets;
}

std::vector<Vec3> FairnessTargets(const std::vector<std::array<VertexIndex, 3>>& triples,
                                  const std::vector<Vec3>& original, bool relative) {
  std::vector<std::vector<VertexIndex>> tuples;
  for (const auto& t : triples) tuples.push_back({t.begin(), t.end()});
  return FairnessTargets(tuples, original, relative);
}

std::vector<Vec3> Positions(const Mesh& mesh) {
  std::vector<Vec3> p;
  p.reserve(mesh.number_of_vertices());
  for (VertexIndex v : mesh.vertices()) p.push_back(ToVec3(mesh.point(v)));
  return p;
}

double MaxMove(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double m = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
    const double dx = a[i][0] - b[i][0], dy = a[i][1] - b[i][1], dz = a[i][2] - b[i][2];
    m = std::max(m, std::sqrt(dx * dx + dy * dy + dz * dz));
  }
  return m;
}

}  // namespace archgeo
