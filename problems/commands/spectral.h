// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `archgeo spectral MESH --list`: the candidates of spectral quad
// meshing (Gebreiter 2012, §6.1.3; Dong et al. 2006). The lowest
// eigenfunctions of the mesh's Laplacian (spectral/laplacian.h, solved by
// spectral/eigenpairs.h), each with its eigenvalue and its critical points
// (spectral/critical_points.h): the Morse–Smale complex of eigenfunction k
// has one chart per saddle, so the table tells a designer which k gives
// charts of the size wanted; --charts N or --edge-length L marks the one
// closest to that target.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mesh/surface_mesh.h"
#include "spectral/critical_points.h"
#include "spectral/laplacian.h"
#include "spectral/morse_smale.h"

namespace archgeo {

// A triangle mesh as the plain arrays of spectral/.
struct SpectralMesh {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::vector<int>> rings;  // one-rings in cyclic order
  std::vector<bool> closed;             // interior vertex
  double area = 0;
  int euler = 0;
  bool has_boundary = false;
};

SpectralMesh SpectralArrays(const Mesh& triangles);

struct SpectralCandidate {
  int k = 0;              // eigenfunction k (k = 0, the constant, is not a candidate)
  double eigenvalue = 0;  // λ_k
  CriticalPoints critical;
};

struct Eigenpairs;  // spectral/eigenpairs.h

// Eigenfunctions 1 … pairs.values.size() − 1 of `m` with their critical points.
std::vector<SpectralCandidate> SpectralCandidatesOf(const SpectralMesh& m,
                                                    const Eigenpairs& pairs);

// Eigenfunctions 1 … count − 1 of `triangles` (a triangle mesh) with their
// critical points. Throws std::invalid_argument (the Laplacian) or
// std::runtime_error (the eigensolver).
std::vector<SpectralCandidate> SpectralCandidates(const Mesh& triangles, int count,
                                                  LaplacianKind kind);

// The charts of a candidate's Morse–Smale complex: one per saddle (counted
// by multiplicity), half a chart per boundary saddle.
int SpectralCharts(const CriticalPoints& critical);

// The target number of charts: `charts` if > 0, else area / edge_length²
// rounded if edge_length > 0, else 0 (no target).
int SpectralTarget(double area, int charts, double edge_length);

// The selection rule of the automatic choice: the candidates' positions in
// `candidates` ordered by |SpectralCharts − target|, ties by lower k (the
// first is the one --list marks).
std::vector<int> SpectralByTarget(const std::vector<SpectralCandidate>& candidates, int target);

struct SpectralRequest {
  std::string mesh;                     // polygons are triangulated
  int count = 30;                       // eigenpairs (the constant one included)
  std::string laplacian = "cotangent";  // or "normalised"
  int charts = 0;                       // target number of charts (0: none)
  double edge_length = 0;               // or target chart edge (file units): area / L²
  // --complex: the Morse–Smale complex of eigenfunction k (spectral_complex.cpp).
  std::string complex_out;     // its arcs as OBJ polylines
  std::string quasi_dual_out;  // its quad base complex as an OBJ mesh
  int eigenfunction = 0;       // k ≥ 1
  int cancel_to = 0;           // cancel down to this many extrema (0: no target)
  double persistence = 0;      // or cancel pairs up to this, a fraction of max |φ_k|
};

// The table to print. Throws InputError for a mesh that cannot be read, a
// count beyond the vertices, or a target that is not positive.
std::string SpectralList(const SpectralRequest& request);

// The arcs of a Morse–Smale complex as OBJ polylines over its vertices
// (saddle to extremum), and its quasi-dual as an OBJ quad mesh
// (spectral_complex.cpp).
// `header`: the comment line on top (without "# ").
std::string MorseSmaleArcsObj(
    const MorseSmaleComplex& c,
    const std::string& header = "Morse-Smale complex: one polyline per arc, saddle to extremum");
std::string QuasiDualObj(
    const QuadBaseComplex& q,
    const std::string& header = "quasi-dual of the Morse-Smale complex: extrema, one quad per saddle");

struct SpectralComplexResult {
  std::string text;    // the counts to print
  bool valid = false;  // a valid quad complex (every cell a disc with four corners, every arc placed)
  std::string why;     // when not valid: one line (invalid cells, arcs not placed)
};

// Builds the complex of `request.eigenfunction` (on a mesh with boundary:
// of its double across the boundary, problems/declarations/surface_complex.h),
// writes the OBJ files asked for (also when the complex is not valid, for
// inspection) and returns the counts. Throws InputError for a bad option
// (named) or a mesh whose double is not a closed manifold.
SpectralComplexResult SpectralComplex(const SpectralRequest& request);

}  // namespace archgeo
