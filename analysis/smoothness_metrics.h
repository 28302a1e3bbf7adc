// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — visual-smoothness analysis of polygon meshes [Pellis et al. 2019].
//
// Works on any mesh the store holds (triangles, quads, polygons, mixed, with
// or without boundary), in double precision; the optimiser's own W′ energy
// (energies/total_absolute_curvature.h) is a separate implementation.
//
// Face normals n_f (unit; the mesh's orientation decides the side):
//   triangle  (b1 − b0) × (b2 − b0), exact;
//   quad      (b2 − b0) × (b3 − b1), the cross product of the diagonals (exact
//             for planar quads, the usual choice for near-planar ones);
//   n-gon     Newell's normal Σ_i b_i × b_{i+1} (the vector area; exact for
//             planar polygons, robust to non-convexity).
// A face whose normal has length ≤ kDegenerateNormal × (its longest edge)²
// is degenerate: its normal is the zero vector, the edges next to it are not
// measured and the vertices around it are left out of the vertex analyses;
// SmoothnessMetrics::degenerate_faces counts them.
//
// Orientation convention (used by W′ and stated once here): for a halfedge
// v → w, f = the face to its LEFT and f′ = the face to its RIGHT, seen from
// the side the normals point to (CGAL: f = face(h), f′ = face(opposite(h))).
#pragma once

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesh/surface_mesh.h"

