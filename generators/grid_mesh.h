// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — a grid on a parametric surface as a CGAL quad mesh, and its files
// with the (u, v) of every vertex.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "mesh/surface_mesh.h"
#include "surfaces/grid.h"
#include "surfaces/surface.h"

namespace archgeo {

// The quad mesh of `grid` on `surface`: vertex index j·n_u + i at x(u_ij, v_ij)
// (exactly the surface point), one face per grid quad (i, j), (i+1, j),
// (i+1, j+1), (i, j+1), so the faces are oriented along x_u × x_v. A Surface_mesh
// must be orientable: on a grid whose u-seam reflects v (a Klein-bottle or
// Möbius grid, Grid::flip) the n_v − 1 or n_v quads across that seam are left
// out (the mesh is the grid cut open along its seam, vertices unchanged); their
// number is stored in `omitted_faces` if non-null.
Mesh GridToMesh(const Grid& grid, const Surface& surface, int* omitted_faces = nullptr);

// Writes `mesh` with the parameter uv[k] of vertex index k:
//   .ply  binary little-endian (ASCII if `ascii_ply`), vertex properties
//         x, y, z, u, v (double);
//   .obj  "v x y z", "vt u v" (one per vertex, same order: raw parameters, not
//         normalised to [0, 1]) and faces "f a/a b/b ...".
// Full double precision. Throws InputError (file = path) for another
// extension (OFF has no per-vertex parameters) or a file that cannot be
// written. Precondition (CHECKed): one finite uv per vertex, no removed
// elements in `mesh`.
void WriteGridMesh(const std::string& path, const Mesh& mesh,
                   const std::vector<Eigen::Vector2d>& uv, bool ascii_ply = false);

}  // namespace archgeo
