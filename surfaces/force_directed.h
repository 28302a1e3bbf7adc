// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the force-directed algorithm for orthogonal, locally equilateral
// grids on parametric surfaces [force-directed grids paper, §3, Listing 1]
// (no CGAL).
//
// Every iteration (Listing 1), with all dispositions computed from the
// positions at its start:
//  Step 1, orthogonality. An interior vertex p with longitudinal neighbours
//    l0, l1 and transversal neighbours t0, t1 gets [eq. 1]
//        F_i = d_o · L · ((l0 − p)* + (l1 − p)* + (t0 − p)* + (t1 − p)*),
//    the sum of the (unnormalised) bisectors of ∠(l0, p, l1) and ∠(t0, p, t1),
//    * = unit vector, each edge taken "projected on the tangential plane" of
//    p. It vanishes iff both grid lines pass straight (180°, geodesically)
//    through p: it straightens the lines. A boundary vertex p0 (3
//    neighbours: p1, p2 along the boundary, p3 inside) gets instead [eq. 2]
//        F_b = d_b · SignedDist(p3, π) · (p2 − p1)*,
//    π the plane through p0 with normal (p2 − p1)*: it slides p0 along the
//    boundary until the transversal edge p0p3 is orthogonal to it. Corners of
//    an open grid (2 neighbours) get neither ("omitted ... since no forces
//    are exerted on them").
//    Orthogonality comes from eq. 2 at the boundary, carried inwards by the
//    straight lines of eq. 1 and the equal lengths of step 2 (a grid of
//    straight, equally long edges meeting the boundary at right angles is
//    a square grid). On a grid closed in both directions only the
//    straightening and the lengths act.
//  Step 2, edge length. Every edge e = (p1, p2), Δl = L − |p2 − p1|:
//        p1.disp −= d_l · Δl · (p2 − p1)*,   p2.disp += d_l · Δl · (p2 − p1)*.
//  Step 3, back-projection [eq. 3]. p' = p + disp. The tangent-plane
//    component of p' − p in the basis {x_u, x_v} at p's (u, v) is the
//    parameter step (du, dv) (the paper's du = du_t / |x_u|, dv = dv_t / |x_v|
//    with (du_t, dv_t) the coordinates in the unit basis); then p' is
//    projected once more onto the tangent plane at the new (u, v) and the
//    step repeated ("one repetition is sufficient"). The vertex is x(u, v):
//    on the surface by construction. A periodic direction wraps (u, v).
//    With hold_boundary, the boundary rows of an open direction are put back
//    on their side of the covered domain after every step (surfaces/
//    grid_cover.h HoldOf: a boundary vertex keeps the one coordinate and
//    keeps the slide along the boundary that eq. 2 gives it, within the
//    side; a corner stays at its corner) — the boundary the paper's eq. 2 assumes, held. Without
//    it an open direction is left free — the paper bounds nothing, and
//    every surface here is defined beyond its domain, so an open grid may
//    contract into or grow out of the domain (its Fig. 8; on the Table 1
//    stand-ins the open grids end up to 37% of the domain's length beyond
//    it, benchmarks/grids_table1) — or, with clamp_to_domain, clamped to the
//    domain's bounds (then an open grid that pushes outwards piles up at
//    the bound and folds: the paper's forces have no term that keeps it in).
//
// L, the ideal edge length, is constant [§3: "a constant ideal length for all
// edges"]: the user's value, or else the mean 3-D edge length of the initial
// grid. (Ideal lengths from the local curvature, which the paper says it
// experiments with, are not implemented.)
//
// Stopping [§3, §4]: the thresholds on the Table 1 measures (any of MDO, ADO,
// MDE, ADE that are set; all set ones must hold), checked every
// history_stride iterations; or the stall criterion — "the changes in
// disposition are negligible from one iteration to the next": the largest
// change of a vertex's applied step between two consecutive iterations,
// measured in the surface's frame, |x_u Δdu + x_v Δdv|, is at most
// stall_tolerance · L (a grid that stands still, and one that only drifts
// along a symmetry of the surface, e.g. turns rigidly about a tower's axis,
// with constant (du, dv)); or a plateau of the goals — none of the four
// Table 1 measures changed by more than plateau_tolerance (degrees, resp.
// percent) over the last plateau_window iterations (an open grid that creeps
// slowly over a surface without symmetry, a vertex caught in a period-2
// oscillation); or max_iterations.
#pragma once

#include <vector>

#include "surfaces/grid.h"
#include "surfaces/grid_quality.h"
#include "surfaces/surface.h"

namespace archgeo {

struct ForceDirectedOptions {
  // §3: "These parameters should take on values between 1% and 5% of the
  // average edge length of the grid." d_o scales a sum of unit vectors, so it
  // is given as that fraction (the disposition is d_o · L · Σ); d_b and d_l
  // scale lengths (a signed distance, a length deviation) and are plain
  // factors. Each ≥ 0; the process becomes unstable well above 5%.
  double d_o = 0.05;
  double d_b = 0.05;
  double d_l = 0.05;
  // > 0: L; 0: the mean edge length of the initial grid.
  double ideal_length = 0.0;
  // Eq. 3: re-projections after the first linear step (the paper: 1).
  int projection_repetitions = 1;
  int max_iterations = 20000;
  // Break conditions on GridQuality::Table1() (degrees, degrees, percent,
  // percent); ≤ 0 leaves one out. With none set, the run ends by stall or
  // max_iterations.
  double stop_mdo = 0.0, stop_ado = 0.0, stop_mde = 0.0, stop_ade = 0.0;
  // Stall: max over vertices of |x_u Δdu + x_v Δdv| ≤ stall_tolerance · L,
  // Δ the change of the vertex's parameter step from the previous
  // iteration; ≤ 0 disables it.
  double stall_tolerance = 1e-11;
  // Plateau: every Table 1 measure within plateau_tolerance (degrees for
  // MDO/ADO, percent for MDE/ADE) of its value plateau_window iterations
  // before (checked at the history entries); plateau_window ≤ 0 disables it.
  int plateau_window = 2000;
  double plateau_tolerance = 0.01;
  // Clamp open directions to the domain's bounds (default: free, see above).
  bool clamp_to_domain = false;
  // Hold the boundary rows of open directions on the sides of `covered`
  // (default: free, see above).
  bool hold_boundary = false;
  ParameterDomain covered;
  // A history entry (and the threshold check) every this many iterations, ≥ 1;
  // the first (iteration 0, the input) and the last are always recorded.
  int history_stride = 10;
};

enum class ForceStop { kThresholds, kStalled, kPlateau, kMaxIterations };
// "thresholds", "stalled", "plateau", "max_iterations"
const char* ForceStopName(ForceStop stop);

struct ForceHistoryEntry {
  int iteration = 0;       // iterations done
  GridQuality quality;     // after them
  double max_move = 0.0;   // largest vertex movement of the last iteration / L (0 at iteration 0)
};

struct ForceDirectedResult {
  Grid grid;              // the final (u, v)
  double ideal_length = 0.0;
  int iterations = 0;
  ForceStop stop = ForceStop::kMaxIterations;
  GridQuality before, after;
  std::vector<ForceHistoryEntry> history;
};

// Runs Listing 1 on `initial` (its (u, v) on `surface`). Preconditions
// (CHECKed): the options in their ranges, initial.uv finite and of size
// n_u·n_v, and the grid closed only in the surface's periodic directions.
ForceDirectedResult RunForceDirected(const Surface& surface, const Grid& initial,
                                     const ForceDirectedOptions& options);

}  // namespace archgeo
