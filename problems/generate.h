// archgeo — `archgeo generate`: analytic test meshes written to a file.
#pragma once

#include <string>

#include "problems/run.h"

namespace archgeo {

struct GenerateOptions {
  // roof | torus | cone_start | hyperbolic_paraboloid | enneper_large |
  // enneper_small | catenoid_band | scherk
  std::string surface = "roof";
  int nu = 20, nv = 15;  // resolution (roof, torus, cone_start; see GenerateSurfaceNames)
  double noise = -1;     // roof, torus: random vertex offsets, mean edge lengths
                         // (< 0: the surface's default, roof 0.1, torus 0)
  double scale = 1.0;    // uniform scale of the written mesh
  unsigned seed = 1;     // roof, torus: random seed of the noise
  int refinement = 1;    // asymptotic nets: quads per parameter step (>= 1)
  std::string reference; // asymptotic nets: optional path for the analytic reference
};

// One line per surface name: what it is, which options it uses, which paper
// example it stands for.
std::string GenerateSurfaceNames();

// Writes the surface to `path` atomically (and the reference, if asked).
// Throws InputError for an unknown surface or bad sizes.
RunResult GenerateSurface(const std::string& path, const GenerateOptions& options);

}  // namespace archgeo
