// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Charts on open surfaces and the paths' cyclic order
// (spectral/base_complex_charts.h): a flat plate charted by a 2 × 2 quad
// complex is sampled exactly on the grid (cotangent weights reproduce the
// identity on a planar chart); decimated spheres and caps are charted into
// conforming quad meshes whose irregular vertices are the base complex's;
// a complex whose boundary is not the surface's is refused naming the vertex.
#include <gtest/gtest.h>

#include <cmath>

#include "spectral/base_complex_charts.h"
#include "spectral/decimate.h"
#include "tests/closed_meshes.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using V3 = Eigen::Vector3d;
using Triangles = std::vector<std::array<int, 3>>;

// An mx × my grid of vertices (i·h, j·h, 0) (vertex id j·(mx + 1) + i),
// each cell two triangles, counter-clockwise seen from +z.
void OpenPlate(int mx, int my, double h, std::vector<V3>& p, Triangles& t) {
  p.clear();
  t.clear();
  for (int j = 0; j <= my; ++j) {
    for (int i = 0; i <= mx; ++i) p.emplace_back(i * h, j * h, 0);
  }
  auto id = [mx](int i, int j) { return j * (mx + 1) + i; };
  for (int j = 0; j < my; ++j) {
    for (int i = 0; i < mx; ++i) {
      t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
}

// The surface vertex at (x, y) of OpenPlate(32, 16, 0.125): [0, 4] × [0, 2].
int PlateVertex(double x, double y) { return int(std::lround(y * 8)) * 33 + int(std::lround(x * 8)); }

// The unit sphere's triangles whose centroid lies above z = `above`, on
// their own vertices: a cap with one boundary loop.
void OpenCap(double above, std::vector<V3>& p, Triangles& t) {
  std::vector<V3> sphere;
  Triangles all;
  OctahedronSphere(4, sphere, all);
  std::vector<int> index(sphere.size(), -1);
  p.clear();
  t.clear();
  for (const auto& f : all) {
    if ((sphere[f[0]] + sphere[f[1]] + sphere[f[2]]).z() / 3 <= above) continue;
    std::array<int, 3> g{};
    for (int k = 0; k < 3; ++k) {
      if (index[f[k]] < 0) {
        index[f[k]] = int(p.size());
        p.push_back(sphere[f[k]]);
      }
      g[k] = index[f[k]];
    }
    t.push_back(g);
  }
}

// What every charted complex must be: no flipped parameter triangle, the
// irregular vertices the base complex predicts, conforming, every boundary
// edge on a boundary base edge.
void ExpectConforming(const ChartQuadsResult& r, const std::string& what) {
  EXPECT_EQ(r.flipped, 0) << what;
  EXPECT_EQ(r.irregular, r.expected_irregular) << what;
  EXPECT_EQ(r.boundary_edges, r.expected_boundary_edges) << what;
  EXPECT_EQ(r.non_manifold_edges, 0) << what;
  EXPECT_EQ(r.t_junctions, 0) << what;
  EXPECT_EQ(r.quads.unlocated, 0) << what;
}

TEST(OpenCharts, PlateFromTwoByTwoQuadsIsSampledOnTheExactGrid) {
  std::vector<V3> p;
  Triangles t;
  OpenPlate(16, 16, 1.0 / 16, p, t);
  BaseComplex base;
  auto node = [](int i, int j) { return j * 17 + i; };  // surface vertex of grid point (i, j)
  for (int j = 0; j <= 16; j += 8) {
    for (int i = 0; i <= 16; i += 8) base.nodes.push_back(node(i, j));
  }
  auto b = [](int i, int j) { return j * 3 + i; };
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i) base.faces.push_back({b(i, j), b(i + 1, j), b(i + 1, j + 1), b(i, j + 1)});
  }
  const ChartQuadsResult r = ChartQuads(p, t, base, 4, 0, ChartWeights::kCotangent);
  ExpectConforming(r, "plate");
  EXPECT_EQ(r.refinements, 0);
  EXPECT_EQ(r.quads.quads.size(), 4u * 16);
  EXPECT_EQ(r.expected_boundary_edges, 8 * 4);  // eight boundary base edges, n = 4 each
  // Irregular: the four corners (valence 2); the boundary midpoints keep 3, the centre 4.
  ASSERT_EQ(r.irregular.size(), 4u);
  for (int v : r.irregular) EXPECT_EQ(r.valence[v], 2);
  for (const V3& x : r.quads.points) {
    EXPECT_NEAR(x.x() * 8, std::round(x.x() * 8), 1e-10) << x.transpose();
    EXPECT_NEAR(x.y() * 8, std::round(x.y() * 8), 1e-10) << x.transpose();
    EXPECT_EQ(x.z(), 0);
  }
}

