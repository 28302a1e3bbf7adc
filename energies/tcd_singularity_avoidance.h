// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Singularity avoidance of a TCD field in one face, 1 residual:
//
//   t = sqrt(‖z_N − z_M‖² + ε²),   r = (1 − t/ρ)² if t < ρ, else 0,
//   so ½ r² = ½ Ψ(t/ρ),   Ψ(s) = (s − 1)⁴ for s < 1, 0 else
//
//   [Zadravec 2010, §4: Σ_f λ_reg,f Ψ(‖z_N,f − z_M,f‖), Ψ(t) = (t − 1)⁴ for
//    t < 1, 0 else]
//
// The field is singular in a face where z_N = z_M (then N⁻¹M is a multiple of
// the identity and the conjugate pair is undetermined; proof of Prop. 3), so a
// term that grows as z_N approaches z_M discourages singularities. Ψ is
// written as the square of r = (1 − t/ρ)², which is C¹ at t = ρ (r and dr/dt
// vanish there) and grows monotonically to 1 (Ψ = 1) as t → 0; how strongly it
// repels is the builder's weight λ_reg. ρ = 1 (the radius of the auxiliary
// circle) is the paper's choice; a smaller ρ confines the term to a smaller
// neighbourhood of z_M.
//
// Units / normalisation: dimensionless. Ceres minimises ½Σr².
//
// Singular configurations: the distance is not differentiable at z_N = z_M;
// it is regularised as sqrt(d² + ε²) with ε = kTcdAvoidanceEpsilon (relative
// to the unit circle). At z_N = z_M exactly the Jacobian is 0 (a stationary
// point, the maximum of Ψ: a field that is exactly singular is not pushed in
// any particular direction). Faces whose z_M is at infinity (mean curvature
// 0, fields/face_curvature.h z_m_finite == false) have t = ∞ and Ψ = 0: do
// not add the term there. Never returns false.
//
// Invariances: rotations of the face frame (z_N and z_M turn together about
// e1); independent of the mesh geometry.
#ifndef ARCHGEO_ENERGIES_TCD_SINGULARITY_AVOIDANCE_H_
#define ARCHGEO_ENERGIES_TCD_SINGULARITY_AVOIDANCE_H_

#include <cmath>

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

inline constexpr double kTcdAvoidanceEpsilon = 1e-6;

struct TcdSingularityAvoidance {
  using Shape = CostShape<1, 2>;

  // z_m: 2 doubles, z_M of the face (own frame); radius: ρ > 0.
  TcdSingularityAvoidance(const double z_m[2], double radius)
      : z_m(z_m[0], z_m[1]), inv_radius(1.0 / radius) {}

  // z: 2 doubles (z_N of the face, own frame); residual: 1.
  template <typename T>
  bool operator()(const T* z, T* residual) const {
    using std::sqrt;
    const T d0 = z[0] - T(z_m.x()), d1 = z[1] - T(z_m.y());
    const T s = sqrt(d0 * d0 + d1 * d1 + T(kTcdAvoidanceEpsilon * kTcdAvoidanceEpsilon)) *
                T(inv_radius);
    if (s < T(1.0)) {
      const T a = T(1.0) - s;
      residual[0] = a * a;
    } else {
      residual[0] = T(0.0);
    }
    return true;
  }

  Eigen::Vector2d z_m;
  double inv_radius;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_TCD_SINGULARITY_AVOIDANCE_H_
