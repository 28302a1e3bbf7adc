// archgeo — the principal_symmetric builder: make a triangle mesh
// principal-symmetric [Pellis 2019, §2.3, §5.2; Fig. 5, 14].
//
// Principal edges. Exactly two opposite edges of each valence-6 vertex are
// "principal" (along a principal curvature direction; one third of all edges
// of a regular mesh); the user marks them in one of two ways:
//  (a) `split:` a quad mesh is triangulated by one diagonal per quad and one
//      of its three edge families is principal:
//        diagonal: first | second   the diagonal v0–v2 (first) or v1–v3
//                                   (second) of each quad, in the file's
//                                   vertex order of the face
//        principal: diagonals | first | second
//                                   diagonals: the new diagonals (a quad mesh
//                                   along directions symmetric to the principal
//                                   ones, e.g. an asymptotic net of a saddle);
//                                   first / second: a family of quad edges,
//                                   "first" being the family of the first edge
//                                   (v0–v1) of the first quad, propagated to
//                                   opposite edges across quads (a 60° rhombus
//                                   mesh along curvature lines). A family that
//                                   is not consistent (a singular vertex joins
//                                   the two families) is an InputError.
//      Triangles of the input are kept.
//  (b) `principal_edges: PATH` on a triangle mesh: a text file, one principal
//      edge per line as two 0-based vertex indices "i j" (whitespace
//      separated); '#' starts a comment; blank lines are ignored. A line that
//      is not two non-negative integers, names a vertex out of range, a pair
//      that is not an edge of the mesh, or an edge listed twice is an
//      InputError naming the file and line.
// Exactly one of `split` and `principal_edges` must be given. An interior
// valence-6 vertex with principal edges must have exactly two, opposite in
// its star (else InputError naming the vertex); interior valence-6 vertices
// without principal edges, vertices of other valence and boundary vertices
// get no vertex conditions (singularities, §2.3; Fig. 14h: the condition
// may be imposed on part of a mesh). The labels follow loop subdivision
// (`multiresolution: {scheme: loop}`: the halves of a principal edge are
// principal); other schemes are refused.
//
// Variables and conditions (energies/principal_symmetric.h), minimised by
// Ceres as ½ Σ w r² in the canonical frame (unit mean edge length):
//   per constrained vertex v: sphere normal n(v) (unit) and curvature κ(v);
//     co_spherical  the four non-principal neighbours on the sphere Σ(v)
//     saddle        where the angle sum at v exceeds 2π in the input (fixed
//                   for the run: re-classifying near parabolic lines, where
//                   the angle sum is ≈ 2π, made the set flicker between
//                   rounds), each principal neighbour on the other side of the
//                   tangent plane than Σ(v), with a dummy δ per (v, w)
//   per principal edge vw whose two endpoints carry spheres: unit n(e);
//     strip         n(e) ⟂ v − w, n(v), n(w) (a developable normal strip)
// plus the regularisers of §5.1: proximity / boundary_proximity / anchor to
// the reference, fairness (second differences, problems/smooth_mesh.h's
// triples), step (w_reg ‖X − X_prev‖²) and optionally dihedral_energy
// (w_target, the IRLS surrogate of E = Σ ℓ_e ℓ*_e).
//
// Spec keys of the builder (besides split / principal_edges):
//   terms:                       if given, an unlisted term is off
//     co_spherical: 10000
//     strip: 10000
//     saddle: 1000000            (its residual is second order in the edge length)
//     proximity: {weight: 0.01, point_weight: 0.0001}
//     boundary_proximity: 0.01
//     anchor: 0
//     fairness: {weight: 0.0001, relative_to_original: false}
//     step: 0.001
//     dihedral_energy: 0         w_target
//   tolerance:
//     residual_max: 1e-5         stop when every condition residual (below) is
//                                at most this and no saddle is violated
// Rounds: solver.outer_iterations; each re-projects onto the reference,
// restarts the saddle dummies and the IRLS weights, and solves. The
// conditions act as constraints: their weights are 10⁴–10⁶ times those of
// the regularisers (measured on the example: with 100 against proximity 0.1
// the co-sphericity stalled at ~7e-5; with 10⁴ against 0.01 it reaches 1e-6).
//
// Report (SolveOutcome.details): "conditions_before" / "conditions_after":
// spheres, strips, saddle terms, max |co-sphericity residual| (distance to
// the sphere over the mean edge length), max strip coplanarity
// |det(unit(w − v), n(v), n(w))|, the number of saddle violations
// (κ n·(w − v) > tolerance.residual_max: the penalty leaves violations of
// ~1e-7 at near-parabolic vertices, which are no violation at this
// tolerance) and the largest; and one entry per round.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "mesh/surface_mesh.h"
#include "problems/progress.h"
#include "problems/solve_outcome.h"
#include "problems/solver_options.h"

