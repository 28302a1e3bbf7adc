// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — analytic test meshes.
#include "generators/generators.h"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <glog/logging.h>

namespace archgeo {

Mesh QuadGrid(int nu, int nv, const std::function<Vec3(double, double)>& surface, double noise,
              std::uint64_t seed) {
  if (nu < 1 || nv < 1) {
    throw std::invalid_argument("QuadGrid: needs at least 1 x 1 quads, got " + std::to_string(nu) +
                                " x " + std::to_string(nv));
  }
  if (!(noise >= 0.0) || !std::isfinite(noise)) {
    throw std::invalid_argument("QuadGrid: noise must be finite and >= 0, got " +
                                std::to_string(noise));
  }
  Mesh mesh;
  std::vector<VertexIndex> grid;
  grid.reserve(static_cast<size_t>(nu + 1) * (nv + 1));
  for (int j = 0; j <= nv; ++j) {
    for (int i = 0; i <= nu; ++i) {
      grid.push_back(mesh.add_vertex(ToPoint(surface(double(i) / nu, double(j) / nv))));
    }
  }
  const auto at = [&](int i, int j) { return grid[static_cast<size_t>(j) * (nu + 1) + i]; };
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      // Counter-clockwise in (u, v): the face normal points along S_u x S_v.
      const FaceIndex f = mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
      CHECK(f != Mesh::null_face()) << "QuadGrid: add_face failed at (" << i << ", " << j << ")";
    }
  }
  if (noise != 0.0) AddNoise(mesh, noise, seed);
  return mesh;
}

void AddNoise(Mesh& mesh, double noise, std::uint64_t seed) {
  double length_sum = 0.0;
  for (EdgeIndex e : mesh.edges()) {
    length_sum += std::sqrt(CGAL::squared_distance(mesh.point(mesh.vertex(e, 0)),
                                                   mesh.point(mesh.vertex(e, 1))));
  }
  const double max_offset = noise * length_sum / double(mesh.number_of_edges());
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, max_offset);
  for (VertexIndex v : mesh.vertices()) {
    Vector direction;
    do {  // a normalised isotropic Gaussian is uniform on the unit sphere
      direction = Vector(gaussian(rng), gaussian(rng), gaussian(rng));
    } while (direction.squared_length() < 1e-12);
    direction = direction / std::sqrt(direction.squared_length());
    mesh.point(v) = mesh.point(v) + uniform(rng) * direction;
  }
}

Vec3 RoofSurface(double u, double v) {
  const double x = 2.0 * u, y = 1.5 * v;
  return {x, y, 0.3 * std::sin(2.0 * x) + 0.25 * std::cos(2.0 * y)};
}

}  // namespace archgeo
