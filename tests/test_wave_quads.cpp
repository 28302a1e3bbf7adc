// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// `wave_quads` end to end [Gebreiter 2012, §8.3; Zhang et al. 2010]: one test
// per term of the standing wave, each named after it and failing when its
// residuals are zeroed (ARCHGEO_ZERO_TERM, tools/mutation_check.sh), and the
// input checks.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "core/input_error.h"
#include "fields/triangle_surfaces.h"
#include "generators/smoothness_surfaces.h"
#include "io/io.h"
#include "problems/commands/run.h"
#include "problems/declarations/wave_start.h"
#include "problems/runtime/mesh_inputs.h"
#include "problems/runtime/solve.h"
#include "problems/spec/spec.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

// The torus R = 3, r = 1 (60 × 30 principal quads), 3 waves round the tube
// (μ = 2π/3) and 6 round the axis (η = 2π ρ/6): the exact wave cos(3v) cos(6u)
// has 2 · 3 · 6 maxima, as many minima, twice as many saddles, and its
// quasi-dual is a regular torus grid of 4 · 3 · 6 = 72 quads. The terms'
// tests start from random angles at every vertex (wave.start: random): the
// integrated start is already a wave of unit product-form vectors, which
// would hide a term that does nothing.
std::unique_ptr<Solution> WaveTorus(const std::string& start = "random", int restarts = 3) {
  const std::string yaml =
      "problem: wave_quads\n"
      "wave: {wavelength: 2.0943951023931953, wavelength_y: 1.0471975511965976,\n"
      "       size_field_y: axis_distance, curl_correction: off, restarts: " +
      std::to_string(restarts) +
      ", start: " + start + "}\n";
  return Solve(ParseSpec(yaml, "/in-memory/wave.yaml"), TorusPrincipalQuads(3, 1, 60, 30),
               nullptr, {});
}

const double* WaveF(const Solution& s, int v) { return s.store->At("wave_f", v); }

// Every start is solved by LeanSolve's Cholesky steps (wave_quads' default
// solver.back_end), to the wave Ceres' steps reach from the same random
// start: the same steps, but that LeanSolve does not take the last one
// where the next change of E, extrapolated, is below the function
// tolerance (1e-4 of E), so E agrees to about that.
TEST(WaveQuads, StartsAreSolvedByLeanCholeskyStepsToCeresWave) {
  const auto lean = WaveTorus("random", 1);
  const std::string yaml =
      "problem: wave_quads\n"
      "solver: {back_end: ceres}\n"
      "wave: {wavelength: 2.0943951023931953, wavelength_y: 1.0471975511965976,\n"
      "       size_field_y: axis_distance, curl_correction: off, restarts: 1, start: random}\n";
  const auto ceres = Solve(ParseSpec(yaml, "/in-memory/wave.yaml"),
                           TorusPrincipalQuads(3, 1, 60, 30), nullptr, {});
  ASSERT_TRUE(lean->loop.usable && ceres->loop.usable);
  EXPECT_EQ(lean->loop.cholesky_rounds, lean->loop.rounds);
  EXPECT_GT(lean->loop.cholesky_rounds, 0);
  EXPECT_EQ(ceres->loop.cholesky_rounds, 0);
  EXPECT_LE(std::abs(lean->loop.iterations - ceres->loop.iterations), 1);
  const double e_lean = lean->details.at("wave").at("energy").get<double>();
  const double e_ceres = ceres->details.at("wave").at("energy").get<double>();
  std::printf("wave back ends: lean %d iterations E %.8g, ceres %d E %.8g\n",
              lean->loop.iterations, e_lean, ceres->loop.iterations, e_ceres);
  EXPECT_NEAR(e_lean, e_ceres, 1e-3 * e_ceres);
}

TEST(WaveQuads, WaveTransferGivesTheTorusARegularComplex) {
  const auto s = WaveTorus();
  ASSERT_TRUE(s->loop.usable) << s->loop.message;
  const auto& w = s->details.at("wave");
  std::printf("wave torus: E %.4g, max %d min %d saddles %d, valid %d, quasi-dual %d quads, "
              "%d irregular\n",
              w.at("energy").get<double>(), w.at("maxima").get<int>(), w.at("minima").get<int>(),
              w.at("saddles").get<int>(), int(w.at("valid").get<bool>()),
              w.at("quasi_dual").at("quads").get<int>(),
              w.at("quasi_dual").at("irregular_vertices").get<int>());
  EXPECT_EQ(w.at("maxima").get<int>(), 36);
  EXPECT_EQ(w.at("minima").get<int>(), 36);
  EXPECT_EQ(w.at("saddles").get<int>(), 72);
  EXPECT_TRUE(w.at("valid").get<bool>());
  EXPECT_EQ(w.at("quasi_dual").at("quads").get<int>(), 72);
  EXPECT_EQ(w.at("quasi_dual").at("irregular_vertices").get<int>(), 0);
}

