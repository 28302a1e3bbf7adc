// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — meshes in memory for RunSpec (problems/commands/run.h) instead of the
// spec's files: the public API (api/) and the Python module hand them in.
#pragma once

#include "mesh/surface_mesh.h"

namespace archgeo {

// `mesh` (file units) replaces reading `mesh`, `reference` (may be null)
// replaces reading `reference`; the spec's keys may then be missing. When
// `output` is not null it receives the result (file units, the input's
// vertex order) if one is usable and valid (exit 0 or 4).
struct MeshInputs {
  const Mesh* mesh = nullptr;
  const Mesh* reference = nullptr;
  Mesh* output = nullptr;
};

}  // namespace archgeo
