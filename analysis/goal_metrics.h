// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — metrics of the goal library [Gebreiter 2012, §10.1, §11]: conical
// residual and constant face offsets of conical meshes [Liu et al. 2006],
// spread of edge lengths and of boundary spacing, force balance of a hanging
// net, and the tributary areas that turn a load per area into vertex loads.
// All lengths in file units.
#pragma once

#include <vector>

#include "mesh/surface_mesh.h"

namespace archgeo {

// Conical residual |(ω1 + ω3) − (ω2 + ω4)| (radians) over the interior
// vertices of valence 4, ω_k the angle between consecutive edges of the star
// (atan2 of cross and dot; the faces' corner angles at v for a quad mesh)
// [Liu et al. 2006, §3; energies/conical.h]. max = mean = 0 when there is no
// such vertex (vertices = 0).
struct ConicalMeasure {
  int vertices = 0;  // interior valence-4 vertices measured
  double max = 0, mean = 0;
  int worst_vertex = -1;  // vertex index of max (−1 if none)
};
ConicalMeasure MeasureConical(const Mesh& mesh);

// How far the face planes at a vertex, each offset by the same distance,
// miss a common point. `normals`: unit normals n_f of the planes; `heights`:
// h_f such that the offset plane is {v + q : n_f·q = h_f} (h_f = d for planes
// through v). Returns max_f |n_f·q* − h_f| for the least-squares point q*
// (minimum-norm solution by SVD when the normals do not span space). 0 iff
// the planes meet in a point. Precondition (CHECKed): equal sizes, ≥ 1 plane.
double PlanesMiss(const std::vector<Vec3>& normals, const std::vector<double>& heights);

// Constant face-offset check. A mesh with planar faces has offsets at
// constant distance d (every face plane moved by d along its normal, the
// offset planes of the faces at each vertex meeting in one point, which is
// the offset vertex) iff it is conical [Liu et al. 2006, §3: the faces at a
// vertex are tangent to a cone of revolution, and the offset vertex lies on
// its axis at d / cos(half opening angle)]. For every interior vertex v with
// at least 4 incident faces (3 planes always meet), the plane of face f is
// the plane through its centroid with its unit Newell normal (the exact
// plane of a planar face), moved by `offset` along the normal; miss(v) =
// PlanesMiss of those planes. The miss includes the non-planarity of the
// faces (the planes do not pass through v), which is measured alone with
// offset = 0. relative = miss / mean edge length.
struct FaceOffsetMeasure {
  int vertices = 0;   // interior vertices with ≥ 4 faces
  double offset = 0;  // d
  double mean_edge_length = 0;
  double max_miss = 0, mean_miss = 0;
  double max_relative = 0, mean_relative = 0;
  int worst_vertex = -1;
};
// offset: d (file units, finite; the usual choice is the mean edge length).
FaceOffsetMeasure MeasureFaceOffsets(const Mesh& mesh, double offset);

// Spread of a set of lengths.
struct LengthSpread {
  int count = 0;
  double min = 0, max = 0, mean = 0;
  double ratio = 0;                   // max / min (0 if min = 0)
  double relative_std = 0;            // standard deviation / mean
  double max_relative_deviation = 0;  // max |ℓ / mean − 1|
};
LengthSpread SpreadOf(const std::vector<double>& lengths);
// Every edge of the mesh.
LengthSpread EdgeLengthSpread(const Mesh& mesh);
// Boundary edges only (spacing of the boundary vertices along the perimeter;
// "within 1% of their mean" is max_relative_deviation ≤ 0.01).
LengthSpread BoundaryEdgeLengthSpread(const Mesh& mesh);

// The quads that are not convex: seen along the face's Newell normal n, a
// corner turns the wrong way ((p_k − p_{k−1}) × (p_{k+1} − p_k)·n ≤ 0), or
// the quad has no area. Planar convex panels have none.
int NonConvexQuads(const Mesh& mesh);

// Tributary area of every vertex (indexed by vertex index): the sum over its
// faces of area(f) / degree(f), area = |Newell vector area| (exact for planar
// faces). Sums to the total area. A vertex load is A_v q for a load q per
// area (energies/load.h).
std::vector<double> TributaryAreas(const Mesh& mesh);

// Force balance of a spring net under vertex loads (energies/load.h): at
// every free vertex the resultant f_v + Σ_e k_e (|d_e| − L0_e) d_e/|d_e|
// (d_e = w − v along edge e; L0_e = 0: k_e d_e). `loads`: per vertex index;
// `stiffness`, `rest_length`: per edge index; `fixed`: per vertex index
// (true = support, excluded). relative = resultant / mean |f_v| over the free
// vertices (the "residual forces ≤ 1e-6 of the load").
// Preconditions (CHECKed): sizes match the mesh; stiffness > 0, L0 ≥ 0.
struct ForceBalanceMeasure {
  int free_vertices = 0;
  double mean_load = 0;                          // mean |f_v| over free vertices
  double max_resultant = 0, mean_resultant = 0;  // force units
  double max_relative = 0;                       // max_resultant / mean_load
};
ForceBalanceMeasure MeasureForceBalance(const Mesh& mesh, const std::vector<Vec3>& loads,
                                        const std::vector<double>& stiffness,
                                        const std::vector<double>& rest_length,
                                        const std::vector<bool>& fixed);

}  // namespace archgeo
