#include "energies/tcd_singularity_avoidance.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeTcdSingularityAvoidance(const double z_m[2], double radius) {
  CHECK(z_m != nullptr);
  CHECK(std::isfinite(z_m[0]) && std::isfinite(z_m[1]))
      << "MakeTcdSingularityAvoidance: z_M must be finite (skip faces with z_M at infinity)";
  CHECK(std::isfinite(radius) && radius > 0.0)
      << "MakeTcdSingularityAvoidance: radius must be finite and > 0, got " << radius;
  return new ceres::AutoDiffCostFunction<TcdSingularityAvoidance, 1, 2>(
      new TcdSingularityAvoidance(z_m, radius));
}

}  // namespace archgeo
