// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — writing a sampled patchwork (geometry/hnet.h SampledPatchwork) as a
// PLY triangle mesh with per-vertex normals and, optionally, per-vertex
// colours (e.g. isophote bands, [Shi 2014, Fig. 5]).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "geometry/hnet.h"

namespace archgeo {

// Writes `patchwork` to `path` (binary little-endian PLY, or ASCII with
// `ascii`): vertex x y z nx ny nz [red green blue], face vertex_indices.
// Vertices no triangle uses (e.g. points a Darboux map sent to infinity) are
// left out and the rest renumbered. `colors` is empty or one per vertex.
// Throws InputError(path, ...) if the file cannot be written.
void WritePatchworkPly(const std::string& path, const SampledPatchwork& patchwork,
                       const std::vector<std::array<unsigned char, 3>>& colors = {},
                       bool ascii = false);

}  // namespace archgeo
