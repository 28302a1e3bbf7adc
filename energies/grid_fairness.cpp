#include "energies/grid_fairness.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeGridFairness(const Surface& surface, double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeGridFairness: inv_length must be finite and > 0, got " << inv_length;
  return new ceres::AutoDiffCostFunction<GridFairness, 3, 2, 2, 2>(
      new GridFairness(surface, inv_length));
}

}  // namespace archgeo
