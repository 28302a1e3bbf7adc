// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `planar_quads`: every quad (and polygon) planar to a tolerance
// while the mesh keeps its shape, its boundary and its visual smoothness.
//
// Objective [Zadravec 2010, §6, eq. 8], ½ Σ w r² in the canonical frame (unit
// mean edge length), so every weight is unit-free:
//   pq_diagonal (quads) + face_planarity (every face of 4+ sides: it also
//   ties the plane normals the dihedral energy reads to the vertices)
//   + fairness relative to the input (eq. 8's fairness term)
//   + dihedral_energy [Pellis 2019, eq. 3] (visual smoothness, E = Σ ℓ ℓ*)
//   + boundary_proximity + proximity (+ point_weight) + anchor,
// and the validity barriers convexity and min_edge_length, on by default
// (implicit: a spec that lists its terms keeps them) and continued with the
// planarity weights.
// Why these defaults (measured on the six quad meshes of ../shared/data):
// planarity alone reaches δ_PQ,n 6.8e-4 on libigl's Conjugate layout by
// bending 9-18 quads inward and raises E from 75.9 to 105.5; the barriers
// alone keep every quad convex but stall at 3.3e-3 (the planarity weight
// pushes a few quads against them); fairness relative to the input spreads
// the change over the net so that no quad has to fold: 9.7e-4 with every
// quad convex, and the dihedral energy keeps E at or below the input's on
// all six meshes (docs/methods/planar_quads.md).
// Rounds: project every vertex onto the reference (closest point and tangent
// plane, or boundary tangent line), rebuild, solve. The tolerance τ on max
// δ_PQ,n drives the run, not the weights:
//  - every Ceres iteration measures max δ_PQ,n and the solve stops the moment
//    it is ≤ τ, so the mesh moves no further than planarity demands;
//  - a round that ends short of τ multiplies the planarity weights by
//    continuation.factor (continuation on the penalty weight);
//  - with continuation.band b > 0 a face within b·τ costs nothing and only the
//    excess is penalised (core/tolerance_band.h).
// Measured on the six quad meshes of ../shared/data: per-face weights stalled
// (fixing one face pushed its neighbours out), and a band of 0.8 halves the
// movement for τ = 5e-3 but slows τ = 1e-3 down several times. Without a
// tolerance (τ = 0) the weights stay fixed and the rounds stop when a round
// moves no vertex by more than 1e-6 mean edge lengths.
// Stall: a run whose best valid max δ_PQ,n has not fallen by more than
// stall.fraction (1%) in stall.rounds (3) rounds ends there. On the nets far
// from conjugate (pillow, M2 and four public nets) the rounds after that
// only stiffen the same conflict up to the last of schedule.outer_iterations
// (rounds invalid, or gaining 0.3% each on M2); the four successes above gain more than 1%
// within every three rounds (the bubble's first two rounds nothing, its
// third 31%), and a grid with hexagons 2.7-6% per round for five rounds
// before it meets the tolerance in one step (tests/test_planar_quads.cpp).
// Worst quads: the tolerance bounds the maximum of δ_PQ,n, the planarity
// terms lower the sum of squares, and on a net far from conjugate the two
// part (the pillow's worst quad gets worse as the sum falls). With
// relayout: never a run that misses the tolerance goes on with a second
// stage that lowers a p-norm of δ_PQ,n (pq_worst, p = 16) from the input
// (problems/declarations/worst_quads.h): pillow 0.0470 → 0.0383, M2 0.0765
// → 0.0201 with every panel convex, below the Shape-Up iteration's best
// convex states (0.0402, 0.0218) and moving less
// (docs/methods/planar_quads.md#the-worst-quads).
#include <utility>

#include "core/problem.h"
#include "problems/declarations/design_band.h"
#include "problems/declarations/field_pipeline.h"
#include "problems/declarations/flatness.h"
#include "problems/declarations/relayout.h"
#include "problems/declarations/worst_quads.h"

