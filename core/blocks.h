// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — variable blocks: the named per-vertex, per-face, per-edge or
// global arrays of doubles a problem optimises besides the positions
// (face normals, z_N, level-set values, ...). A term or a problem declares
// them (BlockDecl); the store (mesh/store.h) holds them; the loop hands
// them to the solver as parameter blocks.
#pragma once

#include <string>

#include "core/elements.h"

namespace archgeo {

// How a variable block maps from the file's units to the canonical frame the
// problem is solved in (x_c = Rᵀ(x − c)/s, mesh/similarity.h), and back.
enum class FrameMap {
  kPosition,       // x → Rᵀ(x − c)/s   (points)
  kDirection,      // x → Rᵀx           (unit vectors, normals)
  kVector,         // x → Rᵀx/s         (offsets, displacements)
  kLength,         // x → x/s           (distances, plane offsets)
  kInverseLength,  // x → x·s           (curvatures)
  kInvariant,      // x → x             (angles, surface parameters, weights, ...)
};

// What happens to a block when the mesh is subdivided (multiresolution).
enum class Carry {
  kReinitialise,  // the owner's `init` runs again on the finer mesh
  kInterpolate,   // vertex blocks: kept on old vertices, averaged from the
                  // two end vertices on new edge vertices (Loop and
                  // Catmull–Clark keep vertex ids); others: re-initialised
};

// A named variable block per vertex, face or edge (or `count` global ones).
struct BlockDecl {
  std::string name;   // e.g. "face_plane_normal"
  Site on = Site::kFace;
  int width = 1;      // doubles per element (≤ 9)
  FrameMap frame = FrameMap::kInvariant;
  bool unit = false;  // a unit 3-vector: optimised on the sphere (ceres::SphereManifold)
  Carry carry = Carry::kReinitialise;
  bool output = false;  // written to the output PLY (named float properties) and report
  bool constant = false;  // data, not optimised (e.g. weights a problem computes)
  std::string doc;
};

}  // namespace archgeo
