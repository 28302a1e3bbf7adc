// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Times the standing wave of `wave_quads` (problems/declarations/wave_quads.cpp,
// Gebreiter 2012 §8.3: ~60 s per 10k vertices in the thesis' Matlab) per
// 10,000 vertices: a 10,000-vertex torus (R = 3, r = 1, 125 × 80 principal
// quads) with its known size field (6 waves round the tube, 12 round the
// axis), and the shared Concerthall (6,897 vertices, open) with the
// curvature field and a constant size field, one start each. The time is
// the whole solve's (field, start, the Levenberg–Marquardt rounds and the
// Morse–Smale complex of each).
//
//   ninja -C <build> archgeo_benchmarks && <build>/benchmarks/wave
//
// Prints per surface the vertices, seconds, seconds per 10k vertices, the
// energy and whether the complex is valid; then, for the shared inspired
// mesh and the Concerthall, how many of ten starts (examples/wave_quads.yaml,
// one start per seed) give a valid complex. Exit 1 above kTargetSeconds per
// 10k vertices or below kTargetValid valid complexes.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "benchmarks/program.h"
#include "core/solver_options.h"
#include "generators/smoothness_surfaces.h"
#include "io/io.h"
#include "problems/runtime/solve.h"
#include "problems/spec/spec.h"

namespace ARCHGEO_UNITY_ID {

constexpr double kTargetSeconds = 6.0;  // per 10,000 vertices
constexpr int kStarts = 10, kTargetValid = 9;  // valid complexes of ten starts

// Seconds per 10k vertices of one solve (prints its line).
double TimeWave(const char* name, const archgeo::Mesh& mesh, const std::string& yaml) {
  const auto start = std::chrono::steady_clock::now();
  const auto s = archgeo::Solve(archgeo::ParseSpec(yaml, "/benchmark/wave.yaml"), mesh, nullptr, {});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double per = seconds * 1e4 / double(mesh.number_of_vertices());
  const auto& w = s->details.at("wave");
  std::printf("%-12s %6zu vertices  %6.2f s  %6.2f s per 10k  E %.4g  complex valid %s, "
              "%d irregular quasi-dual vertices\n",
              name, size_t(mesh.number_of_vertices()), seconds, per, w.at("energy").get<double>(),
              w.at("valid").get<bool>() ? "yes" : "no",
              w.at("quasi_dual").at("irregular_vertices").get<int>());
  return per;
}

// Starts 1 … kStarts one by one (wave.seed), the example's settings (the
// curvature field, 12 mean edge lengths): how many give a valid complex.
int ValidStarts(const char* name, const archgeo::Mesh& mesh) {
  int valid = 0;
  double worst_sin = 0, seconds = 0;
  double e_low = 1e300, e_high = 0;
  int quads_low = 1 << 30, quads_high = 0, irregular_low = 1 << 30, irregular_high = 0;
  for (int seed = 1; seed <= kStarts; ++seed) {
    const auto start = std::chrono::steady_clock::now();
    const auto s = archgeo::Solve(
        archgeo::ParseSpec("problem: wave_quads\nwave: {seed: " + std::to_string(seed) + "}\n",
                           "/benchmark/wave.yaml"),
        mesh, nullptr, {});
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto& w = s->details.at("wave");
    valid += w.at("valid").get<bool>() ? 1 : 0;
    worst_sin = std::max(worst_sin, w.at("feature_sin_max").get<double>());
    const double e = w.at("energy").get<double>();
    const int quads = w.at("quasi_dual").at("quads").get<int>();
    const int irregular = w.at("quasi_dual").at("irregular_vertices").get<int>();
    e_low = std::min(e_low, e);
    e_high = std::max(e_high, e);
    quads_low = std::min(quads_low, quads);
    quads_high = std::max(quads_high, quads);
    irregular_low = std::min(irregular_low, irregular);
    irregular_high = std::max(irregular_high, irregular);
  }
  std::printf("%-28s %d of %d starts give a valid complex, boundary |sin| max %.2g, E %.0f-%.0f, "
              "quasi-dual %d-%d quads, %d-%d irregular vertices, %.1f s per start\n",
              name, valid, kStarts, worst_sin, e_low, e_high, quads_low, quads_high,
              irregular_low, irregular_high, seconds / kStarts);
  return valid;
}

int Main(int argc, char** argv) {
  if (!bench::NoArguments(argc, argv)) return 2;
  archgeo::ConfigureThreading();  // as `archgeo solve` does
  const double torus = TimeWave(
      "torus", archgeo::TorusPrincipalQuads(3, 1, 125, 80),
      "problem: wave_quads\nwave: {wavelength: 1.0471975511965976, wavelength_y: "
      "0.5235987755982988, size_field_y: axis_distance, curl_correction: off}\n");
  const double hall = TimeWave(
      "Concerthall", archgeo::ReadMesh(std::string(ARCHGEO_DATA_DIR) + "/directional_Concerthall.off"),
      "problem: wave_quads\nwave: {wavelength: 3}\n");
  const double worst = std::max(torus, hall);
  std::printf("worst %.2f s per 10k vertices (target %.1f s)\n", worst, kTargetSeconds);
  // examples/wave_quads.yaml's ten starts on two shared surfaces.
  int fewest = kStarts;
  for (const char* name : {"libigl_inspired_mesh.obj", "directional_Concerthall.off"}) {
    fewest = std::min(fewest, ValidStarts(name, archgeo::ReadMesh(std::string(ARCHGEO_DATA_DIR) +
                                                                  "/" + name)));
  }
  const bool pass = worst <= kTargetSeconds && fewest >= kTargetValid;
  std::printf("fewest valid complexes %d of %d (target %d)\n%s\n", fewest, kStarts, kTargetValid,
              pass ? "PASS" : "FAIL");
  return pass ? 0 : 1;
}

}  // namespace ARCHGEO_UNITY_ID

ARCHGEO_BENCHMARK_PROGRAM(wave, ARCHGEO_UNITY_ID::Main);
