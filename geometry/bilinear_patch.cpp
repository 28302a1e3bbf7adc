// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — rational bilinear patches, smooth joins, Darboux transformation
// [Shi, Wang, Pottmann 2014, §2, §4].
#include "geometry/bilinear_patch.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>
#include <glog/logging.h>

#include "core/input_error.h"

namespace archgeo {
namespace {

// Relative size below which a computed quantity counts as zero.
constexpr double kRelativeZero = 1e-14;

void CheckWeights(const BilinearPatch& patch) {
  for (double w : patch.w) CHECK(std::isfinite(w) && w > 0) << "patch weight " << w;
}

// Bernstein-like bilinear basis at (u, v) in the cyclic order b0..b3 and its
// partial derivatives.
struct Basis {
  std::array<double, 4> B, Bu, Bv;
};
Basis BilinearBasis(double u, double v) {
  return {{(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v},
          {-(1 - v), 1 - v, v, -v},
          {-(1 - u), -u, u, 1 - u}};
}

}  // namespace

PatchJet PatchDerivatives(const BilinearPatch& patch, double u, double v) {
  CheckWeights(patch);
  const Basis basis = BilinearBasis(u, v);
  // [Shi 2014, eq. 1]: x = N / D, N = Σ B_i w_i b_i, D = Σ B_i w_i.
  Eigen::Vector3d N = Eigen::Vector3d::Zero(), Nu = N, Nv = N;
  double D = 0, Du = 0, Dv = 0;
  for (int i = 0; i < 4; ++i) {
    N += basis.B[i] * patch.w[i] * patch.b[i];
    Nu += basis.Bu[i] * patch.w[i] * patch.b[i];
    Nv += basis.Bv[i] * patch.w[i] * patch.b[i];
    D += basis.B[i] * patch.w[i];
    Du += basis.Bu[i] * patch.w[i];
    Dv += basis.Bv[i] * patch.w[i];
  }
  CHECK_GT(D, 0.0) << "rational bilinear patch: denominator ≤ 0 at (" << u << ", " << v << ")";
  PatchJet jet;
  jet.x = N / D;
  jet.xu = (Nu - jet.x * Du) / D;
  jet.xv = (Nv - jet.x * Dv) / D;
  return jet;
}

Eigen::Vector3d PatchPoint(const BilinearPatch& patch, double u, double v) {
  return PatchDerivatives(patch, u, v).x;
}

Eigen::Vector3d PatchNormal(const BilinearPatch& patch, double u, double v) {
  const PatchJet jet = PatchDerivatives(patch, u, v);
  const Eigen::Vector3d n = jet.xu.cross(jet.xv);
  const double norm = n.norm();
  if (!(norm > kRelativeZero * jet.xu.norm() * jet.xv.norm())) return Eigen::Vector3d::Zero();
  return n / norm;
}

Eigen::Vector2d EdgeParameter(int edge, double s) {
  CHECK(edge >= 0 && edge < 4) << "edge " << edge;
  switch (edge) {
    case 0: return {s, 0.0};
    case 1: return {1.0, s};
    case 2: return {1.0 - s, 1.0};
    default: return {0.0, 1.0 - s};
  }
}

Eigen::Vector3d FramePoint(const BilinearPatch& patch, int i) {
  CHECK(i >= 0 && i < 4) << "frame point " << i;
  CheckWeights(patch);
  const int j = (i + 1) % 4;
  return (patch.w[i] * patch.b[i] + patch.w[j] * patch.b[j]) / (patch.w[i] + patch.w[j]);
}

std::array<Eigen::Vector3d, 4> FramePoints(const BilinearPatch& patch) {
  return {FramePoint(patch, 0), FramePoint(patch, 1), FramePoint(patch, 2), FramePoint(patch, 3)};
}

double ShapeParameter(const std::array<double, 4>& w) {
  for (double wi : w) CHECK(std::isfinite(wi) && wi > 0) << "patch weight " << wi;
  return w[0] * w[2] / (w[1] * w[3]);
}

std::array<double, 4> WeightsFromShapeParameter(double W) {
  CHECK(std::isfinite(W) && W > 0) << "shape parameter " << W;
  return {1.0, 1.0, W, 1.0};
}

double JoinDeterminants::ratio() const {
  CHECK(equitwist()) << "eq. 7 ratio of a join violating the equitwist condition";
  return numerator / denominator;
}

JoinDeterminants SmoothJoinDeterminants(const Eigen::Vector3d& b0, const Eigen::Vector3d& b1,
                                        const Eigen::Vector3d& b2, const Eigen::Vector3d& b3,
                                        const Eigen::Vector3d& b4, const Eigen::Vector3d& b5) {
  // det(a, b, c) = a · (b × c).  [Shi 2014, eqs. 5 and 7]
  const Eigen::Vector3d b30 = b3 - b0;
  JoinDeterminants d;
  d.numerator = b30.dot((b5 - b0).cross(b2 - b0));
  d.denominator = b30.dot((b1 - b0).cross(b4 - b0));
  return d;
}

double SharedEdgeKinkDegrees(const BilinearPatch& a, int edge_a, const BilinearPatch& b,
                             int edge_b, int samples) {
  CHECK_GE(samples, 2);
  CheckWeights(a);
  CheckWeights(b);
  // On edge i the parameter t maps to the fraction σ = t w_{i+1} / ((1−t) w_i +
  // t w_{i+1}) of the segment b_i b_{i+1}; inverted, t = σ w_i / (σ w_i + (1−σ) w_{i+1}).
  const auto parameter = [](const BilinearPatch& patch, int edge, double sigma) {
    const double wi = patch.w[edge], wj = patch.w[(edge + 1) % 4];
    return EdgeParameter(edge, sigma * wi / (sigma * wi + (1 - sigma) * wj));
  };
  double kink = -1;
  for (int k = 0; k < samples; ++k) {
    const double sigma = double(k) / (samples - 1);
    // The point at fraction σ along a's edge is at fraction 1 − σ along b's.
    const Eigen::Vector2d pa = parameter(a, edge_a, sigma), pb = parameter(b, edge_b, 1 - sigma);
    const Eigen::Vector3d na = PatchNormal(a, pa[0], pa[1]), nb = PatchNormal(b, pb[0], pb[1]);
    if (na.squaredNorm() == 0 || nb.squaredNorm() == 0) continue;  // undefined normal
    const double angle = std::atan2(na.cross(nb).norm(), na.dot(nb)) * 180.0 / M_PI;
    kink = std::max(kink, angle);
  }
  return kink;
}

DarbouxResult ApplyDarboux(const DarbouxTransform& transform, const Eigen::Vector3d& x) {
  const double c = transform.c;
  if (!std::isfinite(c) || c == 1.0) {
    throw InputError("", 0, "c", "Darboux transformation needs a finite c != 1, got " +
                                     std::to_string(c));
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  DarbouxResult result{Eigen::Vector3d::Constant(nan), DarbouxStatus::kOk};
  // Projective map on column vectors (x, 1).
  const Eigen::Vector4d h = transform.projective * x.homogeneous();
  const double h_scale = transform.projective.cwiseAbs().rowwise().sum().maxCoeff() *
                         std::max(1.0, x.cwiseAbs().maxCoeff());
  if (!(std::abs(h[3]) > kRelativeZero * h_scale)) {
    result.status = DarbouxStatus::kPointAtInfinity;
    return result;
  }
  const Eigen::Vector3d y = h.head<3>() / h[3];
  // [Shi 2014, eq. 12].
  const double y2 = y.squaredNorm();
  const double radicand = (c - 1) * (c - 1) + (1 - c * c) * y2;
  const double radicand_scale = (c - 1) * (c - 1) + std::abs(1 - c * c) * y2;
  double s = 0;
  if (radicand < -kRelativeZero * radicand_scale) {
    result.status = DarbouxStatus::kNegativeRadicand;
    return result;
  }
  if (radicand > 0) s = std::sqrt(radicand);
  const double sign = transform.branch == DarbouxBranch::kPlus ? 1.0 : -1.0;
  const double numerator = c * c - c + sign * s;
  const double denominator = y2 + 1 - c - sign * s;
  if (!(std::abs(denominator) > kRelativeZero * (y2 + std::abs(1 - c) + s))) {
    result.status = DarbouxStatus::kZeroDenominator;
    return result;
  }
  result.point = numerator / denominator * y;
  return result;
}

}  // namespace archgeo
