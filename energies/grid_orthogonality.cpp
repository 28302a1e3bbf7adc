#include "energies/grid_orthogonality.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeGridOrthogonality(const Surface& surface, double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeGridOrthogonality: inv_length must be finite and > 0, got " << inv_length;
  return new ceres::AutoDiffCostFunction<GridOrthogonality, 1, 2, 2, 2, 2>(
      new GridOrthogonality(surface, inv_length));
}

}  // namespace archgeo
