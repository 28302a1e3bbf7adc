// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the per-face scalar a solve shows: the face colours and named
// float properties of the output PLY, the pictures (output.image, `archgeo
// render`) and the report's arrays (output.arrays). Each problem shows the
// quantity it lowers (ProblemDecl::colors), by name:
//   planarity      δ_PQ,n per face (diagonal distance / mean diagonal,
//                  unitless); red at tolerance.pq_normalized_max when the
//                  problem has that tolerance (> 0), else 1e-3 (planar_quads'
//                  default tolerance)
//   energy         the face's share of E = Σ_e ℓ_e ℓ*_e [Pellis 2019, §3]:
//                  half of each of its edges' ℓ ℓ*, in input mean edge
//                  lengths (smooth_mesh); the faces' values add up to E
//   curvature      the face's share of C = Σ_v |λ1| + |λ2| of W′ [Pellis
//                  2019, §5.3]: each corner's value over its number of faces,
//                  in input mean edge lengths (total_absolute_curvature)
//   bending        max over the face's edges of ℓ_e|α_e| / (mean edge length)
//                  [Pellis 2019, the summand of E′ per edge, Fig. 7], rad
//   orthogonality  the face's largest |90° − corner angle|, degrees (grid);
//                  red at tolerance.mdo when it is set
//   kinks          hnet: the largest kink angle along a face's edges, degrees
//                  [Shi 2014, Table 1]; red at 1°
// Without a tolerance the scale is the input's 95th percentile (the same for
// the input's and the output's picture). A problem whose quantity needs its
// own state (principal_symmetric's condition residuals) gives it through
// ProblemDecl::state_colors (StateFaceValues). `output.color_max`, when
// given, is the value shown red in every case (in the scalar's units).
// Colours go green (0) → yellow → red (≥ red_at).
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

// A problem's own per-face quantity (ProblemDecl::state_colors) on the
// output, scaled by its input values as above.
FaceValues StateFaceValues(std::string name, std::string label, std::string units,
                           std::vector<double> values, const std::vector<double>& input_values,
                           const Settings* settings);

// Names ComputeFaceValues knows (for `archgeo render --value`).
const std::vector<std::string>& FaceValueNames();

// One colour per face of `values`.
FaceColors ColorsOf(const FaceValues& values);

// ComputeFaceValues(name, output, input, &settings) as colours.
FaceColors OutputColors(const std::string& name, const Mesh& output, const Settings& settings,
                        const Mesh* input = nullptr);

}  // namespace archgeo
