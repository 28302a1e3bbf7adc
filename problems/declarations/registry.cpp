// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/declarations/registry.h"

// One line per problem: X(<name>) for ProblemDecl problems::<name>() in
// problems/declarations/<name>.cpp.
#define ARCHGEO_PROBLEMS(X)   \
  X(planar_quads)             \
  X(smooth_mesh)              \
  X(total_absolute_curvature) \
  X(principal_symmetric)      \
  X(hnet)                     \
  X(conjugate_field)          \
  X(level_sets)               \
  X(conjugate_layout)         \
  X(grid)                     \
  X(base_complex_quads)       \
  X(spectral_quads)           \
  X(wave_quads)               \
  X(subdivide)                \
  X(remesh)

namespace archgeo {
namespace problems {
#define ARCHGEO_DECLARE(name) ProblemDecl name();
ARCHGEO_PROBLEMS(ARCHGEO_DECLARE)
#undef ARCHGEO_DECLARE
}  // namespace problems

namespace {

const std::vector<ProblemDecl>& All() {
#define ARCHGEO_LIST(name) problems::name(),
  static const std::vector<ProblemDecl> all = {ARCHGEO_PROBLEMS(ARCHGEO_LIST)};
#undef ARCHGEO_LIST
  return all;
}

}  // namespace

std::vector<std::string> ProblemNames() {
  std::vector<std::string> names;
  for (const ProblemDecl& d : All()) names.push_back(d.name);
  names.push_back("custom");
  return names;
}

const ProblemDecl* FindProblem(const std::string& name) {
  for (const ProblemDecl& d : All()) {
    if (d.name == name) return &d;
  }
  return nullptr;
}

}  // namespace archgeo
