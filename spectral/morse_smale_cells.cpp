// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The cells of the Morse–Smale complex, their check, and its quasi-dual.
#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "spectral/morse_smale_detail.h"

namespace archgeo {
namespace {

uint64_t CellEdgeKey(int a, int b) {
  return (uint64_t(uint32_t(std::min(a, b))) << 32) | uint32_t(std::max(a, b));
}

int CellFind(std::vector<int>& parent, int i) {
  while (parent[size_t(i)] != i) i = parent[size_t(i)] = parent[size_t(parent[size_t(i)])];
  return i;
}

using CellSides = std::unordered_map<uint64_t, std::array<int, 2>>;

// The cells the triangles with `keep` fall into when joined across every
// edge with `join` (both sides kept): per kept triangle its cell in
// `cell_of_triangle` (−1 for the others), per cell V − E + F of its
// closure, whether an edge in `cut` has the cell on both sides (a slit),
// and its corners (`node_of`: per vertex its node or −1), cells numbered in
// the order of their first triangle.
template <typename Keep, typename Join>
std::vector<MorseSmaleCell> CutCells(const std::vector<std::array<int, 3>>& triangles,
                                     const CellSides& sides, const std::unordered_set<uint64_t>& cut,
                                     const std::vector<int>& node_of, Keep keep, Join join,
                                     std::vector<int>& cell_of_triangle) {
  const size_t t_count = triangles.size();
  std::vector<int> parent(t_count);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [key, s] : sides) {
    if (s[1] >= 0 && keep(size_t(s[0])) && keep(size_t(s[1])) && join(key)) {
      parent[size_t(CellFind(parent, s[0]))] = CellFind(parent, s[1]);
    }
  }
  std::vector<MorseSmaleCell> cells;
  std::vector<int> cell_of_root(t_count, -1);
  cell_of_triangle.assign(t_count, -1);
  for (size_t t = 0; t < t_count; ++t) {
    if (!keep(t)) continue;
    int& cell = cell_of_root[size_t(CellFind(parent, int(t)))];
    if (cell < 0) {
      cell = int(cells.size());
      cells.emplace_back();
    }
    cell_of_triangle[t] = cell;
    ++cells[size_t(cell)].euler;  // F
  }
  for (const auto& [key, s] : sides) {
    const int a = cell_of_triangle[size_t(s[0])], b = s[1] < 0 ? -1 : cell_of_triangle[size_t(s[1])];
    if (a >= 0) --cells[size_t(a)].euler;  // E
    if (b >= 0 && b != a) --cells[size_t(b)].euler;
    if (a >= 0 && a == b && cut.count(key)) cells[size_t(a)].slit = true;
  }
  std::vector<std::vector<int>> cells_at(node_of.size());
  for (size_t t = 0; t < t_count; ++t) {
    if (cell_of_triangle[t] < 0) continue;
    for (int v : triangles[t]) cells_at[size_t(v)].push_back(cell_of_triangle[t]);
  }
  for (size_t v = 0; v < cells_at.size(); ++v) {
    std::vector<int>& around = cells_at[v];
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    for (int cell : around) {
      ++cells[size_t(cell)].euler;  // V
      std::vector<int>& corners = cells[size_t(cell)].corners;
      if (node_of[v] >= 0 && std::find(corners.begin(), corners.end(), node_of[v]) == corners.end()) {
        corners.push_back(node_of[v]);
      }
    }
  }
  return cells;
}

// Vertices on two arcs (or twice on one), and arcs through a node.
int CellSharedVertices(const MorseSmaleComplex& c, int vertex_count) {
  std::vector<int> uses(static_cast<size_t>(vertex_count), 0);
  std::vector<bool> node(static_cast<size_t>(vertex_count), false);
  for (const MorseSmaleNode& n : c.nodes) node[size_t(n.vertex)] = true;
  int shared = 0;
  for (const MorseSmaleArc& a : c.arcs) {
    // A connection of two saddles is traced from both ends: counted once.
    if (c.nodes[size_t(a.extremum)].kind == 0 && a.extremum < a.saddle) continue;
    for (size_t i = 1; i + 1 < a.path.size(); ++i) {
      shared += node[size_t(a.path[i])] || uses[size_t(a.path[i])]++ > 0;
    }
  }
  return shared;
}

// Each cell a disc with corners max, min, saddle, saddle (four distinct);
// `boundary`: a half cell of a double that meets the boundary off the arcs,
// corners max, min and one saddle (HalfCellsValid).
bool CellValid(const MorseSmaleCell& cell, const std::vector<MorseSmaleNode>& nodes, bool boundary = false) {
  if (cell.euler != 1 || cell.slit) return false;
  int kinds[3] = {0, 0, 0};
  for (int n : cell.corners) ++kinds[nodes[size_t(n)].kind + 1];
  if (kinds[0] != 1 || kinds[2] != 1) return false;
  return boundary ? cell.corners.size() == 3 && kinds[1] == 1 : cell.corners.size() == 4 && kinds[1] == 2;
}

// On a double: the cells of the surface's side (its triangles, cut along
// the arcs and the boundary), each checked as CellValid checks, with one
// saddle where it meets the boundary off the arcs (the half of a cell that
// is its own mirror image). Per cell of `c`: whether its parts on the
// surface's side are valid (cells of the images only: true, their images
// judge them). `node_of`: per vertex its (grouped) node or −1.
std::vector<bool> HalfCellsValid(const std::vector<std::array<int, 3>>& triangles,
                                 const std::vector<char>& side, const std::unordered_set<uint64_t>& cut,
                                 const CellSides& sides, const std::vector<int>& node_of,
                                 const MorseSmaleComplex& c) {
  auto surface = [&](size_t t) {
    return side[size_t(triangles[t][0])] != 2 && side[size_t(triangles[t][1])] != 2 &&
           side[size_t(triangles[t][2])] != 2;
  };
  auto boundary_edge = [&](uint64_t key) {
    return side[size_t(key >> 32)] == 1 && side[size_t(key & 0xffffffffu)] == 1;
  };
  std::vector<int> half_of_triangle;
  const std::vector<MorseSmaleCell> half = CutCells(
      triangles, sides, cut, node_of, surface,
      [&](uint64_t key) { return !cut.count(key) && !boundary_edge(key); }, half_of_triangle);
  std::vector<bool> meets(half.size(), false);  // a boundary edge off the arcs
  for (const auto& [key, s] : sides) {
    if (!boundary_edge(key) || cut.count(key)) continue;
    const int a = half_of_triangle[size_t(s[0])], b = s[1] < 0 ? -1 : half_of_triangle[size_t(s[1])];
    if (a >= 0 || b >= 0) meets[size_t(a >= 0 ? a : b)] = true;
  }
  std::vector<bool> valid(c.cells.size(), true);
  for (size_t t = 0; t < triangles.size(); ++t) {
    const int h = half_of_triangle[t];
    if (h >= 0 && !CellValid(half[size_t(h)], c.nodes, meets[size_t(h)])) {
      valid[size_t(c.cell_of_triangle[t])] = false;
    }
  }
  return valid;
}

}  // namespace

