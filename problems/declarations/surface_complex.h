// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the Morse–Smale complex (spectral/morse_smale.h) of a function
// on the vertices of any triangle mesh, and its quasi-dual: `wave_quads`
// (the standing wave's first component cos θ cos φ) and `archgeo spectral
// --complex` (an eigenfunction) [Gebreiter 2012, §7, §8.3.4]. A mesh with
// boundary is doubled across it first (a second, mirrored copy glued along
// the boundary, the function copied), so the complex is that of the closed
// double: its nodes, arcs and quads on the boundary are shared, the others
// appear twice. The boundary is thus a mirror line of the function, as for
// an eigenfunction of the Laplacian with a free (Neumann) boundary or the
// wave under its feature constraint (sin φ = 0 or sin θ = 0 there), and
// its critical points on the boundary are those critical_points.h counts
// half; the complex is built mirror-symmetric (MorseSmaleMirror), so none
// of its arcs crosses the boundary and the half on the surface is a base
// complex of it (HalfBaseComplex). Where the arcs cannot all be placed
// apart on that mesh it is refined (below, mirrored too).
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mesh/surface_mesh.h"
#include "spectral/base_complex_charts.h"
#include "spectral/morse_smale.h"

namespace archgeo {

struct SurfaceComplex {
  bool doubled = false;   // the mesh had a boundary: the complex is its double's
  bool built = false;     // false: the double is not a closed manifold (`error`)
  std::string error;
  // The (doubled) triangle mesh the complex lies on: when arcs could not
  // all be placed on it, refined `refinements` times (0–2: the faces split
  // at their centroids, then 1 to 4), with the function linear on each triangle,
  // so the same critical points, until they can. (BuildMorseSmale may refine
  // further near arcs it cannot place: the arcs lie on complex.points.)
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> original;  // per vertex of the double: the vertex of the input it copies
  int refinements = 0;
  MorseSmaleComplex complex;
  QuadBaseComplex quasi_dual;
  // A mesh with boundary: the input the double was made of (triangulated,
  // its chords split), whose vertices are the double's first ones, and
  // which of them lie on the boundary.
  std::vector<Eigen::Vector3d> half_points;
  std::vector<std::array<int, 3>> half_triangles;
  std::vector<bool> half_boundary;
};

// `mesh` any polygon mesh (triangulated here), `f` one value per vertex;
// `options` the cancellation (persistence or a target count of extrema);
// `max_refinements` the whole-mesh refinements allowed (0–2: the faces split
// at their centroids, then every edge at its midpoint).
SurfaceComplex BuildSurfaceComplex(const Mesh& mesh, const Eigen::VectorXd& f,
                                   const MorseSmaleOptions& options, int max_refinements = 2);

// A doubled complex's base complex on the input itself (half_points,
// half_triangles): the quads of the input's saddles, and of each boundary
// saddle's quad (its arcs along the boundary, into the input, along the
// boundary, into the mirror image) the triangle on the input's side, its
// third side along the boundary (Gebreiter 2012, §4.1.4: charts of
// open-boundary triangles). Throws BaseComplexError naming a boundary
// saddle's quad that is not so (a boundary multi-saddle).
BaseComplex HalfBaseComplex(const SurfaceComplex& c);

// The arcs as OBJ polylines (the header names `function`), the quasi-dual
// as an OBJ quad mesh.
std::string SurfaceComplexArcsObj(const SurfaceComplex& c, const std::string& function);
std::string SurfaceQuasiDualObj(const SurfaceComplex& c);

}  // namespace archgeo
