// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/declarations/base_complex_input.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "io/base_complex_ids.h"
#include "io/io.h"
#include "mesh/surface_mesh.h"

namespace archgeo {
namespace {

// Each base vertex on its nearest surface vertex (brute force: a base
// complex has few vertices).
UserBaseComplex BcSnapMesh(const std::string& path, const std::vector<Eigen::Vector3d>& points,
                           double tolerance) {
  const Mesh coarse = ReadMesh(path);
  UserBaseComplex out;
  out.file = path;
  out.key = "base_complex.mesh";
  for (VertexIndex v : coarse.vertices()) {
    const Eigen::Vector3d q(coarse.point(v).x(), coarse.point(v).y(), coarse.point(v).z());
    int best = -1;
    double distance = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < points.size(); ++i) {
      const double d = (points[i] - q).squaredNorm();
      if (d < distance) {
        distance = d;
        best = int(i);
      }
    }
    distance = std::sqrt(distance);
    if (!(distance <= tolerance)) {
      char text[320];
      std::snprintf(text, sizeof text,
                    "base vertex %u (%.6g, %.6g, %.6g) is %.3g from the nearest vertex of the "
                    "surface, beyond base_complex.tolerance (%.3g in file units): it is not on "
                    "the surface",
                    unsigned(v.idx()), q.x(), q.y(), q.z(), distance, tolerance);
      throw InputError(path, 0, out.key, text);
    }
    out.snap_distance = std::max(out.snap_distance, distance);
    out.complex.nodes.push_back(best);
  }
  for (FaceIndex f : coarse.faces()) {
    std::vector<int> face;
    for (VertexIndex v : CGAL::vertices_around_face(coarse.halfedge(f), coarse)) {
      face.push_back(int(v.idx()));
    }
    out.complex.faces.push_back(face);
  }
  return out;
}

}  // namespace

UserBaseComplex ReadUserBaseComplex(const Settings& s, const std::vector<Eigen::Vector3d>& points,
                                    double diagonal) {
  const std::string& mesh = s.String("base_complex.mesh");
  const std::string& ids = s.String("base_complex.ids");
  if (mesh.empty() == ids.empty()) {
    throw s.Error(mesh.empty() ? "base_complex.mesh" : "base_complex.ids",
                  "give the base complex as exactly one of base_complex.mesh (a triangle/quad mesh "
                  "on the surface) and base_complex.ids (surface vertex ids and faces)");
  }
  if (!mesh.empty()) {
    return BcSnapMesh(mesh, points, s.Number("base_complex.tolerance") * diagonal);
  }
  const BaseComplexIds read = ReadBaseComplexIds(ids, "base_complex.ids");
  UserBaseComplex out;
  out.file = ids;
  out.key = "base_complex.ids";
  out.complex.nodes = read.nodes;
  out.complex.faces = read.faces;
  return out;
}

}  // namespace archgeo
