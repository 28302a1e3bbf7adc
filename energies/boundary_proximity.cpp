#include "energies/boundary_proximity.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeBoundaryProximity(const double point[3],
                                           const double tangent[3],
                                           double inv_length) {
  CHECK(point != nullptr && tangent != nullptr);
  for (int i = 0; i < 3; ++i) {
    CHECK(std::isfinite(point[i]) && std::isfinite(tangent[i]))
        << "MakeBoundaryProximity: non-finite point or tangent";
  }
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeBoundaryProximity: inv_length must be finite and > 0, got "
      << inv_length;
  return new ceres::AutoDiffCostFunction<BoundaryProximity, 3, 3>(
      new BoundaryProximity(point, tangent, inv_length));
}

}  // namespace archgeo
