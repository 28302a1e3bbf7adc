#include "energies/load.h"

#include <cmath>

#include <ceres/dynamic_autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {
namespace {

// Jet size of the dynamic autodiff: 12 of the 3(n + 1) parameters per pass.
constexpr int kStride = 12;

}  // namespace

ceres::CostFunction* MakeLoadEquilibrium(const double force[3],
                                         const std::vector<double>& stiffness,
                                         const std::vector<double>& rest_length,
                                         double inv_force) {
  CHECK(force != nullptr);
  CHECK(std::isfinite(force[0]) && std::isfinite(force[1]) &&
        std::isfinite(force[2]))
      << "MakeLoadEquilibrium: non-finite force";
  CHECK_GE(stiffness.size(), 1u) << "MakeLoadEquilibrium: no spring";
  CHECK_EQ(stiffness.size(), rest_length.size())
      << "MakeLoadEquilibrium: one rest length per spring";
  for (size_t j = 0; j < stiffness.size(); ++j) {
    CHECK(std::isfinite(stiffness[j]) && stiffness[j] > 0.0)
        << "MakeLoadEquilibrium: stiffness must be finite and > 0, got "
        << stiffness[j];
    CHECK(std::isfinite(rest_length[j]) && rest_length[j] >= 0.0)
        << "MakeLoadEquilibrium: rest length must be finite and >= 0, got "
        << rest_length[j];
  }
  CHECK(std::isfinite(inv_force) && inv_force > 0.0)
      << "MakeLoadEquilibrium: inv_force must be finite and > 0, got "
      << inv_force;
  auto* cost = new ceres::DynamicAutoDiffCostFunction<LoadEquilibrium, kStride>(
      new LoadEquilibrium(force, stiffness, rest_length, inv_force));
  for (size_t j = 0; j <= stiffness.size(); ++j) cost->AddParameterBlock(3);
  cost->SetNumResiduals(3);
  return cost;
}

}  // namespace archgeo
