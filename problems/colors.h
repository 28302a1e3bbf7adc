// archgeo — the face colours of an output PLY, by the name a problem
// declaration gives (ProblemDecl::colors):
//   planarity  δ_PQ,n per face, green 0 → red at output.color_max
//   bending    the largest ℓ|α| of a face's edges, red at output.color_max ×
//              the mean edge length (an edge of mean length bent by color_max
//              radians)
//   curvature  the largest ℓ|α| of a face's edges, red at the mesh's maximum
//   kinks      hnet: the largest kink angle along a face's edges, red at 1°
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/settings.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

using FaceColors = std::vector<std::array<unsigned char, 3>>;

// One colour per face of `output` (file units). CHECKs the name is known.
FaceColors OutputColors(const std::string& name, const Mesh& output, const Settings& settings);

}  // namespace archgeo
