// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the extracted quads of a base complex (spectral/base_complex_charts.h)
// relaxed on the design surface, and how straight their grid lines run.
//
// Each chart is mapped to its primitive domain on its own (§4.1.3–4.1.5), so
// a grid line that crosses a chart boundary turns there: the two harmonic
// maps meet with matching samples but different derivatives. RelaxQuads
// straightens them: every vertex of valence 4 moves half-way to the mean of
// its four edge neighbours, then onto the design surface (its closest
// point), `sweeps` times (Jacobi), except that the edge neighbours (spokes)
// of an interior node of valence 3 turn about it, a quarter of the way per
// sweep, towards 120° apart (a base edge that leaves the node at 180° from
// its neighbour otherwise leaves a corner of 180° or more: a folded panel;
// at valences 5–7 the turn folded more panels than it saved, so it is not
// done there); the vertices of another valence — the
// base complex's irregular nodes, the boundary — and the connectivity stay,
// but for the `centres` (the triangle charts' centres, placed by the
// parameterisation, not by the designer): each moves half-way to the mean
// of its edge neighbours, so a centre mapped close to one side of a
// distorted chart is drawn to the middle of its three spokes. (A node of valence 4 is a chart corner only: it moves
// like any other vertex, so that no line turns there either.) No quad turns
// over, folds or collapses: one whose normal would leave its normal as
// mapped by more than 45°, that would bend inward at a corner convex as
// mapped, or whose shortest side would fall below half its length as
// mapped, keeps the corners of the sweep before.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include <Eigen/Core>

namespace archgeo {

// Twice the vector area of quad q (Newell: the cross product of its
// diagonals): its normal, as long as the quad is large.
Eigen::Vector3d QuadNormal(const std::vector<Eigen::Vector3d>& points, const std::array<int, 4>& q);

// The largest and the mean turn (degrees) of the grid lines at the vertices
// of valence 4: at such a vertex v with opposite neighbours a, b, the angle
// between v − a and b − v in the tangent plane at v (normal: the cross
// product of the two lines' central differences), both pairs; 0 where the
// line runs on without turning within the surface.
struct GridLineKinks {
  double max_degrees = 0, mean_degrees = 0;
};
GridLineKinks MeasureGridLineKinks(const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<std::array<int, 4>>& quads);

// Relaxes `points` (the vertices of `quads`, an all-quad mesh) as above;
// `onto` maps a point to its closest point on the design surface;
// `centres`: irregular vertices that move too (−1 entries ignored).
void RelaxQuads(const std::vector<std::array<int, 4>>& quads, int sweeps,
                const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& onto,
                std::vector<Eigen::Vector3d>* points, const std::vector<int>& centres = {});

}  // namespace archgeo
