// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "surfaces/surface.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>
#include <ceres/jet.h>
#include <glog/logging.h>

namespace archgeo {
namespace {

constexpr int kMaxNewtonIterations = 100;
constexpr int kMaxHalvings = 40;
// Relative step size below which Newton stops (a few ulps of the parameter).
constexpr double kStepTolerance = 4.0 * std::numeric_limits<double>::epsilon();
constexpr int kSearchSamples = 33;

bool AllFinite(const Eigen::Matrix3d& m) { return m.allFinite(); }

double Wrap(double x, double lo, double period, long* turns) {
  const double k = std::floor((x - lo) / period);
  double y = x - k * period;
  *turns = static_cast<long>(k);
  if (y >= lo + period) {  // rounding of x − k·period
    y -= period;
    ++*turns;
  }
  if (y < lo) y = lo;
  return y;
}

}  // namespace

Eigen::Vector3d Surface::Normal(const Eigen::Vector2d& uv) const {
  Eigen::Vector3d xu, xv;
  Tangents(uv[0], uv[1], &xu, &xv);
  const Eigen::Vector3d n = xu.cross(xv);
  const double norm = n.norm();
  return norm > 0.0 ? Eigen::Vector3d(n / norm) : Eigen::Vector3d::Zero();
}

Surface Surface::Placed(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation) const {
  CHECK(AllFinite(rotation) && translation.allFinite()) << "Surface::Placed: non-finite motion";
  CHECK((rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm() < 1e-12 &&
        rotation.determinant() > 0.0)
      << "Surface::Placed: not a rotation";
  Surface moved = *this;
  moved.placed_ = true;
  moved.rotation_ = rotation * rotation_;
  moved.translation_ = rotation * translation_ + translation;
  return moved;
}

Eigen::Vector2d Surface::Wrapped(Eigen::Vector2d uv) const {
  const ParameterDomain d = Domain();
  if (d.periodic_u) {
    long turns = 0;
    uv[0] = Wrap(uv[0], d.u0, d.PeriodU(), &turns);
    if (d.u_seam_flips_v && (turns % 2 != 0)) uv[1] = d.v0 + d.v1 - uv[1];
  }
  if (d.periodic_v) {
    long turns = 0;
    uv[1] = Wrap(uv[1], d.v0, d.PeriodV(), &turns);
  }
  return uv;
}

Eigen::Vector2d Surface::NearestChart(Eigen::Vector2d uv, const Eigen::Vector2d& near) const {
  const ParameterDomain d = Domain();
  if (d.periodic_u) {
    const long turns = std::lround((uv[0] - near[0]) / d.PeriodU());
    uv[0] -= double(turns) * d.PeriodU();
    if (d.u_seam_flips_v && turns % 2 != 0) uv[1] = d.v0 + d.v1 - uv[1];
  }
  if (d.periodic_v) uv[1] -= double(std::lround((uv[1] - near[1]) / d.PeriodV())) * d.PeriodV();
  return uv;
}

Eigen::Vector2d Surface::Canonical(Eigen::Vector2d uv) const {
  const ParameterDomain d = Domain();
  uv = Wrapped(uv);
  if (!d.periodic_u) uv[0] = std::clamp(uv[0], d.u0, d.u1);
  if (!d.periodic_v) uv[1] = std::clamp(uv[1], d.v0, d.v1);
  return uv;
}

Eigen::Vector2d Surface::ClosestParameter(const Eigen::Vector3d& x, const Eigen::Vector2d& start,
                                          bool keep_in_domain) const {
  CHECK(x.allFinite() && start.allFinite()) << "ClosestParameter: non-finite input";
  using Jet = ceres::Jet<double, 2>;
  const auto value = [&](const Eigen::Vector2d& uv) { return 0.5 * (Point(uv) - x).squaredNorm(); };
  const auto canonical = [&](const Eigen::Vector2d& p) {
    return keep_in_domain ? Canonical(p) : Wrapped(p);
  };
  Eigen::Vector2d uv = canonical(start);
  double f = value(uv);
  for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
    // x_u, x_v and, in their infinitesimal parts, x_uu, x_uv, x_vv.
    Vec3T<Jet> ju, jv;
    Tangents(Jet(uv[0], 0), Jet(uv[1], 1), &ju, &jv);
    Eigen::Vector3d xu, xv, xuu, xuv, xvv;
    for (int k = 0; k < 3; ++k) {
      xu[k] = ju[k].a;
      xv[k] = jv[k].a;
      xuu[k] = ju[k].v[0];
      xuv[k] = ju[k].v[1];
      xvv[k] = jv[k].v[1];
    }
    const Eigen::Vector3d r = Point(uv) - x;
    const Eigen::Vector2d gradient(xu.dot(r), xv.dot(r));
    Eigen::Matrix2d gauss_newton;
    gauss_newton << xu.dot(xu), xu.dot(xv), xu.dot(xv), xv.dot(xv);
    Eigen::Matrix2d hessian = gauss_newton;
    hessian(0, 0) += xuu.dot(r);
    hessian(0, 1) += xuv.dot(r);
    hessian(1, 0) += xuv.dot(r);
    hessian(1, 1) += xvv.dot(r);
    const auto positive = [](const Eigen::Matrix2d& m) {
      return m(0, 0) > 0.0 && m.determinant() > 1e-14 * m(0, 0) * m(1, 1);
    };
    Eigen::Vector2d step;
    if (positive(hessian)) {
      step = -hessian.inverse() * gradient;
    } else if (positive(gauss_newton)) {
      step = -gauss_newton.inverse() * gradient;
    } else {
      break;  // singular point of the map (x_u ∥ x_v): stay
    }
    if (!step.allFinite()) break;
    if (step.norm() <= kStepTolerance * (1.0 + uv.norm())) break;
    // Backtracking: accept the first step that does not increase f.
    bool accepted = false;
    double alpha = 1.0;
    for (int halving = 0; halving < kMaxHalvings; ++halving, alpha *= 0.5) {
      const Eigen::Vector2d candidate = canonical(uv + alpha * step);
      const double fc = value(candidate);
      if (fc <= f) {
        accepted = (candidate - uv).norm() > 0.0;
        uv = candidate;
        f = fc;
        break;
      }
    }
    if (!accepted) break;
  }
  return uv;
}

Eigen::Vector2d Surface::ClosestParameter(const Eigen::Vector3d& x, bool keep_in_domain) const {
  const ParameterDomain d = Domain();
  Eigen::Vector2d best(d.u0, d.v0);
  double best_distance = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kSearchSamples; ++i) {
    for (int j = 0; j < kSearchSamples; ++j) {
      const Eigen::Vector2d uv(d.u0 + d.PeriodU() * i / (kSearchSamples - 1),
                               d.v0 + d.PeriodV() * j / (kSearchSamples - 1));
      const double distance = (Point(uv) - x).squaredNorm();
      if (distance < best_distance) {
        best_distance = distance;
        best = uv;
      }
    }
  }
  return ClosestParameter(x, best, keep_in_domain);
}

}  // namespace archgeo