// The surface decimated to `target` vertices, charted with n = 4.
ChartQuadsResult ChartDecimated(const std::vector<V3>& p, const Triangles& t, int target) {
  DecimateOptions options;
  options.target_vertices = target;
  const DecimateResult d = Decimate(p, t, options);
  EXPECT_TRUE(d.reached) << target;
  const ChartQuadsResult r = ChartQuads(p, t, d.Complex(), 4, 0, ChartWeights::kCotangent);
  ExpectConforming(r, "decimated to " + std::to_string(target));
  return r;
}

TEST(OpenCharts, DecimatedCapGivesAConformingQuadMesh) {
  std::vector<V3> p;
  Triangles t;
  OpenCap(0.3, p, t);
  for (int target : {15, 30, 60}) {
    const ChartQuadsResult r = ChartDecimated(p, t, target);
    EXPECT_GT(r.expected_boundary_edges, 0);
    for (const V3& x : r.quads.points) EXPECT_NEAR(x.norm(), 1, 0.05);  // on the faceted sphere
  }
}

// A decimated complex's nodes keep about their surface valence, so their
// paths need nearly every surface edge at them: without the split of the
// surface these spheres' complexes find no room for their paths.
TEST(ChartPaths, DecimatedSpheresAreChartedOnTheSplitSurface) {
  std::vector<V3> p;
  Triangles t;
  OctahedronSphere(4, p, t);
  int refined = 0;
  for (int target : {9, 12, 20, 30, 40}) {
    const ChartQuadsResult r = ChartDecimated(p, t, target);
    EXPECT_EQ(r.boundary_edges, 0);
    refined += r.refinements > 0;
    for (const V3& x : r.quads.points) EXPECT_NEAR(x.norm(), 1, 0.02);
  }
  EXPECT_GT(refined, 0);  // the split of the surface is exercised
}

// Base edge C–B must pass above node D (the complex's cyclic order at C and
// B says so), though the way below A is far shorter: on the plate
// [0, 4] × [0, 2] with C (1, 1), A (2, 1), D (2, 1.75), B (3, 0.5) and the
// corners, face (C, D, B) is the sliver between C–D–B and the path of C–B
// above D. The short way below A would shut A off from the corner (0, 0),
// whose paths run later: the sectors at the nodes, or the re-placement of
// the edge it bars, keep it out.
TEST(ChartPaths, APathRunsOnTheSideOfANodeTheComplexSays) {
  std::vector<V3> p;
  Triangles t;
  OpenPlate(32, 16, 0.125, p, t);
  const auto at = PlateVertex;
  BaseComplex base;
  base.nodes = {at(0, 0), at(4, 0), at(4, 2), at(0, 2), at(1, 1), at(2, 1), at(3, 0.5), at(2, 1.75)};
  enum { P0, P1, P2, P3, C, A, B, D };
  base.faces = {{C, D, B}, {C, A, D}, {A, B, D}, {P0, A, C}, {P0, B, A},
                {P0, P1, B}, {P1, P2, B}, {C, B, P2}, {C, P2, P3}, {P0, C, P3}};
  const ChartQuadsResult r = ChartQuads(p, t, base, 4, 0, ChartWeights::kCotangent);
  ExpectConforming(r, "plate with a sliver");
  EXPECT_GT(r.refinements, 0);  // the corners' three surface edges are too few for their paths
  // The path of C–B runs above D: a detour of about 1.1 over the way below A.
  for (const BaseEdgePath& e : r.layout.edges) {
    if (e.a == C && e.b == B) {
      EXPECT_GT(e.length, 3.4);
    }
  }
}