namespace morse_smale {

void BuildCells(int vertex_count, const std::vector<std::array<int, 3>>& triangles,
                const MorseSmaleMirror& mirror, MorseSmaleComplex& c) {
  std::unordered_set<uint64_t> cut;
  for (const MorseSmaleArc& a : c.arcs) {
    for (size_t i = 0; i + 1 < a.path.size(); ++i) cut.insert(CellEdgeKey(a.path[i], a.path[i + 1]));
  }
  CellSides sides;
  sides.reserve(triangles.size() * 2);
  for (size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      auto [it, fresh] =
          sides.try_emplace(CellEdgeKey(triangles[t][size_t(k)], triangles[t][size_t((k + 1) % 3)]),
                            std::array<int, 2>{int(t), -1});
      if (!fresh) it->second[1] = int(t);
    }
  }
  for (const auto& [key, s] : sides) {
    if (s[1] < 0) throw std::invalid_argument("the Morse-Smale complex needs a closed mesh");
  }
  // Saddles joined by a connection along a double's boundary count as one
  // corner (the multi-saddle they make, SaddlePolygons).
  std::vector<int> group(c.nodes.size());
  std::iota(group.begin(), group.end(), 0);
  for (const MorseSmaleArc& a : c.arcs) {
    if (c.nodes[size_t(a.extremum)].kind == 0) {
      group[size_t(CellFind(group, a.saddle))] = CellFind(group, a.extremum);
    }
  }
  std::vector<int> node_of(static_cast<size_t>(vertex_count), -1);
  for (size_t n = 0; n < c.nodes.size(); ++n) node_of[size_t(c.nodes[n].vertex)] = CellFind(group, int(n));
  c.cells = CutCells(
      triangles, sides, cut, node_of, [](size_t) { return true; },
      [&](uint64_t key) { return !cut.count(key); }, c.cell_of_triangle);
  for (MorseSmaleArc& a : c.arcs) {
    const std::array<int, 2>& s = sides.at(CellEdgeKey(a.path[0], a.path[1]));
    a.side_cells = {c.cell_of_triangle[size_t(s[0])], c.cell_of_triangle[size_t(s[1])]};
  }
  if (mirror.side.empty()) {
    for (MorseSmaleCell& cell : c.cells) cell.valid = CellValid(cell, c.nodes);
  } else {
    const std::vector<bool> valid = HalfCellsValid(triangles, mirror.side, cut, sides, node_of, c);
    for (size_t k = 0; k < c.cells.size(); ++k) c.cells[k].valid = valid[k];
  }
  for (const MorseSmaleCell& cell : c.cells) c.invalid_cells += !cell.valid;
  c.shared_vertices = CellSharedVertices(c, vertex_count);
  c.valid = c.unresolved == 0 && c.shared_vertices == 0 && c.invalid_cells == 0 && !c.cells.empty();
}

}  // namespace morse_smale

