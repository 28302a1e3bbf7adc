// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Test helpers on meshes: a Surface_mesh from points and faces (indices into
// points; every face must be added, EXPECTed), an open quad cylinder, a
// vertex's position as an Eigen vector, the vertex nearest a point, and the
// angle of a point continued from another's (branched functions z^p on plane
// meshes).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "mesh/surface_mesh.h"

namespace archgeo {

inline Mesh MakeMesh(const std::vector<Vec3>& points, const std::vector<std::vector<int>>& faces) {
  Mesh mesh;
  for (const Vec3& p : points) mesh.add_vertex(ToPoint(p));
  for (const auto& face : faces) {
    std::vector<VertexIndex> vs;
    for (int i : face) vs.push_back(VertexIndex(i));
    EXPECT_NE(mesh.add_face(vs), Mesh::null_face());
  }
  return mesh;
}

// Open cylinder of radius `radius` and height `height` around the z axis:
// `around` x `rows` quads, rings of `around` vertices glued at the seam,
// vertex (i, j) = j * around + i, outward normals.
inline Mesh QuadCylinder(double radius, double height, int around, int rows) {
  std::vector<Vec3> points;
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i < around; ++i) {
      const double a = 2 * M_PI * i / around;
      points.push_back({radius * std::cos(a), radius * std::sin(a), height * j / rows});
    }
  }
  std::vector<std::vector<int>> faces;
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < around; ++i) {
      const int k = (i + 1) % around;
      faces.push_back({j * around + i, j * around + k, (j + 1) * around + k, (j + 1) * around + i});
    }
  }
  return MakeMesh(points, faces);
}

// The position of vertex v.
inline Eigen::Vector3d Pos(const Mesh& m, VertexIndex v) {
  return Eigen::Vector3d(m.point(v).x(), m.point(v).y(), m.point(v).z());
}

// The vertex of m nearest to p (the first of equally near ones; null for a
// mesh without vertices).
inline VertexIndex Nearest(const Mesh& m, const Eigen::Vector3d& p) {
  VertexIndex best;
  double d = INFINITY;
  for (VertexIndex v : m.vertices()) {
    if ((Pos(m, v) - p).norm() < d) d = (Pos(m, v) - p).norm(), best = v;
  }
  return best;
}

// arg(p) in the xy-plane continued from arg(c) (within π).
inline double ArgNear(const Eigen::Vector3d& p, const Eigen::Vector3d& c) {
  double a = std::atan2(p.y(), p.x());
  const double ac = std::atan2(c.y(), c.x());
  while (a - ac > M_PI) a -= 2 * M_PI;
  while (ac - a > M_PI) a += 2 * M_PI;
  return a;
}

}  // namespace archgeo
