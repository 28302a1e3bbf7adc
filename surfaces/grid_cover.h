// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — how much of its surface patch a grid covers, and the boundary
// that makes an open grid cover it (no CGAL).
//
// Covered part. An open direction of a grid has its two boundary rows held on
// the two sides of the covered part of the parameter domain: the whole
// domain, or the rectangle centred in it that is `fraction` of its parameter
// area (each open direction shrunk by √fraction when both are open, by
// `fraction` when one is; a closed direction keeps its period). A vertex on
// such a side keeps that coordinate and slides along the other; a corner of
// an open grid keeps both.
//
// Coverage of a grid on its surface:
//   area fraction      = grid area / patch area, the grid area Σ over its
//                        quads (seam quads included) of the mean of the two
//                        triangulations' areas, the patch area ∫∫_D |x_u × x_v|
//                        over the whole domain D (one period of a closed
//                        direction) by Gauss–Legendre quadrature (3 × 3 points
//                        on 64 × 64 cells);
//   parameter fraction = Σ over the quads of their oriented (u, v) area / area
//                        of D. Each quad's corners are taken in the chart of
//                        its first corner (Surface::NearestChart), and its area
//                        counts with the sign its quad has in a reference grid
//                        (the initial one), so a folded quad subtracts. For an
//                        open grid this is the area of its (u, v) boundary
//                        polygon; for a closed direction the area between its
//                        boundary rows; 1 for a grid closed both ways.
// The grid's quads are chords of the surface, so a grid whose boundary lies
// on the patch's boundary has an area fraction slightly below 1 (by the
// chordal error) and a parameter fraction of exactly 1.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "surfaces/grid.h"
#include "surfaces/surface.h"

namespace archgeo {

// The covered part of `domain` for a grid closed as `grid` is (see above).
// Precondition (CHECKed): 0 < fraction ≤ 1.
ParameterDomain CoveredDomain(const ParameterDomain& domain, const Grid& grid, double fraction);

// The grid's open directions mapped affinely from `from` onto `to` (the
// uniform grid of a domain onto its covered part).
void MapOpenDirections(Grid* grid, const ParameterDomain& from, const ParameterDomain& to);

// Which parameters of a vertex the boundary holds, and their values: a
// vertex in the first or last column of an open u holds u at covered.u0 resp.
// covered.u1; in the first or last row of an open v, v at covered.v0 resp. v1.
struct BoundaryHold {
  bool u = false, v = false;
  double u_value = 0.0, v_value = 0.0;
  bool Any() const { return u || v; }
};
BoundaryHold HoldOf(const Grid& grid, int vertex, const ParameterDomain& covered);

// ∫∫ |x_u × x_v| du dv over `domain` (file units squared).
double PatchArea(const Surface& surface, const ParameterDomain& domain);

struct GridCoverage {
  double grid_area = 0.0, patch_area = 0.0, area_fraction = 0.0;
  double parameter_area = 0.0, domain_area = 0.0, parameter_fraction = 0.0;
};

// The coverage of `grid` (its (u, v)) on `surface`, whose whole domain has
// the area `patch_area` (PatchArea). `reference` is a grid of the same
// topology (the initial one) whose quads give each quad's orientation.
GridCoverage MeasureCoverage(const Grid& grid, const Grid& reference, const Surface& surface,
                             double patch_area);

}  // namespace archgeo
