// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/grid_side_manifold.h"

#include <algorithm>
#include <cmath>

#include <glog/logging.h>

namespace archgeo {
namespace {

// cos θ below which MinusJacobian is regularised (a vertex within ~1e-24 of
// the side's length from its end).
constexpr double kMinCos = 1e-12;

}  // namespace

GridSideManifold::GridSideManifold(int held, double lo, double hi)
    : held_(held), free_(1 - held), mid_(0.5 * (lo + hi)), radius_(0.5 * (hi - lo)) {
  CHECK(held == 0 || held == 1) << "GridSideManifold: held coordinate " << held;
  CHECK(lo < hi && std::isfinite(lo) && std::isfinite(hi)) << "GridSideManifold: side " << lo
                                                             << ", " << hi;
}

double GridSideManifold::Angle(const double* x) const {
  return std::asin(std::clamp((x[free_] - mid_) / radius_, -1.0, 1.0));
}

bool GridSideManifold::Plus(const double* x, const double* delta, double* x_plus_delta) const {
  x_plus_delta[held_] = x[held_];
  x_plus_delta[free_] =
      delta[0] == 0.0 ? x[free_] : mid_ + radius_ * std::sin(Angle(x) + delta[0] / radius_);
  return true;
}

bool GridSideManifold::PlusJacobian(const double* x, double* jacobian) const {
  jacobian[held_] = 0.0;  // 2 × 1
  jacobian[free_] = std::cos(Angle(x));
  return true;
}

bool GridSideManifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  y_minus_x[0] = radius_ * (Angle(y) - Angle(x));
  return true;
}

bool GridSideManifold::MinusJacobian(const double* x, double* jacobian) const {
  jacobian[held_] = 0.0;  // 1 × 2
  jacobian[free_] = 1.0 / std::max(std::cos(Angle(x)), kMinCos);
  return true;
}

ceres::Manifold* MakeGridSideManifold(int held, double lo, double hi) {
  return new GridSideManifold(held, lo, hi);
}

}  // namespace archgeo
