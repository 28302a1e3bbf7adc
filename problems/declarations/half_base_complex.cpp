// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// HalfBaseComplex (problems/declarations/surface_complex.h): the base
// complex of a surface with boundary from the quasi-dual of its double's
// mirror-symmetric Morse–Smale complex (Gebreiter 2012, §4.1.4, §7.1.4).
#include <map>
#include <set>
#include <string>
#include <vector>

#include "problems/declarations/surface_complex.h"

namespace archgeo {
namespace {

// HalfBaseComplex's faces, built polygon by polygon.
struct HalfFaces {
  const MorseSmaleComplex& mc;
  BaseComplex out;
  std::vector<int> base_vertex;  // per node of the complex
  std::map<int, long> arc_id;    // base edges along arcs (saddles as nodes)
  long next_id;                  // ids past the cells': diagonals, boundary sides, arcs

  explicit HalfFaces(const MorseSmaleComplex& c)
      : mc(c), base_vertex(c.nodes.size(), -1), next_id(long(c.cells.size())) {}

  int Node(int n) {
    if (base_vertex[size_t(n)] < 0) {
      base_vertex[size_t(n)] = int(out.nodes.size());
      out.nodes.push_back(mc.nodes[size_t(n)].vertex);
    }
    return base_vertex[size_t(n)];
  }
  int End(int arc) { return Node(mc.arcs[size_t(arc)].extremum); }
  int Saddle(int arc) { return Node(mc.arcs[size_t(arc)].saddle); }
  long Along(int arc) {
    const auto it = arc_id.find(arc);
    return it != arc_id.end() ? it->second : arc_id[arc] = next_id++;
  }
  long Cell(long cell) { return cell >= 0 ? cell : next_id++; }
  std::string polygon;  // the one being built, for errors

  void Face(std::vector<int> corners, std::vector<long> sides) {
    if (std::set<int>(corners.begin(), corners.end()).size() < corners.size()) {
      throw BaseComplexError(polygon, "repeats a corner (a saddle with two arcs to one extremum)");
    }
    out.faces.push_back(std::move(corners));
    out.edges.push_back(std::move(sides));
  }

  // Corners 0 … m − 1, side k from corner k to k + 1: quads (0, k, k + 1,
  // k + 2) split off by diagonals from corner 0, a triangle last where the
  // corners are odd.
  void Polygon(const std::vector<int>& corner, const std::vector<long>& side) {
    const size_t m = corner.size();
    long previous = side[0];
    size_t k = 1;
    for (; k + 2 < m; k += 2) {
      const long closing = k + 3 == m ? side[m - 1] : next_id++;
      Face({corner[0], corner[k], corner[k + 1], corner[k + 2]}, {previous, side[k], side[k + 1], closing});
      previous = closing;
    }
    if (k + 2 == m) Face({corner[0], corner[k], corner[k + 1]}, {previous, side[k], side[m - 1]});
  }

