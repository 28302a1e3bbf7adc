// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — triangle meshes of analytic surfaces for the field tests and
// benchmarks (generators/generators.h makes quad grids; the field pipeline starts
// from triangle meshes).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "mesh/surface_mesh.h"

namespace archgeo {

struct TriangleGridOptions {
  // Glue the column u = 1 onto u = 0 (surfaces of revolution, cylinders):
  // nu columns of vertices instead of nu + 1.
  bool closed_u = false;
  // Interior parameter points (and, along closed_u, every row's points) are
  // moved by up to `jitter` times the parameter cell size in u and v
  // (uniform, fixed `seed`); boundary parameter points stay on [0,1]².
  double jitter = 0.0;
  std::uint64_t seed = 1;
  // Split quad (i, j) along the diagonal (i, j)–(i+1, j+1) when (i + j) is
  // even and along the other diagonal otherwise ("alternate"), or always along
  // the first one.
  bool alternate_diagonals = true;
};

// A triangulated (nu x nv)-cell grid on surface(u, v), (u, v) ∈ [0, 1]²;
// vertex (i, j) has index j * (nu or nu + 1) + i. Faces are oriented so that
// the normal is along ∂u × ∂v. Preconditions (CHECKed): nu, nv ≥ 1 (nu ≥ 3
// when closed_u), jitter ∈ [0, 0.45].
Mesh TriangulatedGrid(int nu, int nv, const std::function<Vec3(double, double)>& surface,
                      const TriangleGridOptions& options = {});

// The parameter point (u, v) of every vertex of TriangulatedGrid with the same
// arguments (after jitter), indexed by vertex index.
std::vector<std::array<double, 2>> TriangulatedGridParameters(int nu, int nv,
                                                               const TriangleGridOptions& options = {});

// Closed ellipsoid x²/a² + y²/b² + z²/c² = 1: an icosahedron refined
// `subdivisions` times by midpoint splitting, projected radially onto the unit
// sphere and scaled by (a, b, c); outward normals; 20·4^subdivisions faces.
// Preconditions (CHECKed): a, b, c > 0, 0 ≤ subdivisions ≤ 7.
Mesh TriangulatedEllipsoid(double a, double b, double c, int subdivisions);

}  // namespace archgeo
