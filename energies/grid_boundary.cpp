#include "energies/grid_boundary.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeGridBoundary(const Surface& surface, double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeGridBoundary: inv_length must be finite and > 0, got " << inv_length;
  return new ceres::AutoDiffCostFunction<GridBoundary, 1, 2, 2, 2, 2>(
      new GridBoundary(surface, inv_length));
}

}  // namespace archgeo