std::vector<MorseSmalePolygon> SaddlePolygons(const MorseSmaleComplex& c) {
  // Each saddle's arcs: consecutive in `arcs`, in the cyclic order of its wedges.
  std::vector<size_t> first(c.nodes.size(), 0), count(c.nodes.size(), 0);
  for (size_t a = 0; a < c.arcs.size(); ++a) {
    const size_t s = size_t(c.arcs[a].saddle);
    if (count[s]++ == 0) first[s] = a;
  }
  auto connection = [&](size_t a) { return c.nodes[size_t(c.arcs[a].extremum)].kind == 0; };
  auto next = [&](size_t a) {  // the saddle's next arc round it
    const size_t s = size_t(c.arcs[a].saddle);
    return a + 1 < first[s] + count[s] ? a + 1 : first[s];
  };
  // The arc back along connection a, from its other end.
  auto back = [&](size_t a) -> long {
    const MorseSmaleArc& arc = c.arcs[a];
    const size_t t = size_t(arc.extremum);
    for (size_t b = first[t]; b < first[t] + count[t]; ++b) {
      const std::vector<int>& p = c.arcs[b].path;
      if (c.arcs[b].extremum == arc.saddle && p.size() == arc.path.size() && p[1] == arc.path[arc.path.size() - 2]) {
        return long(b);
      }
    }
    return -1;
  };
  std::vector<bool> seen(c.arcs.size(), false);
  std::vector<MorseSmalePolygon> out;
  for (size_t start = 0; start < c.arcs.size(); ++start) {
    if (seen[start] || connection(start)) continue;
    MorseSmalePolygon p;
    int multiplicity = 0;
    std::vector<bool> member(c.nodes.size(), false);
    // Round the saddle, and past each connection round the saddle at its
    // other end, from the arc after the connection back.
    size_t a = start;
    for (size_t steps = 0; steps <= c.arcs.size(); ++steps) {
      seen[a] = true;
      p.arcs.push_back(int(a));
      const int s = c.arcs[a].saddle;
      if (!member[size_t(s)]) multiplicity += c.nodes[size_t(s)].multiplicity;
      member[size_t(s)] = true;
      a = next(a);
      while (connection(a)) {
        seen[a] = true;
        const long b = back(a);
        if (b < 0) break;
        seen[size_t(b)] = true;
        if (!member[size_t(c.arcs[a].extremum)]) multiplicity += c.nodes[size_t(c.arcs[a].extremum)].multiplicity;
        member[size_t(c.arcs[a].extremum)] = true;
        a = next(size_t(b));
      }
      if (a == start || connection(a)) break;
    }
    p.complete = int(p.arcs.size()) == 2 * (multiplicity + 1) && !connection(a);
    // A maximum first.
    const auto up = std::find_if(p.arcs.begin(), p.arcs.end(), [&](int x) { return c.arcs[size_t(x)].ascending; });
    if (up != p.arcs.end()) std::rotate(p.arcs.begin(), up, p.arcs.end());
    for (size_t k = 0; k < p.arcs.size(); ++k) {
      const MorseSmaleArc& x = c.arcs[size_t(p.arcs[k])];
      const MorseSmaleArc& y = c.arcs[size_t(p.arcs[(k + 1) % p.arcs.size()])];
      long shared = -1;
      for (int cell : x.side_cells) {
        if (cell >= 0 && (cell == y.side_cells[0] || cell == y.side_cells[1])) shared = cell;
      }
      p.cells.push_back(shared);
    }
    out.push_back(std::move(p));
  }
  return out;
}

