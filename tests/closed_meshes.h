// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Closed triangle meshes of the tests, as plain arrays: the unit sphere from
// the octahedron and a torus grid (tests of charts, decimation, remeshing).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace archgeo {

// The octahedron split `levels` times at edge midpoints, every vertex on the
// unit sphere: 8·4^levels triangles, outward.
inline void OctahedronSphere(int levels, std::vector<Eigen::Vector3d>& p,
                             std::vector<std::array<int, 3>>& t) {
  p = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  t = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto at = [&](int a, int b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      p.push_back(((p[size_t(a)] + p[size_t(b)]) / 2).normalized());
      return mid[key] = int(p.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& f : t) {
      const int a = at(f[0], f[1]), b = at(f[1], f[2]), c = at(f[2], f[0]);
      finer.push_back({f[0], a, c});
      finer.push_back({a, f[1], b});
      finer.push_back({c, b, f[2]});
      finer.push_back({a, b, c});
    }
    t = finer;
  }
}

// A torus (radii 2, 0.7) of u × v vertices, vertex j·u + i, two triangles
// per cell, outward.
inline void GridTorus(int u, int v, std::vector<Eigen::Vector3d>& p, std::vector<std::array<int, 3>>& t) {
  p.clear();
  t.clear();
  for (int j = 0; j < v; ++j) {
    for (int i = 0; i < u; ++i) {
      const double a = 2 * M_PI * i / u, b = 2 * M_PI * j / v;
      p.push_back({(2 + 0.7 * std::cos(b)) * std::cos(a), (2 + 0.7 * std::cos(b)) * std::sin(a),
                   0.7 * std::sin(b)});
    }
  }
  auto id = [&](int i, int j) { return ((j + v) % v) * u + (i + u) % u; };
  for (int j = 0; j < v; ++j) {
    for (int i = 0; i < u; ++i) {
      t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
}

}  // namespace archgeo
