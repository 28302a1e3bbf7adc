// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — from a base complex on a triangle mesh (closed, or open with
// the base complex's boundary on the surface boundary) to a conforming quad
// mesh (Gebreiter 2012, §4.1): charts, their parameterisation over a
// primitive domain, and the extraction of a regular grid per chart.
//
//  1. Charts (§4.1.1–4.1.2, BuildChartLayout): a base edge on one base face
//     (open surfaces) runs along the surface boundary between its nodes;
//     every other base edge is one shortest path on the interior edge graph
//     (Dijkstra, edge lengths) between its two nodes, over vertices no
//     earlier path, no other node and no boundary uses, so no two paths
//     share a vertex other than their nodes. Paths are traced as Praun et
//     al. (2001, "Consistent mesh parameterizations") do: a spanning tree of
//     the base edges first, then the rest, each shortest chord first, and
//     every path leaves and enters its nodes between the paths of its
//     neighbouring base edges in the cyclic order of the base complex. The
//     triangles between the paths are flood-filled into charts; each chart
//     must be the base face it lies left of, a disc (V − E + F = 1, one
//     boundary loop) whose boundary is exactly that face's paths. Where the
//     surface has no room for them (ChartRoomError), ChartQuads splits
//     every surface triangle into four at its edge midpoints (the same
//     surface, so samples stay on the input) and tries again, twice at most.
//  2. Parameterisation (§4.1.3–4.1.5, ParameteriseChart): a triangle chart to
//     the equilateral triangle (0,0), (1,0), (½, √3/2), a quad chart to the
//     unit square, corners in the base face's order; boundary vertices by
//     arc length between the corners; interior vertices by the harmonic map
//     with cotangent weights (½(cot α + cot β)) or Floater's mean-value
//     weights (tan(γ/2)/‖e‖, positive on every mesh, so never flipped with a
//     convex border).
//  3. Extraction (§4.1.6, ExtractQuads): every base edge sampled once at n
//     equal arc-length steps (welded into both its charts); a quad chart's
//     interior at the (i/n, j/n) grid, a triangle chart split into three
//     quads (corner, edge midpoints, centre) of (n/2)² each (n even) — or,
//     with boundary strips (§4.1.4: "along the boundary of quadrilateral
//     meshes, triangular patches ... are divided into a combination of quads
//     lined up with the neighbouring charts with triangles along the open
//     boundary"), a triangle chart with one side on the open boundary as the
//     lattice A + (i/n)(B − A) + (j/n)(C − A), A the corner opposite that
//     side: quads for i + j ≤ n − 2, n triangles along the boundary side, no
//     centre vertex; or, for triangle output (§4.1.4: "a triangular base
//     complex, each chart is mapped onto an equilateral triangle"; §9.2.4,
//     remeshing using subdivision: at n = 2^k the connectivity of k Loop
//     steps of the base complex), every chart as the whole lattice, n²
//     triangles; every sample mapped back through the barycentric
//     coordinates of the parameter triangle holding it, so it lies on the
//     input surface.
//
// Plain arrays in, plain structs out (no CGAL). Errors in the base complex
// throw BaseComplexError naming the element.
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace archgeo {

// A base complex on a surface mesh: its nodes are surface vertices.
struct BaseComplex {
  std::vector<int> nodes;               // surface vertex id per base vertex
  std::vector<std::vector<int>> faces;  // base vertex indices, 3 or 4 per face
  // Optional, per face and side k (corner k → k + 1): an edge id; sides with
  // the same id are one base edge, so two base edges may join the same two
  // nodes (a quasi-dual whose saddles share their extrema). Empty: one base
  // edge per pair of nodes.
  std::vector<std::vector<long>> edges;
};

// A base complex the surface cannot carry; `element` names it ("base face 3",
// "base edge 2-5", "base vertex 7"), numbered from 0 as in the input.
class BaseComplexError : public std::invalid_argument {
 public:
  BaseComplexError(std::string element, const std::string& message)
      : std::invalid_argument(element + ": " + message), element_(std::move(element)) {}
  const std::string& element() const { return element_; }

 private:
  std::string element_;
};

// A base complex the surface has no room for at its resolution: a base edge
// with no free path in its sectors, or charts that are not the discs of their
// faces. ChartQuads refines the surface and tries again.
class ChartRoomError : public BaseComplexError {
 public:
  using BaseComplexError::BaseComplexError;
};

struct BaseEdgePath {
  int a = 0, b = 0;       // base vertices, a < b
  std::vector<int> path;  // surface vertices from node a to node b
  double length = 0;      // along the surface edges
  bool boundary = false;  // on one base face: its path is the surface boundary between its nodes
};

struct Chart {
  int face = 0;                   // base face
  std::vector<int> triangles;     // surface triangles
  std::vector<int> vertices;      // surface vertices (local index → surface id)
  std::vector<int> boundary;      // local indices of the boundary loop, from corner 0
  std::vector<int> corner_at;     // per side k: position in `boundary` of corner k
  int euler = 0;                  // V − E + F of the chart's closure
  int boundary_loops = 0;
};

struct ChartLayout {
  std::vector<BaseEdgePath> edges;
  // Per base face, per side k (corner k → k + 1): the edge and whether it
  // runs b → a.
  std::vector<std::vector<std::pair<int, bool>>> sides;
  std::vector<Chart> charts;           // one per base face, in face order
  std::vector<int> chart_of_triangle;  // per surface triangle
  bool turned = false;  // the base faces were oriented against the surface and turned
};

// `triangles`: a consistently oriented manifold triangle mesh on `points`.
// Throws BaseComplexError for a base complex that is not a manifold of
// triangles and quads on distinct nodes, closed where the surface is, with
// its boundary nodes exactly on the surface boundary; ChartRoomError for a
// base edge with no free path or a chart that is not the disc of its face.
ChartLayout BuildChartLayout(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<std::array<int, 3>>& triangles,
                             const BaseComplex& base);

enum class ChartWeights { kCotangent, kMeanValue };

struct ChartMap {
  std::vector<Eigen::Vector2d> uv;  // per chart vertex (local index)
  int flipped = 0;                  // parameter triangles of signed area ≤ 0
  double min_area = 0;              // the smallest signed area / the domain's
};

// The domain corners of a chart with `sides` sides (3 or 4), counter-clockwise.
std::vector<Eigen::Vector2d> ChartDomain(int sides);

ChartMap ParameteriseChart(const std::vector<Eigen::Vector3d>& points,
                           const std::vector<std::array<int, 3>>& triangles,
                           const ChartLayout& layout, int chart, ChartWeights weights);

struct QuadExtraction {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 4>> quads;  // oriented as the surface
  std::vector<std::array<int, 3>> triangles;  // of lattice charts (strips: along the open boundary)
  // Samples strictly inside a strip chart's boundary side: 2 triangles and 1
  // quad meet there, so their regular valence is 4, not 3.
  std::vector<int> strip_boundary_vertex;
  std::vector<int> node_vertex;           // output vertex of each base vertex
  std::vector<int> centre_vertex;         // per base face: its centre (triangles), else −1
  // Every base edge's samples (at equal arc length along its path, welded)
  // against the same parameters mapped back through each of its two charts:
  // the largest distance (0: both charts sample the shared edge identically).
  double shared_edge_mismatch = 0;
  int unlocated = 0;  // samples in no parameter triangle (taken from the nearest one)
};

// How triangle charts are filled: split into three quads; as boundary
// strips where they have one side on the open boundary (split elsewhere);
// or all charts as triangle lattices (a triangle complex only).
enum class ChartFill { kSplit, kStrip, kTriangles };

// Whether triangle chart f is extracted as a boundary strip: kStrip and
// exactly one of its three sides on the surface boundary.
bool StripChart(const ChartLayout& layout, int f, ChartFill fill);

// `n`: samples per base edge (even when a triangle chart is split into three
// quads). Throws BaseComplexError naming a quad face for kTriangles.
QuadExtraction ExtractQuads(const std::vector<Eigen::Vector3d>& points,
                            const std::vector<std::array<int, 3>>& triangles,
                            const BaseComplex& base, const ChartLayout& layout,
                            const std::vector<ChartMap>& maps, int n,
                            ChartFill fill = ChartFill::kSplit);

// The samples per base edge: `n` if > 0, else the mean path length over
// `edge_length`, rounded (at least 1); even (at least 2) when a triangle chart
// is split into three quads (not a strip). Throws std::invalid_argument for an
// odd n > 0 with such a chart.
int ChartSamples(const ChartLayout& layout, int n, double edge_length,
                 ChartFill fill = ChartFill::kSplit);

// The whole path with the figures that judge it (spectral/base_complex_check.cpp).
struct ChartQuadsResult {
  int refinements = 0;  // midpoint splits of the surface the charts needed (layout is on the last)
  ChartLayout layout;
  std::vector<ChartMap> maps;
  QuadExtraction quads;
  int n = 0;
  int flipped = 0;          // parameter triangles of signed area ≤ 0, all charts
  double min_area = 0;      // smallest signed parameter area / its domain's
  std::vector<int> valence;  // per output vertex: edges at it
  // Output vertices of valence ≠ 4 inside or ≠ 3 on the boundary (≠ 4 inside
  // a strip's boundary side), and those the base complex predicts: its inner
  // nodes with ≠ 4 base edges, its boundary nodes with ≠ 3, and the centres
  // of its split triangles (valence 3). Triangle output (kTriangles):
  // valence ≠ 6 inside, ≠ 4 on the boundary, and the nodes with as many
  // base edges.
  std::vector<int> irregular, expected_irregular;
  int strips = 0;              // triangle charts extracted as boundary strips
  int boundary_edges = 0;      // output edges on one face
  int expected_boundary_edges = 0;  // n per boundary base edge
  int non_manifold_edges = 0;  // output edges on more than two faces
  int t_junctions = 0;         // output vertices inside a boundary edge of another face
  double seconds_charts = 0, seconds_parameterisation = 0, seconds_extraction = 0;
};

ChartQuadsResult ChartQuads(const std::vector<Eigen::Vector3d>& points,
                            const std::vector<std::array<int, 3>>& triangles,
                            const BaseComplex& base, int n, double edge_length,
                            ChartWeights weights, ChartFill fill = ChartFill::kSplit);

}  // namespace archgeo
