// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the closest points of two segments in space [Ericson 2005,
// Real-Time Collision Detection, §5.1.9].
#pragma once

#include <algorithm>
#include <utility>

#include <Eigen/Core>

namespace archgeo {

// The parameters (s, t) in [0, 1] of the closest points p0 + s (p1 − p0) and
// q0 + t (q1 − q0) of the segments [p0, p1] and [q0, q1]; a segment that is a
// point has parameter 0, parallel segments one of their closest pairs.
inline std::pair<double, double> ClosestSegmentParameters(const Eigen::Vector3d& p0,
                                                          const Eigen::Vector3d& p1,
                                                          const Eigen::Vector3d& q0,
                                                          const Eigen::Vector3d& q1) {
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  const double tiny = 1e-300;
  if (a <= tiny && e <= tiny) return {0.0, 0.0};
  if (a <= tiny) return {0.0, std::clamp(f / e, 0.0, 1.0)};
  const double c = d1.dot(r);
  if (e <= tiny) return {std::clamp(-c / a, 0.0, 1.0), 0.0};
  const double b = d1.dot(d2), denom = a * e - b * b;
  double s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0) {
    t = 0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1) {
    t = 1;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return {s, t};
}

}  // namespace archgeo
