// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — Newell's normal of a polygon, the one place it is computed.
//
//   N = Σ_k (p_k − p_0) × (p_{k+1} − p_0)   (k = 0 .. n−1, p_n = p_0)
//
// N is twice the polygon's vector area: its length is twice the area of a
// planar polygon, its direction the normal (for a non-planar polygon the
// normal of the plane of the projected areas, whatever the corner order
// starts at). Σ p_k × p_{k+1} is the same vector; relative to the first
// corner it keeps its digits far from the origin (a mesh 1e8 edge lengths
// away). Corner types: anything indexed [0..2] (const double*, Eigen or
// std::array vectors, CGAL points).
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace archgeo {

// N of the polygon whose corner k is corner(k), k = 0 .. count−1.
template <typename Corner>
Eigen::Vector3d NewellVector(int count, const Corner& corner) {
  double n[3] = {0, 0, 0};
  if (count == 0) return {0, 0, 0};
  const auto& origin = corner(0);
  const double o[3] = {double(origin[0]), double(origin[1]), double(origin[2])};
  for (int k = 1; k + 1 < count; ++k) {  // the terms with p_0 vanish
    const auto& pa = corner(k);
    const auto& pb = corner(k + 1);
    const double a[3] = {pa[0] - o[0], pa[1] - o[1], pa[2] - o[2]};
    const double b[3] = {pb[0] - o[0], pb[1] - o[1], pb[2] - o[2]};
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
