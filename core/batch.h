// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — many residual blocks of one cost functor type, one per element,
// evaluated by one object: a term adds its elements to a batch instead of
// allocating a ceres::CostFunction per element. At 100k quads a planar_quads
// round has ~1.7M residual blocks; one cost object each (the functor, the
// CostFunction with its vector of block sizes, a band wrapper) would be
// ~300 MB of small allocations, most of the round's build.
//
// The batches of autodiff functors are energies/autodiff.h's; a batch
// element evaluates to exactly what the functor's cost function (wrapped in
// a ToleranceBand when band ≥ 0) returns.
#pragma once

#include <cstdint>
#include <vector>

#include <ceres/cost_function.h>

#include "core/tolerance_band.h"

namespace archgeo {

class Batch {
 public:
  // rows: residuals per element; sizes: its parameter blocks' sizes; band:
  // a tolerance band applied to every element's scalar residual (< 0: none).
  Batch(int rows, std::vector<int32_t> sizes, double band);
  virtual ~Batch() = default;
  Batch(const Batch&) = delete;
  Batch& operator=(const Batch&) = delete;

  // Releases spare capacity once every element is added.
  virtual void Fit() = 0;
  int num_residuals() const { return rows_; }
  const std::vector<int32_t>& parameter_block_sizes() const { return sizes_; }

  // ceres::CostFunction::Evaluate of element `element`.
  bool Evaluate(int element, double const* const* parameters, double* residuals,
                double** jacobians) const {
    if (!EvaluateElement(element, parameters, residuals, jacobians)) return false;
    if (band_ >= 0) ApplyToleranceBand(band_, sizes_, residuals, jacobians);
    return true;
  }

 protected:
  virtual bool EvaluateElement(int element, double const* const* parameters, double* residuals,
                               double** jacobians) const = 0;

 private:
  int rows_;
  std::vector<int32_t> sizes_;
  double band_;
};

// One element of a batch as a ceres::CostFunction (borrowing the batch), for
// a ceres::Problem and for wrappers.
class BatchElement final : public ceres::CostFunction {
 public:
  BatchElement(const Batch& batch, int element);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  const Batch& batch_;
  int element_;
};

}  // namespace archgeo
