#include "energies/tcd_singularity_placement.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeTcdSingularityPlacement(const double z_m[2]) {
  CHECK(z_m != nullptr);
  CHECK(std::isfinite(z_m[0]) && std::isfinite(z_m[1]))
      << "MakeTcdSingularityPlacement: z_M must be finite";
  return new ceres::AutoDiffCostFunction<TcdSingularityPlacement, 2, 2>(
      new TcdSingularityPlacement(z_m));
}

}  // namespace archgeo
