// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — Newell's normal of a polygon, the one place it is computed.
//
//   N = Σ_k p_k × p_{k+1}   (k = 0 .. n−1, p_n = p_0)
//
// N is twice the polygon's vector area: its length is twice the area of a
// planar polygon, its direction the normal (for a non-planar polygon the
// normal of the plane of the projected areas, whatever the corner order
// starts at). Corner types: anything indexed [0..2] (const double*, Eigen or
// std::array vectors, CGAL points).
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace archgeo {

// N of the polygon whose corner k is corner(k), k = 0 .. count−1.
template <typename Corner>
Eigen::Vector3d NewellVector(int count, const Corner& corner) {
  double n[3] = {0, 0, 0};
  for (int k = 0; k < count; ++k) {
    const auto& a = corner(k);
    const auto& b = corner((k + 1) % count);
    n[0] += a[1] * b[2] - a[2] * b[1];
    n[1] += a[2] * b[0] - a[0] * b[2];
    n[2] += a[0] * b[1] - a[1] * b[0];
  }
  return {n[0], n[1], n[2]};
}

// N / |N|, or the zero vector for a polygon without area.
template <typename Corner>
Eigen::Vector3d NewellNormal(int count, const Corner& corner) {
  const Eigen::Vector3d n = NewellVector(count, corner);
  const double length = n.norm();
  return length > 0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
}

}  // namespace archgeo
