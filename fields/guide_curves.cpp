// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — guide curves for a conjugate field (Gebreiter 2012, §8.1.1); see
// guide_curves.h.
#include "fields/guide_curves.h"

#include <algorithm>
#include <cmath>

namespace archgeo {

double GuideWeight(double distance, double radius) {
  if (!(radius > 0) || distance >= radius) return 0;
  const double inner = 0.5 * radius;
  if (distance <= inner) return 1;
  return 0.5 * (1 + std::cos(M_PI * (distance - inner) / (radius - inner)));
}

std::vector<GuideFace> GuideFaces(const std::vector<Eigen::Vector3d>& centroids,
                                  const std::vector<std::vector<Eigen::Vector3d>>& curves,
                                  const std::vector<bool>& closed, double radius) {
  std::vector<GuideFace> out;
  std::vector<double> distance(curves.size());
  std::vector<Eigen::Vector3d> tangent(curves.size());
  for (size_t f = 0; f < centroids.size(); ++f) {
    const Eigen::Vector3d& c = centroids[f];
    GuideFace best;
    best.distance = INFINITY;
    for (size_t k = 0; k < curves.size(); ++k) {
      const auto& p = curves[k];
      distance[k] = INFINITY;
      const size_t segments = p.size() - 1 + (closed[k] ? 1 : 0);
      for (size_t i = 0; i < segments; ++i) {
        const Eigen::Vector3d a = p[i], b = p[(i + 1) % p.size()];
        const Eigen::Vector3d ab = b - a;
        const double len2 = ab.squaredNorm();
        if (len2 <= 0) continue;
        const double t = std::clamp(ab.dot(c - a) / len2, 0.0, 1.0);
        const double d = (a + t * ab - c).norm();
        if (d < distance[k]) {
          distance[k] = d;
          tangent[k] = ab / std::sqrt(len2);
        }
      }
      if (distance[k] < best.distance) {
        best.distance = distance[k];
        best.curve = int(k);
      }
    }
    best.weight = GuideWeight(best.distance, radius);
    if (best.weight <= 0) continue;
    // Blend the tangents of the curves of the nearest one's family (lines
    // within 45° of it) that are within the radius, by 1/d: between two
    // neighbouring curves the direction turns in proportion to the position
    // from one to the other instead of jumping half way.
    const Eigen::Vector3d& nearest = tangent[size_t(best.curve)];
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (size_t k = 0; k < curves.size(); ++k) {
      if (!(distance[k] < radius)) continue;
      const double along = tangent[k].dot(nearest);
      if (std::abs(along) < std::sqrt(0.5)) continue;  // the other family
      const double w = 1 / (distance[k] + 1e-6 * radius);
      sum += w * (along < 0 ? -tangent[k] : tangent[k]);
    }
    best.tangent = sum.normalized();
    best.face = int(f);
    out.push_back(best);
  }
  return out;
}

}  // namespace archgeo
