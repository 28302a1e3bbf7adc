#include "energies/level_set_branch_point.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeLevelSetBranchPoint(int sign, double inv_length) {
  CHECK(sign == 1 || sign == -1) << "MakeLevelSetBranchPoint: sign must be +1 or -1, got " << sign;
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeLevelSetBranchPoint: inv_length must be finite and > 0";
  return new ceres::AutoDiffCostFunction<LevelSetBranchPoint, 1, 1, 1>(
      new LevelSetBranchPoint(sign, inv_length));
}

}  // namespace archgeo
