// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A mesh point or a Vec3 as an Eigen vector, for the geometry that needs
// Eigen's algebra.
#pragma once

#include <Eigen/Core>

#include "mesh/surface_mesh.h"

namespace archgeo {

inline Eigen::Vector3d EigenVector(const Vec3& x) { return {x[0], x[1], x[2]}; }

// The position of vertex `v`.
inline Eigen::Vector3d EigenPoint(const Mesh& mesh, VertexIndex v) {
  const Point& p = mesh.point(v);
  return {p.x(), p.y(), p.z()};
}

}  // namespace archgeo
