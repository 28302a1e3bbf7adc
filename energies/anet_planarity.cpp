#include "energies/anet_planarity.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

std::vector<std::array<int, 3>> AnetStarQuadNeighbours(int valence) {
  CHECK_GE(valence, 3) << "AnetStarQuadNeighbours: a star needs >= 3 neighbours";
  std::vector<std::array<int, 3>> quads;
  quads.reserve(valence - 2);
  for (int i = 0; i + 2 < valence; ++i) quads.push_back({i, i + 1, i + 2});
  return quads;
}

ceres::CostFunction* MakeAnetVertexNormal(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeAnetVertexNormal: inv_length must be finite and > 0, got "
      << inv_length;
  return new ceres::AutoDiffCostFunction<AnetVertexNormal, 1, 3, 3, 3>(
      new AnetVertexNormal(inv_length));
}

ceres::CostFunction* MakeAnetStarQuad(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakeAnetStarQuad: inv_length must be finite and > 0, got "
      << inv_length;
  return new ceres::AutoDiffCostFunction<AnetStarQuad, 1, 3, 3, 3, 3>(
      new AnetStarQuad(inv_length));
}

}  // namespace archgeo
