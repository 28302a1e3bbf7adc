// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the Morse–Smale complex of the standing wave's first component
// cos θ cos φ (spectral/morse_smale.h) and its quasi-dual, for `wave_quads`
// [Gebreiter 2012, §8.3.4]. A mesh with boundary is doubled across it first
// (a second, mirrored copy glued along the boundary; the wave's feature
// constraint sin φ = 0 or sin θ = 0 there makes cos θ cos φ symmetric under
// the mirror), so the complex is that of the closed double: its nodes, arcs
// and quads on the boundary are shared, the others appear twice. Where the
// arcs cannot all be placed apart on that mesh it is refined (below).
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mesh/surface_mesh.h"
#include "spectral/morse_smale.h"

namespace archgeo {

struct WaveComplex {
  bool doubled = false;   // the mesh had a boundary: the complex is its double's
  bool built = false;     // false: the double is not a closed manifold (`error`)
  std::string error;
  // The (doubled) triangle mesh the complex lies on: when arcs could not
  // all be placed on it, refined `refinements` times (0–2: the faces split
  // at their centroids, then 1 to 4), with the wave linear on each triangle,
  // so the same critical points, until they can. (BuildMorseSmale may refine
  // further near arcs it cannot place: the arcs lie on complex.points.)
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> original;  // per vertex of the double: the vertex of the input it copies
  int refinements = 0;
  MorseSmaleComplex complex;
  QuadBaseComplex quasi_dual;
};

// `mesh` any polygon mesh (triangulated here), `f` one value per vertex.
WaveComplex BuildWaveComplex(const Mesh& mesh, const Eigen::VectorXd& f, double persistence);

// The arcs as OBJ polylines, the quasi-dual as an OBJ quad mesh.
std::string WaveComplexArcsObj(const WaveComplex& c);
std::string WaveQuasiDualObj(const WaveComplex& c);

}  // namespace archgeo
