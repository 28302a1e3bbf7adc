// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/elements.h"

#include <glog/logging.h>

#include <algorithm>
#include <functional>
#include <map>

#include "mesh/topology.h"

namespace archgeo {
namespace {

using Builder = std::function<void(const Mesh&, const std::vector<bool>&, ElementSet&)>;

int I(VertexIndex v) { return int(v.idx()); }

std::vector<int> FaceVertices(const Mesh& mesh, FaceIndex f) {
  std::vector<int> vs;
  for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) vs.push_back(I(v));
  return vs;
}

bool TouchesBoundary(const std::vector<int>& vs, const std::vector<bool>& boundary) {
  for (int v : vs) {
    if (boundary[v]) return true;
  }
  return false;
}

void Faces(const Mesh& mesh, const std::vector<bool>& boundary, ElementSet& out,
           const std::function<bool(size_t degree)>& keep) {
  out.site = Site::kFace;
  for (FaceIndex f : mesh.faces()) {
    const std::vector<int> vs = FaceVertices(mesh, f);
    if (!keep(vs.size())) continue;
    out.Add(vs, int(f.idx()), int(f.idx()), -1, TouchesBoundary(vs, boundary) ? kBoundary : 0);
  }
}


// The counter-clockwise one-ring (an open fan from one boundary neighbour to
// the other); false for isolated vertices, more than one boundary gap, and
// rings without an interior edge.
bool Fan(const Mesh& mesh, VertexIndex v, std::vector<int>* ring, bool* closed) {
  if (mesh.is_isolated(v)) return false;
  ring->clear();
  HalfedgeIndex start = Mesh::null_halfedge();
  int gaps = 0;
  for (HalfedgeIndex h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh)) {
    const HalfedgeIndex out = mesh.opposite(h);
    if (mesh.is_border(mesh.opposite(out))) {  // border to the right of v → w
      start = out;
      ++gaps;
    }
  }
  if (gaps > 1) return false;
  *closed = gaps == 0;
  if (*closed) start = mesh.opposite(mesh.halfedge(v));
  HalfedgeIndex h = start;
  const size_t limit = mesh.number_of_halfedges();
  do {
    ring->push_back(I(mesh.target(h)));
    if (mesh.is_border(h)) break;       // last spoke of an open fan
    h = mesh.opposite(mesh.prev(h));   // next spoke counter-clockwise
    CHECK_LE(ring->size(), limit);
  } while (h != start);
  return ring->size() >= 3;
}

void Fans(const Mesh& mesh, const std::vector<bool>& boundary, ElementSet& out) {
  std::vector<int> ring;
  bool closed = true;
  for (VertexIndex v : mesh.vertices()) {
    if (!Fan(mesh, v, &ring, &closed)) continue;
    std::vector<int> vs{I(v)};
    vs.insert(vs.end(), ring.begin(), ring.end());
    out.Add(vs, I(v), -1, -1,
            std::uint8_t((closed ? 0 : kOpen) | (boundary[v.idx()] ? kBoundary : 0)));
  }
}

void UmbrellaTriples(const Mesh& mesh, const std::vector<bool>& boundary, ElementSet& out) {
  std::vector<int> ring;
  bool closed = true;
  for (VertexIndex v : mesh.vertices()) {
    if (!Fan(mesh, v, &ring, &closed)) continue;
    const std::uint8_t flags = boundary[v.idx()] ? kBoundary : 0;
    const int k = int(ring.size());
    if (closed) {
      const int half = k / 2;
      const int count = k % 2 == 0 ? half : k;
      for (int i = 0; i < count; ++i) out.Add({ring[i], I(v), ring[(i + half) % k]}, I(v), -1, -1, flags);
    } else {
      out.Add({ring.front(), I(v), ring.back()}, I(v), -1, -1, std::uint8_t(flags | kOpen));
    }
  }
}

void StraightTriples(const Mesh& mesh, const std::vector<bool>& boundary, ElementSet& out) {
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_isolated(v)) continue;
    if (mesh.is_border(v, /*check_all_incident_halfedges=*/true)) {
      // The two boundary neighbours: source of the border halfedge into v
      // and target of the border halfedge out of v.
      for (HalfedgeIndex h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh)) {
        if (mesh.is_border(h)) {
          const VertexIndex prev = mesh.source(h);
          const VertexIndex next = mesh.target(mesh.next(h));
          if (prev != next && prev != v && next != v) {
            out.Add({I(prev), I(v), I(next)}, I(v), -1, -1, std::uint8_t(kBoundary | kOpen));
          }
          break;
        }
      }
      continue;
    }
    std::vector<int> ring;
    for (VertexIndex w : CGAL::vertices_around_target(mesh.halfedge(v), mesh)) ring.push_back(I(w));
    const size_t k = ring.size();
    if (k < 4 || k % 2 != 0) continue;
    for (size_t j = 0; j < k / 2; ++j) out.Add({ring[j], I(v), ring[j + k / 2]}, I(v));
  }
}

