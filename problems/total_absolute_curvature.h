// archgeo — the total_absolute_curvature builder: form finding of a surface
// of small total absolute curvature C(Φ) = ∫ |κ1| + |κ2| dA under boundary
// conditions [Pellis 2019, §4, §5.3; Fig. 13, 15, 19].
//
// Objective, minimised by Ceres as ½ Σ w r² in the canonical frame (unit mean
// edge length L = 1, mesh/similarity.h), so every weight is unit-free:
//   w_target Σ_v Σ_j λ_{j,v}² / (|λ⁽ⁱ⁻¹⁾_{j,v}| + ε)                 [§5.3, E_target]
//   + w_reg Σ_v ‖v − v⁽ⁱ⁻¹⁾‖²                                     [§5.1, R(X)]
//   + w_fair Σ_(u,v,w) ‖(u − 2v + w) − N_v N_vᵀ(u⁽ⁱ⁻¹⁾ − 2v⁽ⁱ⁻¹⁾ + w⁽ⁱ⁻¹⁾)‖²
//   + w_tp Σ_{b ∈ ∂, w ~ b, w ∉ ∂} (n_b · (w − b⁰))²                  (tangent planes)
//   + w_prox Σ_v (proximity to the reference, as in planar_quads)
// λ_{1,v} ≥ λ_{2,v}: the tangential eigenvalues of the modified normal-cycle
// shape operator W′_v = ½ Σ_{e=vw} (n_f × n_f′)(w − v)ᵀ of every vertex with
// at least one interior edge (energies/total_absolute_curvature.h); C ≈ Σ_v
// |λ1,v| + |λ2,v|.
//
// Rounds (the weight iteration of §5.3): round i evaluates λ⁽ⁱ⁻¹⁾, the
// positions v⁽ⁱ⁻¹⁾ and the vertex normals N_v on the current mesh, builds the
// problem and runs at most solver.max_iterations Ceres iterations; at most
// solver.outer_iterations rounds, fewer when a round moves no vertex by more
// than irls.rest_move mean edge lengths or changes C by less than the
// fraction irls.rest_change. Each round logs C (from the exact
// λ, canonical frame), the largest vertex move and its time.
//
// Fairness [§5.3: "a sum of squares of umbrella vectors", Kobbelt 1998]:
// at a vertex of valence k the triples (w_i, v, w_{i+⌊k/2⌋}), i = 1..k (i <
// k/2 for even k), are "straight through v" second differences
// (energies/fairness.h) whose sum is 2k (or k) times the umbrella vector
// (1/k) Σ w_i − v; on a free boundary vertex the triple along the boundary.
// By default (normal_part: free) each triple's target is its own previous
// round's component along N_v, so at a fixed point of the rounds only the
// tangential part of the second differences is penalised: the fairness keeps
// the triangulation regular without pulling the surface towards a minimal
// surface. Measured on the cone of Fig. 13 (24 × 11 vertices, max radial
// deviation from the cone / height): w_fair = 0.05 gives 0.24% either way;
// w_fair = 5 gives 0.29% with normal_part: free, 1.29% with penalised.
//
// Boundary conditions: hard-fixed vertices come from the common `fixed:` key
// (normally `fixed: boundary`); the tangent planes along the boundary are
// those of the input mesh at its boundary vertices b (normal n_b = unit sum of
// the unit normals of the faces at b, mesh/smoothness_metrics.h VertexNormal),
// prescribed [Fig. 15] either by fixing the second ring (every non-boundary
// neighbour of a boundary vertex keeps its input position) or softly by the
// tangent-plane term above, or both.
//
// Spec keys of the builder (all optional; defaults as shown):
//   terms:                      listing `terms` turns every unlisted term off
//     target: 1                 w_target, the IRLS total absolute curvature
//     regularizer: 0.01         w_reg, pull towards the previous round
//     fairness: {weight: 0.05, normal_part: free}   (or a number):
//                               w_fair; normal_part: free (tangential
//                               second differences only, see above) or
//                               penalised (the full umbrella triples)
//     proximity: {weight: 0, point_weight: 0}   optional pull to the
//                               reference surface (the input by default):
//                               distance to its tangent plane at the closest
//                               point (+ to the point itself); 0 = off
//   boundary:
//     tangent_planes: free      free | fix_second_ring | term | both
//     weight: 10                w_tp of the tangent-plane term (term, both)
//   irls:
//     epsilon: 1e-3             ε of the weights |λ⁽ⁱ⁻¹⁾|/L + ε (unit-free)
//     rest_move: 1e-3           stop when a round moves every vertex less
//                               than this (mean edge lengths) ...
//     rest_change: 1e-3         ... or changes C by less than this fraction
//                               (the shape has settled; what still moves is
//                               the fairness sliding vertices along it)
// Triangle meshes only (CheckInput throws InputError naming the file).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "mesh/surface_mesh.h"
#include "problems/builder.h"
#include "problems/progress.h"
#include "problems/solve_outcome.h"
#include "problems/solver_options.h"

