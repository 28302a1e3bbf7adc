// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the AABB tree of a triangle mesh's faces (see triangle_tree.h).
#include "geometry/triangle_tree.h"

#include <future>
#include <vector>

namespace archgeo {

void BuildTriangleTree(const Mesh& triangles, TriangleTree* tree) {
  tree->insert(faces(triangles).first, faces(triangles).second, triangles);
  std::future<void> search = std::async(std::launch::async, [&] {
    std::vector<TriangleTree::Point_and_primitive_id> points;
    points.reserve(triangles.number_of_faces());
    for (FaceIndex f : triangles.faces()) {
      points.emplace_back(triangles.point(triangles.target(triangles.halfedge(f))), f);
    }
    tree->accelerate_distance_queries(points.begin(), points.end());
  });
  tree->build();
  search.get();
}

}  // namespace archgeo
