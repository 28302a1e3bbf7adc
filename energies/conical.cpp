#include "energies/conical.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeConical(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeConical: inv_length must be finite and > 0, got " << inv_length;
  return new ceres::AutoDiffCostFunction<Conical, 1, 3, 3, 3, 3, 3>(
      new Conical(inv_length));
}

}  // namespace archgeo
