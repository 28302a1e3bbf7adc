// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// `spectral_quads` end to end [Gebreiter 2012, §6, §7, §4.1]: an
// eigenfunction's Morse–Smale complex, its quasi-dual as the base complex,
// the charts and the all-quad mesh; the input checks.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "core/input_error.h"
#include "fields/triangle_surfaces.h"
#include "generators/smoothness_surfaces.h"
#include "io/io.h"
#include "problems/commands/run.h"
#include "problems/runtime/mesh_inputs.h"
#include "problems/spec/spec.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

RunResult SqRun(const std::string& yaml, const Mesh& mesh) {
  MeshInputs inputs;
  inputs.mesh = &mesh;
  return RunSpec(ParseSpec(yaml, "/in-memory/spectral.yaml"), {}, inputs);
}

// A conforming all-quad mesh on the input whose irregular vertices are the
// quasi-dual's nodes of valence ≠ 4 (`irregular`).
void SqExpectQuads(const RunResult& run, int irregular) {
  ASSERT_EQ(run.exit_code, 0) << run.summary;
  const auto& c = run.report.at("details").at("charts");
  EXPECT_GT(c.at("output_quads").get<int>(), 0);
  EXPECT_EQ(c.at("irregular_vertices").get<int>(), irregular);
  EXPECT_TRUE(c.at("irregular_as_predicted").get<bool>());
  EXPECT_EQ(c.at("flipped_parameter_triangles").get<int>(), 0);
  EXPECT_EQ(c.at("t_junctions").get<int>(), 0);
  EXPECT_EQ(c.at("boundary_edges").get<int>(), 0);
  EXPECT_EQ(c.at("non_manifold_edges").get<int>(), 0);
  EXPECT_LE(c.at("surface_distance_max_relative").get<double>(), 1e-9);
}

// Eigenfunction 9 of a 642-vertex icosphere (the first of l = 3, eigenvalue
// ≈ 12; Gebreiter's "10th" counting the constant as the first): the
// quad mesh's irregular vertices are exactly the quasi-dual's nodes of
// valence ≠ 4, V − E + F = 2 on the quasi-dual and max + min − saddles = 2.
TEST(SpectralQuads, SphereEigenfunctionGivesAnAllQuadMesh) {
  const RunResult run = SqRun("problem: spectral_quads\nspectral: {eigenfunction: 9}\n",
                              TriangulatedEllipsoid(1, 1, 1, 3));
  const auto& sp = run.report.at("details").at("spectral");
  const auto& dual = sp.at("complex").at("quasi_dual");
  std::printf("sphere k = 9: eigenvalue %.4f, max %d min %d saddles %d; quasi-dual %d quads, "
              "%d irregular; output %d quads, %d irregular\n",
              sp.at("eigenvalue").get<double>(), sp.at("complex").at("maxima").get<int>(),
              sp.at("complex").at("minima").get<int>(), sp.at("complex").at("saddles").get<int>(),
              dual.at("quads").get<int>(), dual.at("irregular_vertices").get<int>(),
              run.report.at("details").at("charts").at("output_quads").get<int>(),
              run.report.at("details").at("charts").at("irregular_vertices").get<int>());
  EXPECT_EQ(sp.at("eigenfunction").get<int>(), 9);
  EXPECT_NEAR(sp.at("eigenvalue").get<double>(), 12, 0.2);  // l(l + 1), l = 3
  EXPECT_EQ(sp.at("complex").at("euler_sum").get<int>(), 2);
  EXPECT_EQ(dual.at("euler").get<int>(), 2);
  EXPECT_GT(dual.at("irregular_vertices").get<int>(), 0);
  SqExpectQuads(run, dual.at("irregular_vertices").get<int>());
}