namespace archgeo {

class ReferenceSurface;

// How the tangent planes along the boundary are prescribed (see above).
enum class TangentPlanes { kFree, kFixSecondRing, kTerm, kBoth };

// Weights of the terms (½ Σ w r², canonical frame).
struct TacWeights {
  double target = 1.0;
  double regularizer = 0.01;
  double fairness = 0.05;
  bool fairness_normal_free = true;  // normal_part: free
  double proximity = 0.0;
  double proximity_point = 0.0;
};

struct TotalAbsoluteCurvatureSettings {
  TacWeights terms;
  TangentPlanes tangent_planes = TangentPlanes::kFree;
  double tangent_plane_weight = 10.0;
  double irls_epsilon = 1e-3;
  double rest_move = 1e-3;    // mean edge lengths
  double rest_change = 1e-3;  // relative change of C in a round
  std::vector<bool> fixed;  // per vertex index; empty = none
  SolverSettings solver;
};

// One round of the weight iteration.
struct TacRoundLog {
  int round = 0;
  int iterations = 0;    // Ceres iterations
  double cost = 0;       // Ceres' final cost (½ Σ w r²)
  double C = 0;          // Σ |λ1| + |λ2| after the round (canonical frame, length)
  double max_move = 0;   // largest vertex move in the round (mean edge lengths)
  double seconds = 0;
};

// SolveOutcome's counts (outer_iterations: rounds), objective ("target",
// "regularizer", "fairness", "tangent_planes", "proximity", ..., "total"),
// seconds ("ceres", "linear_solver", "jacobian") and usability, plus:
struct TotalAbsoluteCurvatureResult : SolveOutcome {
  double C_start = 0;   // Σ |λ1| + |λ2| before the first round (canonical frame)
  std::vector<TacRoundLog> log;
};

// Σ_v |λ1,v| + |λ2,v| of `mesh` with the exact tangential eigenvalues of
// EvaluateVertexShapeOperator (energies/total_absolute_curvature.h), over the
// vertices with at least one interior edge; units: length (the mesh's).
// Precondition: a triangle mesh.   [Pellis 2019, §5.3]
double DiscreteTotalAbsoluteCurvature(const Mesh& mesh);

// Optimises the triangle mesh `mesh` in place (it should be in the canonical
// frame: the weights assume unit mean edge length). `reference` (same frame)
// is used only when the proximity weight is > 0 and may then not be null.
// `progress` (may be empty) receives one line per Ceres iteration and one per
// round. Precondition (CHECKed): every face a triangle; settings.fixed empty
// or one entry per vertex.
TotalAbsoluteCurvatureResult SolveTotalAbsoluteCurvature(
    Mesh& mesh, const ReferenceSurface* reference,
    const TotalAbsoluteCurvatureSettings& settings, const ProgressSink& progress);

}  // namespace archgeo