  // The arcs `run` into the surface, in the polygon's order, of saddles on
  // the boundary, between the arcs `first` and `last` along it (−1: a
  // boundary loop of saddles only): the faces between consecutive arcs,
  // the saddles their corners on the boundary (Gebreiter 2012, §4.1.4).
  void Fan(const MorseSmalePolygon& p, int first, const std::vector<size_t>& run, int last) {
    const size_t n = p.arcs.size();
    auto arc = [&](size_t k) { return p.arcs[k % n]; };
    if (first >= 0) {  // the first arc along the boundary, the first into the surface
      Face({End(arc(size_t(first))), End(arc(run[0])), Saddle(arc(run[0]))},
           {Cell(p.cells[size_t(first)]), Along(arc(run[0])), next_id++});
    }
    const size_t pairs = first >= 0 ? run.size() - 1 : run.size();
    for (size_t k = 0; k < pairs; ++k) {
      const int a = arc(run[k]), b = arc(run[(k + 1) % run.size()]);
      const long between = Cell(p.cells[run[k]]);
      if (mc.arcs[size_t(a)].saddle == mc.arcs[size_t(b)].saddle) {
        Face({End(a), End(b), Saddle(a)}, {between, Along(b), Along(a)});
      } else {
        Face({End(a), End(b), Saddle(b), Saddle(a)}, {between, Along(b), next_id++, Along(a)});
      }
    }
    if (last >= 0) {
      const int a = arc(run.back());
      Face({End(a), End(arc(size_t(last))), Saddle(a)},
           {Cell(p.cells[run.back()]), next_id++, Along(a)});
    }
  }
};

}  // namespace

BaseComplex HalfBaseComplex(const SurfaceComplex& c) {
  const MorseSmaleComplex& mc = c.complex;
  HalfFaces h(mc);
  auto on_boundary = [&](int arc) {
    const int v = mc.nodes[size_t(mc.arcs[size_t(arc)].saddle)].vertex;
    return mc.mirror_image[size_t(v)] == v;
  };
  for (const MorseSmalePolygon& p : SaddlePolygons(mc)) {
    const size_t n = p.arcs.size();
    const std::string name = "the quasi-dual polygon of saddle " +
                             std::to_string(mc.nodes[size_t(mc.arcs[size_t(p.arcs[0])].saddle)].vertex);
    h.polygon = name;
    std::vector<size_t> along, inside;  // its arcs along the boundary, into the surface
    int images = 0;
    for (size_t k = 0; k < n; ++k) {
      const int side = mc.arcs[size_t(p.arcs[k])].side;
      if (side == 1) along.push_back(k);
      if (side == 0) inside.push_back(k);
      images += side == 2;
    }
    if (along.empty() && inside.empty()) continue;  // a mirror image's
    if (along.empty() && images == 0 && on_boundary(p.arcs[0])) {
      // A boundary loop whose critical points are all saddles: the ring
      // of their arcs into the surface round it, fanned to the saddles.
      h.Fan(p, -1, inside, -1);
      continue;
    }
    if (!p.complete) throw BaseComplexError(name, "lacks arcs");
    if (along.empty()) {  // an inner saddle's
      if (images > 0) throw BaseComplexError(name, "has arcs on both sides of the boundary");
      std::vector<int> corner;
      std::vector<long> side;
      for (size_t k = 0; k < n; ++k) {
        corner.push_back(h.End(p.arcs[k]));
        side.push_back(h.Cell(p.cells[k]));
      }
      if (std::set<int>(corner.begin(), corner.end()).size() < corner.size()) {
        throw BaseComplexError(name, "repeats a corner (a saddle with two arcs to one extremum)");
      }
      h.Polygon(corner, side);
      continue;
    }
    // Saddles on the boundary: from one arc along it through those into
    // the surface to the other, closed by a side along the boundary.
    if (along.size() != 2) {
      throw BaseComplexError(name, "has " + std::to_string(along.size()) + " arcs along the boundary (2 expected)");
    }
    size_t first = along[0];
    if (mc.arcs[size_t(p.arcs[(first + 1) % n])].side != 0) first = along[1];
    std::vector<size_t> run;
    size_t last = first;
    for (size_t k = (first + 1) % n;; k = (k + 1) % n) {
      const int side = mc.arcs[size_t(p.arcs[k])].side;
      if (side == 1) {
        last = k;
        break;
      }
      if (side == 2) throw BaseComplexError(name, "has arcs into the mirror image between its arcs into the surface");
      run.push_back(k);
    }
    std::vector<int> corner{h.End(p.arcs[first])};
    for (size_t k : run) corner.push_back(h.End(p.arcs[k]));
    corner.push_back(h.End(p.arcs[last]));
    if (std::set<int>(corner.begin(), corner.end()).size() < corner.size()) {
      // Both ends at one extremum (a boundary loop with one extremum), or
      // an arc into the surface to an extremum on the boundary: the
      // saddles as corners on the boundary.
      h.Fan(p, int(first), run, int(last));
      continue;
    }
    std::vector<long> side{h.Cell(p.cells[first])};
    for (size_t k : run) side.push_back(h.Cell(p.cells[k]));
    side.push_back(h.next_id++);  // along the boundary
    h.Polygon(corner, side);
  }
  return std::move(h.out);
}

}  // namespace archgeo