namespace archgeo::problems {

ProblemDecl PlanarQuadsGoals() {
  ProblemDecl d;
  d.name = "planar_quads";
  d.summary = "make every quad (and polygon) planar while the mesh keeps its shape and boundary";
  d.paper = "[Zadravec 2010, §6, eq. 8]";
  d.input = InputKind::kHasPolygons;
  d.terms = {{"pq_diagonal", 10},
             {"pq_worst", 30, {}, "", true},
             {"face_planarity", 10, {}, "non_triangles"},
             {"boundary_proximity", 10},
             {"proximity", 2, {{"point_weight", 0.01}}},
             {"anchor", 1},
             {"fairness", 10, {{"relative_to_original", true}}},
             {"dihedral_energy", 0.5},
             {"convexity", 1000, {}, "", true},
             {"min_edge_length", 1000, {}, "", true}};
  // Every round by LeanSolve (core/lean_solve.h): Levenberg–Marquardt on the
  // assembled normal equations, each step one sparse Cholesky factorisation
  // up to 100k variables (~15k quads), block-Jacobi conjugate gradients
  // above; docs/performance.md has the measurements. Ceres' SUBSET
  // preconditioner, if chosen, from the planarity terms and the barriers
  // (the terms the continuation stiffens).
  d.defaults = {{"solver.back_end", std::string("lean")},
                {"solver.pcg_above", 100000LL},
                {"solver.subset_preconditioner_parts",
                 std::string("pq_diagonal,face_planarity,convexity,min_edge_length")}};
  d.keys = {
      NumberKey("tolerance.pq_normalized_max", 1e-3, 0, 1,
                "stop as soon as every quad has δ_PQ,n at most this; 0 = fixed weights, "
                "rounds until at rest"),
      BoolKey("tolerance.energy_not_above_input", true,
              "the output's E (Σ ℓ ℓ*, Pellis §3) at most the input's (a net the user gave, "
              "not one archgeo laid out): planar panels that cost "
              "the design's fairness end exit 4 (the report's tolerances entry: bound = the "
              "input's E, met); false = off"),
      NumberKey("continuation.band", 0, 0, 1,
                "a face within band × tolerance costs nothing (only the excess is penalised): "
                "less movement for a loose tolerance"),
      NumberKey("continuation.factor", 10, 1, 1e6,
                "planarity weight growth per round that ends short of the tolerance"),
      NumberKey("continuation.start", 1, 1, 1e30,
                "scale of the continued weights (planarity, barriers) in the first round; it grows by "
                "continuation.factor per round short of the tolerance. A session's re-solve "
                "(archgeo::Session) starts at the scale its last solve ended with"),
      NumberKey("stall.fraction", 0.01, 0, 1,
                "stall: the run ends (exit 4: the tolerance is missed) once stall.rounds "
                "rounds in a row have not lowered the best valid max δ_PQ,n by more than "
                "this fraction; 0 = off (also without a tolerance)"),
      IntegerKey("stall.rounds", 3, 1, 100000,
                 "rounds without a gain of stall.fraction that end the run"),
      ChoiceKey("relayout", "suggest", {"never", "suggest", "auto"},
                "a net far from conjugate (problems/declarations/relayout.h): suggest = a missed "
                "tolerance ends with the conjugate_layout command for the net's surface; auto = "
                "an unsuitable net is replaced by the conjugate layout of its surface (a new "
                "connectivity) before planarising; never = neither")};
  d.stages = [](const Settings& settings) {
    Stage s;
    s.rounds_key = "schedule.outer_iterations";
    s.tolerances = {{"pq_normalized_max", "tolerance.pq_normalized_max", true}};
    s.continued = {"pq_diagonal", "face_planarity", "convexity", "min_edge_length"};
    s.factor_key = "continuation.factor";
    s.band_key = "continuation.band";
    s.rest_move = 1e-6;
    // A run that misses the tolerance returns its flattest valid round (the
    // input itself if no round was flatter), never a less planar one.
    s.keep_best = "pq_normalized_max";
    // A net that cannot become planar with valid panels stops gaining within
    // a few rounds (continuation only stiffens the same conflict): end there.
    // Without a tolerance the weights stay fixed and the rest rule ends the run.
    if (settings.Number("tolerance.pq_normalized_max") > 0) {
      s.patience_measure = "pq_normalized_max";
      s.patience_key = "stall.fraction";
      s.patience_rounds_key = "stall.rounds";
      s.patience_valid = true;
    }
    s.logged = {"pq_normalized_max", "E"};
    s.terms = {"pq_diagonal", "face_planarity", "boundary_proximity", "proximity", "anchor",
               "fairness", "dihedral_energy", "convexity", "min_edge_length"};
    std::vector<Stage> stages{s};
    // A net kept as it is (relayout: never) that misses the tolerance gets
    // the worst-quads stage (problems/declarations/worst_quads.h); suggest
    // and auto end at the stall and hand the net to the conjugate layout.
    if (HasWorstQuadsStage(settings)) {
      stages.push_back(WorstQuadsStage(s));
    }
    return stages;
  };
  d.analyses = {"planarity", "smoothness"};
  // Before solving: warn when the quads are far from a conjugate net
  // (problems/declarations/suitability.h); with relayout: auto, re-lay such a
  // net; with relayout: suggest, a missed tolerance ends with the command
  // that does (problems/declarations/relayout.h).
  d.net = &CheckOrRelayout;
  d.init = &KeepStartState;
  d.measures[kWorstStagePq] = &WorstStagePq;
  return d;
}

// The band tightening runs on a net near conjugate: the suitability check
// (problems/declarations/suitability.h) finds it so, or the net is a layout
// along a conjugate field (relayout: auto). On a net far from conjugate the
// goals do not hold with the band open either: the stall is the net's.
namespace {
bool NearConjugate(HookContext& c) {
  if (c.net.derived) return true;
  c.RecordChecks(true);
  return !c.details.contains("suitability") || c.details["suitability"].value("suitable", true);
}
}  // namespace

ProblemDecl WithPlanarQuadsBounds(ProblemDecl d, bool measure_need) {
  // The deviation band (problems/declarations/design_band.h): 1.5% of the
  // diagonal. With today's terms the shared Conjugate net needs 0.65% for
  // δ_PQ,n ≤ 1e-3 and Smooth 1.03%; at 0.3% both end exit 4 with the band
  // binding (docs/methods/design_band.md), and with measure_need the report
  // gives the deviation the same run reaches without the band.
  // Flatness in millimetres beside δ_PQ,n (problems/declarations/flatness.h).
  // planar_quads itself (measure_need) also gets the band tightening stage.
  return WithDesignBand(WithFlatness(std::move(d)), 0.015, measure_need,
                        measure_need ? BandTighteningIf(&NearConjugate) : BandTighteningIf());
}

ProblemDecl planar_quads() {
  ProblemDecl d = PlanarQuadsGoals();
  d.finish = &SuggestRelayout;
  return WithPlanarQuadsBounds(std::move(d), true);
}

}  // namespace archgeo::problems
