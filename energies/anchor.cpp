#include "energies/anchor.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeAnchor(const double target[3], double inv_length) {
  CHECK(target != nullptr);
  CHECK(std::isfinite(target[0]) && std::isfinite(target[1]) &&
        std::isfinite(target[2]))
      << "MakeAnchor: non-finite target";
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeAnchor: inv_length must be finite and > 0, got " << inv_length;
  return new ceres::AutoDiffCostFunction<Anchor, 3, 3>(
      new Anchor(target, inv_length));
}

}  // namespace archgeo
