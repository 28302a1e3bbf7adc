#include "energies/fairness.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeFairness(const double target[3], double inv_length) {
  CHECK(target != nullptr);
  CHECK(std::isfinite(target[0]) && std::isfinite(target[1]) &&
        std::isfinite(target[2]))
      << "MakeFairness: non-finite target";
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeFairness: inv_length must be finite and > 0, got " << inv_length;
  return new ceres::AutoDiffCostFunction<Fairness, 3, 3, 3, 3>(
      new Fairness(target, inv_length));
}

ceres::CostFunction* MakeFairnessThird(const double target[3],
                                       double inv_length) {
  CHECK(target != nullptr);
  CHECK(std::isfinite(target[0]) && std::isfinite(target[1]) &&
        std::isfinite(target[2]))
      << "MakeFairnessThird: non-finite target";
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeFairnessThird: inv_length must be finite and > 0, got "
      << inv_length;
  return new ceres::AutoDiffCostFunction<FairnessThird, 3, 3, 3, 3, 3>(
      new FairnessThird(target, inv_length));
}

}  // namespace archgeo
