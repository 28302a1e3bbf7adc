// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/declarations/surface_complex.h"

#include <algorithm>
#include <initializer_list>
#include <stdexcept>

#include <CGAL/boost/graph/Euler_operations.h>

#include "geometry/reference.h"
#include "mesh/eigen_point.h"
#include "problems/commands/spectral.h"

namespace archgeo {
namespace {

// Splits every interior edge between two boundary vertices (a chord, e.g.
// the inner edge of a corner triangle) at its midpoint, where f is the mean
// of its ends: otherwise the double would hold that edge twice.
void ComplexSplitChords(Mesh* m, std::vector<double>* f) {
  std::vector<HalfedgeIndex> chords;
  for (EdgeIndex e : m->edges()) {
    const HalfedgeIndex h = m->halfedge(e);
    if (m->is_border(e)) continue;
    if (m->is_border(m->source(h)) && m->is_border(m->target(h))) chords.push_back(h);
  }
  for (const HalfedgeIndex h : chords) {
    const double value = 0.5 * ((*f)[m->source(h).idx()] + (*f)[m->target(h).idx()]);
    const Point mid = CGAL::midpoint(m->point(m->source(h)), m->point(m->target(h)));
    const HalfedgeIndex hn = CGAL::Euler::split_edge(h, *m);  // target(hn): the new vertex
    m->point(m->target(hn)) = mid;
    f->push_back(value);
    CGAL::Euler::split_face(hn, m->next(h), *m);
    const HalfedgeIndex o = m->opposite(h);  // into the new vertex on the other side
    CGAL::Euler::split_face(o, m->next(m->next(o)), *m);
  }
}

// `mesh` (triangles) glued to its mirror copy along the boundary; `original`
// gets each vertex's source, `sides` the mirror. False when the double is
// not a closed manifold.
bool ComplexDouble(const Mesh& mesh, Mesh* out, std::vector<int>* original, MorseSmaleMirror* sides) {
  const size_t n = mesh.number_of_vertices();
  std::vector<int> mirror(n, -1);
  for (VertexIndex v : mesh.vertices()) {
    out->add_vertex(mesh.point(v));
    original->push_back(int(v.idx()));
  }
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_border(v)) {
      mirror[v.idx()] = int(v.idx());
    } else {
      mirror[v.idx()] = int(out->add_vertex(mesh.point(v)).idx());
      original->push_back(int(v.idx()));
    }
  }
  std::vector<std::array<int, 3>> faces;
  for (FaceIndex f : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) t[size_t(k++)] = int(v.idx());
    faces.push_back(t);
  }
  for (const auto& t : faces) {
    if (out->add_face(VertexIndex(t[0]), VertexIndex(t[1]), VertexIndex(t[2])) ==
        Mesh::null_face()) {
      return false;
    }
  }
  for (const auto& t : faces) {
    if (out->add_face(VertexIndex(mirror[t[2]]), VertexIndex(mirror[t[1]]),
                      VertexIndex(mirror[t[0]])) == Mesh::null_face()) {
      return false;
    }
  }
  for (VertexIndex v : out->vertices()) {
    if (out->is_border(v) || out->is_isolated(v)) return false;
  }
  sides->image.assign(out->number_of_vertices(), -1);
  sides->side.assign(out->number_of_vertices(), 2);
  for (size_t v = 0; v < n; ++v) {
    sides->image[v] = mirror[v];
    sides->image[size_t(mirror[v])] = int(v);
    sides->side[v] = mirror[v] == int(v) ? 1 : 0;
  }
  return true;
}

// The side of a new vertex between (or inside) vertices of these sides:
// the boundary only between boundary vertices.
char ComplexSide(std::initializer_list<char> sides) {
  char out = 1;
  for (char c : sides) {
    if (c != 1) out = c;
  }
  return out;
}

// The closed triangle mesh `m` split 1 to 4 (a vertex at every edge's
// midpoint), `f` linearly: the function is the same piecewise-linear one,
// so every old vertex keeps the signs of its ring (the midpoint of vu is
// above v exactly when u is) and no midpoint is critical: the same critical
// points, with twice as many vertices between them for the arcs
// (Gebreiter 2012, §7.1.3: refinement where separatrices still merge).
Mesh ComplexRefined(const Mesh& m, std::vector<double>* f, MorseSmaleMirror* sides) {
  Mesh out;
  for (VertexIndex v : m.vertices()) out.add_vertex(m.point(v));
  std::vector<int> midpoint(m.number_of_edges(), -1);
  for (EdgeIndex e : m.edges()) {
    const HalfedgeIndex h = m.halfedge(e);
    const VertexIndex a = m.source(h), b = m.target(h);
    midpoint[e.idx()] = int(out.add_vertex(CGAL::midpoint(m.point(a), m.point(b))).idx());
    f->push_back(0.5 * ((*f)[a.idx()] + (*f)[b.idx()]));
  }
  if (!sides->side.empty()) {
    MorseSmaleMirror next{sides->image, sides->side};
    for (EdgeIndex e : m.edges()) {
      const HalfedgeIndex h = m.halfedge(e);
      const size_t a = m.source(h).idx(), b = m.target(h).idx();
      const HalfedgeIndex g = m.halfedge(VertexIndex(VertexIndex::size_type(sides->image[a])),
                                         VertexIndex(VertexIndex::size_type(sides->image[b])));
      next.image.push_back(midpoint[m.edge(g).idx()]);
      next.side.push_back(ComplexSide({sides->side[a], sides->side[b]}));
    }
    *sides = std::move(next);
  }
  for (FaceIndex t : m.faces()) {
    std::array<VertexIndex, 3> corner, mid;  // mid[k]: on the edge from corner k to k + 1
    HalfedgeIndex h = m.halfedge(t);
    for (size_t k = 0; k < 3; ++k, h = m.next(h)) {
      corner[k] = m.source(h);
      mid[k] = VertexIndex(VertexIndex::size_type(midpoint[m.edge(h).idx()]));
    }
    out.add_face(corner[0], mid[0], mid[2]);
    out.add_face(mid[0], corner[1], mid[1]);
    out.add_face(mid[2], mid[1], corner[2]);
    out.add_face(mid[0], mid[1], mid[2]);
  }
  return out;
}

