// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/weld.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace archgeo {
namespace {

using P = std::array<double, 3>;

double Distance2(const P& a, const P& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return dx * dx + dy * dy + dz * dz;
}

double MeanEdgeLength(const std::vector<P>& points,
                      const std::vector<std::vector<std::size_t>>& polygons) {
  double sum = 0;
  std::size_t count = 0;
  for (const auto& polygon : polygons) {
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      sum += std::sqrt(Distance2(points[polygon[k]], points[polygon[(k + 1) % polygon.size()]]));
      ++count;
    }
  }
  return count > 0 ? sum / double(count) : 0.0;
}

struct CellHash {
  std::size_t operator()(const std::array<std::int64_t, 3>& c) const {
    return std::size_t(c[0] * 73856093) ^ std::size_t(c[1] * 19349663) ^
           std::size_t(c[2] * 83492791);
  }
};

}  // namespace

std::size_t WeldCoincidentVertices(std::vector<P>* points,
                                   std::vector<std::vector<std::size_t>>* polygons,
                                   double distance) {
  const double tolerance = distance * MeanEdgeLength(*points, *polygons);
  if (!(tolerance > 0) || !std::isfinite(tolerance)) return 0;
  std::vector<bool> used(points->size(), false);
  for (const auto& polygon : *polygons) {
    for (std::size_t v : polygon) used[v] = true;
  }
  using Cell = std::array<std::int64_t, 3>;
  const auto cell_of = [&](const P& p) {
    return Cell{std::int64_t(std::floor(p[0] / tolerance)),
                std::int64_t(std::floor(p[1] / tolerance)),
                std::int64_t(std::floor(p[2] / tolerance))};
  };
  std::unordered_map<Cell, std::vector<std::size_t>, CellHash> grid;
  std::vector<std::size_t> target(points->size());
  std::size_t welded = 0;
  for (std::size_t i = 0; i < points->size(); ++i) {
    target[i] = i;
    if (!used[i]) continue;
    const P& p = (*points)[i];
    const Cell c = cell_of(p);
    for (std::int64_t dx = -1; dx <= 1 && target[i] == i; ++dx) {
      for (std::int64_t dy = -1; dy <= 1 && target[i] == i; ++dy) {
        for (std::int64_t dz = -1; dz <= 1 && target[i] == i; ++dz) {
          const auto it = grid.find(Cell{c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == grid.end()) continue;
          for (std::size_t k : it->second) {
            if (Distance2(p, (*points)[k]) <= tolerance * tolerance) {
              target[i] = k;
              break;
            }
          }
        }
      }
    }
    if (target[i] == i) {
      grid[c].push_back(i);
    } else {
      ++welded;
    }
  }
  if (welded == 0) return 0;
  std::vector<std::size_t> index(points->size());
  std::vector<P> kept;
  kept.reserve(points->size() - welded);
  for (std::size_t i = 0; i < points->size(); ++i) {
    if (target[i] != i) continue;
    index[i] = kept.size();
    kept.push_back((*points)[i]);
  }
  for (auto& polygon : *polygons) {
    for (std::size_t& v : polygon) v = index[target[v]];
  }
  *points = std::move(kept);
  return welded;
}

}  // namespace archgeo
