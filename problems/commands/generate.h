// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `archgeo generate`: analytic test meshes written to a file.
#pragma once

#include <optional>
#include <string>

#include "problems/commands/run.h"

namespace archgeo {

// Bounds on the options, checked before anything is built (see
// GenerateSurface). The generated shapes are a few units across, so every
// coordinate written stays below ~1e7 in magnitude and every face count
// below kMaxGeneratedFaces.
constexpr double kMinGenerateScale = 1e-6, kMaxGenerateScale = 1e6;
constexpr double kMaxGenerateNoise = 10;          // mean edge lengths
constexpr long long kMaxGeneratedFaces = 4'000'000;  // 4x a 1000 x 1000 grid
// Asymptotic nets grow as refinement²: at 16 the Scherk net has 147,456
// quads and its analytic reference (--reference) 6.8M triangles (~1 GB).
constexpr int kMaxGenerateRefinement = 16;

struct GenerateOptions {
  // roof | torus | cone_start | hyperbolic_paraboloid | enneper_large |
  // enneper_small | catenoid_band | scherk
  std::string surface = "roof";
  // Resolution (roof, torus, cone_start; see GenerateSurfaceNames): >= 1
  // (torus: >= 3, cone_start: nu >= 3), nu·nv quads (cone_start: 2·nu·nv
  // triangles) at most kMaxGeneratedFaces.
  int nu = 20, nv = 15;
  // roof, torus: random vertex offsets, mean edge lengths, in
  // [0, kMaxGenerateNoise]; unset: the surface's default (roof 0.1, torus 0).
  std::optional<double> noise;
  double scale = 1.0;    // uniform scale of the written mesh, in
                         // [kMinGenerateScale, kMaxGenerateScale]
  unsigned seed = 1;     // roof, torus: random seed of the noise
  int refinement = 1;    // asymptotic nets: quads per parameter step, in
                         // [1, kMaxGenerateRefinement]
  std::string reference; // asymptotic nets: optional path for the analytic reference
};

// One line per surface name: what it is, which options it uses, which paper
// example it stands for.
std::string GenerateSurfaceNames();

// Writes the surface to `path` atomically (and the reference, if asked).
// Throws InputError, before building anything, for an unknown surface and
// for options outside the bounds above (non-finite values included; the
// message names the option); and, as a last guard, if a mesh would be written
// with a non-finite coordinate (nothing is written then).
RunResult GenerateSurface(const std::string& path, const GenerateOptions& options);

}  // namespace archgeo