// `m` with a vertex at every triangle's centroid (1 to 3), `f` linearly: as
// ComplexRefined, the same critical points; every old vertex's valence doubles,
// so more arcs can reach an extremum apart.
Mesh ComplexCentroidSplit(const Mesh& m, std::vector<double>* f, MorseSmaleMirror* sides) {
  Mesh out;
  for (VertexIndex v : m.vertices()) out.add_vertex(m.point(v));
  std::vector<int> centroid(m.number_of_faces(), -1);
  for (FaceIndex t : m.faces()) {
    std::array<VertexIndex, 3> c;
    size_t k = 0;
    for (VertexIndex v : m.vertices_around_face(m.halfedge(t))) c[k++] = v;
    const VertexIndex mid = out.add_vertex(CGAL::centroid(m.point(c[0]), m.point(c[1]), m.point(c[2])));
    centroid[t.idx()] = int(mid.idx());
    f->push_back(((*f)[c[0].idx()] + (*f)[c[1].idx()] + (*f)[c[2].idx()]) / 3);
    for (size_t i = 0; i < 3; ++i) out.add_face(c[i], c[(i + 1) % 3], mid);
  }
  if (!sides->side.empty()) {
    MorseSmaleMirror next{sides->image, sides->side};
    for (FaceIndex t : m.faces()) {  // its image holds the image of each halfedge, reversed
      const HalfedgeIndex h = m.halfedge(t);
      const size_t a = m.source(h).idx(), b = m.target(h).idx(), c = m.target(m.next(h)).idx();
      const HalfedgeIndex g = m.halfedge(VertexIndex(VertexIndex::size_type(sides->image[b])),
                                         VertexIndex(VertexIndex::size_type(sides->image[a])));
      next.image.push_back(centroid[m.face(g).idx()]);
      next.side.push_back(ComplexSide({sides->side[a], sides->side[b], sides->side[c]}));
    }
    *sides = std::move(next);
  }
  return out;
}

}  // namespace

SurfaceComplex BuildSurfaceComplex(const Mesh& mesh, const Eigen::VectorXd& f,
                                   const MorseSmaleOptions& options, int max_refinements) {
  SurfaceComplex out;
  Mesh triangles = TriangulatedCopy(mesh);
  std::vector<double> values(f.data(), f.data() + f.size());
  Mesh closed;
  MorseSmaleMirror sides;  // the double's mirror
  bool has_boundary = false;
  for (VertexIndex v : triangles.vertices()) has_boundary = has_boundary || triangles.is_border(v);
  if (has_boundary) {
    out.doubled = true;
    ComplexSplitChords(&triangles, &values);
    const SpectralMesh half = SpectralArrays(triangles);
    out.half_points = half.points;
    out.half_triangles = half.triangles;
    for (bool inside : half.closed) out.half_boundary.push_back(!inside);
    if (!ComplexDouble(triangles, &closed, &out.original, &sides)) {
      out.error = "the mesh doubled across its boundary is not a closed manifold";
      return out;
    }
  } else {
    closed = triangles;
    for (VertexIndex v : triangles.vertices()) out.original.push_back(int(v.idx()));
  }
  std::vector<double> g;
  for (int v : out.original) g.push_back(values[size_t(v)]);
  SpectralMesh m;
  for (int level = 0;; ++level) {
    m = SpectralArrays(closed);
    try {
      out.complex = BuildMorseSmale(m.points, m.triangles, m.rings,
                                    Eigen::Map<const Eigen::VectorXd>(g.data(), Eigen::Index(g.size())),
                                    options, out.doubled ? &sides : nullptr);
    } catch (const std::invalid_argument& e) {
      out.error = e.what();
      return out;
    }
    if (out.complex.valid || level >= max_refinements) break;
    closed = level % 2 == 0 ? ComplexCentroidSplit(closed, &g, &sides) : ComplexRefined(closed, &g, &sides);
    out.refinements = level + 1;
  }
  out.points = m.points;
  out.triangles = m.triangles;
  out.quasi_dual = QuasiDual(out.complex, m.points);
  out.built = true;
  return out;
}

std::string SurfaceComplexArcsObj(const SurfaceComplex& c, const std::string& function) {
  return MorseSmaleArcsObj(c.complex, "Morse-Smale complex of " + function +
                                          ": one polyline per arc, saddle to extremum" +
                                          (c.doubled ? " (of the surface doubled across its boundary)" : ""));
}

std::string SurfaceQuasiDualObj(const SurfaceComplex& c) {
  return QuasiDualObj(c.quasi_dual,
                      "quasi-dual of the Morse-Smale complex: extrema, one quad per saddle" +
                          std::string(c.doubled ? " (of the surface doubled across its boundary)" : ""));
}

}  // namespace archgeo
