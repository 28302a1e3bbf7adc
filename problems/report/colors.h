// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the per-face scalar a solve shows: the face colours and named
// float properties of the output PLY, the pictures (output.image, `archgeo
// render`) and the report's arrays (output.arrays). By the name a problem
// declaration gives (ProblemDecl::colors):
//   planarity  δ_PQ,n per face (diagonal distance / mean diagonal, unitless);
//              red at tolerance.pq_normalized_max when the problem has that
//              tolerance (> 0), else 1e-3 (planar_quads' default tolerance)
//   bending    max over the face's edges of ℓ_e|α_e| / (mean edge length)
//              [Pellis 2019, the summand of E′ per edge, made scale-free]:
//              radians of an edge of mean length; red at the input's largest
//              value (these problems have no per-face tolerance), so the
//              before picture spans the whole scale
//   curvature  the same scalar as bending (total_absolute_curvature)
//   kinks      hnet: the largest kink angle along a face's edges, degrees
//              [Shi 2014, Table 1]; red at 1°
// `output.color_max`, when given, is the value shown red in every case (in
// the scalar's units). Colours go green (0) → yellow → red (≥ red_at).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/settings.h"
#include "mesh/surface_mesh.h"
#include "render/colormap.h"  // ScaleColor

namespace archgeo {

using FaceColors = std::vector<std::array<unsigned char, 3>>;

struct FaceValues {
  std::string name;    // PLY property and report array name, e.g. "pq_normalized"
  std::string label;   // for picture titles and colour bars
  std::string units;   // e.g. "1 (relative)", "rad", "degrees"
  std::vector<double> values;  // one per face, indexed by face index
  double red_at = 1;   // the value drawn pure red (> 0)
  std::string red_from;  // where red_at comes from (for the report and the picture)
};

// The scalar called `name` on `mesh` (file units). `input` (may be null) is
// the mesh the solve started from: the bending scale is taken from it. With
// `settings` null, only output.color_max-free defaults apply and `color_max`
// (if > 0) sets red_at. CHECKs the name is known.
FaceValues ComputeFaceValues(const std::string& name, const Mesh& mesh, const Mesh* input,
                             const Settings* settings, double color_max = 0);

// Names ComputeFaceValues knows (for `archgeo render --value`).
const std::vector<std::string>& FaceValueNames();

// One colour per face of `values`.
FaceColors ColorsOf(const FaceValues& values);

// ComputeFaceValues(name, output, input, &settings) as colours.
FaceColors OutputColors(const std::string& name, const Mesh& output, const Settings& settings,
                        const Mesh* input = nullptr);

}  // namespace archgeo
