// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fields/triangle_surfaces.h"

#include <cmath>
#include <map>
#include <random>

#include <glog/logging.h>

namespace archgeo {

std::vector<std::array<double, 2>> TriangulatedGridParameters(int nu, int nv,
                                                               const TriangleGridOptions& options) {
  CHECK(nu >= 1 && nv >= 1) << "TriangulatedGrid: nu, nv must be >= 1";
  CHECK(!options.closed_u || nu >= 3) << "TriangulatedGrid: closed_u needs nu >= 3";
  CHECK(options.jitter >= 0.0 && options.jitter <= 0.45) << "TriangulatedGrid: jitter in [0, 0.45]";
  const int cols = options.closed_u ? nu : nu + 1;
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<std::array<double, 2>> uv;
  for (int j = 0; j <= nv; ++j) {
    for (int i = 0; i < cols; ++i) {
      double u = static_cast<double>(i) / nu, v = static_cast<double>(j) / nv;
      const double du = options.jitter * unit(rng) / nu, dv = options.jitter * unit(rng) / nv;
      const bool inner_u = options.closed_u || (i > 0 && i < nu);
      const bool inner_v = j > 0 && j < nv;
      if (inner_u && inner_v) {
        u += du;
        v += dv;
      }
      uv.push_back({u, v});
    }
  }
  return uv;
}

Mesh TriangulatedGrid(int nu, int nv, const std::function<Vec3(double, double)>& surface,
                      const TriangleGridOptions& options) {
  const auto uv = TriangulatedGridParameters(nu, nv, options);
  const int cols = options.closed_u ? nu : nu + 1;
  Mesh mesh;
  for (const auto& p : uv) mesh.add_vertex(ToPoint(surface(p[0], p[1])));
  auto id = [&](int i, int j) { return VertexIndex(j * cols + (i % cols)); };
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const VertexIndex a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      const bool main = !options.alternate_diagonals || (i + j) % 2 == 0;
      const bool ok = main ? (mesh.add_face(a, b, c) != Mesh::null_face() &&
                              mesh.add_face(a, c, d) != Mesh::null_face())
                           : (mesh.add_face(a, b, d) != Mesh::null_face() &&
                              mesh.add_face(b, c, d) != Mesh::null_face());
      CHECK(ok) << "TriangulatedGrid: non-manifold face at cell " << i << ", " << j;
    }
  }
  return mesh;
}

Mesh TriangulatedEllipsoid(double a, double b, double c, int subdivisions) {
  CHECK(a > 0 && b > 0 && c > 0) << "TriangulatedEllipsoid: semi-axes must be > 0";
  CHECK(subdivisions >= 0 && subdivisions <= 7) << "TriangulatedEllipsoid: subdivisions 0..7";
  const double t = 0.5 * (1.0 + std::sqrt(5.0));
  std::vector<std::array<double, 3>> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                          {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                          {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  auto normalise = [](std::array<double, 3> x) {
    const double n = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    return std::array<double, 3>{x[0] / n, x[1] / n, x[2] / n};
  };
  for (auto& x : p) x = normalise(x);
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int i, int j) {
      const auto key = std::minmax(i, j);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      p.push_back(normalise({p[i][0] + p[j][0], p[i][1] + p[j][1], p[i][2] + p[j][2]}));
      const int k = static_cast<int>(p.size()) - 1;
      mid[key] = k;
      return k;
    };
    std::vector<std::array<int, 3>> g;
    for (const auto& tri : f) {
      const int ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]),
                ca = midpoint(tri[2], tri[0]);
      g.push_back({tri[0], ab, ca});
      g.push_back({tri[1], bc, ab});
      g.push_back({tri[2], ca, bc});
      g.push_back({ab, bc, ca});
    }
    f.swap(g);
  }
  Mesh mesh;
  for (const auto& x : p) mesh.add_vertex(Point(a * x[0], b * x[1], c * x[2]));
  for (const auto& tri : f) {
    CHECK(mesh.add_face(VertexIndex(tri[0]), VertexIndex(tri[1]), VertexIndex(tri[2])) !=
          Mesh::null_face());
  }
  return mesh;
}

}  // namespace archgeo
