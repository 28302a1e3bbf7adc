#include "energies/laplacian.h"

#include <cmath>

#include <ceres/dynamic_autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {
namespace {

// Jet size of the dynamic autodiff: 12 of the 3(n + 1) parameters per pass.
constexpr int kStride = 12;

}  // namespace

ceres::CostFunction* MakeLaplacian(int valence, double inv_length) {
  CHECK_GE(valence, 1) << "MakeLaplacian: valence must be >= 1";
  return MakeWeightedLaplacian(std::vector<double>(valence, 1.0), inv_length);
}

ceres::CostFunction* MakeWeightedLaplacian(const std::vector<double>& weights,
                                           double inv_length) {
  CHECK_GE(weights.size(), 1u) << "MakeWeightedLaplacian: no neighbour";
  double sum = 0.0;
  for (double c : weights) {
    CHECK(std::isfinite(c)) << "MakeWeightedLaplacian: non-finite weight";
    sum += c;
  }
  CHECK(sum > 0.0) << "MakeWeightedLaplacian: the weights must have a "
                      "positive sum, got "
                   << sum;
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeWeightedLaplacian: inv_length must be finite and > 0, got "
      << inv_length;
  auto* cost = new ceres::DynamicAutoDiffCostFunction<Laplacian, kStride>(
      new Laplacian(weights, inv_length));
  for (size_t j = 0; j <= weights.size(); ++j) cost->AddParameterBlock(3);
  cost->SetNumResiduals(3);
  return cost;
}

}  // namespace archgeo
