// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — a tolerance band around a scalar residual.
//
//   r' = r − clamp(r, −b, b),   ∂r'/∂x = ∂r/∂x if |r| > b, else 0
//
// Wraps a cost function with one residual so that values within ±b cost
// nothing and only the excess is penalised: with a planarity residual
// (δ_PQ,n per face) and b = target × tolerance, faces already within the
// tolerance are left alone and the rest are pulled just inside it — the
// least-movement way to meet a tolerance (an exterior penalty on the
// inequality |r| ≤ b). r'² is C¹, so Gauss–Newton/LM steps stay well defined.
// b = 0 gives r back unchanged.
#pragma once

#include <ceres/cost_function.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace archgeo {

// The band applied in place to an evaluated scalar residual and its
// Jacobians (blocks of `sizes`; null Jacobians are skipped).
void ApplyToleranceBand(double band, const std::vector<int32_t>& sizes, double* residual,
                        double** jacobians);

class ToleranceBand : public ceres::CostFunction {
 public:
  // Takes ownership of `inner`, which must have exactly one residual.
  ToleranceBand(ceres::CostFunction* inner, double band);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  std::unique_ptr<ceres::CostFunction> inner_;
  double band_;
};

}  // namespace archgeo
