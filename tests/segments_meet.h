// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Whether two plane segments cross or touch (the outline-overlap checks of
// the fabrication tests).
#pragma once

#include <algorithm>

#include <Eigen/Core>

namespace archgeo {

inline bool SegmentsMeet(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                         const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
  const auto side = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q,
                       const Eigen::Vector2d& r) {
    const double x = (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x();
    return x > 0 ? 1 : x < 0 ? -1 : 0;
  };
  // r on the segment pq, given that the three are collinear.
  const auto within = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q,
                         const Eigen::Vector2d& r) {
    return r.x() >= std::min(p.x(), q.x()) && r.x() <= std::max(p.x(), q.x()) &&
           r.y() >= std::min(p.y(), q.y()) && r.y() <= std::max(p.y(), q.y());
  };
  const int c_side = side(a, b, c), d_side = side(a, b, d), a_side = side(c, d, a),
            b_side = side(c, d, b);
  if (c_side * d_side < 0 && a_side * b_side < 0) return true;
  return (c_side == 0 && within(a, b, c)) || (d_side == 0 && within(a, b, d)) ||
         (a_side == 0 && within(c, d, a)) || (b_side == 0 && within(c, d, b));
}

}  // namespace archgeo
