#include "energies/spring.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeSpring(double rest_length, double inv_length) {
  CHECK(std::isfinite(rest_length) && rest_length >= 0.0)
      << "MakeSpring: rest_length must be finite and >= 0, got " << rest_length;
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeSpring: inv_length must be finite and > 0, got " << inv_length;
  if (rest_length == 0.0) {
    return new ceres::AutoDiffCostFunction<ZeroLengthSpring, 3, 3, 3>(
        new ZeroLengthSpring(inv_length));
  }
  return new ceres::AutoDiffCostFunction<Spring, 1, 3, 3>(
      new Spring(rest_length, inv_length));
}

}  // namespace archgeo
