#include "energies/level_set_normalised.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeLevelSetNormalised(const double corners[6], const double v[2],
                                            double inv_total_area, double gradient_scale) {
  CHECK(corners != nullptr && v != nullptr);
  for (int i = 0; i < 6; ++i) CHECK(std::isfinite(corners[i])) << "MakeLevelSetNormalised: corners";
  CHECK(std::isfinite(v[0]) && std::isfinite(v[1]) && (v[0] != 0.0 || v[1] != 0.0))
      << "MakeLevelSetNormalised: v must be finite and nonzero";
  CHECK(std::isfinite(inv_total_area) && inv_total_area > 0.0)
      << "MakeLevelSetNormalised: inv_total_area must be finite and > 0";
  CHECK(std::isfinite(gradient_scale) && gradient_scale > 0.0)
      << "MakeLevelSetNormalised: gradient_scale must be finite and > 0";
  CHECK(TriangleGradient(corners).area > 0.0)
      << "MakeLevelSetNormalised: corners must be counter-clockwise with positive area";
  return new ceres::AutoDiffCostFunction<LevelSetNormalised, 1, 1, 1, 1>(
      new LevelSetNormalised(corners, v, inv_total_area, gradient_scale));
}

}  // namespace archgeo
