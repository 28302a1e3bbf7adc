#include "energies/face_planarity.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeFacePlanarity(const double center[3],
                                       double inv_length) {
  CHECK(center != nullptr);
  CHECK(std::isfinite(center[0]) && std::isfinite(center[1]) &&
        std::isfinite(center[2]))
      << "MakeFacePlanarity: non-finite center";
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeFacePlanarity: inv_length must be finite and > 0, got "
      << inv_length;
  return new ceres::AutoDiffCostFunction<FacePlanarity, 1, 3, 1, 3>(
      new FacePlanarity(center, inv_length));
}

}  // namespace archgeo