void PolylineTuplesSet(const Mesh& mesh, const std::vector<bool>& boundary, size_t k,
                       ElementSet& out) {
  for (const auto& t : PolylineTuples(MeshPolylines(mesh), k)) {
    std::vector<int> vs;
    for (VertexIndex v : t) vs.push_back(I(v));
    out.Add(vs, vs[1], -1, -1, boundary[vs[1]] ? kBoundary : 0);
  }
}

void InteriorEdges(const Mesh& mesh, const std::vector<bool>& boundary, ElementSet& out) {
  out.site = Site::kEdge;
  for (EdgeIndex e : mesh.edges()) {
    if (mesh.is_border(e)) continue;
    const HalfedgeIndex h = mesh.halfedge(e, 0);
    const HalfedgeIndex o = mesh.opposite(h);
    const FaceIndex left = mesh.face(h), right = mesh.face(o);
    const std::vector<int> vs = {I(mesh.source(h)), I(mesh.target(h)), I(mesh.target(mesh.next(h))),
                                 I(mesh.target(mesh.next(o)))};
    std::uint8_t flags = 0;
    if (mesh.degree(left) > 3) flags |= kLeftPolygon;
    if (mesh.degree(right) > 3) flags |= kRightPolygon;
    if (boundary[vs[0]] || boundary[vs[1]]) flags |= kBoundary;
    out.Add(vs, int(e.idx()), int(left.idx()), int(e.idx()), flags, {}, int(right.idx()));
  }
}

void EdgeQuads(const Mesh& mesh, const std::vector<bool>& boundary, ElementSet& out) {
  out.site = Site::kEdge;
  for (EdgeIndex e : mesh.edges()) {
    if (mesh.is_border(e)) continue;
    const HalfedgeIndex h = mesh.halfedge(e, 0);  // b3 → b0 in the left face
    const HalfedgeIndex g = mesh.opposite(h);     // b0 → b3 in the right face
    if (mesh.degree(mesh.face(h)) != 4 || mesh.degree(mesh.face(g)) != 4) continue;
    const std::vector<int> b = {I(mesh.target(h)),
                                I(mesh.target(mesh.next(h))),
                                I(mesh.target(mesh.next(mesh.next(h)))),
                                I(mesh.source(h)),
                                I(mesh.target(mesh.next(g))),
                                I(mesh.target(mesh.next(mesh.next(g))))};
    out.Add(b, int(e.idx()), int(mesh.face(h).idx()), int(e.idx()),
            boundary[b[0]] || boundary[b[3]] ? kBoundary : 0, {}, int(mesh.face(g).idx()));
  }
}

// Every edge (a, b) as halfedge 0 runs, or only the border edges along their
// border halfedge (a loop's edges chain head to tail). kBoundary: the edge
// itself lies on the boundary (not merely one of its ends).
void Edges(const Mesh& mesh, ElementSet& out, bool border_only) {
  out.site = Site::kEdge;
  for (EdgeIndex e : mesh.edges()) {
    const bool border = mesh.is_border(e);
    if (border_only && !border) continue;
    HalfedgeIndex h = mesh.halfedge(e, 0);
    if (border_only && !mesh.is_border(h)) h = mesh.opposite(h);
    const FaceIndex f = mesh.face(mesh.is_border(h) ? mesh.opposite(h) : h);
    out.Add({I(mesh.source(h)), I(mesh.target(h))}, int(e.idx()), int(f.idx()), int(e.idx()),
            border ? kBoundary : 0);
  }
}

// Every vertex with a face and all its neighbours, in order around it (a
// boundary gap last, kOpen), as `stars` but for any valence.
void OneRings(const Mesh& mesh, const std::vector<bool>& boundary, ElementSet& out,
              const std::function<bool(VertexIndex)>& keep) {
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_isolated(v) || !keep(v)) continue;
    std::vector<HalfedgeIndex> in;
    for (HalfedgeIndex h : mesh.halfedges_around_target(mesh.halfedge(v))) in.push_back(h);
    bool open = false;
    for (size_t k = 0; k < in.size(); ++k) {
      if (mesh.is_border(in[k])) {
        std::rotate(in.begin(), in.begin() + (k + 1) % in.size(), in.end());
        open = true;
        break;
      }
    }
    std::vector<int> vs{I(v)};
    for (HalfedgeIndex h : in) vs.push_back(I(mesh.source(h)));
    out.Add(vs, I(v), -1, -1,
            std::uint8_t((open ? kOpen : 0) | (boundary[v.idx()] ? kBoundary : 0)));
  }
}

// Neighbours of v in order, a boundary gap last (hnet's stars): the one rings
// of vertices with three neighbours or more.
void Stars(const Mesh& mesh, const std::vector<bool>& boundary, ElementSet& out) {
  OneRings(mesh, boundary, out, [&](VertexIndex v) { return mesh.degree(v) >= 3; });
}