// An open surface (the shared libigl inspired mesh, a disc): the complex of
// its double across the boundary, the half of its quasi-dual on the input
// as base complex (boundary saddles' quads cut into triangles along the
// boundary), charted on the input: a conforming quad mesh whose boundary
// edges are the base complex's boundary sampled, irregular vertices as the
// base complex predicts.
TEST(SpectralQuads, AnOpenSurfaceIsChartedFromTheComplexOfItsDouble) {
  const RunResult run = SqRun("problem: spectral_quads\nspectral: {charts: 24}\n",
                              ReadMesh(ARCHGEO_DATA_DIR "/libigl_inspired_mesh.obj"));
  ASSERT_EQ(run.exit_code, 0) << run.summary;
  const auto& sp = run.report.at("details").at("spectral");
  EXPECT_TRUE(sp.at("doubled").get<bool>());
  EXPECT_EQ(sp.at("complex").at("euler_sum").get<int>(), 2);  // the double: a sphere
  const auto& c = run.report.at("details").at("charts");
  std::printf("inspired mesh: eigenfunction %d, %d charts, %d quads, %d triangles, %d irregular\n",
              sp.at("eigenfunction").get<int>(), c.at("charts").get<int>(),
              c.at("output_quads").get<int>(), c.at("output_triangles").get<int>(),
              c.at("irregular_vertices").get<int>());
  EXPECT_GT(c.at("output_quads").get<int>(), 500);
  EXPECT_TRUE(c.at("irregular_as_predicted").get<bool>());
  EXPECT_EQ(c.at("flipped_parameter_triangles").get<int>(), 0);
  EXPECT_EQ(c.at("t_junctions").get<int>(), 0);
  EXPECT_EQ(c.at("non_manifold_edges").get<int>(), 0);
  EXPECT_GT(c.at("boundary_edges").get<int>(), 0);
  EXPECT_EQ(c.at("boundary_edges").get<int>(), c.at("expected_boundary_edges").get<int>());
  EXPECT_LE(c.at("surface_distance_max_relative").get<double>(), 1e-9);
}

// The shared Concerthall roof (open): the two candidates nearest 24 charts
// (k = 44, 48) give quad meshes with panels that cannot be built (a corner
// bent inward, faces that intersect); the automatic choice goes on to the
// third, k = 45, whose mesh passes every check.
TEST(SpectralQuads, TheAutomaticChoiceGoesOnPastQuadMeshesThatCannotBeBuilt) {
  const RunResult run = SqRun("problem: spectral_quads\nspectral: {charts: 24}\n",
                              ReadMesh(ARCHGEO_DATA_DIR "/directional_Concerthall.off"));
  ASSERT_EQ(run.exit_code, 0) << run.summary;
  const auto& tried = run.report.at("details").at("spectral").at("tried");
  ASSERT_GE(tried.size(), 2u);
  for (size_t i = 0; i + 1 < tried.size(); ++i) {
    EXPECT_EQ(tried[i].at("fault").get<std::string>().rfind("its quad mesh has panels that cannot be built", 0), 0u);
  }
  EXPECT_TRUE(tried.back().at("fault").get<std::string>().empty());
  EXPECT_EQ(run.report.at("details").at("spectral").at("eigenfunction").get<int>(), 45);
  EXPECT_TRUE(run.report.at("details").at("charts").at("irregular_as_predicted").get<bool>());
}

// The torus (48 × 24 quads, triangulated by the problem): the automatic choice's complex has only
// valence-4 extrema, so the quad mesh has no irregular vertex (χ = 0).
TEST(SpectralQuads, TorusGivesNoIrregularVertex) {
  const RunResult run = SqRun("problem: spectral_quads\nspectral: {charts: 16}\n",
                              TorusPrincipalQuads(3, 1, 48, 24));
  const auto& sp = run.report.at("details").at("spectral");
  std::printf("torus: eigenfunction %d, %d quasi-dual quads\n", sp.at("eigenfunction").get<int>(),
              sp.at("complex").at("quasi_dual").at("quads").get<int>());
  EXPECT_EQ(sp.at("complex").at("quasi_dual").at("irregular_vertices").get<int>(), 0);
  SqExpectQuads(run, 0);
  // The grid lines kink where they cross the charts' boundaries as mapped;
  // charts.smoothing (default 20 sweeps) straightens them (docs/methods/charts.md).
  const auto& kink = run.report.at("details").at("charts").at("grid_line_kink_max_degrees");
  std::printf("grid lines turn at most %.1f° as mapped, %.1f° in the output\n",
              kink.at("mapped").get<double>(), kink.at("output").get<double>());
  EXPECT_LT(kink.at("output").get<double>(), 0.5 * kink.at("mapped").get<double>());
}

