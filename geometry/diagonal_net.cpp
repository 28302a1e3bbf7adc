// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the diagonal nets of a quad mesh (see diagonal_net.h).
#include "geometry/diagonal_net.h"

#include <glog/logging.h>

#include <string>

#include "core/input_error.h"
#include "mesh/topology.h"

namespace archgeo {

DiagonalNet MakeDiagonalNet(const Mesh& mesh, int colour) {
  CHECK(colour == 0 || colour == 1) << "diagonal net colour " << colour;
  CHECK(!mesh.has_garbage()) << "MakeDiagonalNet: collect_garbage() first";
  std::vector<int> monochrome;
  const std::vector<int> colours = TwoColouring(mesh, &monochrome);
  if (!monochrome.empty()) {
    throw InputError("", 0, "mesh",
                     "the mesh has no diagonal nets: its vertices cannot be coloured alternately "
                     "(an odd cycle; edge " + std::to_string(monochrome[0]) + " joins equal colours)");
  }
  const std::vector<bool> boundary = BoundaryVertices(mesh);
  DiagonalNet net;
  net.colour = colour;
  // Rings of the other colour's interior vertices, counter-clockwise like the
  // faces: with h = a → c in face (a, c, n, ·), the ring runs n → a, and the
  // next face around c is that of prev(opposite(h)).
  std::vector<std::vector<int>> rings;
  for (VertexIndex c : mesh.vertices()) {
    if (colours[c.idx()] == colour || boundary[c.idx()] || mesh.is_isolated(c)) continue;
    if (mesh.degree(c) != 4) {
      ++net.holes;
      continue;
    }
    std::vector<int> ring;
    const HalfedgeIndex start = mesh.halfedge(c);  // target c
    HalfedgeIndex h = start;
    do {
      ring.push_back(int(mesh.source(h).idx()));
      h = mesh.prev(mesh.opposite(h));
    } while (h != start);
    rings.push_back(ring);
  }
  std::vector<int> index(mesh.num_vertices(), -1);
  for (const auto& ring : rings) {
    for (int v : ring) index[v] = 0;
  }
  for (size_t v = 0; v < index.size(); ++v) {
    if (index[v] < 0) continue;
    index[v] = int(net.source.size());
    net.source.push_back(int(v));
    net.mesh.add_vertex(mesh.point(VertexIndex(v)));
  }
  for (const auto& ring : rings) {
    std::vector<VertexIndex> face;
    for (int v : ring) face.push_back(VertexIndex(index[v]));
    if (net.mesh.add_face(face) == Mesh::null_face()) {
      throw InputError("", 0, "mesh",
                       "the colour-" + std::to_string(colour) +
                           " diagonal net is not a manifold at the ring of vertices " +
                           std::to_string(ring[0]) + ", " + std::to_string(ring[1]) + ", " +
                           std::to_string(ring[2]) + ", " + std::to_string(ring[3]));
    }
  }
  if (net.mesh.number_of_faces() == 0) {
    throw InputError("", 0, "mesh",
                     "the colour-" + std::to_string(colour) +
                         " diagonal net has no face (no interior vertex of valence 4 of the "
                         "other colour)");
  }
  // A vertex with two separate fans (two border gaps) is not a manifold vertex.
  std::vector<int> gaps(net.mesh.num_vertices(), 0);
  for (HalfedgeIndex h : net.mesh.halfedges()) {
    if (net.mesh.is_border(h) && ++gaps[net.mesh.target(h).idx()] > 1) {
      throw InputError("", 0, "mesh",
                       "the colour-" + std::to_string(colour) +
                           " diagonal net is not a manifold at input vertex " +
                           std::to_string(net.source[net.mesh.target(h).idx()]) +
                           " (two separate fans of faces)");
    }
  }
  return net;
}

}  // namespace archgeo
