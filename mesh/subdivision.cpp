// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/subdivision.h"

#include <CGAL/subdivision_method_3.h>
#include <glog/logging.h>

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

}  // namespace archgeo
