#include "energies/shear.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeShear(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeShear: inv_length must be finite and > 0, got " << inv_length;
  return new ceres::AutoDiffCostFunction<Shear, 1, 3, 3, 3, 3>(
      new Shear(inv_length));
}

}  // namespace archgeo