QuadBaseComplex QuasiDual(const MorseSmaleComplex& c, const std::vector<Eigen::Vector3d>& points) {
  QuadBaseComplex out;
  std::vector<int> vertex_of(c.nodes.size(), -1);
  for (size_t n = 0; n < c.nodes.size(); ++n) {
    if (c.nodes[n].kind == 0) continue;
    vertex_of[n] = int(out.points.size());
    out.points.push_back(points[size_t(c.nodes[n].vertex)]);
    out.nodes.push_back(c.nodes[n].vertex);
  }
  // The dual edge between two consecutive arcs of a saddle's polygon
  // crosses the cell they share.
  std::unordered_map<long, std::array<int, 2>> edges;  // key: the cell, or a diagonal
  long diagonals = long(c.cells.size());
  for (const MorseSmalePolygon& p : SaddlePolygons(c)) {
    const size_t n = p.arcs.size();
    if (!p.complete) {
      ++out.missing_saddles;
      continue;
    }
    std::vector<int> polygon;
    std::vector<long> side;  // side k: between corners k and k + 1
    for (size_t k = 0; k < n; ++k) {
      polygon.push_back(vertex_of[size_t(c.arcs[size_t(p.arcs[k])].extremum)]);
      side.push_back(p.cells[k] >= 0 ? p.cells[k] : diagonals++);
    }
    long previous = side[0];  // quads (0, k, k+1, k+2), split by diagonals from corner 0
    for (size_t k = 1; k + 2 < n; k += 2) {
      const long closing = k + 3 == n ? side[n - 1] : diagonals++;
      const std::array<int, 4> q{polygon[0], polygon[k], polygon[k + 1], polygon[k + 2]};
      const std::array<long, 4> e{previous, side[k], side[k + 1], closing};
      for (size_t m = 0; m < 4; ++m) edges[e[m]] = {q[m], q[(m + 1) % 4]};
      std::array<int, 4> sorted = q;
      std::sort(sorted.begin(), sorted.end());
      out.degenerate_quads += std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
      out.quads.push_back(q);
      out.quad_edges.push_back(e);
      previous = closing;
    }
  }
  std::vector<int> valence(out.points.size(), 0);
  for (const auto& [key, e] : edges) {
    ++valence[size_t(e[0])];
    ++valence[size_t(e[1])];
  }
  for (int v : valence) out.irregular_vertices += v != 4;
  out.edges = int(edges.size());
  out.euler = int(out.points.size()) - out.edges + int(out.quads.size());
  return out;
}

QuadBaseComplex PrimalQuads(const MorseSmaleComplex& c, const std::vector<Eigen::Vector3d>& points) {
  QuadBaseComplex out;
  for (const MorseSmaleNode& n : c.nodes) {
    out.points.push_back(points[size_t(n.vertex)]);
    out.nodes.push_back(n.vertex);
  }
  // The arc of saddle s to extremum e that has cell `cell` on one side.
  auto arc_of = [&](int s, int e, int cell) -> long {
    for (size_t a = 0; a < c.arcs.size(); ++a) {
      const MorseSmaleArc& arc = c.arcs[a];
      if (arc.saddle == s && arc.extremum == e &&
          (arc.side_cells[0] == cell || arc.side_cells[1] == cell)) {
        return long(a);
      }
    }
    return -1;
  };
  std::vector<bool> done(c.cells.size(), false);
  std::unordered_set<long> edges;
  for (size_t i = 0; i < c.arcs.size();) {
    size_t j = i;
    while (j < c.arcs.size() && c.arcs[j].saddle == c.arcs[i].saddle) ++j;
    const int s = c.arcs[i].saddle;
    // Consecutive arcs a, b of s (its wedges' cyclic order) bound the cell
    // they share: the quad s, a's extremum, the cell's other saddle, b's.
    for (size_t k = i; k < j; ++k) {
      const MorseSmaleArc& a = c.arcs[k];
      const MorseSmaleArc& b = c.arcs[k + 1 < j ? k + 1 : i];
      int cell = -1;
      for (int x : a.side_cells) {
        if (x >= 0 && (x == b.side_cells[0] || x == b.side_cells[1])) cell = x;
      }
      if (cell < 0 || done[size_t(cell)]) continue;
      done[size_t(cell)] = true;
      int other = -1;
      for (int n : c.cells[size_t(cell)].corners) {
        if (c.nodes[size_t(n)].kind == 0 && n != s) other = n;
      }
      const std::array<int, 4> q{s, a.extremum, other, b.extremum};
      const std::array<long, 4> e{long(k), other < 0 ? -1 : arc_of(other, a.extremum, cell),
                                  other < 0 ? -1 : arc_of(other, b.extremum, cell),
                                  long(k + 1 < j ? k + 1 : i)};
      std::array<int, 4> sorted = q;
      std::sort(sorted.begin(), sorted.end());
      out.degenerate_quads += other < 0 || e[1] < 0 || e[2] < 0 ||
                              std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
      out.quads.push_back(q);
      out.quad_edges.push_back(e);
      for (long x : e) edges.insert(x);
    }
    i = j;
  }
  std::vector<int> valence(out.points.size(), 0);
  for (const MorseSmaleArc& a : c.arcs) {
    ++valence[size_t(a.saddle)];
    ++valence[size_t(a.extremum)];
  }
  for (int v : valence) out.irregular_vertices += v != 4;
  out.edges = int(edges.size());
  out.euler = int(out.points.size()) - out.edges + int(out.quads.size());
  return out;
}

}  // namespace archgeo
