// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// mesh/subdivision: the multiresolution step [Pellis 2019, §6]. Loop and
// Catmull–Clark keep the old vertices' indices (run.cpp relies on it to keep
// `fixed` vertex ids through the levels), counts follow the schemes' rules,
// and the refined mesh stays close to the coarse one.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "generators/generators.h"
#include "io/io.h"
#include "generators/smoothness_surfaces.h"
#include "mesh/subdivision.h"
#include "mesh/topology.h"
#include "core/input_error.h"
#include "problems/commands/run.h"
#include "problems/spec/spec.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

Vec3 Flat(double u, double v) { return {2 * u, 1.5 * v, 0.0}; }

TEST(Subdivision, LoopKeepsIndicesAndQuadruplesTriangles) {
  const Mesh coarse = RevolutionTriangles(RevolutionProfile{}, 12, 4);
  ASSERT_TRUE(CanSubdivide(coarse, "loop"));
  const Mesh fine = Subdivide(coarse, "loop");
  EXPECT_EQ(fine.number_of_faces(), 4 * coarse.number_of_faces());
  EXPECT_EQ(fine.number_of_vertices(), coarse.number_of_vertices() + coarse.number_of_edges());
  // Old vertex i is still vertex i: repositioned by the Loop mask, so close.
  const double h = 2 * M_PI * 0.5 / 12;  // roughly the shortest edge
  for (VertexIndex v : coarse.vertices()) {
    const Point& a = coarse.point(v);
    const Point& b = fine.point(VertexIndex(v.idx()));
    EXPECT_LT(std::sqrt(CGAL::squared_distance(a, b)), 0.5 * h) << v.idx();
  }
  // Boundary vertices stay boundary vertices.
  const std::vector<bool> before = BoundaryVertices(coarse), after = BoundaryVertices(fine);
  for (size_t i = 0; i < before.size(); ++i) EXPECT_EQ(before[i], after[i]) << i;
}

TEST(Subdivision, CatmullClarkKeepsIndicesOnAFlatGrid) {
  const Mesh coarse = QuadGrid(4, 3, Flat);
  EXPECT_FALSE(CanSubdivide(coarse, "loop"));
  ASSERT_TRUE(CanSubdivide(coarse, "catmull_clark"));
  const Mesh fine = Subdivide(coarse, "catmull_clark");
  EXPECT_EQ(fine.number_of_faces(), 4 * coarse.number_of_faces());
  EXPECT_EQ(fine.number_of_vertices(), coarse.number_of_vertices() + coarse.number_of_edges() +
                                           coarse.number_of_faces());
  // An interior vertex of a regular flat grid is a fixed point of the mask.
  const VertexIndex interior(1 * 5 + 1);
  EXPECT_NEAR(fine.point(interior).x(), coarse.point(interior).x(), 1e-12);
  EXPECT_NEAR(fine.point(interior).y(), coarse.point(interior).y(), 1e-12);
  for (VertexIndex v : fine.vertices()) EXPECT_NEAR(fine.point(v).z(), 0.0, 1e-12);
}

TEST(Subdivision, Sqrt3AndDooSabinRefine) {
  const Mesh tri = RevolutionTriangles(RevolutionProfile{}, 8, 3);
  EXPECT_EQ(Subdivide(tri, "sqrt3").number_of_faces(), 3 * tri.number_of_faces());
  const Mesh quads = QuadGrid(3, 3, Flat);
  EXPECT_GT(Subdivide(quads, "doo_sabin").number_of_faces(), quads.number_of_faces());
}

using MultiresolutionTest = ScratchDirTest;

// One YAML pipeline: solve, Loop-subdivide, solve again; the fixed boundary
// circles stay fixed on the finer level, and the report logs both levels.
TEST_F(MultiresolutionTest, SolvesSubdividesAndSolvesAgain) {
  const Mesh start = RevolutionTriangles(RevolutionProfile{}, 16, 4);
  WriteMesh(Path("start.obj"), start);
  const ProblemSpec spec = ReadSpec(WriteFile("spec.yaml",
                                              "mesh: start.obj\n"
                                              "problem: total_absolute_curvature\n"
                                              "fixed: boundary\n"
                                              "multiresolution: {levels: 1, scheme: loop}\n"
                                              "solver: {max_num_iterations: 10}\nschedule: {outer_iterations: 3}\n"
                                              "output: {mesh: out.obj}\n"));
  const RunResult run = RunSpec(spec, {});
  ASSERT_EQ(run.exit_code, 0) << run.summary;
  const auto& levels = run.report["multiresolution"]["levels"];
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_EQ(levels[0]["vertices"].get<int>(), int(start.number_of_vertices()));
  EXPECT_EQ(levels[1]["vertices"].get<int>(),
            int(start.number_of_vertices() + start.number_of_edges()));
  const Mesh out = ReadMesh(Path("out.obj"));
  EXPECT_EQ(out.number_of_faces(), 4 * start.number_of_faces());
  // The boundary circles (radius 1 at z = 0, 0.5 at z = 1) are fixed on both
  // levels: the old boundary vertices (same ids after Loop) keep their
  // positions although Loop's boundary mask would pull them inwards.
  for (VertexIndex v : start.vertices()) {
    if (!BoundaryVertices(start)[v.idx()]) continue;
    const Point& p = out.point(v);
    const double rho = std::hypot(p.x(), p.y());
    EXPECT_NEAR(rho, p.z() < 0.5 ? 1.0 : 0.5, 1e-12) << v.idx();
  }
}

// A vertex on no face has no subdivision rule: with multiresolution it is
// bad input naming the key and the vertex, for every quad scheme (Doo–Sabin
// crashed on it, Catmull–Clark ended exit 3; issue 48, item 2).
TEST_F(MultiresolutionTest, AVertexOnNoFaceIsBadInput) {
  std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0.1\nv 0 1 0\nv 5 5 5\nf 1 2 3 4\n";
  WriteFile("iso.obj", obj);
  for (const char* scheme : {"catmull_clark", "doo_sabin"}) {
    SCOPED_TRACE(scheme);
    try {
      RunSpec(ReadSpec(WriteFile("spec.yaml", std::string("mesh: iso.obj\n"
                                                          "multiresolution: {levels: 1, scheme: ") +
                                                  scheme + "}\noutput: {mesh: out.obj}\n")),
              {});
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "multiresolution.levels");
      EXPECT_NE(e.message().find("vertex 4"), std::string::npos) << e.message();
    }
    EXPECT_FALSE(std::filesystem::exists(Path("out.obj")));
  }
}

}  // namespace
}  // namespace archgeo
