// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — see io/soup_halfedges.h.
#include "io/soup_halfedges.h"

#include <algorithm>
#include <cstdint>

namespace archgeo {

bool EachOrderedEdgeOnce(const std::vector<std::vector<std::size_t>>& polygons,
                         std::size_t num_points) {
  // The edges leaving each vertex, grouped by vertex (a counting sort).
  std::vector<std::size_t> first(num_points + 1, 0);
  for (const auto& polygon : polygons) {
    for (std::size_t v : polygon) ++first[v + 1];
  }
  for (std::size_t v = 0; v < num_points; ++v) first[v + 1] += first[v];
  std::vector<std::size_t> next = first;
  std::vector<std::size_t> target(first[num_points]);
  for (const auto& polygon : polygons) {
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) target[next[polygon[i]]++] = polygon[(i + 1) % n];
  }
  for (std::size_t v = 0; v < num_points; ++v) {
    const auto begin = target.begin() + std::ptrdiff_t(first[v]);
    const auto end = target.begin() + std::ptrdiff_t(first[v + 1]);
    std::sort(begin, end);
    if (std::adjacent_find(begin, end) != end) return false;
  }
  return true;
}

}  // namespace archgeo
