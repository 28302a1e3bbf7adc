#include "core/tolerance_band.h"

#include <glog/logging.h>

#include <algorithm>

namespace archgeo {

ToleranceBand::ToleranceBand(ceres::CostFunction* inner, double band)
    : inner_(inner), band_(band) {
  CHECK_EQ(inner->num_residuals(), 1);
  CHECK_GE(band, 0.0);
  set_num_residuals(1);
  *mutable_parameter_block_sizes() = inner->parameter_block_sizes();
}

bool ToleranceBand::Evaluate(double const* const* parameters, double* residuals,
                             double** jacobians) const {
  if (!inner_->Evaluate(parameters, residuals, jacobians)) return false;
  const double r = residuals[0];
  residuals[0] = r - std::clamp(r, -band_, band_);
  if (jacobians && std::abs(r) <= band_) {
    const auto& sizes = parameter_block_sizes();
    for (size_t i = 0; i < sizes.size(); ++i) {
      if (jacobians[i]) std::fill(jacobians[i], jacobians[i] + sizes[i], 0.0);
    }
  }
  return true;
}

}  // namespace archgeo
