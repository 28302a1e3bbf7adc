// archgeo — the smooth_mesh builder: lower the visual-smoothness energy
// E = Σ_e ℓ_e ℓ*_e of a triangle or hybrid (triangle + planar polygon) mesh
// while it keeps to its reference surface or follows moved handles.
//
//   [Pellis 2019, §3 (E), §5.1 (energy-minimal meshes: target functional E,
//    proximity to a reference or to handles, fairness, regulariser
//    R(X) = w_reg ‖X − X_prev‖² + w_fair E_fair + w_target E_target),
//    Fig. 12 (design by handles), Fig. 18 (hybrid mesh, planar quads kept
//    planar), Fig. 20 (statistics)]
//
// Objective of one round, minimised by Ceres as ½ Σ w r² in the canonical
// frame (unit mean edge length, mesh/similarity.h), so every weight is
// unit-free:
//   w_target Σ_e ‖r_e‖²                 dihedral_energy (energies/dihedral_energy.h)
//                                       r_e = ℓ_e (n_f − n_f′)/sqrt(ω_e), IRLS:
//                                       ω_e = ℓ_e ℓ*_e + ε of the previous round,
//                                       so ½‖r_e‖² ≈ ½ ℓ_e ℓ*_e at the fixed point
// + w_poly Σ_{f, deg f > 3} Σ_{v ∈ f} (n_f·(v − c_f) − d_f)²   face_planarity
// + w_prox Σ_{v ∉ ∂} (ν(π v)·(v − π v))² + w_pt Σ_v ‖v − π v‖²  proximity
// + w_∂ Σ_{v ∈ ∂} dist(v, tangent line at π̃ v)²                  boundary_proximity
// + w_anchor Σ_v ‖v − v⁰‖²                                        anchor
// + w_handle Σ_{handles h} ‖v_h − target_h‖²                      handles
// + w_fair Σ_{(u,v,w)} ‖u − 2v + w − Δ⁰‖²                          fairness
// + w_reg Σ_v ‖v − v_prev‖²                                       step (§5.1's R)
// Every round ("outer iteration") re-projects the vertices onto the
// reference, recomputes the IRLS weights ω_e from the current mesh and the
// step anchors v_prev, rebuilds the problem and solves it. The true E, E′
// and the number of self-intersecting normal pyramids (mesh/smoothness_
// metrics.h) are measured before the first round and after every round and
// reported per round (SmoothMeshResult::log; the run report's "rounds").
// The output is the round with the lowest true E (report: "output_round"),
// or the last round when there are handles.
//
// Faces. Triangles carry no variables: their normals are computed from the
// vertices. A face with more than three sides (quads included) gets a unit
// normal block n_f (ceres::SphereManifold<3>, started at the Newell normal)
// and an offset d_f, tied to its vertices by face_planarity; the edges
// between two faces use the TriTri / TriPoly / PolyPoly variants of the
// dihedral energy. Planar quads therefore stay planar and their diagonals
// carry no energy (the paper's ℓ*_e = 0 on the diagonals, Fig. 18).
// Boundary edges carry no energy (they have one face).
//
// Fairness triples (SmoothFairnessTriples): at an interior vertex of even
// valence k, each pair of opposite neighbours (w_j, v, w_{j+k/2}) (the
// continuation of a mesh polyline through a valence-6 vertex of a triangle
// mesh, or a valence-4 vertex of a quad mesh); at a boundary vertex its two
// boundary neighbours. Interior vertices of odd valence are singular and get
// no triple.
//
// Spec keys of the builder (all optional):
//   terms:                       weights; if `terms` is given, an unlisted term is off
//     dihedral_energy: 1         w_target (the IRLS surrogate of E)
//     face_planarity: 1e6        w_poly, faces with more than 3 sides (a constraint:
//                                the IRLS weight of a flat edge is up to 1/ε = 1000,
//                                and 1e4 left δ_PQ,n at 1.7e-3 in the hybrid test)
//     proximity: {weight: 1, point_weight: 0.01}   distance to the reference's
//                                tangent plane at the closest point (re-projected
//                                every round), and to the closest point itself
//     boundary_proximity: 1      distance to the reference boundary's tangent line
//     anchor: 0.3                pull towards the input positions (limits the
//                                tangential sliding the tangent plane allows)
//     fairness: {weight: 0.01, relative_to_original: false}
//                                second differences along the triples above;
//                                relative_to_original keeps the input's
//                                second differences (Δ⁰), else Δ⁰ = 0
//     step: 0.1                  w_reg, pull towards the previous round's positions
//     handles: 100               w_handle (only with `handles`)
//   handles:                     design by pulling handles (Fig. 12): a list of
//     - {vertex: 12, position: [x, y, z]}   target in file units, or
//     - {vertex: 40, offset: [dx, dy, dz]}  move by this vector (file units)
//                                vertex: 0-based index into the input mesh;
//                                each vertex at most once. With handles the
//                                reference still applies: set proximity,
//                                boundary_proximity and anchor to 0 for a free
//                                design (the handles and fixed vertices then
//                                hold the mesh).
//   tolerance:
//     energy_relative: 1e-4      stop when 3 rounds in a row have not lowered the
//                                lowest true E so far by more than this fraction
//                                (0: run all solver.outer_iterations); the
//                                output is the round of lowest E either way;
//                                not used with handles (E may rise while the
//                                mesh follows them: all rounds run)
//     displacement_relative: 0.005   bound on every vertex's distance from its
//                                input position, as a fraction of the bounding-box
//                                diagonal (the report's displacement_max_relative);
//                                0 = no bound. After each round a vertex beyond
//                                half the bound gets an anchor to its input
//                                position (weight 1, ×10 every further round),
//                                and a vertex beyond the bound is put back just
//                                inside it (0.999 × bound, radially towards its input
//                                position; counted as clamped_vertices) unless
//                                it is a vertex of a polygon (clamping would
//                                break its planarity: the anchor holds it). Off
//                                with handles. On
//                                directional_train-station.off the unguarded
//                                run moved a vertex 1.8% of the diagonal.
// Common keys (problems/spec.h) apply: solver.outer_iterations is the number
// of rounds at most, solver.max_iterations the Ceres iterations per round,
// fixed vertices stay put.
//
// Errors: a handle with a bad vertex index or both/neither of position and
// offset is an InputError naming the spec file, line and key.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "mesh/surface_mesh.h"
#include "problems/progress.h"
#include "problems/solve_outcome.h"
#include "problems/solver_options.h"

