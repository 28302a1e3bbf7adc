// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Placement of a TCD field singularity in a chosen face, 2 residuals:
//
//   r = z_N − z_M
//
//   [Zadravec 2010, §4: "If in a face f we wish to place a singularity we can
//    simply enforce z_M,f = z_N,f."]
//
// z_N = z_M makes N a multiple of M, so every direction is an eigenvector of
// N⁻¹M and the face is singular (proof of Prop. 3). The builder weights the
// term strongly (a soft equality).
//
// Units / normalisation: dimensionless (the auxiliary circle has radius 1).
// Ceres minimises ½Σr².
//
// Singular configurations: none (r is affine). z_M must be finite: a face
// whose z_M is at infinity (mean curvature 0) cannot host a singularity this
// way (by Prop. 4 singularities in K < 0 regions are fixed by the surface).
// Never returns false.
//
// Invariances: rotating the face frame by φ turns r by R(−2φ) (‖r‖ kept);
// independent of the mesh geometry.
#ifndef ARCHGEO_ENERGIES_TCD_SINGULARITY_PLACEMENT_H_
#define ARCHGEO_ENERGIES_TCD_SINGULARITY_PLACEMENT_H_

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

struct TcdSingularityPlacement {
  using Shape = CostShape<2, 2>;

  // z_m: 2 doubles, z_M of the face (own frame).
  explicit TcdSingularityPlacement(const double z_m[2]) : z_m(z_m[0], z_m[1]) {}

  // z: 2 doubles (z_N of the face, own frame); residual: 2.
  template <typename T>
  bool operator()(const T* z, T* residual) const {
    residual[0] = z[0] - T(z_m.x());
    residual[1] = z[1] - T(z_m.y());
    return true;
  }

  Eigen::Vector2d z_m;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_TCD_SINGULARITY_PLACEMENT_H_
