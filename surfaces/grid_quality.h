// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — orthogonality and equilaterality of quad grids: MDO, ADO, MDE, ADE
// [force-directed grids paper, §4, eqs. 4–6, Table 1] (no CGAL).
//
// Works on a GridNetwork — points, grid lines, crossings and quads — so the
// same code measures a Grid on a surface (NetworkOfGrid, here) and any quad
// mesh that is a grid (analysis/grid_metrics.h).
//
// Orthogonality at a crossing (a vertex interior to both grid lines through
// it: eq. 5 sums over i = 2..n_u−1, j = 2..n_v−1 of an open grid, every index
// of a closed direction), θ the angle between the longitudinal and the
// transversal line there:
//   MDO = max |90° − θ|                          (eq. 4, degrees)
//   ADO = mean |90° − θ| over the crossings      (eq. 5, degrees)
// Equilaterality over the quads, L_k / l_k the longest / shortest side of quad k:
//   MDE = 100 (max_k L_k / l_k − 1)              (eq. 6, percent)
//   ADE = 100 (mean_k L_k / l_k − 1)             (eq. 6, percent)
//
// Two evaluations of each:
//  spline   — the paper's (§4: "not calculated directly on the discretized
//             mesh ... Instead, grid interpolating spline curves are used"):
//             one cubic spline through the vertices of every grid line
//             (surfaces/cubic_spline.h: chord length, natural ends, periodic
//             when the line is closed); θ is the angle between the two
//             splines' tangents at the crossing, |90° − θ| = atan2(|a·b|, |a×b|);
//             the sides of a quad are the splines' arc lengths between its
//             vertices.
//  discrete — on the polygon itself: θ = the largest of the four angles
//             between consecutive incident edges (a longitudinal and a
//             transversal edge each, the paper's "maximum angle between
//             longitudinal and transversal edges"); the sides of a quad are
//             its edges (chords).
// The paper states the spline evaluation for MDO and ADO; for MDE and ADE it
// speaks of the "side length of quad k", which we read as the edge (chord)
// length. Table1() returns that combination: spline MDO/ADO, discrete MDE/ADE.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "surfaces/grid.h"

namespace archgeo {

struct GridNetwork {
  struct Line {
    std::vector<int> vertices;  // point indices in order
    bool closed = false;        // the last vertex joins the first
  };
  // A vertex interior to the two grid lines through it.
  struct Crossing {
    int vertex;
    // The four neighbours in rotational order, alternating between the two
    // lines (l0, t0, l1, t1).
    std::array<int, 4> ring;
    int line_a, node_a;  // the first line through the vertex and its position on it
    int line_b, node_b;  // the second
  };
  struct Quad {
    std::array<int, 4> vertices;  // cyclic order
    // Side k (vertices k, k+1) as (line, segment), segment s joining nodes s, s+1.
    std::array<std::array<int, 2>, 4> sides;
  };
  int num_points = 0;
  std::vector<Line> lines;
  std::vector<Crossing> crossings;
  std::vector<Quad> quads;
};

struct QualityMeasures {
  double mdo = 0, ado = 0;  // degrees (NaN without crossings)
  double mde = 0, ade = 0;  // percent (NaN without quads)
};

struct GridQuality {
  QualityMeasures spline;    // on the interpolating splines (see above)
  QualityMeasures discrete;  // on the polygon (see above)
  int crossings = 0, quads = 0;
  // As the paper's Table 1: spline MDO, ADO; discrete MDE, ADE.
  QualityMeasures Table1() const { return {spline.mdo, spline.ado, discrete.mde, discrete.ade}; }
};

// The network of a grid (topology only; the points are given to Measure).
GridNetwork NetworkOfGrid(const Grid& grid);

// Both evaluations for `points` (one per network point, finite).
GridQuality MeasureGridNetwork(const GridNetwork& network,
                               const std::vector<Eigen::Vector3d>& points);

// MeasureGridNetwork(NetworkOfGrid(grid), GridPoints(grid, surface)).
GridQuality MeasureGrid(const Grid& grid, const Surface& surface);

}  // namespace archgeo
