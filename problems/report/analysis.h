// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the analyses a report shows besides the planarity/proximity
// metrics (analysis/metrics.h): visual smoothness [Pellis 2019], A-net / H-net
// quality [Shi 2014], conical meshes and length spreads [Gebreiter 2012, §10,
// §11; analysis/goal_metrics.h] and grid quality [force-directed grids paper, §4].
// `archgeo solve` shows the ones its problem names (ProblemDecl::analyses),
// `archgeo measure` every one that applies to the mesh.
//
// "grid" (any pure quad mesh whose interior vertices have valence 4 and whose
// boundary vertices valence 2 or 3: a grid; analysis/grid_metrics.h): keys
//   mdo, ado   MDO, ADO (eqs. 4–5, degrees) on the grid-interpolating splines
//              (the paper's evaluation)
//   mde, ade   MDE, ADE (eq. 6, percent) on the quad sides (edges)
//   mdo_discrete, ado_discrete, mde_spline, ade_spline  the other evaluation
//   grid_crossings, grid_quads  what was measured
#pragma once

#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/hnet.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

struct AnalysisRow {
  enum class Kind { kLength, kDegrees, kCount, kRatio, kPercent };
  std::string key;    // JSON key
  std::string label;  // table label
  double value = 0;
  Kind kind = Kind::kRatio;
};
using AnalysisRows = std::vector<AnalysisRow>;

// The value of the row named `key`, or null when `rows` has none.
const double* RowValue(const AnalysisRows& rows, const std::string& key);

// Names of the analyses that apply to `mesh` ("smoothness": any mesh with an
// interior edge; "hnet": pure quad meshes; "conical": meshes with quads and
// an interior valence-4 vertex — conical residual, face-offset miss,
// non-convex quads; "spreads": any mesh with an edge — edge-length and
// boundary-spacing spread; "grid": grids, see above).
std::set<std::string> ApplicableAnalyses(const Mesh& mesh);

// The rows of the analyses in `names` that apply to `mesh`, in file units;
// the H-net rows with `hnet` (the hnet problem's settings, see
// problems/declarations/hnet_net.h HNetOptionsOf).
AnalysisRows Analyse(const Mesh& mesh, const std::set<std::string>& names,
                     const HNetOptions& hnet = {});

// The rows of `rows` (Analyse of `mesh`) that describe what the mesh is, for
// `archgeo measure` without --all: saddle rows only with triangles (bad
// saddles are defined on triangle stars), the A-net and H-net rows only for
// an A-net (star planarity max, or its diagonal net's mean, ≤ 1e-3), the
// conical rows only for a near-conical mesh (mean residual ≤ 0.05 rad), and
// no second count of non-convex quads (the panels row has them).
AnalysisRows RowsThatApply(const Mesh& mesh, const AnalysisRows& rows);

// Multiplies every length row by `factor` (rows measured in a frame whose
// unit is `factor` file units, mesh/similarity.h LocalFrame).
void ScaleLengths(AnalysisRows& rows, double factor);

// Adds every row to `json` (lengths also as "<key>_relative" = value / scale).
void AnalysisToJson(const AnalysisRows& rows, double scale, nlohmann::json& json);

// Table rows in the style of FormatMetrics (problems/report/report.h); with `after`,
// before and after side by side (matched by key).
std::string FormatAnalysis(const AnalysisRows& before, const AnalysisRows* after, double scale);

}  // namespace archgeo
