// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — hyperbolic nets (H-nets): the smooth extension of a quad mesh by
// rational bilinear patches [Shi, Wang, Pottmann 2014, §2.3, §3.2 step 2, §4].
//
// Given a quad mesh (ideally an A-net: planar vertex stars, even interior
// valences, equitwist edges), BuildHNet
//  1. checks it: pure quad, odd interior valences, equitwist per interior edge
//     [Shi 2014, Remark 2], vertex-star planarity [§3.2 step 1];
//  2. selects one diagonal per face from a 2-colouring of the vertices
//     [Remark 5];
//  3. propagates the shape parameters W over the faces by eq. 7 from a start
//     face with W = 1 and records, per interior edge, how far the propagated
//     values miss eq. 7 (closing edges of non-simply-connected nets, non-planar
//     stars) [Theorem 4, §3.2 step 2];
//  4. scales W by the λ minimising F_shape (eq. 11) exactly (a quartic);
//  5. derives per-face weights (1, 1, W, 1), frame points and the kink angles
//     along every interior edge (α_max, α_mean of [Shi 2014, Table 1]).
// Further functions sample the patchwork as a triangle mesh with normals and
// isophote bands [§3.3, Fig. 5], extract rulings as polylines, and apply the
// Darboux transformation [§4, eq. 12] to a sampled patchwork.
//
// Indexing: per-vertex, per-edge and per-face vectors are indexed by the CGAL
// index (idx()); the mesh must not hold removed elements (CHECKed). Lengths are
// in mesh units, angles in degrees.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "geometry/bilinear_patch.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

// How the shape parameters W are obtained from eq. 7 [Shi 2014, §3.2 step 2].
enum class HNetShape {
  // The paper's traversal: W is propagated over a spanning tree of the faces
  // (BFS from the start face); every crossed edge meets eq. 7 exactly, and the
  // edges the tree does not cross (closing edges) get whatever mismatch the
  // net's holonomy leaves: around a hole that can be a factor of 2 on one edge.
  kPropagated,
  // log W minimising Σ_edges (log W_r(b0) − log W_l(b0) − log ratio_e)² over
  // every equitwist edge (a sparse Poisson solve, gauge fixed at each
  // component's root). Identical to kPropagated where eq. 7 can hold
  // everywhere (a simply connected A-net); around holes and non-planar stars
  // it spreads the mismatch over all edges instead of one closing edge.
  kLeastSquares,
};

struct HNetOptions {
  HNetShape shape = HNetShape::kLeastSquares;
  int start_face = 0;     // face index whose initial shape parameter is W⁰ = 1
  int kink_samples = 9;   // ≥ 5 points per edge (end points included) for the kink angle
};

// How an interior edge can join its two patches [Shi 2014, Remark 2].
enum class EdgeJoin : signed char {
  kBoundary,      // a boundary edge (one face): no join
  kEquitwist,     // both determinants of eq. 7 non-zero, same sign
  kNotEquitwist,  // eq. 7 needs a non-positive weight ratio: no smooth join
};

struct HNet {
  // --- Checks.
  bool pure_quad = false;
  std::vector<int> non_quad_faces;        // faces with ≠ 4 sides
  std::vector<int> odd_valence_vertices;  // interior vertices of odd valence (§2.3)
  std::vector<EdgeJoin> join;             // per edge
  std::vector<int> not_equitwist_edges;   // the interior edges with kNotEquitwist

  // Vertex-star planarity per vertex [Shi 2014, §3.2 step 1]: max distance of
  // the neighbours from the least-squares plane of the star (the vertex and
  // its neighbours) over the star's mean edge length; −1 at boundary vertices.
  // Max and mean over interior vertices (0 if there are none).
  std::vector<double> star_planarity;
  double star_planarity_max = 0, star_planarity_mean = 0;

