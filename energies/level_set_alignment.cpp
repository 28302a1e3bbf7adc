#include "energies/level_set_alignment.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeLevelSetAlignment(const double corners[6], const double v[2],
                                           double inv_total_area) {
  CHECK(corners != nullptr && v != nullptr);
  for (int i = 0; i < 6; ++i) CHECK(std::isfinite(corners[i])) << "MakeLevelSetAlignment: corners";
  CHECK(std::isfinite(v[0]) && std::isfinite(v[1])) << "MakeLevelSetAlignment: non-finite v";
  CHECK(std::isfinite(inv_total_area) && inv_total_area > 0.0)
      << "MakeLevelSetAlignment: inv_total_area must be finite and > 0";
  CHECK(TriangleGradient(corners).area > 0.0)
      << "MakeLevelSetAlignment: corners must be counter-clockwise with positive area";
  return new ceres::AutoDiffCostFunction<LevelSetAlignment, 2, 1, 1, 1>(
      new LevelSetAlignment(corners, v, inv_total_area));
}

}  // namespace archgeo
