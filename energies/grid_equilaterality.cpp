#include "energies/grid_equilaterality.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeGridEquilaterality(const Surface& surface, double ideal_length) {
  CHECK(std::isfinite(ideal_length) && ideal_length > 0.0)
      << "MakeGridEquilaterality: ideal_length must be finite and > 0, got " << ideal_length;
  return new ceres::AutoDiffCostFunction<GridEquilaterality, 1, 2, 2>(
      new GridEquilaterality(surface, ideal_length));
}

}  // namespace archgeo
