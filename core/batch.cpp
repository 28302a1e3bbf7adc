// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/batch.h"

#include <utility>

#include <glog/logging.h>

namespace archgeo {

Batch::Batch(int rows, std::vector<int32_t> sizes, double band)
    : rows_(rows), sizes_(std::move(sizes)), band_(band) {
  CHECK(band < 0 || rows == 1) << "a tolerance band needs a scalar residual";
}

BatchElement::BatchElement(const Batch& batch, int element) : batch_(batch), element_(element) {
  set_num_residuals(batch.num_residuals());
  *mutable_parameter_block_sizes() = batch.parameter_block_sizes();
}

bool BatchElement::Evaluate(double const* const* parameters, double* residuals,
                            double** jacobians) const {
  return batch_.Evaluate(element_, parameters, residuals, jacobians);
}

}  // namespace archgeo
