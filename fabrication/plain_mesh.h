// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — a mesh as plain arrays, what fabrication/ computes on (no CGAL):
// the problem layer copies its Surface_mesh into one (problems/report/
// fabrication.h).
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

namespace archgeo {

struct PlainMesh {
  std::vector<Eigen::Vector3d> points;  // vertex i, in the mesh's unit
  std::vector<std::vector<int>> faces;  // face f: its vertex ids, in order
  // Per vertex: its faces in cyclic order around it, and whether it is on
  // the boundary. Empty when no caller needs them (panels alone).
  std::vector<std::vector<int>> vertex_faces;
  std::vector<bool> boundary;
  std::vector<std::array<int, 2>> edges;  // edge e: its two vertex ids
};

}  // namespace archgeo