  // --- Diagonals [Shi 2014, Remark 5]. colour: 0/1 per vertex by BFS over the
  // vertex graph (each connected component starts with colour 0 at its
  // smallest vertex index). bipartite: no edge joins equal colours; otherwise
  // monochrome_edges lists those that do (an odd cycle around a hole).
  std::vector<int> colour;
  bool bipartite = false;
  std::vector<int> monochrome_edges;
  // Per face: the vertex indices c0..c3 of its patch, in the face's orientation,
  // with c0c2 the chosen diagonal (W refers to it). The diagonal joins the
  // face's two colour-0 vertices where the colours alternate; otherwise the
  // first opposite pair of colour 0, else the first colour-0 vertex, else the
  // face's first vertex. The choice only fixes which of W, 1/W is stored:
  // propagation and smoothness do not depend on it (eq. 7 is applied with
  // the shape parameter of each face's diagonal through the edge's vertex b0).
  std::vector<std::array<int, 4>> patch_vertices;

  // --- Shape parameters [Shi 2014, §3.2 step 2].
  int start_face = 0;
  // Faces are grouped into components connected across equitwist edges (one
  // component for a usable net); each starts with W⁰ = 1 at one face (the
  // start face for its component, else its smallest face index) and has its
  // own λ (F_shape separates over components).
  std::vector<int> component;      // per face
  // The traversal propagates per face a diagonal consistent across every
  // crossed edge (both through the same end point; Remark 5); it is c0c2
  // everywhere on a bipartite net. λ scales the propagated diagonals' shape
  // parameters Wp (W = λWp where the propagated diagonal is c0c2, else
  // W = 1/(λWp)), so crossed edges stay exact; F_shape (eq. 11) is the same
  // for W and Wp (it is invariant under W ↔ 1/W per face).
  std::vector<double> lambda_of_component;
  double lambda = 1;               // λ of the start face's component (eq. 11)
  std::vector<double> W_initial;   // per face: W⁰ for c0c2 from the propagation (λ = 1)
  std::vector<double> W;           // per face: the final shape parameter for c0c2
  // Per edge: |(W_r/W_l) / (det(b30,b50,b20)/det(b30,b10,b40)) − 1| of eq. 7
  // with the propagated W (0 up to rounding on edges the traversal crossed);
  // −1 at boundary and not-equitwist edges.
  std::vector<double> edge_mismatch;
  std::vector<int> closing_edges;  // interior equitwist edges the traversal did not cross
  double mismatch_max = 0;

  // --- Patches. Per face, in patch order c0..c3: weights (1, 1, W, 1)
  // [Shi 2014, eqs. 2–4] and frame points f0..f3 (§2.1).
  std::vector<std::array<double, 4>> weights;
  std::vector<std::array<Vec3, 4>> frame_points;

  // --- Quality [Shi 2014, Table 1]. kink_degrees per edge: max angle between
  // the two patches' tangent planes over kink_samples points of the edge;
  // −1 at boundary edges (and where no normal is defined). α_max, α_mean over
  // interior edges; W range over faces.
  std::vector<double> kink_degrees;
  double kink_max = 0, kink_mean = 0;
  double W_min = 0, W_max = 0;
};

// Vertex-star planarity of v [Shi 2014, §3.2 step 1]: max distance of the
// neighbours from the least-squares plane of {v} ∪ neighbours, over the mean
// distance of the neighbours from v (0 for a vertex without neighbours).
double StarPlanarity(const Mesh& mesh, VertexIndex v);

// StarPlanarity of every interior (non-boundary, non-isolated) vertex:
// per_vertex indexed by vertex index, −1 elsewhere; max and mean over those
// vertices, −1 if there are none.
struct StarPlanarities {
  std::vector<double> per_vertex;
  double max = -1, mean = -1;
};
StarPlanarities InteriorStarPlanarity(const Mesh& mesh);

// Builds the H-net of `mesh` (see the file comment). Throws InputError if the
// mesh has no faces, is not pure quad, or options.start_face is not a face
// index or options.kink_samples < 5. The other checks (odd valences,
// equitwist, planarity, bipartiteness) are reported, not thrown: the result
// is then the best extension the traversal gives, with mismatches and kinks
// where the net cannot be smooth.
HNet BuildHNet(const Mesh& mesh, const HNetOptions& options = {});

// The rational bilinear patch of face f: control points c0..c3, weights
// hnet.weights[f]. Precondition: hnet was built from this mesh.
BilinearPatch FacePatch(const Mesh& mesh, const HNet& hnet, FaceIndex f);

