#include "energies/proximity.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeProximity(const double point[3],
                                   const double normal[3], double inv_length) {
  CHECK(point != nullptr && normal != nullptr);
  for (int i = 0; i < 3; ++i) {
    CHECK(std::isfinite(point[i]) && std::isfinite(normal[i]))
        << "MakeProximity: non-finite point or normal";
  }
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeProximity: inv_length must be finite and > 0, got " << inv_length;
  return new ceres::AutoDiffCostFunction<Proximity, 1, 3>(
      new Proximity(point, normal, inv_length));
}

}  // namespace archgeo
