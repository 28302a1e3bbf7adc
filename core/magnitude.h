// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the magnitudes of coordinates and lengths archgeo accepts.
//
// Lengths, areas and distances are computed from differences of positions
// and their squares; a coordinate of 1e155 has a square beyond the largest
// double (1.8e308), and a mesh 1e-160 across has squared lengths among the
// subnormal numbers, whose digits are lost. Inputs are refused beyond these
// bounds (exit 2), well inside both: a mesh scaled by 1e±100 is accepted.
#pragma once

namespace archgeo {

// Every coordinate of a mesh is smaller in magnitude than this.
constexpr double kMaxCoordinate = 1e150;
// A mesh's bounding-box diagonal is at least this.
constexpr double kMinDiagonal = 1e-150;
// A parametric surface's parameters (surfaces/surface_factory.h) lie within
// these magnitudes (or are 0): the grid problem evaluates its surface in
// file units and multiplies four lengths (|a|²|b|² of its orthogonality
// term, the squared norm of a cross product of tangents), which overflow
// beyond 1e77 and underflow below 1e-77.
constexpr double kMaxSurfaceParameter = 1e75;
constexpr double kMinSurfaceParameter = 1e-75;

}  // namespace archgeo
