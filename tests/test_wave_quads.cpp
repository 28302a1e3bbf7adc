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
#include "problems/commands/run.h"
#include "problems/runtime/mesh_inputs.h"
#include "problems/runtime/solve.h"
#include "problems/spec/spec.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

// The torus R = 3, r = 1 (60 × 30 principal quads), 3 waves round the tube
// (μ = 2π/3) and 6 round the axis (η = 2π ρ/6): the exact wave cos(3v) cos(6u)
// has 2 · 3 · 6 maxima, as many minima, twice as many saddles, and its
// quasi-dual is a regular torus grid of 4 · 3 · 6 = 72 quads.
std::unique_ptr<Solution> WaveTorus() {
  const std::string yaml =
      "problem: wave_quads\n"
      "wave: {wavelength: 2.0943951023931953, wavelength_y: 1.0471975511965976,\n"
      "       size_field_y: axis_distance, restarts: 3}\n";
  return Solve(ParseSpec(yaml, "/in-memory/wave.yaml"), TorusPrincipalQuads(3, 1, 60, 30),
               nullptr, {});
}

const double* WaveF(const Solution& s, int v) { return s.store->At("wave_f", v); }

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

// The quad base complex is the problem's goal: a wave whose complex is not a
// valid quad complex (one start, a wavelength the torus's circles do not
// hold a whole number of: 139 invalid cells) ends exit 4 naming it, not 0;
// the torus's own wave (WaveTorus's spec) exits 0.
TEST(WaveQuads, AnInvalidComplexIsAMissedGoal) {
  const Mesh torus = TorusPrincipalQuads(3, 1, 60, 30);
  MeshInputs inputs;
  inputs.mesh = &torus;
  const std::string own =
      "problem: wave_quads\n"
      "wave: {wavelength: 2.0943951023931953, wavelength_y: 1.0471975511965976,\n"
      "       size_field_y: axis_distance, restarts: 3}\n";
  const std::string off = "problem: wave_quads\nwave: {restarts: 1, wavelength: 1.3}\n";
  for (const std::string& yaml : {off, own}) {
    const RunResult run = RunSpec(ParseSpec(yaml, "/in-memory/wave.yaml"), {}, inputs);
    const bool valid = run.report.at("details").at("wave").at("valid").get<bool>();
    EXPECT_EQ(valid, yaml == own) << run.summary;
    EXPECT_EQ(run.exit_code, valid ? 0 : 4) << run.summary;
    EXPECT_EQ(run.report.contains("missed"), !valid);
    EXPECT_EQ(run.summary.find("not a valid quad complex") != std::string::npos, !valid);
  }
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
