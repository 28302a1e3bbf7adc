// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the sample grid of the Hausdorff metric (analysis/metrics.cpp), with
// a bounded number of samples.
//
// ComputeMetrics approximates the Hausdorff distance with CGAL's
// approximate_symmetric_Hausdorff_distance on a regular grid per triangle
// (use_grid_sampling, grid_spacing). CGAL's grid puts about n²/2 samples on a
// triangle whose two edges from its first vertex are up to n spacings long,
// however small its area, so a few long slivers (one vertex moved far) can
// ask for billions of samples. The spacing chosen here keeps the grid under a
// fixed number of samples per surface.
#pragma once

#include "mesh/surface_mesh.h"

namespace archgeo {

// The grid spacing, in mean edge lengths of the sampled triangle mesh, when
// the cap below does not apply: ~14 samples per triangle, vertices included.
constexpr double kHausdorffGridSpacing = 0.25;
// At most this many grid samples per surface (on edges and inside
// triangles; every vertex is sampled besides), ~24 MB of points.
constexpr double kHausdorffMaxGridSamples = 1e6;

// The number of grid samples CGAL 5.5's sample_triangle_mesh (grid sampling
// with `spacing`, vertices not counted) puts on the edges and inside the
// triangles of the triangle mesh `triangles`, by its own formulas:
// ceil(|e|/s) − 1 per edge, (n − 1)(n − 2)/2 per triangle with
// n = max(ceil(|p0p1|/s), ceil(|p0p2|/s)) from its first halfedge's source p0.
// Precondition: `triangles` has triangular faces only; spacing > 0.
double HausdorffGridSampleCount(const Mesh& triangles, double spacing);

// kHausdorffGridSpacing mean edge lengths of `triangles`, or the smallest
// larger spacing found (growing by factors ≥ 1.01) at which
// HausdorffGridSampleCount ≤ kHausdorffMaxGridSamples. The Hausdorff
// estimate is then a lower bound with a sampling density of one such
// spacing: the distance to the other surface is 1-Lipschitz and every point
// of a triangle lies within about one spacing of a sample. Infinity (no grid,
// the vertices alone are sampled) if the mean edge length is 0 or not finite.
double HausdorffGridSpacing(const Mesh& triangles);

}  // namespace archgeo
