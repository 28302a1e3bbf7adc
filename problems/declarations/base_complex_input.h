// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the base complex of problem base_complex_quads from the user
// (Gebreiter 2012, §9, §11.6.1): a coarse triangle/quad mesh whose vertices
// are snapped to the nearest vertex of the design mesh, or a file of surface
// vertex ids and faces (io/base_complex_ids.h).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/settings.h"
#include "spectral/base_complex_charts.h"

namespace archgeo {

struct UserBaseComplex {
  BaseComplex complex;
  std::string file, key;       // where it came from (for messages)
  double snap_distance = 0;    // the largest snap, file units (0 for ids)
};

// From `base_complex.mesh` (snapped within base_complex.tolerance × the
// design mesh's diagonal `diagonal`) or `base_complex.ids`. Throws InputError
// naming the file and the base vertex that is too far from the surface.
UserBaseComplex ReadUserBaseComplex(const Settings& s, const std::vector<Eigen::Vector3d>& points,
                                    double diagonal);

}  // namespace archgeo