// The integrated start (the fields carried along a spanning tree from one
// vertex, problems/declarations/wave_start.h) is the torus's wave up to the
// seams where the tree's paths meet: one start reaches the regular complex
// in a few Levenberg–Marquardt iterations, where a start from random angles
// takes several times as many.
TEST(WaveQuads, IntegratedStartReachesTheWaveInFewIterations) {
  const auto integrated = WaveTorus("integrated", 1);
  const auto random = WaveTorus("random", 1);
  ASSERT_TRUE(integrated->loop.usable && random->loop.usable);
  const auto& w = integrated->details.at("wave");
  std::printf("wave start: integrated %d iterations (E %.4g), random %d (E %.4g)\n",
              integrated->loop.iterations, w.at("energy").get<double>(), random->loop.iterations,
              random->details.at("wave").at("energy").get<double>());
  EXPECT_TRUE(w.at("valid").get<bool>());
  EXPECT_EQ(w.at("maxima").get<int>(), 36);
  EXPECT_EQ(w.at("saddles").get<int>(), 72);
  EXPECT_EQ(w.at("quasi_dual").at("irregular_vertices").get<int>(), 0);
  EXPECT_LE(integrated->loop.iterations, 8);
  EXPECT_LT(3 * integrated->loop.iterations, random->loop.iterations);
}

// |f_i| = 1 (the trivial minimiser f = 0 of the transfer term is excluded).
TEST(WaveQuads, WaveNormKeepsTheVectorsUnit) {
  const auto s = WaveTorus();
  double worst = 0;
  for (int v = 0; v < int(s->input.number_of_vertices()); ++v) {
    const double* f = WaveF(*s, v);
    worst = std::max(worst, std::abs(std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2] +
                                               f[3] * f[3]) - 1));
  }
  std::printf("wave_norm: max ||f| - 1| = %.3g\n", worst);
  EXPECT_LT(worst, 0.05);
}

// f_i = (cos θ, sin θ) ⊗ (cos φ, sin φ): f1 f4 − f2 f3 = 0 relative to |f|².
TEST(WaveQuads, WaveProductKeepsTheProductForm) {
  const auto s = WaveTorus();
  double worst = 0;
  for (int v = 0; v < int(s->input.number_of_vertices()); ++v) {
    const double* f = WaveF(*s, v);
    const double n2 = f[0] * f[0] + f[1] * f[1] + f[2] * f[2] + f[3] * f[3];
    worst = std::max(worst, std::abs(f[0] * f[3] - f[1] * f[2]) / n2);
  }
  std::printf("wave_product: max |f1 f4 - f2 f3| / |f|^2 = %.3g\n", worst);
  EXPECT_LT(worst, 0.02);
}

// A quarter cylinder (radius 2, height 4; its boundary runs along the
// principal directions): every boundary vertex on an iso-line, |sin| ≤ 1e-6.
Mesh WaveCylinderPatch() {
  TriangleGridOptions o;
  o.jitter = 0.1;
  return TriangulatedGrid(30, 30, [](double u, double v) -> Vec3 {
    return {2 * std::cos(u * M_PI / 2), 2 * std::sin(u * M_PI / 2), 4 * v};
  }, o);
}

TEST(WaveQuads, WaveFeatureHoldsOnTheBoundary) {
  const auto s = Solve(ParseSpec("problem: wave_quads\nwave: {wavelength: 1.5}\n",
                                 "/in-memory/wave.yaml"),
                       WaveCylinderPatch(), nullptr, {});
  ASSERT_TRUE(s->loop.usable) << s->loop.message;
  const auto& w = s->details.at("wave");
  std::printf("wave_feature: %d boundary vertices, max |sin| %.3g, doubled complex valid %d\n",
              w.at("feature_vertices").get<int>(), w.at("feature_sin_max").get<double>(),
              int(w.at("valid").get<bool>()));
  EXPECT_EQ(w.at("feature_vertices").get<int>(), 4 * 30);
  EXPECT_LE(w.at("feature_sin_max").get<double>(), 1e-6);
}

