// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "surfaces/grid.h"

#include <glog/logging.h>

#include "core/input_error.h"

namespace archgeo {
namespace {

// σ(j): the row that row j continues in across the u-seam.
int SeamRow(const Grid& g, int j) {
  if (!g.flip) return j;
  return g.closed_v ? (g.nv - j) % g.nv : g.nv - 1 - j;
}

}  // namespace

GridType ParseGridType(const std::string& text, const InputContext& where,
                       const std::string& key) {
  for (GridType t : {GridType::kOpen, GridType::kClosedU, GridType::kClosedV,
                     GridType::kClosedBoth}) {
    if (text == GridTypeName(t)) return t;
  }
  throw InputError(where.file, where.line, key,
                   "unknown grid type '" + text + "' (known: open, closed_u, closed_v, closed_both)");
}

const char* GridTypeName(GridType type) {
  switch (type) {
    case GridType::kOpen: return "open";
    case GridType::kClosedU: return "closed_u";
    case GridType::kClosedV: return "closed_v";
    case GridType::kClosedBoth: return "closed_both";
  }
  return "";
}

const char* GridTypePaperName(GridType type) {
  switch (type) {
    case GridType::kOpen: return "C0";
    case GridType::kClosedU:
    case GridType::kClosedV: return "C1";
    case GridType::kClosedBoth: return "C2";
  }
  return "";
}

GridType Grid::Type() const {
  if (closed_u && closed_v) return GridType::kClosedBoth;
  if (closed_u) return GridType::kClosedU;
  if (closed_v) return GridType::kClosedV;
  return GridType::kOpen;
}

GridNeighbours Neighbours(const Grid& g, int vertex) {
  DCHECK(vertex >= 0 && vertex < g.NumVertices());
  const int i = vertex % g.nu, j = vertex / g.nu;
  GridNeighbours n;
  if (i + 1 < g.nu) {
    n.l1 = g.Index(i + 1, j);
  } else if (g.closed_u) {
    n.l1 = g.Index(0, SeamRow(g, j));
  }
  if (i > 0) {
    n.l0 = g.Index(i - 1, j);
  } else if (g.closed_u) {
    n.l0 = g.Index(g.nu - 1, SeamRow(g, j));
  }
  if (j + 1 < g.nv) {
    n.t1 = g.Index(i, j + 1);
  } else if (g.closed_v) {
    n.t1 = g.Index(i, 0);
  }
  if (j > 0) {
    n.t0 = g.Index(i, j - 1);
  } else if (g.closed_v) {
    n.t0 = g.Index(i, g.nv - 1);
  }
  return n;
}

VertexRole Role(const Grid& grid, int vertex) {
  const int count = Neighbours(grid, vertex).Count();
  return count == 4 ? VertexRole::kInterior
                    : (count == 3 ? VertexRole::kBoundary : VertexRole::kCorner);
}

BoundaryStencil BoundaryStencilAt(const Grid& grid, int vertex) {
  const GridNeighbours n = Neighbours(grid, vertex);
  CHECK_EQ(n.Count(), 3) << "BoundaryStencilAt: vertex " << vertex << " is not a boundary vertex";
  if (n.t0 < 0 || n.t1 < 0) return {vertex, n.l0, n.l1, n.t0 >= 0 ? n.t0 : n.t1};
  return {vertex, n.t0, n.t1, n.l0 >= 0 ? n.l0 : n.l1};
}

int CountUEdges(const Grid& g) { return (g.closed_u ? g.nu : g.nu - 1) * g.nv; }

std::vector<std::array<int, 2>> GridEdges(const Grid& g) {
  std::vector<std::array<int, 2>> edges;
  for (int j = 0; j < g.nv; ++j) {
    for (int i = 0; i + 1 < g.nu; ++i) edges.push_back({g.Index(i, j), g.Index(i + 1, j)});
    if (g.closed_u) edges.push_back({g.Index(g.nu - 1, j), g.Index(0, SeamRow(g, j))});
  }
  for (int j = 0; j + 1 < g.nv; ++j) {
    for (int i = 0; i < g.nu; ++i) edges.push_back({g.Index(i, j), g.Index(i, j + 1)});
  }
  if (g.closed_v) {
    for (int i = 0; i < g.nu; ++i) edges.push_back({g.Index(i, g.nv - 1), g.Index(i, 0)});
  }
  return edges;
}

std::vector<std::array<int, 4>> GridQuads(const Grid& g) {
  std::vector<std::array<int, 4>> quads;
  const int rows = g.closed_v ? g.nv : g.nv - 1;
  const int columns = g.closed_u ? g.nu : g.nu - 1;
  for (int j = 0; j < rows; ++j) {
    const int j1 = (j + 1) % g.nv;
    for (int i = 0; i < columns; ++i) {
      if (i + 1 < g.nu) {
        quads.push_back({g.Index(i, j), g.Index(i + 1, j), g.Index(i + 1, j1), g.Index(i, j1)});
      } else {  // the u-seam
        quads.push_back({g.Index(i, j), g.Index(0, SeamRow(g, j)), g.Index(0, SeamRow(g, j1)),
                         g.Index(i, j1)});
      }
    }
  }
  return quads;
}

std::vector<GridLine> GridLines(const Grid& g) {
  std::vector<GridLine> lines;
  std::vector<bool> row_done(g.nv, false);
  for (int j = 0; j < g.nv; ++j) {
    if (row_done[j]) continue;
    GridLine line;
    line.closed = g.closed_u;
    for (int row = j;;) {
      row_done[row] = true;
      for (int i = 0; i < g.nu; ++i) line.vertices.push_back(g.Index(i, row));
      if (!g.closed_u) break;
      row = SeamRow(g, row);
      if (row_done[row]) break;
    }
    lines.push_back(std::move(line));
  }
  for (int i = 0; i < g.nu; ++i) {
    GridLine line;
    line.closed = g.closed_v;
    for (int j = 0; j < g.nv; ++j) line.vertices.push_back(g.Index(i, j));
    lines.push_back(std::move(line));
  }
  return lines;
}

std::vector<Eigen::Vector3d> GridPoints(const Grid& grid, const Surface& surface) {
  std::vector<Eigen::Vector3d> points(grid.uv.size());
  for (size_t k = 0; k < grid.uv.size(); ++k) points[k] = surface.Point(grid.uv[k]);
  return points;
}

void CheckGridRequest(const Surface& surface, int nu, int nv, GridType type,
                      const InputContext& where, const GridKeys& keys) {
  const bool closed_u = type == GridType::kClosedU || type == GridType::kClosedBoth;
  const bool closed_v = type == GridType::kClosedV || type == GridType::kClosedBoth;
  const ParameterDomain d = surface.Domain();
  if (closed_u && !d.periodic_u) {
    throw InputError(where.file, where.line, keys.type,
                     std::string("grid type '") + GridTypeName(type) + "' closes u, but surface '" +
                         surface.KindName() + "' is not periodic in u");
  }
  if (closed_v && !d.periodic_v) {
    throw InputError(where.file, where.line, keys.type,
                     std::string("grid type '") + GridTypeName(type) + "' closes v, but surface '" +
                         surface.KindName() + "' is not periodic in v");
  }
  const auto size = [&](int n, bool closed, const std::string& key) {
    const int least = closed ? 3 : 2;
    if (n < least) {
      throw InputError(where.file, where.line, key,
                       "must be at least " + std::to_string(least) + (closed ? " in a closed direction" : "") +
                           ", got " + std::to_string(n));
    }
  };
  size(nu, closed_u, keys.nu);
  size(nv, closed_v, keys.nv);
}

Grid MakeUniformGrid(const Surface& surface, int nu, int nv, GridType type) {
  Grid g;
  g.nu = nu;
  g.nv = nv;
  g.closed_u = type == GridType::kClosedU || type == GridType::kClosedBoth;
  g.closed_v = type == GridType::kClosedV || type == GridType::kClosedBoth;
  const ParameterDomain d = surface.Domain();
  CHECK(nu >= (g.closed_u ? 3 : 2) && nv >= (g.closed_v ? 3 : 2)) << "MakeUniformGrid: too small";
  CHECK(!g.closed_u || d.periodic_u) << "MakeUniformGrid: u is not periodic";
  CHECK(!g.closed_v || d.periodic_v) << "MakeUniformGrid: v is not periodic";
  g.flip = g.closed_u && d.u_seam_flips_v;
  const double hu = d.PeriodU() / (g.closed_u ? nu : nu - 1);
  const double hv = d.PeriodV() / (g.closed_v ? nv : nv - 1);
  g.uv.resize(nu * nv);
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      // The last open vertex exactly on the bound.
      const double u = (!g.closed_u && i == nu - 1) ? d.u1 : d.u0 + i * hu;
      const double v = (!g.closed_v && j == nv - 1) ? d.v1 : d.v0 + j * hv;
      g.uv[g.Index(i, j)] = Eigen::Vector2d(u, v);
    }
  }
  return g;
}

double MeanEdgeLength(const Grid& grid, const Surface& surface) {
  const std::vector<Eigen::Vector3d> x = GridPoints(grid, surface);
  const auto edges = GridEdges(grid);
  double sum = 0.0;
  for (const auto& e : edges) sum += (x[e[1]] - x[e[0]]).norm();
  return edges.empty() ? 0.0 : sum / edges.size();
}

}  // namespace archgeo
