// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The standing-wave energies [Gebreiter 2012, §8.3.1–8.3.2; Zhang et al.
// 2010]: values at known angles (the transfer is exact for θ_j = θ_i + α,
// φ_j = φ_i + β under every matching), autodiff against numeric derivatives.
#include <cmath>
#include <memory>
#include <vector>

#include <ceres/cost_function.h>
#include <gtest/gtest.h>

#include "energies/autodiff.h"
#include "energies/wave_elements.h"
#include "energies/wave_feature.h"
#include "energies/wave_norm.h"
#include "energies/wave_product.h"
#include "energies/wave_transfer.h"
#include "tests/energy_checks.h"

namespace archgeo {
namespace {

using namespace energy_checks;
constexpr double kExact = 1e-12;

std::vector<double> WaveOf(double theta, double phi) {
  return {std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi),
          std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi)};
}

// j's angles (θ_j, φ_j) such that i's θ at j is s_θ · ang_j[src_θ] = θ_i + α
// and i's φ at j is s_φ · ang_j[src_φ] = φ_i + β.
std::vector<double> MatchedWave(double ti, double pi, double a, double b, int src_t, double s_t,
                                double s_p) {
  double ang[2];
  ang[src_t] = s_t * (ti + a);
  ang[1 - src_t] = s_p * (pi + b);
  return WaveOf(ang[0], ang[1]);
}

TEST(WaveTransfer, ExactForEveryMatchingAndGradientsMatch) {
  const double ti = 0.7, pi = -1.3, a = 0.4, b = -0.25;
  for (int src_t : {0, 1}) {
    for (double s_t : {1.0, -1.0}) {
      for (double s_p : {1.0, -1.0}) {
        std::unique_ptr<ceres::CostFunction> cost(
            MakeAutoDiff(WaveTransfer(a, b, src_t, s_t, 1 - src_t, s_p)));
        const std::vector<double> r =
            Evaluate(*cost, {WaveOf(ti, pi), MatchedWave(ti, pi, a, b, src_t, s_t, s_p)});
        EXPECT_LT(SquaredNorm(r), kExact) << src_t << " " << s_t << " " << s_p;
        // A wrong phase on θ: |r|² = |f_j − f_j'|² with θ off by 0.3.
        const std::vector<double> off = Evaluate(
            *cost, {WaveOf(ti, pi), MatchedWave(ti, pi, a + 0.3, b, src_t, s_t, s_p)});
        EXPECT_NEAR(SquaredNorm(off), 2 - 2 * std::cos(0.3), 1e-12);
        ExpectGradientsMatch(*cost, {{0.3, -0.2, 0.5, 0.1}, {-0.4, 0.6, 0.2, -0.7}});
      }
    }
  }
}

// The thesis' c_ij is the first row of C_ij: cos α cos β, −cos α sin β,
// −sin α cos β, sin α sin β.
TEST(WaveTransfer, FirstRowIsTheThesisCij) {
  const double a = 0.3, b = 1.1;
  const WaveTransfer t(a, b, 0, 1, 1, 1);
  EXPECT_NEAR(t.C[0], std::cos(a) * std::cos(b), kExact);
  EXPECT_NEAR(t.C[1], -std::cos(a) * std::sin(b), kExact);
  EXPECT_NEAR(t.C[2], -std::sin(a) * std::cos(b), kExact);
  EXPECT_NEAR(t.C[3], std::sin(a) * std::sin(b), kExact);
}

TEST(WaveNorm, UnitVectorsAndGradients) {
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(WaveNorm()));
  EXPECT_NEAR(Evaluate(*cost, {WaveOf(0.4, 2.0)})[0], 0.0, kExact);
  EXPECT_NEAR(Evaluate(*cost, {{0.5, 0.5, 0.5, 0.0}})[0], -0.25, kExact);
  ExpectGradientsMatch(*cost, {{0.3, -0.2, 0.5, 0.1}});
}

TEST(WaveProduct, RankOneAndGradients) {
  std::unique_ptr<ceres::CostFunction> cost(MakeAutoDiff(WaveProduct()));
  EXPECT_NEAR(Evaluate(*cost, {WaveOf(0.4, 2.0)})[0], 0.0, kExact);
  EXPECT_NEAR(Evaluate(*cost, {{0.5, 0.5, -0.5, 0.5}})[0], 0.5, kExact);
  ExpectGradientsMatch(*cost, {{0.3, -0.2, 0.5, 0.1}});
}

TEST(WaveFeature, SinesOfTheConstrainedAnglesAndGradients) {
  namespace wd = wave_data;
  std::unique_ptr<ceres::CostFunction> phi(MakeAutoDiff(WaveFeature(wd::kSinPhi)));
  std::unique_ptr<ceres::CostFunction> theta(MakeAutoDiff(WaveFeature(wd::kSinTheta)));
  std::unique_ptr<ceres::CostFunction> corner(MakeAutoDiff(WaveFeature(wd::kCorner)));
  // |r| = |sin φ| (or |sin θ|) for a unit f.
  EXPECT_NEAR(std::sqrt(SquaredNorm(Evaluate(*phi, {WaveOf(0.4, 0.3)}))), std::sin(0.3), kExact);
  EXPECT_NEAR(std::sqrt(SquaredNorm(Evaluate(*theta, {WaveOf(0.4, 0.3)}))), std::sin(0.4), kExact);
  EXPECT_LT(SquaredNorm(Evaluate(*phi, {WaveOf(0.4, M_PI)})), kExact);
  EXPECT_LT(SquaredNorm(Evaluate(*theta, {WaveOf(M_PI, 0.4)})), kExact);
  EXPECT_LT(SquaredNorm(Evaluate(*corner, {WaveOf(M_PI, 0.0)})), kExact);
  EXPECT_GT(SquaredNorm(Evaluate(*corner, {WaveOf(0.0, 0.2)})), 0.03);
  for (const auto* c : {phi.get(), theta.get(), corner.get()}) {
    ExpectGradientsMatch(*c, {{0.3, -0.2, 0.5, 0.1}});
  }
}

}  // namespace
}  // namespace archgeo
