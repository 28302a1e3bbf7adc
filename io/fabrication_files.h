// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the fabrication files: the panel table and the node and beam
// tables (CSV), and the panels' flat outlines on sheets (DXF R12, ASCII).
// Each writes exactly `path` (use StagedOutputs for atomic outputs) and
// throws InputError naming `path` and `key` when it cannot be written.
// Numbers are written with 17 significant digits (they read back to the
// same double); lists within a CSV field are separated by ';'.
#pragma once

#include <string>
#include <vector>

#include "fabrication/nodes.h"
#include "fabrication/panels.h"
#include "fabrication/sheet_layout.h"

namespace archgeo {

// output.panels: one row per panel (docs/fabrication.md lists the columns).
// `mm_per_unit` > 0 adds the flatness in millimetres.
void WritePanelsCsv(const std::string& path, const std::vector<PanelRecord>& panels,
                    double mm_per_unit, const std::string& key);

// output.cutting: every sheet as a rectangle (layer SHEETS, with its
// number), every outline as a closed POLYLINE (layer PANELS) with its face
// id as TEXT at its centre (layer IDS). Sheet k lies right of sheet k−1,
// a tenth of a sheet width apart. `face_ids[i]` labels layout.outlines[i];
// `unit`: the drawing's unit for $INSUNITS ("mm", "cm", "m", "in", "ft";
// anything else: unitless).
void WriteCuttingDxf(const std::string& path, const SheetLayout& layout,
                     const std::vector<int>& face_ids, const std::string& unit,
                     const std::string& key);

// output.nodes: one row per vertex: position, axis and how it was found.
void WriteNodesCsv(const std::string& path, const std::vector<Eigen::Vector3d>& points,
                   const std::vector<NodeAxis>& nodes, const std::string& key);

// output.beams: one row per edge; with `far_edges`, the ends of its far
// edge (Beam::offset0, offset1) too.
void WriteBeamsCsv(const std::string& path, const std::vector<Beam>& beams,
                   const std::vector<NodeAxis>& nodes, bool far_edges, const std::string& key);

}  // namespace archgeo