// Eigenfunction 13 of a 90 × 30 torus, a wave round the tube: its complex
// is valid, but its saddles send two arcs to one extremum, so the
// quasi-dual's quads repeat a corner; the complex's own cells (max, saddle,
// min, saddle, four distinct corners) are charted instead, and the quad
// mesh's irregular vertices are their nodes of valence ≠ 4. Without that
// the run ends with exit 4.
TEST(SpectralQuads, TorusWaveRoundTheTubeIsChartedOnTheComplexItself) {
  const RunResult run = SqRun("problem: spectral_quads\nspectral: {eigenfunction: 13}\n",
                              TorusPrincipalQuads(3, 1, 90, 30));
  const auto& sp = run.report.at("details").at("spectral");
  const auto& complex = sp.at("complex");
  EXPECT_TRUE(complex.at("valid").get<bool>());
  EXPECT_EQ(complex.at("euler_sum").get<int>(), 0);
  EXPECT_GT(complex.at("quasi_dual").at("degenerate_quads").get<int>(), 0);
  EXPECT_EQ(sp.at("base").get<std::string>(), "complex");
  EXPECT_EQ(sp.at("base_quads").get<int>(), complex.at("cells").get<int>());
  std::printf("torus k = 13: %d cells charted, %d irregular vertices\n",
              sp.at("base_quads").get<int>(), sp.at("base_irregular_vertices").get<int>());
  SqExpectQuads(run, sp.at("base_irregular_vertices").get<int>());
}

// Eigenfunction 22 of the 2,562-vertex icosphere: a base edge leaves a
// valence-3 node nearly straight on from its neighbour, and the panel in
// that corner folds (34° bent inward) unless the relaxation turns the
// node's spokes towards 120° apart (spectral/quad_relax.h): then every
// panel is convex within validity's 10° and the run exits 0.
TEST(SpectralQuads, SpokesOfAnIrregularNodeAreTurnedApartSoNoPanelFolds) {
  const RunResult run = SqRun("problem: spectral_quads\nspectral: {eigenfunction: 22}\n",
                              TriangulatedEllipsoid(1, 1, 1, 4));
  SqExpectQuads(run, run.report.at("details").at("spectral").at("complex").at("quasi_dual")
                         .at("irregular_vertices").get<int>());
}

// Eigenfunction 25 of the 2,562-vertex icosphere: after the relaxation four
// panels beside valence-3 nodes still have a corner bent inward (up to
// 13°: the node's base edges leave it unevenly); unfolding them
// (spectral/quad_untangle.h) leaves none, and the run exits 0.
TEST(SpectralQuads, PanelsFoldedAtANodeAreUnfolded) {
  const RunResult run = SqRun("problem: spectral_quads\nspectral: {eigenfunction: 25}\n",
                              TriangulatedEllipsoid(1, 1, 1, 4));
  const auto& bent = run.report.at("details").at("charts").at("bent_quads");
  std::printf("sphere k = 25: %d quads bent after the relaxation, %d after unfolding\n",
              bent.at("relaxed").get<int>(), bent.at("untangled").get<int>());
  EXPECT_GT(bent.at("relaxed").get<int>(), 0);
  EXPECT_EQ(bent.at("untangled").get<int>(), 0);
  SqExpectQuads(run, run.report.at("details").at("spectral").at("complex").at("quasi_dual")
                         .at("irregular_vertices").get<int>());
}

TEST(SpectralQuads, EigenfunctionBeyondTheVerticesIsAnErrorNamingTheKey) {
  const Mesh sphere = TriangulatedEllipsoid(1, 1, 1, 1);  // 42 vertices
  try {
    SqRun("problem: spectral_quads\nspectral: {eigenfunction: 42}\n", sphere);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("spectral.eigenfunction"), std::string::npos) << e.what();
  }
}

// The quasi-dual is all quads: triangle output is refused before anything
// runs, naming the key (an exit-4 "missed goal" after the solve otherwise).
TEST(SpectralQuads, TriangleOutputIsAnErrorNamingTheKey) {
  const Mesh sphere = TriangulatedEllipsoid(1, 1, 1, 1);
  try {
    SqRun("problem: spectral_quads\nspectral: {eigenfunction: 9}\ncharts: {output: triangles}\n", sphere);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("charts.output"), std::string::npos) << e.what();
  }
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
