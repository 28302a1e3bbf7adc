// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "generators/grid_mesh.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <iomanip>

#include <CGAL/Surface_mesh/IO/PLY.h>
#include <glog/logging.h>

#include "core/input_error.h"
#include "io/output_stream.h"

namespace archgeo {
namespace {

std::string Extension(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  const size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void WriteObj(std::ostream& out, const Mesh& mesh, const std::vector<Eigen::Vector2d>& uv) {
  out << std::setprecision(17);
  out << "# archgeo grid: vt = the surface parameter (u, v) of the vertex of the same index\n";
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  for (VertexIndex v : mesh.vertices()) out << "vt " << uv[v.idx()][0] << ' ' << uv[v.idx()][1] << '\n';
  for (FaceIndex f : mesh.faces()) {
    out << 'f';
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      out << ' ' << v.idx() + 1 << '/' << v.idx() + 1;
    }
    out << '\n';
  }
}

// Through a fresh Surface_mesh with only points, faces and "v:u", "v:v":
// CGAL's Surface_mesh PLY writer writes every double vertex property map
// "v:NAME" as "property double NAME".
bool WritePly(std::ostream& out, const Mesh& mesh, const std::vector<Eigen::Vector2d>& uv,
              bool ascii) {
  Mesh clean;
  for (VertexIndex v : mesh.vertices()) clean.add_vertex(mesh.point(v));
  for (FaceIndex f : mesh.faces()) {
    std::vector<VertexIndex> face;
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) face.push_back(v);
    CHECK(clean.add_face(face) != Mesh::null_face()) << "WriteGridMesh: face not re-added";
  }
  auto u = clean.add_property_map<VertexIndex, double>("v:u", 0.0).first;
  auto w = clean.add_property_map<VertexIndex, double>("v:v", 0.0).first;
  for (VertexIndex v : clean.vertices()) {
    u[v] = uv[v.idx()][0];
    w[v] = uv[v.idx()][1];
  }
  CGAL::IO::set_mode(out, ascii ? CGAL::IO::ASCII : CGAL::IO::BINARY);
  return CGAL::IO::write_PLY(out, clean, CGAL::parameters::stream_precision(17));
}

}  // namespace

Mesh GridToMesh(const Grid& grid, const Surface& surface, int* omitted_faces) {
  CHECK_EQ(static_cast<int>(grid.uv.size()), grid.NumVertices());
  Mesh mesh;
  for (const Eigen::Vector2d& uv : grid.uv) {
    const Eigen::Vector3d x = surface.Point(uv);
    mesh.add_vertex(Point(x[0], x[1], x[2]));
  }
  int omitted = 0;
  for (const auto& q : GridQuads(grid)) {
    // Across a flipping seam the quad joins column n_u − 1 to column 0.
    const bool seam = grid.flip && (q[0] % grid.nu == grid.nu - 1);
    if (seam) {
      ++omitted;
      continue;
    }
    const FaceIndex f = mesh.add_face(VertexIndex(q[0]), VertexIndex(q[1]), VertexIndex(q[2]),
                                      VertexIndex(q[3]));
    CHECK(f != Mesh::null_face()) << "GridToMesh: quad " << q[0] << " " << q[1] << " " << q[2]
                                  << " " << q[3] << " not added";
  }
  if (omitted_faces != nullptr) *omitted_faces = omitted;
  return mesh;
}

void WriteGridMesh(const std::string& path, const Mesh& mesh,
                   const std::vector<Eigen::Vector2d>& uv, bool ascii_ply) {
  CHECK(!mesh.has_garbage()) << "WriteGridMesh: mesh with removed elements";
  CHECK_EQ(uv.size(), mesh.number_of_vertices()) << "WriteGridMesh: one (u, v) per vertex";
  for (const auto& p : uv) CHECK(p.allFinite()) << "WriteGridMesh: non-finite (u, v)";
  const std::string ext = Extension(path);
  if (ext != "ply" && ext != "obj") {
    throw InputError(path, 0, "",
                     "a grid with its (u, v) is written as .ply or .obj, not '." + ext + "'");
  }
  NoFollowOfstream out(path);
  if (!out) throw InputError(path, 0, "", std::string("cannot open for writing: ") + std::strerror(errno));
  bool ok = true;
  if (ext == "obj") {
    WriteObj(out, mesh, uv);
  } else {
    ok = WritePly(out, mesh, uv, ascii_ply);
  }
  out.flush();
  if (!ok || !out) throw InputError(path, 0, "", "writing failed");
}

}  // namespace archgeo
