// Test helper: a Surface_mesh from points and faces (indices into points);
// every face must be added (EXPECTed).
#pragma once

#include <gtest/gtest.h>

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

}  // namespace archgeo
