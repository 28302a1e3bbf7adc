// Test helper: a Surface_mesh from points and faces (indices into points);
// every face must be added (EXPECTed).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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

}  // namespace archgeo
