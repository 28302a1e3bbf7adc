// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Surface band: every vertex stays within a distance b of the design
// (reference) surface — a constraint, not a penalty: the term adds no
// residual; it makes each vertex's position a point of a bounded manifold
// (ceres::Manifold) that cannot leave the band, whatever step the solver
// takes:
//
//   x = p + (I − D Dᵀ) e + D o,   o = s(|η|) η / |η|,   |o| < B
//   s(ρ) = ρ (ρ ≤ a = B/2),   a + (B − a) tanh((ρ − a)/(B − a)) beyond
//
//   [archgeo; the façade brief's "deviation from the design surface" as a
//    hard bound: Zadravec 2010 §6 and Pellis 2019 §5.1 keep the mesh close
//    to the reference by penalties only, which bound nothing]
//
// p is the closest reference point π(v) at the start of the round; D holds
// the constrained unit directions: the reference normal n (an interior
// vertex: o is the signed distance from the tangent plane, |o| < B, and the
// tangential part e is free) or, for a vertex on the reference's boundary
// curve, all three axes (o = x − p, |o| < B: a ball around the closest curve
// point, since the curve's tangent line leaves the surface where the
// boundary turns). The solver steps in (e, η): η ∈ ℝᵏ is unbounded and o
// its radial squashing s, so |o| → B only as |η| → ∞; within B/2, s is the
// identity (the solver sees no band there). The tangent-space step
// δ ∈ ℝ³ maps as e ← e + (I − D Dᵀ) δ, η ← η + Dᵀ δ.
//
// B = s·b for a vertex within s·b at the start of the round (s =
// terms.surface_band.start, default 0.95: the rest of the band absorbs the
// curvature the linearisation misses); a vertex farther out (the reference
// re-projected, or an input beyond the band) gets B halfway to b, or, beyond
// b, B = 1.001 |o|: it cannot go farther out, and comes back as the goals
// allow. After the round a vertex beyond b is put back on the band, and the
// loop measures the exact distance of every vertex (and face centroid)
// (problems/declarations/design_band.h) and never outputs a round beyond b.
//
// Units: lengths in the canonical frame; η in lengths, so the Jacobian of
// Plus is I for |o| ≤ B/2. Singular configurations: none inside B/2 (the
// maps are the identity there); |o| ≥ B is outside the manifold (Minus clamps it just inside). Invariances:
// rigid motions applied to x, p and D; uniform scaling of x, p and B.
#ifndef ARCHGEO_ENERGIES_SURFACE_BAND_H_
#define ARCHGEO_ENERGIES_SURFACE_BAND_H_

#include <ceres/manifold.h>

#include <Eigen/Core>

namespace archgeo {

class BandManifold : public ceres::Manifold {
 public:
  // point: p; directions: k = 1 to 3 orthonormal columns (D); bound: B > 0.
  BandManifold(const Eigen::Vector3d& point, const Eigen::Matrix<double, 3, Eigen::Dynamic>& directions,
               double bound);

  int AmbientSize() const override { return 3; }
  int TangentSize() const override { return 3; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;

  // The constrained offset o = Dᵀ(x − p) of a position.
  Eigen::VectorXd Offset(const double* x) const;

 private:
  double Radius(double rho) const;  // |o| of |η|
  double Rho(double radius) const;  // its inverse
  Eigen::VectorXd ToEta(const Eigen::VectorXd& o) const;  // inverse squashing
  Eigen::VectorXd ToOffset(const Eigen::VectorXd& eta) const;
  // ∂o/∂η at the offset o (k × k), or its inverse.
  Eigen::MatrixXd Derivative(const Eigen::VectorXd& o, bool inverse) const;

  Eigen::Vector3d point_;
  Eigen::Matrix<double, 3, Eigen::Dynamic> d_;
  double bound_;
};

// The in-round bound B of a vertex at offset distance `distance` from its
// reference point, for the band b and the start fraction s (see above).
double BandBound(double distance, double band, double start);

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_SURFACE_BAND_H_
