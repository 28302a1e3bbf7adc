// archgeo — the hnet builder: optimise a quad mesh towards an A-net and
// extend it to a smooth hyperbolic net (H-net) of rational bilinear patches
// [Shi, Wang, Pottmann 2014, §3.2, Fig. 4, Table 1].
//
// Pipeline (Fig. 4), in the canonical frame (unit mean edge length, see
// mesh/similarity.h), so every weight below is unit-free:
//  step 1  minimise F_anet = Σ F_p + λ1 F_fairness + λ2 F_prox      [eq. 10]
//          (F_p: energies/anet_planarity.h; F_fairness: energies/fairness.h;
//          F_prox: tangent-plane + closest-point distance, problems/common_terms.h);
//  step 2  BuildHNet on the current vertices: W by eq. 7 from one face, the
//          common scale λ from the quartic of eq. 11 (mesh/hnet.h);
//  step 3  minimise F_frame = F_anet + λ3 Σ_edges F_quad(b0, f1, b3, f4) with
//          the shape parameters of step 2 FIXED (energies/frame_coplanarity.h);
//  steps 2 and 3 alternate `hnet.alternations` times, then a final step 2, so
//  the weights reported and written belong to the final vertices (measuring
//  the written net with mesh/hnet.h reproduces the reported kinks). A step-3
//  round after which α_max is larger than before it is undone (vertices and
//  H-net restored; "undone" in the round log) and ends the alternation: on
//  nets that are not simply connected, or have holes, the propagated W can
//  disagree across closing edges by factors of 2 (mismatch ~1), and the frame
//  terms there are then met only by degenerate patches (α_max → 180°).
// Every Ceres solve ("round") re-projects the vertices onto the reference
// first. Step 1 runs rounds until the star planarity (HNet::star_planarity_max:
// max distance of a neighbour from the star's least-squares plane over the
// star's mean edge length) is ≤ hnet.star_planarity, at most
// solver.outer_iterations rounds; a round that ends above that tolerance
// multiplies the planarity weights (anet_planarity and frame_coplanarity) by
// hnet.continuation_factor (continuation on the penalty weight, as in
// problems/planar_quads.h). Step 3 rounds continue the same continuation.
//
// Frame-coplanarity weights: per interior edge b0b3 (Shi Fig. 2 labels) the
// left patch is normalised to w0 = w1 = w3 = 1, w2 = W_l (its shape parameter
// for the diagonal b0b2) and the right one to w0 = w3 = w5 = 1, w4 = W_r (for
// b0b4), the normalisation of Shi Prop. 1, so both give the edge the same
// frame point and r = 0 is eq. 5 (with planar stars: the smooth join).
//
// A-net planarity of boundary vertices: a boundary vertex of valence ≥ 3 gets
// the n − 2 quads (or neighbour distances) of its open star, neighbours in
// order from one boundary neighbour to the other — its tangent plane is
// shared by the patches of the interior edges ending there, so their joins
// need it planar too. Corners (valence 2) get none.
//
// Inputs must be pure quad meshes (CheckInput throws InputError for key
// 'mesh'). Odd interior valences, not-equitwist edges, a non-bipartite vertex
// graph and the closing edges of non-simply-connected nets (e.g. a catenoid
// band) are not errors: the pipeline optimises beyond the theory, as the
// paper does, and reports them and the resulting kinks honestly (details and
// headline).
//
// Spec keys (all optional; `terms`, if given, turns every unlisted term off):
//   terms:
//     anet_planarity: {weight: 10, variant: normals}
//                     F_p, weight of the vertex-star planarity; variant
//                     normals: a unit vertex normal per vertex and the
//                     distances of its neighbours from its plane (Shi §3.2
//                     (i)); quads: the n − 2 star quads of (ii) (the paper's
//                     choice). On the negshell's diagonal net and on the
//                     test nets both work (negshell: 1.6e-7 with quads,
//                     5.3e-7 with normals). Forced onto the negshell's own
//                     stars (hnet.net: mesh, 0.145 off-plane), normals reach
//                     2.5e-5 with 2.6% displacement and quads stall at 0.37
//                     (their residual also shrinks when a star shrinks or
//                     slides, so they drift).
//     fairness: {weight: 0.01, order: 3, relative_to_original: false}
//                     λ1: second (order 2) or third (order 3) differences
//                     along the mesh polylines [Deng 2011 via Shi §3.2];
//                     relative_to_original keeps the input's differences.
//     proximity: {weight: 1, point_weight: 0.1}
//                     λ2: distance to the reference's tangent plane at the
//                     closest point, plus (point_weight) to the closest point.
//     boundary_proximity: 1   distance of boundary vertices to the tangent
//                     line of the reference's boundary.
//     anchor: 0.1     pull towards each vertex's input position (the
//                     tangent-plane distance alone lets vertices slide).
//     frame_coplanarity: 10   λ3 of F_frame (step 3 only); only on equitwist
//                     edges between faces of one W component with
//                     1e-3 < W < 1e3 (elsewhere no smooth join exists or the
//                     frame points degenerate).
//   hnet:
//     net: auto             which net to solve: the input (mesh) or one of
//                           its diagonal nets (diagonal_0, diagonal_1); auto
//                           picks a diagonal net whose stars are 10× flatter
//                           on average (problems/hnet_net.h). A diagonal net
//                           is then what is solved, measured and written.
//     alternations: 3       step 3 + step 2 repetitions after step 1 (0: step
//                           1 and one step 2 only).
//     star_planarity: 1e-6  tolerance on the max relative star planarity
//                           that ends step 1 and stops the weight growth.
//     continuation_factor: 10   planarity weight growth per round above it.
//     start_face: 0         the face with W⁰ = 1 (eq. 11 makes the result
//                           independent of it on a simply connected net).
//     kink_samples: 9       points per edge for the kink angles (≥ 5).
//   patchwork:              the `output.patchwork` PLY
//     samples: 8            n × n quads (2 triangles each) per patch
//     isophotes: {direction: [0, 0, 1], band_degrees: 5}
//                           vertex colours: light/dark bands of the angle
//                           between the normal and `direction` [Shi §3.3];
//                           `isophotes: false` writes no colours.
//     ascii: false          ASCII instead of binary PLY
//   rulings:                the `output.rulings` OBJ
//     per_family: 1         lines per parameter family and patch (1: through
//                           the frame points)
// Output keys (paths): output.patchwork (.ply: sampled patches, per-vertex
// normals and colours) and output.rulings (.obj polylines), both in file
// units. The output mesh's face colours (output.mesh as PLY) show the largest
// kink angle along each face's edges: green 0° → red ≥ 1°.
//
// Weights were chosen by experiment on the test nets of
// mesh/asymptotic_nets.h and the negshell A-net of ../shared/data (see
// benchmarks/shi_table1.cpp). The paper's Table 1 uses λ1 ≈ 0.4–0.86,
// λ2 ≈ 0.02–0.12, λ3 ≈ 0.6 relative to F_p in its own (unstated)
// normalisation; here the planarity terms are normalised by the star's
// mean edge length and grow by continuation instead.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesh/hnet.h"
#include "mesh/surface_mesh.h"
#include "problems/progress.h"
#include "problems/solve_outcome.h"
#include "problems/solver_options.h"

