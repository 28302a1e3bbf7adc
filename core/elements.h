// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the elements a term acts on: quads, interior edges, vertex
// stars, polyline triples, ... Each element lists vertex indices in the order
// the term expects, the face or edge it belongs to, its "site" (the vertex,
// face or edge a selection such as `boundary` or `ids` refers to), a few
// flags, and optional per-element constants (in the canonical frame).
//
// Element sets are built from the mesh by mesh/elements.h (named providers)
// or by a problem (e.g. principal_symmetric's labelled stars). Flat storage:
// a million quads are four million ints, not a million small vectors.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace archgeo {

enum class Site { kVertex, kFace, kEdge };

// Element flags (bits of ElementSet::flags).
enum ElementFlag : std::uint8_t {
  kOpen = 1,         // a star or fan with a boundary gap (neighbours from one boundary
                     // neighbour to the other)
  kLeftPolygon = 2,  // interior edges: the left face has more than three sides
  kRightPolygon = 4, // ... the right face
  kBoundary = 8,     // the site lies on the mesh boundary
};

struct ElementSet {
  std::string name;
  Site site = Site::kVertex;
  std::vector<int> offsets{0};  // element i: vertices[offsets[i] .. offsets[i+1])
  std::vector<int> vertices;
  std::vector<int> face, edge;  // per element, -1 if none
  std::vector<int> other_face;  // per element: a second face (interior edges: the right one)
  std::vector<int> sites;       // per element: a vertex, face or edge index (see `site`)
  std::vector<std::uint8_t> flags;
  int data_width = 0;           // per-element constants: data[i*width .. (i+1)*width)
  std::vector<double> data;

  size_t size() const { return sites.size(); }
  int Count(size_t i) const { return offsets[i + 1] - offsets[i]; }
  const int* Vertices(size_t i) const { return vertices.data() + offsets[i]; }
  const double* Data(size_t i) const { return data.data() + i * size_t(data_width); }
  bool Has(size_t i, ElementFlag f) const { return (flags[i] & f) != 0; }

  // Appends an element.
  void Add(const std::vector<int>& vs, int site_index, int face_index = -1, int edge_index = -1,
           std::uint8_t element_flags = 0, const std::vector<double>& element_data = {},
           int other_face_index = -1);
  // The elements whose index is listed (in that order).
  ElementSet Subset(const std::vector<size_t>& keep) const;
};

}  // namespace archgeo
