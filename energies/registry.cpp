#include "energies/registry.h"

// One line per term: X(<name>) for the TermSpec terms::<name>() defined in
// energies/<name>.cpp.
#define ARCHGEO_TERMS(X)       \
  X(anchor)                    \
  X(anet_planarity)            \
  X(boundary_proximity)        \
  X(co_spherical)              \
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
  X(pq_diagonal)               \
  X(principal_strip)           \
  X(proximity)                 \
  X(saddle_sign)               \
  X(step)                      \
  X(tangent_plane)             \
  X(total_absolute_curvature)

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

const TermSpec* FindTerm(const std::string& name) {
  for (const TermSpec* t : RegisteredTerms()) {
    if (name == t->name) return t;
  }
  return nullptr;
}

}  // namespace archgeo