// The quad base complex is the problem's goal: a complex that is not a valid
// quad complex in any start (a sphere's wave with every saddle–extremum
// pair cancelled, persistence 2: one maximum, one minimum and a single cell,
// the sphere, not a disc) ends exit 4 naming it, not 0; the torus's own wave
// (WaveTorus's spec) exits 0 with all its starts valid.
TEST(WaveQuads, AnInvalidComplexIsAMissedGoal) {
  const Mesh torus = TorusPrincipalQuads(3, 1, 60, 30);
  const Mesh sphere = TriangulatedEllipsoid(1, 1, 1, 3);
  const std::string own =
      "problem: wave_quads\n"
      "wave: {wavelength: 2.0943951023931953, wavelength_y: 1.0471975511965976,\n"
      "       size_field_y: axis_distance, curl_correction: off, restarts: 3}\n";
  const std::string off = "problem: wave_quads\nwave: {restarts: 2, persistence: 2}\n";
  for (const std::string& yaml : {off, own}) {
    MeshInputs inputs;
    inputs.mesh = yaml == own ? &torus : &sphere;
    const RunResult run = RunSpec(ParseSpec(yaml, "/in-memory/wave.yaml"), {}, inputs);
    const auto& w = run.report.at("details").at("wave");
    const bool valid = w.at("valid").get<bool>();
    EXPECT_EQ(valid, yaml == own) << run.summary;
    EXPECT_EQ(run.exit_code, valid ? 0 : 4) << run.summary;
    EXPECT_EQ(run.report.contains("missed"), !valid);
    EXPECT_EQ(run.summary.find("not a valid quad complex") != std::string::npos, !valid);
    EXPECT_EQ(w.at("valid_starts").get<int>(), valid ? 3 : 0);
    EXPECT_EQ(w.at("kept_start").get<int>() > 0, valid);
  }
}

// The shared inspired mesh (open; the curvature field), start 1: the
// Morse–Smale step places every arc on the double itself (the turns at
// saddle–saddle connections and the local refinement of
// spectral/morse_smale.h), so the double is not refined as a whole.
TEST(WaveQuads, EveryArcIsPlacedOnTheInspiredMesh) {
  const Mesh mesh = ReadMesh(std::string(ARCHGEO_DATA_DIR) + "/libigl_inspired_mesh.obj");
  const auto s = Solve(ParseSpec("problem: wave_quads\nwave: {seed: 1}\n", "/in-memory/wave.yaml"),
                       mesh, nullptr, {});
  ASSERT_TRUE(s->loop.usable) << s->loop.message;
  const auto& w = s->details.at("wave");
  std::printf("inspired mesh, start 1: %d refinements, %d unresolved arcs, %d invalid cells, "
              "%d quads, boundary |sin| %.2g\n",
              w.at("refinements").get<int>(), w.at("unresolved_arcs").get<int>(),
              w.at("invalid_cells").get<int>(), w.at("quasi_dual").at("quads").get<int>(),
              w.at("feature_sin_max").get<double>());
  EXPECT_TRUE(w.at("doubled").get<bool>());
  EXPECT_EQ(w.at("refinements").get<int>(), 0);
  EXPECT_EQ(w.at("unresolved_arcs").get<int>(), 0);
  EXPECT_EQ(w.at("invalid_cells").get<int>(), 0);
  EXPECT_TRUE(w.at("valid").get<bool>());
  EXPECT_EQ(w.at("quasi_dual").at("quads").get<int>(), w.at("saddles").get<int>());
  EXPECT_LE(w.at("feature_sin_max").get<double>(), 1e-6);
}

// The restarts keep the valid complex of lowest E, not the lowest E: a start
// of lower E whose complex is not valid loses to a valid one.
TEST(WaveQuads, RestartsKeepTheValidStartOfLowestEnergy) {
  EXPECT_EQ(KeptWaveStart({false, true, true}, {1.0, 3.0, 2.0}), 3);
  EXPECT_EQ(KeptWaveStart({true, false, true}, {5.0, 1.0, 6.0}), 1);
  EXPECT_EQ(KeptWaveStart({false, false}, {1.0, 2.0}), 0);
}

