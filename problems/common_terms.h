// archgeo — pieces every builder's outer loop shares: projection onto the
// reference, the proximity/anchor terms, fixed vertices, the per-term
// objective and the bookkeeping of one Ceres solve.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <ceres/problem.h>
#include <ceres/solver.h>

#include "mesh/surface_mesh.h"
#include "problems/solve_outcome.h"

namespace archgeo {

class ReferenceSurface;

// Closest points and their tangent planes/lines for every vertex (indexed
// by vertex index): boundary vertices go to the reference's boundary curve
// (tangent line) when the reference has one, the others to the surface
// (normal of the tangent plane).
struct Projection {
  std::vector<Vec3> point, direction;  // direction: normal (surface) or tangent (boundary)
  std::vector<bool> on_boundary_curve;
};
Projection Project(const Mesh& mesh, const ReferenceSurface& reference,
                   const std::vector<bool>& boundary);

// Weights of the shared proximity terms (0 = off); see energies/proximity.h,
// boundary_proximity.h, anchor.h. All in the canonical frame (unit mean edge).
struct ProximityWeights {
  double proximity = 0;           // distance to the tangent plane at π(v)
  double proximity_point = 0;     // distance to π(v) itself
  double boundary_proximity = 0;  // distance to the boundary tangent line
  double anchor = 0;              // distance to `original[v]`
};

// Residual ids per term name (for the per-term objective).
using TermBlocks = std::map<std::string, std::vector<ceres::ResidualBlockId>>;

// A ScaledLoss with weight w (Ceres minimises ½ Σ w r²).
ceres::LossFunction* Weight(double w);

// The proximity weights of a builder's term weights (any struct with
// members proximity, proximity_point, boundary_proximity and anchor).
template <typename Terms>
ProximityWeights ProximityWeightsOf(const Terms& w) {
  return {w.proximity, w.proximity_point, w.boundary_proximity, w.anchor};
}

// Adds the proximity terms for every non-isolated vertex of `mesh`; without
// a projection (`proj` null) only the anchor. `proj` and `original` must
// outlive the problem.
void AddProximityTerms(ceres::Problem& problem, Mesh& mesh, const Projection* proj,
                       const std::vector<Vec3>& original, const ProximityWeights& w,
                       TermBlocks& terms);

// Makes the position blocks of `fixed` vertices constant (those in the problem).
void FixVertices(ceres::Problem& problem, Mesh& mesh, const std::vector<bool>& fixed);

// ½ Σ w r² per term and "total".
std::map<std::string, double> TermObjective(ceres::Problem& problem, const TermBlocks& terms);

// Adds a Ceres summary to `outcome` (iterations, variables, timings) and
// marks it unusable (with Ceres' message) if the solution is not usable or
// a vertex of `mesh` is not finite. Returns outcome.usable.
bool RecordSolve(const ceres::Solver::Summary& summary, const ceres::Problem& problem,
                 const Mesh& mesh, SolveOutcome& outcome);

// Targets of the fairness terms (energies/fairness.h), one per tuple of 3
// (second differences p0 − 2p1 + p2) or 4 vertices (third differences
// p3 − 3p2 + 3p1 − p0): the differences of `original` when `relative`
// (keep the input's shape), else 0.
std::vector<Vec3> FairnessTargets(const std::vector<std::vector<VertexIndex>>& tuples,
                                  const std::vector<Vec3>& original, bool relative);
std::vector<Vec3> FairnessTargets(const std::vector<std::array<VertexIndex, 3>>& triples,
                                  const std::vector<Vec3>& original, bool relative);

// Positions of all vertices, and the largest distance between two such
// snapshots.
std::vector<Vec3> Positions(const Mesh& mesh);
double MaxMove(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

}  // namespace archgeo