namespace archgeo {

class ReferenceSurface;

// An undirected edge as a pair of vertex indices (first < second).
using VertexPair = std::pair<int, int>;

struct PrincipalSymmetricWeights {
  double co_spherical = 1e4;
  double strip = 1e4;
  double saddle = 1e6;
  double proximity = 0.01;
  double proximity_point = 1e-4;
  double boundary_proximity = 0.01;
  double anchor = 0;
  double fairness = 1e-4;
  bool fairness_relative = false;
  double step = 0.001;
  double dihedral_energy = 0;
};

struct PrincipalSymmetricSettings {
  PrincipalSymmetricWeights terms;
  std::vector<VertexPair> principal;  // principal edges of the mesh to solve
  double residual_max = 1e-5;
  std::vector<bool> fixed;  // per vertex index; empty = none
  SolverSettings solver;
};

// How well the conditions hold (see the header comment); counts of the
// constrained elements.
struct PrincipalSymmetricResiduals {
  int spheres = 0, strips = 0, saddle_terms = 0;
  double co_spherical_max = 0;  // max |CoSpherical residual| (≈ distance / mean edge)
  double strip_max = 0;         // max |det(unit(w − v), n(v), n(w))|
  int saddle_violations = 0;    // principal neighbours on the wrong side (beyond residual_max)
  double saddle_violation_max = 0;  // max κ n·(w − v) over violations (unit-free)
};

struct PrincipalSymmetricRound {
  int round = 0, iterations = 0;
  double cost = 0;
  PrincipalSymmetricResiduals residuals;
  double E = 0;             // true E, input mean edge lengths
  int self_intersecting_pyramids = 0;
  double max_move = 0;
  double seconds = 0;
};

// SolveOutcome's counts (outer_iterations: rounds), objective, seconds
// ("ceres", "linear_solver", "jacobian") and usability, plus:
struct PrincipalSymmetricResult : SolveOutcome {
  PrincipalSymmetricResiduals before, after;  // before: spheres fitted to the input
  std::vector<PrincipalSymmetricRound> log;
};

// Optimises `mesh` (a triangle mesh; CHECKed) in place; `settings.principal`
// must be edges of `mesh` satisfying the star rule above (CHECKed; the
// builder validates user input). Same frame for mesh and reference.
PrincipalSymmetricResult SolvePrincipalSymmetric(Mesh& mesh, const ReferenceSurface& reference,
                                                 const PrincipalSymmetricSettings& settings,
                                                 const ProgressSink& progress);

// Reads and validates an edge-label file (format above) for `mesh`. Throws
// InputError(path, line, key, ...).
std::vector<VertexPair> ReadPrincipalEdges(const std::string& path, const std::string& key,
                                           const Mesh& mesh);

// Checks the star rule above; returns an empty string or the first problem.
std::string CheckPrincipalStars(const Mesh& mesh, const std::vector<VertexPair>& principal);

// Splits every quad of `quads` by its first (v0–v2) or second (v1–v3)
// diagonal (`second_diagonal`); other faces are kept. `principal` selects the
// principal family ("diagonals", "first", "second"); the labelled edges are
// returned in *labels (vertex indices are unchanged). Throws InputError(file,
// 0, key, ...) if a face has more than four sides or the quad-edge families
// are inconsistent.
Mesh SplitQuads(const Mesh& quads, bool second_diagonal, const std::string& principal,
                std::vector<VertexPair>* labels, const std::string& file, const std::string& key);

// A principal-symmetric torus triangle mesh (R, r, 0 < r < R): n_v rings
// along the parallels v_j = 2π j/n_v, n_u vertices each at u = 2π(i + j/2)/n_u
// (every ring turned by half a step); vertex (i, j) has index j·n_u + i.
// The ring edges (parallels, curvature lines) are principal and returned in
// *principal; the other four neighbours of a vertex are symmetric to them
// about its meridian plane, hence co-spherical. Outward normals. If
// noise > 0, every vertex moves by a uniform random vector of length ≤ noise
// × the mean edge length (seeded by `seed`). Preconditions (InputError
// otherwise): 0 < r < R, n_u ≥ 3, n_v ≥ 4 even, noise ≥ 0.
Mesh PrincipalSymmetricTorus(double R, double r, int n_u, int n_v, double noise, unsigned seed,
                             std::vector<VertexPair>* principal);

}  // namespace archgeo
