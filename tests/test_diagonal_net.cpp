// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Diagonal nets (geometry/diagonal_net.h): combinatorics and orientation on a
// grid, the exact A-net among the diagonals of a hyperbolic paraboloid
// sampled along its principal-like directions, the two nets of the negshell
// A-net of ../shared/data (holes at its valence-6 vertices), and the errors.
#include <gtest/gtest.h>

#include <set>

#include "geometry/diagonal_net.h"
#include "generators/generators.h"
#include "geometry/hnet.h"
#include "core/input_error.h"
#include "io/io.h"
#include "mesh/topology.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

constexpr double kExact = 1e-12;

double InteriorStarPlanarityMax(const Mesh& mesh) { return InteriorStarPlanarity(mesh).max; }

// z = xy sampled on the grid x = u + v, y = u − v: the mesh's edges bisect
// the rulings, its face diagonals run along them.
Mesh RotatedHyperbolicParaboloid(int n) {
  return QuadGrid(n, n, [](double u, double v) -> Vec3 {
    const double x = u + v - 1, y = u - v;
    return {x, y, x * y};
  });
}

TEST(DiagonalNet, GridCombinatoricsAndOrientation) {
  const int n = 6;  // 7 × 7 vertices, vertex (i, j) has index 7j + i, colour (i + j) % 2
  const Mesh grid = QuadGrid(n, n, [](double u, double v) -> Vec3 { return {u, v, 0}; });
  const std::vector<int> colour = TwoColouring(grid);
  for (int c = 0; c < 2; ++c) {
    const DiagonalNet net = MakeDiagonalNet(grid, c);
    // One face per interior vertex of the other colour.
    int rings = 0;
    for (int j = 1; j < n; ++j) {
      for (int i = 1; i < n; ++i) rings += colour[j * (n + 1) + i] != c;
    }
    EXPECT_EQ(int(net.mesh.number_of_faces()), rings);
    EXPECT_EQ(net.holes, 0);
    ASSERT_EQ(net.source.size(), net.mesh.number_of_vertices());
    for (size_t k = 0; k < net.source.size(); ++k) {
      EXPECT_EQ(colour[net.source[k]], c);
      if (k > 0) {
        EXPECT_LT(net.source[k - 1], net.source[k]);
      }
      EXPECT_EQ(net.mesh.point(VertexIndex(k)), grid.point(VertexIndex(net.source[k])));
    }
    for (FaceIndex f : net.mesh.faces()) {
      ASSERT_EQ(net.mesh.degree(f), 4u);
      std::vector<Point> p;
      for (VertexIndex v : net.mesh.vertices_around_face(net.mesh.halfedge(f))) {
        p.push_back(net.mesh.point(v));
      }
      // Oriented like the grid (normal +z) and a square rotated by 45°.
      EXPECT_GT(CGAL::cross_product(p[1] - p[0], p[2] - p[1]).z(), 0);
      const double side = 1.0 / n * std::sqrt(2.0);
      for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(std::sqrt(CGAL::squared_distance(p[k], p[(k + 1) % 4])), side, kExact);
      }
    }
  }
}

TEST(DiagonalNet, HyperbolicParaboloidRulingsAreTheDiagonalNet) {
  const Mesh mesh = RotatedHyperbolicParaboloid(8);
  EXPECT_GT(InteriorStarPlanarityMax(mesh), 1e-2);
  for (int c = 0; c < 2; ++c) {
    const DiagonalNet net = MakeDiagonalNet(mesh, c);
    EXPECT_LE(InteriorStarPlanarityMax(net.mesh), kExact) << "colour " << c;
  }
}

TEST(DiagonalNet, NegshellNetsHaveHolesOnlyAtTheOtherColoursSixValentVertices) {
  const Mesh shell = ReadMesh(ARCHGEO_DATA_DIR "/dos_free_negshell_marc_anet.obj");
  const std::vector<int> colour = TwoColouring(shell);
  const std::vector<bool> boundary = BoundaryVertices(shell);
  int six[2] = {0, 0};
  for (VertexIndex v : shell.vertices()) {
    if (!boundary[v.idx()] && shell.degree(v) == 6) ++six[colour[v.idx()]];
  }
  EXPECT_EQ(six[0] + six[1], 9);
  for (int c = 0; c < 2; ++c) {
    const DiagonalNet net = MakeDiagonalNet(shell, c);
    EXPECT_EQ(net.holes, six[1 - c]) << "colour " << c;
  }
  // The colour with the six-valent vertices keeps them (0 holes); the other
  // colour's net is the flatter one (≤ 1e-5) but has the 9 holes.
  const DiagonalNet with = MakeDiagonalNet(shell, six[0] > 0 ? 0 : 1);
  const DiagonalNet without = MakeDiagonalNet(shell, six[0] > 0 ? 1 : 0);
  EXPECT_EQ(with.holes, 0);
  EXPECT_EQ(without.holes, 9);
  EXPECT_LE(InteriorStarPlanarityMax(without.mesh), 1e-5);
  EXPECT_GT(InteriorStarPlanarityMax(shell), 0.1);
}

TEST(DiagonalNet, OddCycleHasNoDiagonalNet) {
  // A band of three quads around a loop: its circumferences are 3-cycles.
  Mesh band;
  std::vector<VertexIndex> v;
  for (int i = 0; i < 6; ++i) {
    const double a = 2 * M_PI * (i % 3) / 3;
    v.push_back(band.add_vertex(Point(std::cos(a), std::sin(a), i < 3 ? 0 : 1)));
  }
  for (int i = 0; i < 3; ++i) {
    ASSERT_NE(band.add_face(v[i], v[(i + 1) % 3], v[3 + (i + 1) % 3], v[3 + i]), Mesh::null_face());
  }
  try {
    MakeDiagonalNet(band, 0);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "mesh");
    EXPECT_NE(e.message().find("odd cycle"), std::string::npos) << e.what();
  }
}

TEST(DiagonalNet, StripWithoutInteriorVerticesHasNoFace) {
  const Mesh strip = QuadGrid(4, 1, [](double u, double v) -> Vec3 { return {u, v, 0}; });
  EXPECT_THROW(MakeDiagonalNet(strip, 0), InputError);
}

}  // namespace
}  // namespace archgeo
