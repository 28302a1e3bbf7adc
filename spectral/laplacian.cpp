// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "spectral/laplacian.h"

#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

namespace archgeo {

Laplacian BuildLaplacian(const std::vector<Eigen::Vector3d>& points,
                         const std::vector<std::array<int, 3>>& triangles, LaplacianKind kind) {
  const int n = int(points.size());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(triangles.size() * 12);
  Eigen::VectorXd area = Eigen::VectorXd::Zero(n), weight_sum = Eigen::VectorXd::Zero(n);
  for (const std::array<int, 3>& t : triangles) {
    const double twice_area = (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]).norm();
    for (int c = 0; c < 3; ++c) {
      // The corner c's angle is opposite the edge (i, j).
      const int k = t[c], i = t[(c + 1) % 3], j = t[(c + 2) % 3];
      const Eigen::Vector3d a = points[i] - points[k], b = points[j] - points[k];
      const double cross = a.cross(b).norm();
      const double half_cot = cross > 0 ? 0.5 * a.dot(b) / cross : 0.0;
      entries.emplace_back(i, j, -half_cot);
      entries.emplace_back(j, i, -half_cot);
      entries.emplace_back(i, i, half_cot);
      entries.emplace_back(j, j, half_cot);
      weight_sum[i] += half_cot;
      weight_sum[j] += half_cot;
      area[k] += twice_area / 6;  // a third of the triangle
    }
  }
  Laplacian out;
  out.stiffness.resize(n, n);
  out.stiffness.setFromTriplets(entries.begin(), entries.end());
  out.mass = kind == LaplacianKind::kCotangent ? area : weight_sum;
  for (int i = 0; i < n; ++i) {
    if (!(out.mass[i] > 0)) {
      throw std::invalid_argument(
          "vertex " + std::to_string(i) +
          (kind == LaplacianKind::kCotangent ? " has no triangle of positive area"
                                             : " has cotangent weights summing to <= 0"));
    }
  }
  return out;
}

}  // namespace archgeo
