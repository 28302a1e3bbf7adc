#include "energies/tcd_transversality.h"

#include <ceres/autodiff_cost_function.h>

namespace archgeo {

ceres::CostFunction* MakeTcdTransversality() {
  return new ceres::AutoDiffCostFunction<TcdTransversality, 1, 2>(new TcdTransversality());
}

}  // namespace archgeo