namespace archgeo {

// Relative threshold for degenerate face normals (see above), dimensionless.
inline constexpr double kDegenerateNormal = 1e-12;

// Unit normal of face f as defined above, or {0, 0, 0} if f is degenerate.
Vec3 FaceNormal(const Mesh& mesh, FaceIndex f);

// FaceNormal of every face, indexed by face index (size = mesh.num_faces()).
std::vector<Vec3> FaceNormals(const Mesh& mesh);

// Vertex normal used by every vertex analysis here: n_v = unit(Σ_{f∋v} n_f),
// the unweighted sum of the unit normals of the faces around v (as in
// [Pellis 2019, §5.3, constraint (6)]); {0, 0, 0} if the sum vanishes.
// face_normals: FaceNormals(mesh).
Vec3 VertexNormal(const Mesh& mesh, const std::vector<Vec3>& face_normals, VertexIndex v);

// Per-edge quantities of [Pellis 2019, §3], each indexed by edge index. For an
// edge e = f ∩ f′ with two non-degenerate faces (measured[e] = true):
//   length       ℓ_e = ‖w − v‖                                  (length)
//   dual_length  ℓ*_e = ‖n_f − n_f′‖ = 2 sin(|α_e|/2)           (dimensionless)
//   angle        |α_e| = ∠(n_f, n_f′) ∈ [0, π]                   (radians)
//   energy       ℓ_e |α_e|, the summand of E′ and the colour of Fig. 7 (length)
// Boundary edges and edges next to a degenerate face have measured = false and
// dual_length = angle = energy = 0 (length is still set).
struct EdgeSmoothness {
  std::vector<double> length, dual_length, angle, energy;
  std::vector<char> measured;  // per edge: 1 or 0 (char, not bool: written in parallel)
};
// face_normals: FaceNormals(mesh).
EdgeSmoothness MeasureEdgeSmoothness(const Mesh& mesh, const std::vector<Vec3>& face_normals);

// Tangential eigenvalues (λ1 ≥ λ2) of the modified normal-cycle shape operator
//   W′_v = ½ Σ_{e = vw = f ∩ f′} (n_f × n_f′)(w − v)ᵀ      [Pellis 2019, §5.3]
// summed over the measured edges out of v (f left, f′ right of v → w, see the
// top of this file), symmetrised as ½(W′ + W′ᵀ) (W′ is symmetric already when
// every n_f is orthogonal to its edges, i.e. for planar faces). "Tangential"
// = the eigenvalues of the compression P W′ P to the tangent plane
// P = I − n_v n_vᵀ (n_v = VertexNormal); when W′ kills n_v, as Cohen-Steiner
// and Morvan's operator does, these are exactly its two eigenvalues with
// tangential eigenvectors. Units: length (curvature × area of influence).
// Each edge contributes ½ ℓ_e sin|α_e| ê êᵀ to each endpoint (ê along the
// edge), positive where the surface bends away from the side of the normals
// (convex with outward normals ⇒ λ1, λ2 ≥ 0); so Σ_v tr W′_v = Σ_e ℓ_e sin|α_e|.
// The compression drops the part of W′ along n_v: at a cube corner W′ = ½ I
// (trace 3/2) and λ1 = λ2 = ½, so a unit cube has C = 8, not 12. On a
// principal mesh the edges are nearly tangent and C → ∫|κ1| + |κ2| dA
// (torus: tests/test_smoothness_metrics.cpp, benchmarks/pellis_fig7_torus).
// Note that the eigenvector of an edge's curvature is the edge itself, not
// the direction of bending (the normal-cycle swap). Returns {0, 0} for an
// isolated vertex, a vertex next to a degenerate face or a zero n_v.
std::array<double, 2> ShapeOperatorEigenvalues(const Mesh& mesh,
                                               const std::vector<Vec3>& face_normals,
                                               VertexIndex v);

// The star of one interior vertex v with out-edges v w_0 … v w_{k−1} in
// counter-clockwise order (seen from the normals' side) and faces f_j between
// v w_j and v w_{j+1} [Pellis 2019, §2.1–2.2].
//
// Test ("tangent") plane: through v, normal n_v = VertexNormal; heights
// h_j = n_v·(w_j − v); |h_j| ≤ kOnPlane ℓ_j counts as 0 (on the plane).
// sign_changes: cyclic sign changes of the non-zero heights.
// saddle: sign_changes ≥ 4 (the plane meets the star in ≥ 4 segments).
// good_saddle [§2.2]: a saddle with a triangle star of valence 6, no zero
//   height, exactly 4 sign changes with groups of 1, 2, 1, 2 edges cyclically
//   above/below, whose star projects 1-1 onto the test plane (every face
//   keeps its orientation), whose 4 crossing segments are not in a common
//   half-plane (§2.1), and whose two faces that miss the plane (inside the
//   groups of 2) are no inflection faces. A face v w_j w_{j+1} is an
//   inflection face when w_{j−1} and w_{j+2} lie strictly on different sides
//   of its plane [Günther et al. 2017].
// bad saddle: a saddle with a triangle star that is not good (Fig. 4b, c;
//   also saddles of valence ≠ 6). Saddles with a non-triangle face in the
//   star are not classified (§2.2 defines good saddles for triangle stars).
// self_intersecting_pyramid [§2.2]: the normal pyramid — the closed polygon
//   n_{f_0}, …, n_{f_{k−1}} on the unit sphere with great-circle arcs as
//   sides — has two non-adjacent sides that cross. Equivalently (when every
//   n_f·n_v > 0) its central projection onto the plane z = 1 of a frame with
//   z = n_v is not a simple polygon. Consecutive equal normals (zero dihedral
//   angle, within 1e-9) are merged first, and touching or collinear overlaps
//   do not count; a polygon with ≤ 3 distinct normals never self-intersects.
//   A side between antipodal normals (an edge folded flat) is undefined and
//   counts as a self-intersection.
struct VertexStar {
  bool measured = false;  // interior vertex, faces and n_v non-degenerate
  int valence = 0;
  bool triangle_star = false;  // every face of the star is a triangle
  int sign_changes = 0;
  bool saddle = false;
  bool good_saddle = false;
  bool self_intersecting_pyramid = false;
};

// Height tolerance of the test plane, relative to the edge length.
inline constexpr double kOnPlane = 1e-9;

// The analysis above for vertex v; measured = false (and every other field
// default) for boundary and isolated vertices and stars with a degenerate face.
// face_normals: FaceNormals(mesh).
VertexStar ClassifyVertexStar(const Mesh& mesh, const std::vector<Vec3>& face_normals,
                              VertexIndex v);

// Mesh totals [Pellis 2019]. Lengths are in file units.
struct SmoothnessMetrics {
  int vertices = 0, faces = 0, edges = 0;
  int interior_edges = 0;    // edges with two non-degenerate faces (measured)
  int interior_vertices = 0; // vertices with a measured star (VertexStar::measured)
  int degenerate_faces = 0;
  double E = 0;              // Σ_e ℓ_e ℓ*_e, ℓ* = ‖n_f − n_f′‖           [§3] (length)
  double E_prime = 0;        // E′ = Σ_e ℓ_e |α_e|                         [§3] (length)
  double C = 0;              // Σ_v |λ1,v| + |λ2,v| of W′_v              [§5.3] (length)
  double max_edge_energy = 0;  // max_e ℓ_e |α_e| (length)
  int saddles = 0, good_saddles = 0, bad_saddles = 0, unclassified_saddles = 0;
  int self_intersecting_pyramids = 0;
};

// All of the above over every edge and vertex of `mesh` (boundary edges are
// not measured; boundary vertices contribute to C through their measured
// edges but have no star analysis).
SmoothnessMetrics ComputeSmoothnessMetrics(const Mesh& mesh);

// Only the edges' part of the above: interior_edges, degenerate_faces, E,
// E_prime and max_edge_energy (the same values), without the vertices'
// curvature and stars; the rest stays 0. For the loop's per-round measure E,
// where the stars took three quarters of the time.
SmoothnessMetrics ComputeEdgeSmoothnessMetrics(const Mesh& mesh);

// JSON object with every field; the lengths E, E_prime, C, max_edge_energy
// also as "<name>_relative" = value / scale (normally the bounding-box
// diagonal, like MetricsToJson). Precondition (CHECKed): scale > 0.
nlohmann::json SmoothnessMetricsToJson(const SmoothnessMetrics& metrics, double scale);

// A few lines of text, "E = …", "E' = …", "C = …", the saddle and pyramid
// counts; each line ends with '\n'.
std::string FormatSmoothnessMetrics(const SmoothnessMetrics& metrics);

// Face colours for the Fig. 7 colour code: each face gets the largest
// ℓ_e|α_e| of its measured edges, divided by `red_at` (a length), on the
// green (0) → yellow → red (≥ 1) scale of PlanarityColors (analysis/metrics.h).
// red_at ≤ 0 means: the largest ℓ|α| of the mesh (all green if that is 0).
// Indexed by face index.
std::vector<std::array<unsigned char, 3>> SmoothnessColors(const Mesh& mesh,
                                                          const EdgeSmoothness& edges,
                                                          double red_at = 0.0);

// SmoothnessColors with red at an edge of the mesh's mean length bent by
// `red_angle` radians (red_at = red_angle × mean edge length).
std::vector<std::array<unsigned char, 3>> BendingColors(const Mesh& mesh, double red_angle);

}  // namespace archgeo
