// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — guide curves for a conjugate field (Gebreiter 2012, §8.1.1: a
// field a designer steers by curves drawn on the surface). Each face near a
// guide curve gets the curve's tangent at its closest point as a prescribed
// direction (through tcd_prescribed_direction), weighted by a smooth falloff
// of its distance d from the curve within the radius r:
//
//   w(d) = 1                                  for d ≤ r/2,
//   w(d) = ½ (1 + cos(π (d − r/2) / (r/2)))   for r/2 < d < r,
//   w(d) = 0                                  beyond,
//
// so the field follows the curve near it and blends into the free field at r.
// Where several curves of one family (lines within 45° of the nearest one's
// tangent) are within r, as principal-stress lines exported by an FE tool
// are, the tangent is their tangents blended by 1/d, so the directions turn
// in proportion to the position from one curve to its neighbour.
// Plain arrays: no CGAL, no YAML.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace archgeo {

struct GuideFace {
  int face = 0;
  Eigen::Vector3d tangent;  // unit tangent: the nearest curve's, blended with its neighbours' (above)
  double distance = 0;      // from the face's centroid to that point
  double weight = 0;        // w(distance) above, in (0, 1]
  int curve = 0;            // which curve
};

// Faces (by their centroids) within `radius` of any of `curves` (each a
// polyline of ≥ 2 points; `closed[k]` adds its closing segment), nearest
// curve first.
std::vector<GuideFace> GuideFaces(const std::vector<Eigen::Vector3d>& centroids,
                                  const std::vector<std::vector<Eigen::Vector3d>>& curves,
                                  const std::vector<bool>& closed, double radius);

// The falloff w(d) above.
double GuideWeight(double distance, double radius);

}  // namespace archgeo
