// archgeo — the planar_quads builder: make every quad (and polygon) planar
// while the mesh keeps its shape and its boundary.
//
// Objective [Zadravec 2010, §6, eq. 8], minimised by Ceres as ½ Σ w r²:
//   Σ_f w_f pq_diagonal_f² + w_poly Σ face_planarity²
//   + w_prox Σ_{v ∉ ∂} proximity_v² + w_∂ Σ_{v ∈ ∂} boundary_proximity_v²
//   + w_pt Σ_v |v − π(v)|² + w_anchor Σ_v |v − v⁰|² + w_fair Σ_triples fairness²
// in the canonical frame (unit mean edge length; see mesh/similarity.h), so
// every weight is unit-free.
//
// Outer iterations ("rounds"): project every vertex onto the reference
// (closest point and tangent plane, or boundary tangent line), rebuild the
// problem, solve. With a tolerance τ on max δ_PQ,n the run is driven by the
// tolerance, not by the weights:
//  - every Ceres iteration measures max δ_PQ,n and the solve stops the moment
//    it is ≤ τ, so the mesh moves no further than planarity demands;
//  - a round that ends short of τ multiplies the planarity weights by
//    continuation.factor (continuation on the penalty weight);
//  - with continuation.band b > 0 a face within b·τ costs nothing and only
//    the excess is penalised (problems/tolerance_band.h).
// Measured on the six quad meshes of ../shared/data: per-face weights
// stalled (fixing one face pushed its neighbours out), and a band of 0.8
// halves the movement for τ = 5e-3 but slows τ = 1e-3 down several times.
// Without a tolerance (τ = 0) the weights stay fixed and the loop stops when
// a round moves no vertex by more than 1e-6 mean edge lengths.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "mesh/surface_mesh.h"
#include "problems/progress.h"
#include "problems/solve_outcome.h"
#include "problems/solver_options.h"

namespace archgeo {

class ReferenceSurface;

// The `terms:` of a planar_quads spec (weights w; ½ Σ_terms w Σ r²).
// If `terms` is given, a term not listed is off.
//   pq_diagonal: 10        starting planarity weight (× continuation.factor
//                          after every round short of the tolerance).
//   face_planarity: 10     the same for faces with more than 4 sides.
//   fairness: {weight: 0, relative_to_original: true}   (or a number):
//                          second differences along mesh polylines.
//   proximity: {weight: 2, point_weight: 0.01}   distance to the reference's
//                          tangent plane; the point part pulls towards the
//                          closest point itself.
//   boundary_proximity: 2  distance to the reference's boundary tangent.
//   anchor: 0.1            pull towards each vertex's original position
//                          (keeps vertices from sliding along the surface).
// Other keys of the builder:
//   tolerance:
//     pq_normalized_max: 1e-3   stop as soon as every quad has δ_PQ,n ≤ this;
//                               0 turns the tolerance off: fixed weights, all
//                               outer iterations.
//   continuation:
//     band: 0                   a face whose δ_PQ,n is within band × tolerance
//                               costs nothing (only the excess is penalised):
//                               less movement for a loose tolerance, slower for
//                               a tight one. 0 pulls every face to planarity.
//     factor: 10                planarity weight growth per round short of
//                               the tolerance.
struct TermWeights {
  double pq_diagonal = 10.0;
  double face_planarity = 10.0;
  double fairness = 0.0;
  bool fairness_relative = true;
  double proximity = 2.0;
  double proximity_point = 0.01;
  double boundary_proximity = 2.0;
  double anchor = 0.1;
};

struct PlanarQuadsSettings {
  TermWeights terms;
  double tolerance = 1e-3;  // on max δ_PQ,n; 0 = fixed weights
  double continuation_band = 0.0;  // fraction of the tolerance left free
  double continuation_factor = 10;
  std::vector<bool> fixed;  // per vertex index; empty = none
  SolverSettings solver;
};

struct OuterIterationLog {
  int outer = 0;
  int inner_iterations = 0;
  double cost = 0;               // Ceres' final cost of this round (½ Σ w r²)
  double pq_normalized_max = 0;  // measured after the round
  int faces_above_tolerance = 0;
  double weight_max = 0;         // largest planarity weight used in the round
  double max_move = 0;           // largest vertex move in the round (mean edge lengths)
  double seconds = 0;
};

// SolveOutcome's counts, objective, seconds ("ceres", "linear_solver",
// "jacobian", "projection") and usability, plus:
struct PlanarQuadsResult : SolveOutcome {
  bool tolerance_met = false;
  std::vector<OuterIterationLog> log;
};

// Optimises `mesh` in place. `mesh` and `reference` must be in the same
// canonical frame. `progress` (may be empty) receives one line per Ceres
// iteration and one per outer iteration.
PlanarQuadsResult SolvePlanarQuads(Mesh& mesh, const ReferenceSurface& reference,
                                   const PlanarQuadsSettings& settings,
                                   const ProgressSink& progress);

}  // namespace archgeo
