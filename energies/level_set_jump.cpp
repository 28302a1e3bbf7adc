#include "energies/level_set_jump.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeLevelSetJump(int sign, double inv_length) {
  CHECK(sign == 1 || sign == -1) << "MakeLevelSetJump: sign must be +1 or -1, got " << sign;
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeLevelSetJump: inv_length must be finite and > 0";
  return new ceres::AutoDiffCostFunction<LevelSetJump, 1, 1, 1, 1>(
      new LevelSetJump(sign, inv_length));
}

}  // namespace archgeo
