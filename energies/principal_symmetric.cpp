#include "energies/principal_symmetric.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeCoSpherical(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeCoSpherical: inv_length must be finite and > 0, got "
      << inv_length;
  return new ceres::AutoDiffCostFunction<CoSpherical, 1, 3, 3, 1, 3>(
      new CoSpherical(inv_length));
}

ceres::CostFunction* MakePrincipalStrip(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakePrincipalStrip: inv_length must be finite and > 0, got "
      << inv_length;
  return new ceres::AutoDiffCostFunction<PrincipalStrip, 3, 3, 3, 3, 3, 3>(
      new PrincipalStrip(inv_length));
}

ceres::CostFunction* MakeSaddleSign() {
  return new ceres::AutoDiffCostFunction<SaddleSign, 1, 3, 3, 1, 3, 1>(
      new SaddleSign());
}

}  // namespace archgeo
