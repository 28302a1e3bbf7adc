#include "energies/tcd_prescribed_direction.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeTcdPrescribedDirection(const double m[3], const double direction[2]) {
  CHECK(m != nullptr && direction != nullptr);
  CHECK(std::isfinite(m[0]) && std::isfinite(m[1]) && std::isfinite(m[2]))
      << "MakeTcdPrescribedDirection: non-finite M";
  CHECK(std::isfinite(direction[0]) && std::isfinite(direction[1]))
      << "MakeTcdPrescribedDirection: non-finite direction";
  Eigen::Vector2d point, line;
  CHECK(TcdPrescribedLine(m, direction, &point, &line))
      << "MakeTcdPrescribedDirection: every direction is conjugate to the prescribed one "
         "(M d = 0) or d = 0; check with TcdPrescribedLine first";
  return new ceres::AutoDiffCostFunction<TcdPrescribedDirection, 1, 2>(
      new TcdPrescribedDirection(point, line));
}

}  // namespace archgeo
