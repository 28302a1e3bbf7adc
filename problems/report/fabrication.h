// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the fabrication outputs of a run (docs/fabrication.md):
//   output.panels   the panel table (CSV)
//   output.cutting  the panels flattened and laid out on sheets (DXF)
//   output.nodes    node axes (CSV)
//   output.beams    beams on the edges (CSV)
// computed by fabrication/ on the output mesh in file units and written by
// io/fabrication_files.h; `units` names the mesh's unit, `cutting.*` the
// sheets in millimetres.
#pragma once

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "core/settings.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

// Whether `key` is one of the outputs above.
bool IsFabricationOutput(const std::string& key);

// Before any work: an output or tolerance in millimetres needs `units`
// (throws Settings::Error naming the key).
void CheckFabricationSettings(const Settings& settings);

// Writes every fabrication output staged in `temporaries` (output key →
// file) for `output` (file units) and returns the report's `fabrication`
// section (null when none was asked for); `headline`: a warning line for
// the terminal, if any.
nlohmann::json WriteFabrication(const Mesh& output, const Settings& settings,
                                const std::map<std::string, std::string>& temporaries,
                                std::string* headline);

}  // namespace archgeo
