// archgeo — `planar_quads`: every quad (and polygon) planar to a tolerance
// while the mesh keeps its shape and its boundary.
//
// Objective [Zadravec 2010, §6, eq. 8], ½ Σ w r² in the canonical frame (unit
// mean edge length), so every weight is unit-free:
//   pq_diagonal (quads) + face_planarity (polygons > 4 sides)
//   + boundary_proximity + proximity (+ point_weight) + anchor + fairness,
// and, off by default, the validity barriers convexity and min_edge_length
// (continued with the planarity weights when on). Measured with both at 1000
// on the six quad meshes of ../shared/data: every result convex and valid,
// but where planarity needs a fold (M2, pillow, Smooth, the bubble) the
// continued weights then drag vertices 1.1-5.2% of the diagonal and stall at
// δ_PQ,n 3.3e-3-4.2e-2; without them the loop returns the last valid round
// instead. examples/planar_smooth.yaml turns them on with the dihedral energy.
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
#include "core/problem.h"

namespace archgeo::problems {

ProblemDecl planar_quads() {
  ProblemDecl d;
  d.name = "planar_quads";
  d.summary = "make every quad (and polygon) planar while the mesh keeps its shape and boundary";
  d.paper = "[Zadravec 2010, §6, eq. 8]";
  d.input = InputKind::kHasPolygons;
  d.terms = {{"pq_diagonal", 10},
             {"face_planarity", 10, {}, "polygons"},
             {"boundary_proximity", 2},
             {"proximity", 2, {{"point_weight", 0.01}}},
             {"anchor", 0.1},
             {"fairness", 0, {{"relative_to_original", true}}},
             {"convexity", 0},
             {"min_edge_length", 0}};
  d.keys = {
      NumberKey("tolerance.pq_normalized_max", 1e-3, 0, 1,
                "stop as soon as every quad has δ_PQ,n at most this; 0 = fixed weights, "
                "rounds until at rest"),
      NumberKey("continuation.band", 0, 0, 1,
                "a face within band × tolerance costs nothing (only the excess is penalised): "
                "less movement for a loose tolerance"),
      NumberKey("continuation.factor", 10, 1, 1e6,
                "planarity weight growth per round that ends short of the tolerance")};
  d.stages = [](const Settings&) {
    Stage s;
    s.rounds_key = "schedule.outer_iterations";
    s.tolerances = {{"pq_normalized_max", "tolerance.pq_normalized_max", true}};
    s.continued = {"pq_diagonal", "face_planarity", "convexity", "min_edge_length"};
    s.factor_key = "continuation.factor";
    s.band_key = "continuation.band";
    s.rest_move = 1e-6;
    s.logged = {"pq_normalized_max"};
    return std::vector<Stage>{s};
  };
  d.analyses = {"planarity"};
  return d;
}

}  // namespace archgeo::problems
