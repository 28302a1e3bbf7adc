// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/subdivision.h"

#include <CGAL/subdivision_method_3.h>
#include <glog/logging.h>

#include <array>
#include <vector>

namespace archgeo {

bool CanSubdivide(const Mesh& mesh, const std::string& scheme) {
  if (mesh.number_of_faces() == 0) return false;
  if (scheme == "catmull_clark" || scheme == "doo_sabin") return true;
  for (FaceIndex f : mesh.faces()) {
    if (mesh.degree(f) != 3) return false;
  }
  return scheme == "loop" || scheme == "sqrt3";
}

Mesh Subdivide(const Mesh& mesh, const std::string& scheme) {
  CHECK(CanSubdivide(mesh, scheme)) << "Subdivide: scheme " << scheme << " cannot refine this mesh";
  // A copy with positions only: solver properties must not be interpolated.
  Mesh out;
  for (VertexIndex v : mesh.vertices()) out.add_vertex(mesh.point(v));
  for (FaceIndex f : mesh.faces()) {
    std::vector<VertexIndex> vs;
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) vs.push_back(v);
    CHECK(out.add_face(vs) != Mesh::null_face());
  }
  namespace S = CGAL::Subdivision_method_3;
  const auto once = CGAL::parameters::number_of_iterations(1);
  if (scheme == "loop") {
    S::Loop_subdivision(out, once);
  } else if (scheme == "sqrt3") {
    S::Sqrt3_subdivision(out, once);
  } else if (scheme == "catmull_clark") {
    S::CatmullClark_subdivision(out, once);
  } else {
    S::DooSabin_subdivision(out, once);
  }
  out.collect_garbage();
  return out;
}

Mesh MidpointSubdivision(const Mesh& triangles) {
  CHECK(!triangles.has_garbage()) << "MidpointSubdivision: the mesh has removed elements";
  Mesh out;
  for (VertexIndex v : triangles.vertices()) out.add_vertex(triangles.point(v));
  std::vector<VertexIndex> midpoint(triangles.num_edges());
  for (EdgeIndex e : triangles.edges()) {
    const Point& a = triangles.point(triangles.vertex(e, 0));
    const Point& b = triangles.point(triangles.vertex(e, 1));
    midpoint[e.idx()] = out.add_vertex(CGAL::midpoint(a, b));
  }
  for (FaceIndex f : triangles.faces()) {
    CHECK_EQ(triangles.degree(f), 3u) << "MidpointSubdivision: face " << f.idx() << " is not a triangle";
    const HalfedgeIndex h0 = triangles.halfedge(f);
    const HalfedgeIndex h1 = triangles.next(h0), h2 = triangles.next(h1);
    const VertexIndex a = triangles.source(h0), b = triangles.target(h0), c = triangles.target(h1);
    const VertexIndex ab = midpoint[triangles.edge(h0).idx()];
    const VertexIndex bc = midpoint[triangles.edge(h1).idx()];
    const VertexIndex ca = midpoint[triangles.edge(h2).idx()];
    for (const std::array<VertexIndex, 3>& child :
         {std::array<VertexIndex, 3>{a, ab, ca}, std::array<VertexIndex, 3>{ab, b, bc},
          std::array<VertexIndex, 3>{ca, bc, c}, std::array<VertexIndex, 3>{ab, bc, ca}}) {
      CHECK(out.add_face(child[0], child[1], child[2]) != Mesh::null_face());
    }
  }
  return out;
}

}  // namespace archgeo
