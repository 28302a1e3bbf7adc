// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/tolerance_band.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>

namespace archgeo {

ToleranceBand::ToleranceBand(ceres::CostFunction* inner, double band)
    : inner_(inner), band_(band) {
  CHECK_EQ(inner->num_residuals(), 1);
  CHECK_GE(band, 0.0);
  set_num_residuals(1);
  *mutable_parameter_block_sizes() = inner->parameter_block_sizes();
}

void ApplyToleranceBand(double band, const std::vector<int32_t>& sizes, double* residual,
                        double** jacobians) {
  const double r = residual[0];
  residual[0] = r - std::clamp(r, -band, band);
  if (jacobians && std::abs(r) <= band) {
    for (size_t i = 0; i < sizes.size(); ++i) {
      if (jacobians[i]) std::fill(jacobians[i], jacobians[i] + sizes[i], 0.0);
    }
  }
}

bool ToleranceBand::Evaluate(double const* const* parameters, double* residuals,
                             double** jacobians) const {
  if (!inner_->Evaluate(parameters, residuals, jacobians)) return false;
  ApplyToleranceBand(band_, parameter_block_sizes(), residuals, jacobians);
  return true;
}

}  // namespace archgeo
