// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the canonical frame a problem is solved in.
//
// Builders work on a copy of the input moved to its centroid, rotated onto
// its principal axes and scaled to unit mean edge length. Solver tolerances,
// trust-region scaling and regularisation constants then see the same numbers
// whatever the file's units, position and orientation, so a similar input
// gives a similar output (up to rounding) and unit-free defaults hold.
#pragma once

#include <array>

#include "mesh/surface_mesh.h"

namespace archgeo {

struct Similarity {
  Vec3 center{0, 0, 0};                            // centroid of the vertices
  std::array<Vec3, 3> axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};  // orthonormal, right-handed
  double scale = 1;                                // mean edge length

  Vec3 ToCanonical(const Vec3& x) const;    // axesᵀ (x − center) / scale
  Vec3 FromCanonical(const Vec3& y) const;  // center + scale · axes y
};

// The canonical frame of `mesh`: principal axes of the vertex cloud (largest
// variance first), each oriented so the third moment along it is positive
// (the sign is arbitrary only for a mesh symmetric about that axis).
Similarity CanonicalFrame(const Mesh& mesh);

// The frame meshes are measured in: the centroid as origin, the axes of the
// file, and as unit the power of two nearest the mean edge length (1 for a
// mesh without edges). Positions are combined near the origin at unit
// scale (a mesh 1e8 edge lengths away, or scaled by 1e±100, is measured as
// the original), and a length measured in it maps back to file units
// exactly: times `scale`, a power of two.
Similarity LocalFrame(const Mesh& mesh);

// `mesh` with every vertex at s.ToCanonical.
Mesh InFrame(const Similarity& s, Mesh mesh);

// Diagonal of the bounding box aligned with the principal axes of the
// vertices: invariant under rotation, translation and reflection, and it
// scales with the mesh. Precondition: at least one vertex.
double PrincipalBoxDiagonal(const Mesh& mesh);

// Applies ToCanonical (or FromCanonical) to every vertex of `mesh`.
void ToCanonical(const Similarity& s, Mesh& mesh);
void FromCanonical(const Similarity& s, Mesh& mesh);

}  // namespace archgeo
