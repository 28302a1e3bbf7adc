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

#include <string>
#include <vector>

#include "mesh/surface_mesh.h"
#include "spectral/critical_points.h"
#include "spectral/laplacian.h"

namespace archgeo {

struct SpectralCandidate {
  int k = 0;              // eigenfunction k (k = 0, the constant, is not a candidate)
  double eigenvalue = 0;  // λ_k
  CriticalPoints critical;
};

// Eigenfunctions 1 … count − 1 of `triangles` (a triangle mesh) with their
// critical points. Throws std::invalid_argument (the Laplacian) or
// std::runtime_error (the eigensolver).
std::vector<SpectralCandidate> SpectralCandidates(const Mesh& triangles, int count,
                                                  LaplacianKind kind);

struct SpectralRequest {
  std::string mesh;                     // polygons are triangulated
  int count = 30;                       // eigenpairs (the constant one included)
  std::string laplacian = "cotangent";  // or "normalised"
  int charts = 0;                       // target number of charts (0: none)
  double edge_length = 0;               // or target chart edge (file units): area / L²
};

// The table to print. Throws InputError for a mesh that cannot be read, a
// count beyond the vertices, or a target that is not positive.
std::string SpectralList(const SpectralRequest& request);

}  // namespace archgeo
