// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the sample grid of the Hausdorff metric (see hausdorff_sampling.h).
#include "geometry/hausdorff_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace archgeo {
namespace {

double Distance(const Point& a, const Point& b) { return std::sqrt(CGAL::squared_distance(a, b)); }

}  // namespace

double HausdorffGridSampleCount(const Mesh& triangles, double spacing) {
  double count = 0;
  for (EdgeIndex e : triangles.edges()) {
    const double n =
        std::ceil(Distance(triangles.point(triangles.vertex(e, 0)),
                           triangles.point(triangles.vertex(e, 1))) /
                  spacing);
    count += std::max(0.0, n - 1);
  }
  for (FaceIndex f : triangles.faces()) {
    const HalfedgeIndex h = triangles.halfedge(f);
    const Point& p0 = triangles.point(triangles.source(h));
    const Point& p1 = triangles.point(triangles.target(h));
    const Point& p2 = triangles.point(triangles.target(triangles.next(h)));
    const double n = std::max(std::ceil(Distance(p0, p1) / spacing),
                              std::ceil(Distance(p0, p2) / spacing));
    if (n > 2) count += 0.5 * (n - 1) * (n - 2);
  }
  return count;
}

double HausdorffGridSpacing(const Mesh& triangles) {
  double length = 0;
  for (EdgeIndex e : triangles.edges()) {
    length += Distance(triangles.point(triangles.vertex(e, 0)),
                       triangles.point(triangles.vertex(e, 1)));
  }
  double spacing = triangles.number_of_edges() > 0
                       ? kHausdorffGridSpacing * length / triangles.number_of_edges()
                       : 0.0;
  // No length (or an overflow): no grid at all, the vertices are the samples.
  // (CGAL reads a spacing of 0 as "the shortest edge", 0 here: an endless loop.)
  if (!(spacing > 0) || !std::isfinite(spacing)) return std::numeric_limits<double>::infinity();
  // Face samples shrink as 1/spacing², edge samples as 1/spacing: growing by
  // sqrt(count / cap) reaches the cap in a few rounds.
  for (int round = 0; round < 100; ++round) {
    const double count = HausdorffGridSampleCount(triangles, spacing);
    if (count <= kHausdorffMaxGridSamples) break;
    spacing *= std::max(1.01, std::sqrt(count / kHausdorffMaxGridSamples));
  }
  return spacing;
}

}  // namespace archgeo
