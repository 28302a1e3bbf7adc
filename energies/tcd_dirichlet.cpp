#include "energies/tcd_dirichlet.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakeTcdDirichlet(double transport_angle, double weight) {
  CHECK(std::isfinite(transport_angle)) << "MakeTcdDirichlet: non-finite transport angle";
  CHECK(std::isfinite(weight) && weight >= 0.0)
      << "MakeTcdDirichlet: weight must be finite and >= 0, got " << weight;
  return new ceres::AutoDiffCostFunction<TcdDirichlet, 2, 2, 2>(
      new TcdDirichlet(transport_angle, weight));
}

}  // namespace archgeo
