#include "energies/level_set_conjugacy.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeLevelSetConjugacy(const double corners[6], const double m[3],
                                           double gradient_scale) {
  CHECK(corners != nullptr && m != nullptr);
  for (int i = 0; i < 6; ++i) CHECK(std::isfinite(corners[i])) << "MakeLevelSetConjugacy: corners";
  CHECK(std::isfinite(m[0]) && std::isfinite(m[1]) && std::isfinite(m[2]))
      << "MakeLevelSetConjugacy: non-finite M";
  CHECK(std::isfinite(gradient_scale) && gradient_scale > 0.0)
      << "MakeLevelSetConjugacy: gradient_scale must be finite and > 0";
  CHECK(TriangleGradient(corners).area > 0.0)
      << "MakeLevelSetConjugacy: corners must be counter-clockwise with positive area";
  return new ceres::AutoDiffCostFunction<LevelSetConjugacy, 1, 1, 1, 1, 1, 1, 1>(
      new LevelSetConjugacy(corners, m, gradient_scale));
}

}  // namespace archgeo