namespace archgeo {

class ReferenceSurface;

struct HNetTerms {
  double anet_planarity = 10;
  bool anet_normals = true;  // variant (i) vertex normals; false: (ii) star quads
  double fairness = 0.01;
  int fairness_order = 3;     // 2 or 3
  bool fairness_relative = false;
  double proximity = 1;
  double proximity_point = 0.1;
  double boundary_proximity = 1;
  double anchor = 0.1;
  double frame_coplanarity = 10;
};

struct HNetPipelineSettings {
  HNetTerms terms;
  int alternations = 3;
  double star_planarity = 1e-6;
  double continuation_factor = 10;
  HNetOptions hnet;           // start_face, kink_samples
  std::vector<bool> fixed;    // per vertex index; empty = none
  SolverSettings solver;
};

// One round (one Ceres solve) of the pipeline.
struct HNetRoundLog {
  int step = 1;            // 1 (A-net) or 3 (frame, fixed W)
  int round = 0;           // 1-based over the whole run
  int iterations = 0;      // Ceres iterations
  double cost = 0;         // Ceres' final cost
  double weight_scale = 1; // continuation factor applied to the planarity weights
  double star_planarity_max = 0, kink_max = 0, kink_mean = 0;  // after the round (H-net of step 2)
  double max_move = 0;     // mean edge lengths
  double seconds = 0;
  bool undone = false;     // a step-3 round that raised α_max, reverted
};

// SolveOutcome's counts (outer_iterations: rounds), objective (last round),
// seconds ("ceres", "linear_solver", "jacobian", "projection", "hnet") and
// usability, plus:
struct HNetPipelineResult : SolveOutcome {
  bool tolerance_met = false;
  HNet hnet;  // step 2 on the final vertices
  std::vector<HNetRoundLog> log;
};

// Runs the pipeline on `mesh` (pure quad, canonical frame, same frame as
// `reference`), in place. `progress` (may be empty) gets one line per round.
HNetPipelineResult SolveHNetPipeline(Mesh& mesh, const ReferenceSurface& reference,
                                     const HNetPipelineSettings& settings,
                                     const ProgressSink& progress);

// The report entries of an H-net [Shi 2014, Table 1]: star_planarity_max/
// mean, alpha_max, alpha_mean (degrees), W_min, W_max, lambda, counts of odd
// valences, not-equitwist edges, closing edges, bipartite, mismatch_max.
nlohmann::json HNetJson(const HNet& hnet);

}  // namespace archgeo
