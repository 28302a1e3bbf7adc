// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the diagonal nets of a quad mesh.
//
// Colour the vertices of a quad mesh alternately (a bipartite vertex graph).
// The diagonals of the faces that join two vertices of colour k form the
// edges of the colour-k diagonal net; its faces are the vertex rings of the
// interior vertices of the other colour (a valence-4 vertex c has the ring
// quad w0 w1 w2 w3 of its neighbours, whose sides are the diagonals of the
// four faces around c). A quad mesh along the principal directions of a
// negatively curved surface has its asymptotic net among its diagonals: tools
// such as ArchGeo store A-nets this way (e.g. ../shared/data/
// dos_free_negshell_marc_anet.obj, whose own vertex stars are 0.145 off-plane
// while those of one diagonal net are planar to 5e-6). [Shi 2014, §2.3 and
// Remark 5 use the same colouring for the patch diagonals.]
//
// Rings that are not quads (interior vertices of valence ≠ 4 of the other
// colour) and boundary vertices of the other colour leave no face: the net
// then has a hole there, and the boundary is the input's less one row of
// half-faces. Vertices of colour k that end up in no ring are dropped.
#pragma once

#include <vector>

#include "mesh/surface_mesh.h"

namespace archgeo {

struct DiagonalNet {
  Mesh mesh;                // pure quad, oriented like the input
  int colour = 0;           // the colour class of its vertices
  std::vector<int> source;  // per net vertex index: the input vertex index (increasing)
  int holes = 0;            // interior rings of the other colour that are not quads
};

// The colour-`colour` (0 or 1, see TwoColouring in mesh/topology.h) diagonal
// net of `mesh`. Throws InputError (key "mesh", no file) if the mesh is not
// bipartite, if the net has no face, or if a net vertex would join two
// separate fans of faces (a non-manifold vertex).
DiagonalNet MakeDiagonalNet(const Mesh& mesh, int colour);

}  // namespace archgeo
