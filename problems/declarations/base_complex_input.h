// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — base complexes in the problems: the one of base_complex_quads
// from the user (Gebreiter 2012, §9, §11.6.1): a coarse triangle/quad mesh
// whose vertices are snapped to the nearest vertex of the design mesh, or a
// file of surface vertex ids and faces (io/base_complex_ids.h); and the step
// every base complex goes through, from the user's or a Morse–Smale
// complex's quasi-dual (spectral_quads, wave_quads): charts →
// parameterisation → extraction (spectral/base_complex_charts.h), judged.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "core/problem.h"
#include "core/settings.h"
#include "mesh/surface_mesh.h"
#include "spectral/base_complex_charts.h"
#include "spectral/morse_smale.h"

namespace archgeo {

struct UserBaseComplex {
  BaseComplex complex;
  std::string file, key;       // where it came from (for messages)
  double snap_distance = 0;    // the largest snap, file units (0 for ids)
};

// From `base_complex.mesh` (snapped within base_complex.tolerance × the
// design mesh's diagonal `diagonal`) or `base_complex.ids`. Throws InputError
// naming the file and the base vertex that is too far from the surface.
UserBaseComplex ReadUserBaseComplex(const Settings& s, const std::vector<Eigen::Vector3d>& points,
                                    double diagonal);

// The quasi-dual of a Morse–Smale complex as a base complex: its extrema's
// vertices the nodes, its quads the faces, each side's edge its own.
BaseComplex QuasiDualBaseComplex(const QuadBaseComplex& q);

// The keys charts.* (n, edge_length, weights, smoothing, boundary_triangles,
// output), and the check that charts.n and charts.edge_length are not both given.
std::vector<Key> ChartKeys();
void CheckChartKeys(const Settings& s);
// CheckChartKeys, and charts.output: triangles refused (a quad base complex).
void CheckQuadComplexChartKeys(const Settings& s);

// The schedule of a problem whose `net` hook makes the result (the quads of
// the charts): one stage, `extract`, of one round that records it; no solve.
std::vector<Stage> NetIsTheResult(const Settings& s);

struct ChartStep {
  ChartQuadsResult result;
  Mesh mesh;               // the all-quad mesh (the points' units)
  nlohmann::json details;  // the report's details.charts
  std::string headline;    // lines for the terminal
  // "" or one line per failed check: a flipped parameter triangle, irregular
  // vertices other than the base complex's, a boundary edge off the base
  // complex's boundary, a non-manifold edge or T-junction, a vertex farther than 1e-9 of the diagonal from `design`.
  std::string invalid;
};

// `base` on the triangle mesh (`points`, `triangles`; `design` or a
// refinement of it: the output is judged against `design`) → charts →
// parameterisation → the all-quad mesh, by the chart keys of `s`. Throws
// BaseComplexError for a complex the surface cannot carry and
// std::invalid_argument for an odd charts.n with a triangle face. Folded
// quads are unfolded (spectral/quad_untangle.h); `move_nodes`: the base
// complex's nodes may move on the surface for it (nodes a function's
// critical points placed, not the designer).
ChartStep RunChartStep(const Settings& s, const Mesh& design,
                       const std::vector<Eigen::Vector3d>& points,
                       const std::vector<std::array<int, 3>>& triangles, const BaseComplex& base,
                       bool move_nodes);

}  // namespace archgeo
