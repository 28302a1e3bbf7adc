// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — MDO, ADO, MDE, ADE of any quad mesh that is a grid
// [force-directed grids paper, §4, eqs. 4–6; definitions and the spline /
// discrete evaluations in surfaces/grid_quality.h].
#pragma once

#include <nlohmann/json.hpp>

#include "mesh/surface_mesh.h"
#include "surfaces/grid_quality.h"

namespace archgeo {

// The grid network of `mesh`: its grid lines are the mesh polylines
// (mesh/topology.h MeshPolylines: straight through interior vertices of
// valence 4 and boundary vertices of valence 3; closed ones detected); its
// crossings the interior vertices of valence 4; its quads the 4-sided faces.
// Vertices of other valences (a quad-dominant mesh's singularities) end
// lines and are not crossings; other faces are not measured. Points are
// indexed by vertex index. Precondition (CHECKed): no removed elements.
GridNetwork GridNetworkOfMesh(const Mesh& mesh);

// MeasureGridNetwork(GridNetworkOfMesh(mesh), the mesh's points).
GridQuality MeasureQuadGridMesh(const Mesh& mesh);

// {"mdo", "ado", "mde", "ade"} as Table 1 (spline MDO/ADO in degrees,
// discrete MDE/ADE in percent), "spline" and "discrete" objects with all
// four of each evaluation, "crossings" and "quads". NaN (nothing to
// measure) is written as null.
nlohmann::json GridQualityToJson(const GridQuality& quality);

}  // namespace archgeo