// wave_quads with output.quads: the torus's wave (3 waves round the tube, 6
// round the axis, as WaveTorus) through the same step gives
// the quasi-dual's 72 quads as 72 n × n charts with no irregular vertex.
TEST(WaveQuads, OutputQuadsIsTheQuadMeshThroughTheCharts) {
  const std::string yaml =
      "problem: wave_quads\n"
      "wave: {wavelength: 2.0943951023931953, wavelength_y: 1.0471975511965976,\n"
      "       size_field_y: axis_distance, curl_correction: off, restarts: 1}\n"
      "charts: {n: 4}\n"
      "output: {quads: /in-memory/quads.obj}\n";
  const auto s = Solve(ParseSpec(yaml, "/in-memory/wave.yaml"), TorusPrincipalQuads(3, 1, 60, 30),
                       nullptr, {});
  ASSERT_TRUE(s->hooks.missed.empty()) << s->hooks.missed;
  const auto& c = s->details.at("charts");
  EXPECT_EQ(c.at("charts").get<int>(), 72);
  EXPECT_EQ(c.at("output_quads").get<int>(), 72 * 16);
  EXPECT_EQ(c.at("irregular_vertices").get<int>(), 0);
  EXPECT_EQ(c.at("flipped_parameter_triangles").get<int>(), 0);
  EXPECT_EQ(c.at("t_junctions").get<int>(), 0);
  EXPECT_LE(c.at("surface_distance_max_relative").get<double>(), 1e-9);
}

// An open surface, the shared inspired mesh (start 1): output.quads is the
// half of the double's quasi-dual on the surface through its charts (triangle
// charts along the boundary as strips); the boundary constraint holds and
// the quad mesh covers the surface without a hole (the chart step checks
// that every surface triangle lies in a chart) and its boundary edges are
// the base complex's boundary sides' samples, no more.
TEST(WaveQuads, OutputQuadsOnAnOpenSurfaceCoversIt) {
  const Mesh mesh = ReadMesh(std::string(ARCHGEO_DATA_DIR) + "/libigl_inspired_mesh.obj");
  const auto s = Solve(ParseSpec("problem: wave_quads\nwave: {seed: 1, restarts: 1}\ncharts: {n: 4}\n"
                                 "output: {quads: /in-memory/quads.obj}\n",
                                 "/in-memory/wave.yaml"),
                       mesh, nullptr, {});
  ASSERT_TRUE(s->hooks.missed.empty()) << s->hooks.missed;
  const auto& w = s->details.at("wave");
  EXPECT_TRUE(w.at("doubled").get<bool>());
  EXPECT_LE(w.at("feature_sin_max").get<double>(), 1e-6);
  const auto& c = s->details.at("charts");
  std::printf("inspired mesh, output.quads: %d charts, %d quads, %d triangles, %d boundary edges\n",
              c.at("charts").get<int>(), c.at("output_quads").get<int>(),
              c.at("output_triangles").get<int>(), c.at("boundary_edges").get<int>());
  EXPECT_GT(c.at("output_quads").get<int>(), 500);
  EXPECT_GT(c.at("boundary_edges").get<int>(), 0);
  EXPECT_EQ(c.at("boundary_edges").get<int>(), c.at("expected_boundary_edges").get<int>());
  EXPECT_TRUE(c.at("irregular_as_predicted").get<bool>());
  EXPECT_EQ(c.at("flipped_parameter_triangles").get<int>(), 0);
  EXPECT_EQ(c.at("t_junctions").get<int>(), 0);
  EXPECT_EQ(c.at("non_manifold_edges").get<int>(), 0);
  EXPECT_LE(c.at("surface_distance_max_relative").get<double>(), 1e-9);
}

TEST(WaveQuads, SizeFieldOnTheAxisIsAnErrorNamingTheKey) {
  // A vertex on the z axis: distance 0, μ = 0.
  const Mesh disc = TriangulatedGrid(6, 6, [](double u, double v) -> Vec3 {
    return {u - 0.5, v - 0.5, 0};
  });
  try {
    Solve(ParseSpec("problem: wave_quads\nwave: {size_field: axis_distance, wavelength: 1}\n",
                    "/in-memory/wave.yaml"),
          disc, nullptr, {});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("wave.size_field"), std::string::npos) << e.what();
  }
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