// F_shape(λ) = Σ_i [(λ W_i − 1)² + (1/(λ W_i) − 1)²]  [Shi 2014, eq. 11].
// Preconditions (CHECKed): λ > 0, every W_i finite and > 0.
double ShapeEnergy(double lambda, const std::vector<double>& W);

// The λ > 0 minimising ShapeEnergy(λ, W) exactly. dF/dλ = 0 is equivalent to
//   A λ⁴ − B λ³ + C λ − D = 0,  A = ΣW², B = ΣW, C = Σ1/W, D = Σ1/W²,
// solved via the eigenvalues of its companion matrix; the real positive roots
// are polished by Newton's method and the one of least F is returned
// (p(0) = −D < 0 < p(∞), so one exists). Preconditions (CHECKed): W non-empty,
// every W_i finite and > 0.
double OptimalShapeScale(const std::vector<double>& W);

// A patchwork sampled as a triangle mesh. Each face's patch is sampled on its
// own (n+1)² grid at (u, v) = (i/n, j/n) (vertices on shared edges repeated,
// one copy per patch); vertex (i, j) of face slot k has index
// k (n+1)² + j (n+1) + i, where k counts the faces in index order.
struct SampledPatchwork {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // unit; from the patch derivatives (or triangles, see below)
  std::vector<std::array<int, 3>> triangles;  // oriented like x_u × x_v
  std::vector<int> triangle_face;             // source face index per triangle
};

// Samples every patch with n × n quads (2 triangles each), n ≥ 1. Normals are
// PatchNormal(u, v); where that is undefined (degenerate corner) the
// area-weighted mean of the incident triangles' normals is used.
SampledPatchwork SamplePatchwork(const Mesh& mesh, const HNet& hnet, int n);

// Isophotes [Shi 2014, §3.3, Fig. 5]: angle (degrees, [0, 180]) between each
// unit normal and `direction` (any non-zero vector, normalised here; throws
// InputError if it is zero or not finite).
std::vector<double> IsophoteAngles(const std::vector<Vec3>& normals, const Vec3& direction);

// Banded colours of isophote angles: light (235, 235, 235) where
// floor(angle / band_degrees) is even, dark (40, 40, 40) where it is odd, so
// band borders are isophotes at multiples of band_degrees. Throws InputError
// if band_degrees is not finite and > 0.
std::vector<std::array<unsigned char, 3>> IsophoteColors(const std::vector<double>& angles,
                                                         double band_degrees);

// Polylines with their origin.
struct Polylines {
  std::vector<std::vector<Vec3>> lines;
  std::vector<int> face;    // source face index per line
  std::vector<int> family;  // 0: u = const, 1: v = const
};

// The rulings of every patch [Shi 2014, §2.1]: per face, `per_family` ≥ 1
// lines u = k/(per_family+1) and as many v = k/(per_family+1),
// k = 1..per_family (per_family = 1: the lines through the frame points), each
// sampled at `points_per_line` ≥ 2 equally spaced parameters (the rulings are
// straight; more points are useful after a Darboux map).
Polylines PatchRulings(const Mesh& mesh, const HNet& hnet, int per_family, int points_per_line);

// Writes polylines as ASCII OBJ: all points as `v x y z`, then one
// `l i j k ...` record (1-based) per line. Lines with < 2 points are skipped.
// To the given path (callers stage outputs with StagedOutputs). Throws
// InputError if the file cannot be written.
void WritePolylinesObj(const std::string& path, const std::vector<std::vector<Vec3>>& lines);

// Applies the Darboux transformation [Shi 2014, eq. 12] to every sample vertex.
// Triangles with a vertex whose image is not real or at infinity are dropped
// and those vertices listed in `failed_vertices` (if non-null; their
// positions are NaN). Normals are recomputed as area-weighted means of the
// mapped triangles' normals (zero for a vertex without a triangle).
SampledPatchwork DarbouxMapPatchwork(const SampledPatchwork& patchwork,
                                     const DarbouxTransform& transform,
                                     std::vector<int>* failed_vertices = nullptr);

}  // namespace archgeo
