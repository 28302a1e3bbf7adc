// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/registry.h"

#include <cstdlib>

// One line per term: X(<name>) for the TermSpec terms::<name>() defined in
// energies/<name>.cpp.
#define ARCHGEO_TERMS(X)       \
  X(anchor)                    \
  X(anet_planarity)            \
  X(bending)                   \
  X(boundary_proximity)        \
  X(co_spherical)              \
  X(conical)                   \
  X(convexity)                 \
  X(dihedral_energy)           \
  X(direction_dirichlet)       \
  X(displacement_guard)        \
  X(face_planarity)            \
  X(fairness)                  \
  X(frame_coplanarity)         \
  X(grid_boundary)             \
  X(grid_equilaterality)       \
  X(grid_fairness)             \
  X(grid_orthogonality)        \
  X(grid_quad_equilaterality)  \
  X(handles)                   \
  X(laplacian)                 \
  X(level_set_alignment)       \
  X(level_set_boundary)        \
  X(level_set_branch_point)    \
  X(level_set_conjugacy)       \
  X(level_set_jump)            \
  X(level_set_normalised)      \
  X(load)                      \
  X(mean_curvature_flow)       \
  X(min_edge_length)           \
  X(on_curve)                  \
  X(pq_diagonal)               \
  X(pq_worst)                  \
  X(principal_fit)             \
  X(principal_smoothing)       \
  X(principal_strip)           \
  X(proximity)                 \
  X(saddle_sign)               \
  X(shear)                     \
  X(size_curl)                 \
  X(size_smoothing)            \
  X(size_target)               \
  X(smoothed_dihedral_energy)  \
  X(spring)                    \
  X(step)                      \
  X(surface_band)              \
  X(tangent_plane)             \
  X(tcd_dirichlet)             \
  X(tcd_prescribed_direction)  \
  X(tcd_singularity_avoidance) \
  X(tcd_singularity_placement) \
  X(tcd_transversality)        \
  X(total_absolute_curvature)  \
  X(wave_feature)              \
  X(wave_norm)                 \
  X(wave_product)              \
  X(wave_transfer)

namespace archgeo {
namespace terms {
#define ARCHGEO_DECLARE(name) const TermSpec& name();
ARCHGEO_TERMS(ARCHGEO_DECLARE)
#undef ARCHGEO_DECLARE
}  // namespace terms

const std::vector<const TermSpec*>& RegisteredTerms() {
#define ARCHGEO_LIST(name) &terms::name(),
  static const std::vector<const TermSpec*> all = {ARCHGEO_TERMS(ARCHGEO_LIST)};
#undef ARCHGEO_LIST
  return all;
}

const std::string& ZeroedTerm() {
  static const std::string name = [] {
    const char* zeroed = std::getenv("ARCHGEO_ZERO_TERM");
    return std::string(zeroed ? zeroed : "");
  }();
  return name;
}

const TermSpec* FindTerm(const std::string& name) {
  for (const TermSpec* t : RegisteredTerms()) {
    if (name == t->name) return t;
  }
  return nullptr;
}

}  // namespace archgeo