namespace archgeo {

class ReferenceSurface;

// Weights of the smooth_mesh terms (see above), canonical frame.
struct SmoothTermWeights {
  double dihedral_energy = 1.0;
  double face_planarity = 1e6;
  double proximity = 1.0;
  double proximity_point = 0.01;
  double boundary_proximity = 1.0;
  double anchor = 0.3;
  double fairness = 0.01;
  bool fairness_relative = false;
  double step = 0.1;
  double handles = 100.0;
};

// A handle in the canonical frame: vertex index and its target position.
struct CanonicalHandle {
  int vertex = 0;
  Vec3 target{0, 0, 0};
};

struct SmoothMeshSettings {
  SmoothTermWeights terms;
  std::vector<CanonicalHandle> handles;  // canonical frame
  double energy_relative = 1e-4;  // a gain in E below this fraction does not count (3 rounds: stop)
  double displacement_relative = 0.005;  // bound / bounding-box diagonal; 0 = none
  std::vector<bool> fixed;        // per vertex index; empty = none
  SolverSettings solver;
};

// One round, measured after it (round 0: the input).
struct SmoothRoundLog {
  int round = 0;
  int iterations = 0;          // Ceres iterations of the round
  double cost = 0;             // Ceres' final cost of the round (½ Σ w r²)
  double E = 0, E_prime = 0;   // true E and E′ (canonical units: input mean edge lengths)
  double surrogate = 0;        // the IRLS dihedral term ½ Σ ‖r_e‖² / w_target at the end
  int self_intersecting_pyramids = 0;
  int bad_saddles = 0;
  double max_move = 0;         // largest vertex move of the round (canonical units)
  double displacement = 0;     // largest distance from the input position (canonical units)
  int clamped = 0;             // vertices put back onto the displacement bound
  double seconds = 0;
};

// SolveOutcome's counts (outer_iterations: rounds), objective, seconds
// ("ceres", "linear_solver", "jacobian", "projection") and usability, plus:
struct SmoothMeshResult : SolveOutcome {
  std::vector<SmoothRoundLog> log;  // log[0] = input, then one per round
  int best_round = 0;               // the round returned (lowest true E; the last with handles)
};

// Optimises `mesh` in place. `mesh` and `reference` must be in the same
// canonical frame (unit mean edge length). Handle vertex indices must be
// valid (CHECKed; the builder validates user input). `progress` (may be
// empty) receives one line per round.   [Pellis 2019, §5.1]
SmoothMeshResult SolveSmoothMesh(Mesh& mesh, const ReferenceSurface& reference,
                                 const SmoothMeshSettings& settings,
                                 const ProgressSink& progress);

// The fairness triples (u, v, w) described above, for any polygon mesh.
std::vector<std::array<VertexIndex, 3>> SmoothFairnessTriples(const Mesh& mesh);

}  // namespace archgeo
