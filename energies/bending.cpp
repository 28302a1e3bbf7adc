#include "energies/bending.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeBending(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeBending: inv_length must be finite and > 0, got " << inv_length;
  return new ceres::AutoDiffCostFunction<Bending, 3, 3, 3, 3>(
      new Bending(inv_length));
}

}  // namespace archgeo