// Thesis §4.1.4: a triangle chart of a quad complex with one side on the
// open boundary is quads lined up with its two inner sides and triangles
// along the boundary. The plate [0, 4] × [0, 2] with four quads round the
// interior node A (2, 1) and the triangle L (1, 0), R (3, 0), A between them.
TEST(OpenCharts, BoundaryTriangleOfAQuadComplexIsAStripOfQuadsAndBoundaryTriangles) {
  std::vector<V3> p;
  Triangles t;
  OpenPlate(32, 16, 0.125, p, t);
  const auto at = PlateVertex;
  BaseComplex base;
  base.nodes = {at(0, 0), at(1, 0), at(3, 0), at(4, 0), at(4, 1), at(4, 2), at(2, 2), at(0, 2),
                at(0, 1), at(2, 1)};
  enum { C0, L, R, C1, E, C2, M, C3, W, A };
  base.faces = {{C0, L, A, W}, {R, C1, E, A}, {L, R, A}, {W, A, M, C3}, {A, E, C2, M}};
  const int n = 4;
  const ChartQuadsResult split = ChartQuads(p, t, base, n, 0, ChartWeights::kCotangent, ChartFill::kSplit);
  const ChartQuadsResult strip = ChartQuads(p, t, base, n, 0, ChartWeights::kCotangent, ChartFill::kStrip);
  ExpectConforming(split, "split");
  ExpectConforming(strip, "strip");
  EXPECT_EQ(split.strips, 0);
  EXPECT_EQ(strip.strips, 1);
  EXPECT_TRUE(split.quads.triangles.empty());
  EXPECT_EQ(split.quads.quads.size(), 4u * n * n + 3 * (n / 2) * (n / 2));
  // The strip: (n − 1) n / 2 quads, n triangles, no centre vertex.
  EXPECT_EQ(strip.quads.quads.size(), 4u * n * n + (n - 1) * n / 2);
  ASSERT_EQ(strip.quads.triangles.size(), size_t(n));
  EXPECT_EQ(strip.irregular.size() + 1, split.irregular.size());  // the split's valence-3 centre
  EXPECT_EQ(strip.quads.strip_boundary_vertex.size(), size_t(n - 1));
  for (int v : strip.quads.strip_boundary_vertex) EXPECT_EQ(strip.valence[v], 4);
  // Each triangle has its boundary edge on y = 0, between L and R, at spacing 2 / n.
  for (const auto& tri : strip.quads.triangles) {
    const V3 &a = strip.quads.points[tri[1]], &b = strip.quads.points[tri[2]];
    EXPECT_NEAR(a.y(), 0, 1e-12);
    EXPECT_NEAR(b.y(), 0, 1e-12);
    EXPECT_NEAR(std::abs(a.x() - b.x()), 2.0 / n, 1e-12);
    EXPECT_GE(std::min(a.x(), b.x()), 1 - 1e-12);
    EXPECT_LE(std::max(a.x(), b.x()), 3 + 1e-12);
  }
  for (const V3& x : strip.quads.points) EXPECT_EQ(x.z(), 0);
  // An odd n: the strip needs no even n (the split would).
  EXPECT_EQ(ChartQuads(p, t, base, 3, 0, ChartWeights::kCotangent, ChartFill::kStrip).quads.triangles.size(), 3u);
  EXPECT_THROW(ChartQuads(p, t, base, 3, 0, ChartWeights::kCotangent, ChartFill::kSplit), std::invalid_argument);
}

TEST(OpenCharts, ABaseBoundaryOffTheSurfaceBoundaryIsRefusedNamingTheVertex) {
  std::vector<V3> p;
  Triangles t;
  OpenPlate(8, 8, 1.0 / 8, p, t);
  BaseComplex base;
  // One quad whose corner 2 is inside the plate: its edges 1-2 and 2-3 are
  // on one face only but vertex 2 is not on the surface boundary.
  base.nodes = {0, 8, 4 * 9 + 4, 8 * 9};
  base.faces = {{0, 1, 2, 3}};
  try {
    BuildChartLayout(p, t, base);
    ADD_FAILURE() << "no error";
  } catch (const BaseComplexError& e) {
    EXPECT_EQ(e.element(), "base vertex 2") << e.what();
  }
  // The plate as two triangles.
  base.nodes = {0, 8, 8 * 9 + 8, 8 * 9};
  base.faces = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_EQ(BuildChartLayout(p, t, base).charts.size(), 2u);
  // A closed fan around base vertex 0 (surface vertex 4, on the plate's
  // boundary): inside the complex, on the surface boundary.
  base.nodes = {4, 8, 8 * 9 + 8, 8 * 9};
  base.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}};
  try {
    BuildChartLayout(p, t, base);
    ADD_FAILURE() << "no error";
  } catch (const BaseComplexError& e) {
    EXPECT_EQ(e.element(), "base vertex 0") << e.what();
  }
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