// Interior vertices of valence 4 none of whose faces is a triangle.
bool QuadStar(const Mesh& mesh, const std::vector<bool>& boundary, VertexIndex v) {
  if (boundary[v.idx()] || mesh.degree(v) != 4) return false;
  for (FaceIndex f : CGAL::faces_around_target(mesh.halfedge(v), mesh)) {
    if (f == Mesh::null_face() || mesh.degree(f) < 4) return false;
  }
  return true;
}

// The fans whose faces are all triangles.
void TriangleFans(const Mesh& mesh, const std::vector<bool>& boundary, ElementSet& out) {
  std::vector<int> ring;
  bool closed = true;
  for (VertexIndex v : mesh.vertices()) {
    if (!Fan(mesh, v, &ring, &closed)) continue;
    bool triangles = true;
    for (FaceIndex f : CGAL::faces_around_target(mesh.halfedge(v), mesh)) {
      if (f != Mesh::null_face() && mesh.degree(f) != 3) triangles = false;
    }
    if (!triangles) continue;
    std::vector<int> vs{I(v)};
    vs.insert(vs.end(), ring.begin(), ring.end());
    out.Add(vs, I(v), -1, -1,
            std::uint8_t((closed ? 0 : kOpen) | (boundary[v.idx()] ? kBoundary : 0)));
  }
}

const std::map<std::string, Builder>& Builders() {
  static const std::map<std::string, Builder> builders = {
      {"vertices",
       [](const Mesh& m, const std::vector<bool>& b, ElementSet& out) {
         for (VertexIndex v : m.vertices()) {
           if (!m.is_isolated(v)) out.Add({I(v)}, I(v), -1, -1, b[v.idx()] ? kBoundary : 0);
         }
       }},
      {"faces", [](const Mesh& m, const std::vector<bool>& b,
                   ElementSet& out) { Faces(m, b, out, [](size_t) { return true; }); }},
      {"triangles", [](const Mesh& m, const std::vector<bool>& b,
                       ElementSet& out) { Faces(m, b, out, [](size_t d) { return d == 3; }); }},
      {"quads", [](const Mesh& m, const std::vector<bool>& b,
                   ElementSet& out) { Faces(m, b, out, [](size_t d) { return d == 4; }); }},
      {"polygons", [](const Mesh& m, const std::vector<bool>& b,
                      ElementSet& out) { Faces(m, b, out, [](size_t d) { return d > 4; }); }},
      {"non_triangles", [](const Mesh& m, const std::vector<bool>& b,
                           ElementSet& out) { Faces(m, b, out, [](size_t d) { return d > 3; }); }},
      {"boundary_vertices",
       [](const Mesh& m, const std::vector<bool>& b, ElementSet& out) {
         for (VertexIndex v : m.vertices()) {
           if (!m.is_isolated(v) && b[v.idx()]) out.Add({I(v)}, I(v), -1, -1, kBoundary);
         }
       }},
      {"edges", [](const Mesh& m, const std::vector<bool>&,
                   ElementSet& out) { Edges(m, out, false); }},
      {"boundary_edges", [](const Mesh& m, const std::vector<bool>&,
                            ElementSet& out) { Edges(m, out, true); }},
      {"one_rings", [](const Mesh& m, const std::vector<bool>& b,
                       ElementSet& out) { OneRings(m, b, out, [](VertexIndex) { return true; }); }},
      {"valence4_stars",
       [](const Mesh& m, const std::vector<bool>& b, ElementSet& out) {
         OneRings(m, b, out, [&](VertexIndex v) { return QuadStar(m, b, v); });
       }},
      {"triangle_fans", &TriangleFans},
      {"interior_edges", &InteriorEdges},
      {"edge_quads", &EdgeQuads},
      {"stars", &Stars},
      {"fans", &Fans},
      {"polyline_triples", [](const Mesh& m, const std::vector<bool>& b,
                              ElementSet& out) { PolylineTuplesSet(m, b, 3, out); }},
      {"polyline_quadruples", [](const Mesh& m, const std::vector<bool>& b,
                                 ElementSet& out) { PolylineTuplesSet(m, b, 4, out); }},
      {"straight_triples", &StraightTriples},
      {"umbrella_triples", &UmbrellaTriples},
  };
  return builders;
}

}  // namespace

const std::vector<std::string>& ElementSetNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& [name, builder] : Builders()) n.push_back(name);
    return n;
  }();
  return names;
}

ElementSet BuildElementSet(const Mesh& mesh, const std::string& name) {
  const auto it = Builders().find(name);
  CHECK(it != Builders().end()) << "no element set '" << name << "'";
  ElementSet set;
  set.name = name;
  it->second(mesh, BoundaryVertices(mesh), set);
  return set;
}

}  // namespace archgeo
