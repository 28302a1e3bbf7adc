// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — conjugate_layout's second layout path (layout.method:
// streamlines, [Gebreiter 2012, §8.2]): the field's evenly spaced streamlines
// of both families (fields/streamlines.h), their crossings walked into a
// polygon mesh (fields/streamline_mesh.h), then the level-set path's
// clean-up (the extraction.* keys, fields/extract.h LayoutFromSoup).
#pragma once

#include <map>
#include <memory>
#include <string>

#include "core/loop.h"
#include "core/settings.h"
#include "fields/streamlines.h"
#include "mesh/surface_mesh.h"
#include "problems/declarations/field_pipeline.h"

namespace archgeo {

// The layout.method key (level_sets | streamlines).
Key LayoutMethodKey();

// The field of `parent` on `design` (file units; `overrides` as for
// SolveField), its streamlines (the streamlines.* keys; d_sep =
// streamlines.separation × the principal box diagonal if that key is given,
// else the square root of the surface's area over level_sets.target_faces, or
// level_sets.edge_length), and the layout of their crossings as a
// LevelSetResult without level-set functions (cut and functions empty). Its
// details "layout" has level_sets' counts plus the streamline mesh's
// diagnostics and the edge-to-field angle measured on the cleaned layout
// (fields/streamline_mesh.h MeasureEdgeFieldAngle). `lines` (if not null)
// receives the traced lines. Throws InputError on layout.method when no face
// is cut out.
std::shared_ptr<const LevelSetResult> SolveStreamlineLayout(
    const Settings& parent, const Mesh& design, const ProgressSink& progress,
    const std::map<std::string, Value>& overrides, StreamlineResult* lines);

}  // namespace archgeo
