// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — subdivision for multiresolution optimisation [Pellis 2019, §6]:
// "we first design a coarse mesh ... subsequently we apply subdivision and
// optimize again". Thin wrappers over CGAL Subdivision_method_3.
#pragma once

#include <string>

#include "mesh/surface_mesh.h"

namespace archgeo {

// True if `scheme` can subdivide `mesh`: loop and sqrt3 need a triangle
// mesh; catmull_clark and doo_sabin take any polygon mesh.
bool CanSubdivide(const Mesh& mesh, const std::string& scheme);

// One subdivision step of `mesh` with `scheme` (loop | sqrt3 | catmull_clark |
// doo_sabin). Loop and Catmull–Clark keep the original vertices' indices (they
// are repositioned by the smoothing masks; new vertices are appended);
// sqrt3 and Doo–Sabin renumber. Removes every property map but positions (the
// property vectors would be invalid anyway). Precondition: CanSubdivide.
Mesh Subdivide(const Mesh& mesh, const std::string& scheme);

// Each triangle split into four at its edge midpoints: the same surface
// (every new vertex lies on an old edge), four times the faces. Vertices
// keep their indices (midpoints appended in edge order); the children of
// face f are faces 4f .. 4f + 3. Precondition: a triangle mesh without
// removed elements.
Mesh MidpointSubdivision(const Mesh& triangles);

}  // namespace archgeo
