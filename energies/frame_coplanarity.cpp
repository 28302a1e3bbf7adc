#include "energies/frame_coplanarity.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeFrameCoplanarity(double w1, double w2, double w4,
                                          double w5, double inv_length) {
  for (double w : {w1, w2, w4, w5}) {
    CHECK(std::isfinite(w) && w > 0.0)
        << "MakeFrameCoplanarity: weights must be finite and > 0, got " << w;
  }
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeFrameCoplanarity: inv_length must be finite and > 0, got "
      << inv_length;
  return new ceres::AutoDiffCostFunction<FrameCoplanarity, 1, 3, 3, 3, 3, 3, 3>(
      new FrameCoplanarity(w1, w2, w4, w5, inv_length));
}

}  // namespace archgeo
