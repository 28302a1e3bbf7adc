// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fields/conjugate.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <glog/logging.h>

namespace archgeo {

bool ZOfMatrix(const Eigen::Matrix2d& M, Eigen::Vector2d* z, double relative_tolerance) {
  CHECK(z != nullptr);
  const double trace = M(0, 0) + M(1, 1);
  const double size = M.norm();
  if (!(std::abs(trace) > relative_tolerance * size)) return false;
  *z = Eigen::Vector2d(M(1, 1), -M(0, 1)) * (2.0 / trace);
  return true;
}

Eigen::Vector2d CirclePoint(const Eigen::Vector2d& d) {
  const double t = std::atan2(d.y(), d.x());
  return Eigen::Vector2d(1.0 + std::cos(2.0 * t), std::sin(2.0 * t));
}

Eigen::Matrix2d NOfZ(const Eigen::Vector2d& z_n) {
  CHECK(z_n.x() != 2.0) << "NOfZ: z_N = (2, y) has no N with n11 = 1";
  const double s = 1.0 / (2.0 - z_n.x());
  Eigen::Matrix2d N;
  N << 1.0, -z_n.y() * s, -z_n.y() * s, z_n.x() * s;
  return N;
}

SymmetricEigen2 EigenOfSymmetric2(const Eigen::Matrix2d& m) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(m);
  return {eig.eigenvalues(), eig.eigenvectors()};
}

Principal PrincipalOf(const Eigen::Matrix2d& M) {
  const SymmetricEigen2 eig = EigenOfSymmetric2(0.5 * (M + M.transpose()));
  Principal p;
  p.k1 = eig.values(1);
  p.k2 = eig.values(0);
  p.d1 = eig.vectors.col(1).normalized();
  p.d2 = Eigen::Vector2d(-p.d1.y(), p.d1.x());
  return p;
}

int AsymptoticDirections(const Eigen::Matrix2d& M, Eigen::Vector2d out[2],
                         double relative_tolerance) {
  const Principal p = PrincipalOf(M);
  const double kmax = std::max(std::abs(p.k1), std::abs(p.k2));
  if (kmax == 0.0) return 0;
  const double tol = relative_tolerance * kmax;
  if (p.k1 > tol && p.k2 < -tol) {
    // k1 cos²φ + k2 sin²φ = 0 ⇒ tan φ = sqrt(k1 / −k2), measured from d1.
    const double phi = std::atan(std::sqrt(p.k1 / -p.k2));
    out[0] = std::cos(phi) * p.d1 + std::sin(phi) * p.d2;
    out[1] = std::cos(phi) * p.d1 - std::sin(phi) * p.d2;
    return 2;
  }
  if (std::abs(p.k1) <= tol) {
    out[0] = p.d1;
    return 1;
  }
  if (std::abs(p.k2) <= tol) {
    out[0] = p.d2;
    return 1;
  }
  return 0;
}

ConjugatePair ConjugatePairOf(const Eigen::Matrix2d& M, const Eigen::Vector2d& z_n,
                              double relative_tolerance) {
  ConjugatePair pair;
  // Strictly inside c ⇔ det N > 0 (and then z1 ∈ (0, 2), so N exists).
  if (!((z_n - Eigen::Vector2d(1.0, 0.0)).squaredNorm() < 1.0)) return pair;
  const Eigen::Matrix2d N = NOfZ(z_n);
  const Eigen::Matrix2d sym = 0.5 * (M + M.transpose());
  // M x = λ N x with N positive definite: Cholesky N = L Lᵀ, symmetric
  // eigenproblem of L⁻¹ M L⁻ᵀ; the eigenvectors are M- and N-orthogonal to
  // rounding, which is what makes the pair conjugate "by construction".
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> eig(sym, N);
  if (eig.info() != Eigen::Success) return pair;
  const double l0 = eig.eigenvalues()(0), l1 = eig.eigenvalues()(1);
  pair.v = eig.eigenvectors().col(1).normalized();
  pair.w = eig.eigenvectors().col(0).normalized();
  pair.valid = (l1 - l0) > relative_tolerance * (std::abs(l0) + std::abs(l1)) &&
               std::isfinite(l0) && std::isfinite(l1);
  return pair;
}

double ConjugacyError(const Eigen::Matrix2d& M, const Eigen::Vector2d& v,
                      const Eigen::Vector2d& w) {
  const Principal p = PrincipalOf(M);
  const double kmax = std::max(std::abs(p.k1), std::abs(p.k2));
  if (kmax == 0.0) return 0.0;
  const Eigen::Matrix2d sym = 0.5 * (M + M.transpose());
  return std::abs(v.dot(sym * w)) / (kmax * v.norm() * w.norm());
}

double LineAngle(const Eigen::Vector2d& d) {
  double a = std::atan2(d.y(), d.x());
  if (a < 0.0) a += M_PI;
  if (a >= M_PI) a -= M_PI;
  return a;
}

double WrapLineAngle(double x) {
  double r = std::remainder(x, M_PI);  // in [−π/2, π/2]
  if (r <= -0.5 * M_PI) r += M_PI;
  return r;
}

double BisectorAngle(const Eigen::Vector2d& v, const Eigen::Vector2d& w) {
  const double tv = LineAngle(v);
  double delta = LineAngle(w) - tv;  // counter-clockwise turn from line v to line w
  if (delta < 0.0) delta += M_PI;
  double b = tv + 0.5 * delta;
  if (b >= M_PI) b -= M_PI;
  return b;
}

}  // namespace archgeo
