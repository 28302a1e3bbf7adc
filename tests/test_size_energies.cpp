// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The curl correction's energies [Gebreiter 2012, §8.1.4; Zhang et al.
// 2010]: values at known log sizes (every corner's source), autodiff against
// numeric derivatives. The discretisation and the solve:
// tests/test_size_curl.cpp.
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include <ceres/cost_function.h>
#include <gtest/gtest.h>

#include "energies/autodiff.h"
#include "energies/size_curl.h"
#include "energies/size_smoothing.h"
#include "energies/size_target.h"
#include "tests/energy_checks.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using namespace energy_checks;
constexpr double kSizeExact = 1e-12;

// r = a + Σ g_k s_k[source_k]: each corner reads the log size its source names.
TEST(SizeCurl, ValuesForEverySourceAndGradientsMatch) {
  const Blocks s = {{0.3, -0.7}, {1.1, 0.4}, {-0.2, 0.9}};
  const std::array<double, 3> g = {0.5, -1.5, 2.0};
  for (int code = 0; code < 8; ++code) {
    const std::array<int, 3> source = {code & 1, (code >> 1) & 1, (code >> 2) & 1};
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(SizeCurl(0.25, g, source)));
    double expected = 0.25;
    for (int k = 0; k < 3; ++k) expected += g[size_t(k)] * s[size_t(k)][size_t(source[size_t(k)])];
    EXPECT_NEAR(Evaluate(*cost, s)[0], expected, kSizeExact) << code;
    ExpectGradientsMatch(*cost, s);
  }
}

// (w_μ (μ̃ − t_μ), w_η (η̃ − t_η)).
TEST(SizeTarget, ValuesAndGradients) {
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(SizeTarget(0.5, -1.0, 2.0, 3.0)));
  const std::vector<double> r = Evaluate(*cost, {{1.5, 0.0}});
  EXPECT_NEAR(r[0], 2.0, kSizeExact);
  EXPECT_NEAR(r[1], 3.0, kSizeExact);
  EXPECT_LT(SquaredNorm(Evaluate(*cost, {{0.5, -1.0}})), kSizeExact);
  ExpectGradientsMatch(*cost, {{0.3, -0.2}});
}

// (μ̃_i − μ̃_j^(i), η̃_i − η̃_j^(i)), j's sizes swapped when source_mu = 1.
TEST(SizeSmoothing, MatchedDifferencesAndGradients) {
  for (int source : {0, 1}) {
    std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(SizeSmoothing(source)));
    const std::vector<double> r = Evaluate(*cost, {{1.0, 2.0}, {0.25, 0.5}});
    EXPECT_NEAR(r[0], source == 0 ? 0.75 : 0.5, kSizeExact);
    EXPECT_NEAR(r[1], source == 0 ? 1.5 : 1.75, kSizeExact);
    ExpectGradientsMatch(*cost, {{0.3, -0.2}, {0.7, 0.1}});
  }
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
