// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — quad grids on parametric surfaces (no CGAL).
//
// A grid is n_u × n_v vertices, each carrying its surface parameter (u, v);
// its position is x(u, v), so every vertex lies on the surface by
// construction. Vertex (i, j), 0 ≤ i < n_u, 0 ≤ j < n_v, has index j·n_u + i.
// i runs along the u-lines ("longitudinal"), j along the v-lines
// ("transversal").
//
// Types [force-directed grids paper, §3, Table 1]: open in both directions
// (C0), closed in u or in v (C1), closed in both (C2). A closed direction
// wraps its last edge to the first vertex: (n_u − 1, j) — (0, σ(j)), where
// σ(j) = j, or, on a surface whose u-seam reflects v (the Klein bottle,
// ParameterDomain::u_seam_flips_v), the row of the reflected parameter,
// σ(j) = (n_v − j) mod n_v (v closed) or n_v − 1 − j (v open). Such a grid
// is non-orientable (a Klein-bottle or Möbius quad grid).
// Roles: an interior vertex has 4 neighbours, a boundary vertex 3, a corner of
// an open grid 2 (the paper leaves corners out of the orthogonality forces).
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "surfaces/surface.h"
#include "surfaces/surface_factory.h"

namespace archgeo {

enum class GridType { kOpen, kClosedU, kClosedV, kClosedBoth };

// "open", "closed_u", "closed_v", "closed_both"; throws InputError (key
// `key`) for anything else.
GridType ParseGridType(const std::string& text, const InputContext& where,
                       const std::string& key);
const char* GridTypeName(GridType type);
// The paper's Table 1 notation: "C0", "C1", "C2".
const char* GridTypePaperName(GridType type);

struct Grid {
  int nu = 0, nv = 0;
  bool closed_u = false, closed_v = false;
  bool flip = false;  // the u-seam maps row j to row σ(j) (see above)
  // Surface parameter of every vertex, index j·n_u + i.
  std::vector<Eigen::Vector2d> uv;

  int NumVertices() const { return nu * nv; }
  int Index(int i, int j) const { return j * nu + i; }
  GridType Type() const;
};

// The four neighbours of a vertex: l0 = −u, l1 = +u, t0 = −v, t1 = +v, −1
// where the grid ends. Across a flipping seam the neighbour's own ±v are
// reversed (only the positions matter to the forces and measures).
struct GridNeighbours {
  int l0 = -1, l1 = -1, t0 = -1, t1 = -1;
  int Count() const { return (l0 >= 0) + (l1 >= 0) + (t0 >= 0) + (t1 >= 0); }
};
GridNeighbours Neighbours(const Grid& grid, int vertex);

enum class VertexRole { kInterior, kBoundary, kCorner };
VertexRole Role(const Grid& grid, int vertex);

// The boundary stencil of eq. 2 at a boundary vertex p0: its two neighbours
// along the boundary, p1 and p2 (in the order −, +), and its one neighbour
// inside, p3. Precondition (CHECKed): Role(vertex) == kBoundary.
struct BoundaryStencil {
  int p0, p1, p2, p3;
};
BoundaryStencil BoundaryStencilAt(const Grid& grid, int vertex);

// Every edge once: the u-edges (i, j)–(i+1, j) row by row, with the wrap
// edges of a closed u, then the v-edges (i, j)–(i, j+1), with the wrap
// edges of a closed v.
std::vector<std::array<int, 2>> GridEdges(const Grid& grid);
int CountUEdges(const Grid& grid);

// Every quad (i, j), (i+1, j), (i+1, j+1), (i, j+1) (indices wrapped / σ
// applied across closed seams), in this cyclic order.
std::vector<std::array<int, 4>> GridQuads(const Grid& grid);

// The grid lines: u-lines (rows; across a flipping seam a row continues in
// row σ(j), so rows j and σ(j) form one closed line) then v-lines (columns).
struct GridLine {
  std::vector<int> vertices;
  bool closed = false;  // the last vertex joins the first
};
std::vector<GridLine> GridLines(const Grid& grid);

// x(u, v) of every vertex.
std::vector<Eigen::Vector3d> GridPoints(const Grid& grid, const Surface& surface);

// Throws InputError unless a grid of this size and type can be laid on
// `surface`: n_u, n_v ≥ 2, a closed direction needs ≥ 3 vertices and a
// periodic direction of the surface. The error names keys.nu / keys.nv for a
// size and keys.type for a closure on a non-periodic direction.
struct GridKeys {
  std::string nu = "grid.nu", nv = "grid.nv", type = "grid.type";
};
void CheckGridRequest(const Surface& surface, int nu, int nv, GridType type,
                      const InputContext& where, const GridKeys& keys = {});

// The uniform grid: a closed direction spaced P/n over one period starting at
// u0 (resp. v0), an open one from bound to bound. Preconditions (CHECKed): the
// request passes CheckGridRequest.
Grid MakeUniformGrid(const Surface& surface, int nu, int nv, GridType type);

// Mean 3-D edge length of the grid on `surface`.
double MeanEdgeLength(const Grid& grid, const Surface& surface);

}  // namespace archgeo
