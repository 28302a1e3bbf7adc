// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Batches (core/batch.h): an element evaluates to the bits of its
// ceres::AutoDiffCostFunction (inside a ToleranceBand when banded), and a
// residual list of batch elements gives LeanSolve and Ceres (MakeProblem) the
// same problem as one cost object per element.
#include <gtest/gtest.h>

#include <ceres/ceres.h>

#include <memory>
#include <random>
#include <vector>

#include "core/batch.h"
#include "core/lean_solve.h"
#include "core/residuals.h"
#include "core/tolerance_band.h"
#include "energies/convexity.h"
#include "energies/pq_diagonal.h"

namespace archgeo {
namespace {

using PqCost = ceres::AutoDiffCostFunction<PqDiagonal, 1, 3, 3, 3, 3>;
using PqBatch = BatchOf<PqCost>::type;

// Residual and Jacobians of `cost` at `x` (four 3-blocks).
std::vector<double> Evaluate(const ceres::CostFunction& cost, const std::vector<double>& x) {
  const double* blocks[4] = {&x[0], &x[3], &x[6], &x[9]};
  std::vector<double> out(1 + 12);
  double* jacobians[4] = {&out[1], &out[4], &out[7], &out[10]};
  EXPECT_TRUE(cost.Evaluate(blocks, out.data(), jacobians));
  return out;
}

TEST(Batch, AnElementGivesTheBitsOfItsCostFunction) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const double band : {-1.0, 0.0, 0.05, 10.0}) {
    PqBatch batch(band);
    std::vector<std::unique_ptr<ceres::CostFunction>> costs;
    for (int k = 0; k < 20; ++k) {
      const double inv_length = 0.5 + 0.1 * k;
      EXPECT_EQ(batch.Push(PqDiagonal(inv_length)), k);
      ceres::CostFunction* cost = MakePqDiagonal(inv_length);
      costs.emplace_back(band >= 0 ? new ToleranceBand(cost, band) : cost);
    }
    int zeroed = 0;
    for (int k = 0; k < 20; ++k) {
      std::vector<double> x(12);
      for (double& v : x) v = u(random);
      const BatchElement element(batch, k);
      const std::vector<double> mine = Evaluate(element, x);
      const std::vector<double> theirs = Evaluate(*costs[size_t(k)], x);
      for (size_t i = 0; i < mine.size(); ++i) EXPECT_EQ(mine[i], theirs[i]) << band << " " << k;
      zeroed += mine[1] == 0.0 && mine[0] == 0.0;
    }
    // The band 10 holds every residual, so it zeroes every Jacobian.
    if (band == 10.0) {
      EXPECT_EQ(zeroed, 20);
    }
    if (band < 0) {
      EXPECT_EQ(zeroed, 0);
    }
  }
}

// A barrier (kFlatWhereZero) element is differentiated only where it is not
// idle: bit-equal residual and Jacobians to its AutoDiffCostFunction on idle
// corners (zero Jacobians written over garbage) and on violated ones.
TEST(Batch, AnIdleBarrierElementGivesTheBitsOfItsCostFunction) {
  using ConvexityCost = ceres::AutoDiffCostFunction<Convexity, 1, 3, 3, 3>;
  BatchOf<ConvexityCost>::type batch(-1.0);
  const double normal[3] = {0, 0, 1};
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int idle = 0, violated = 0;
  for (int k = 0; k < 40; ++k) {
    const double threshold = 0.05 * (k % 7);
    const int element = batch.Push(Convexity(normal, threshold));
    const std::unique_ptr<ceres::CostFunction> cost(MakeConvexity(normal, threshold));
    std::vector<double> x(9);
    for (double& v : x) v = u(random);
    const double* blocks[3] = {&x[0], &x[3], &x[6]};
    std::vector<double> mine(10, 7.0), theirs(10, -7.0);
    double* mj[3] = {&mine[1], &mine[4], &mine[7]};
    double* tj[3] = {&theirs[1], &theirs[4], &theirs[7]};
    ASSERT_TRUE(batch.Evaluate(element, blocks, mine.data(), mj));
    ASSERT_TRUE(cost->Evaluate(blocks, theirs.data(), tj));
    EXPECT_EQ(mine, theirs) << k;
    (theirs[0] == 0.0 ? idle : violated) += 1;
  }
  EXPECT_GT(idle, 5);
  EXPECT_GT(violated, 5);
}

// Noisy quads pulled planar against anchors: n quads over shared corners.
struct Strip {
  std::vector<double> x;
  explicit Strip(int n) : x(3 * size_t(2 * n + 2)) {
    std::mt19937 random(3);
    std::normal_distribution<double> noise(0.0, 0.2);
    for (int i = 0; i <= n; ++i) {
      for (int side = 0; side < 2; ++side) {
        double* p = &x[3 * size_t(2 * i + side)];
        p[0] = i + noise(random);
        p[1] = side + noise(random);
        p[2] = noise(random);
      }
    }
  }
  double* P(int i, int side) { return &x[3 * size_t(2 * i + side)]; }
  // Quad planarity (batched or not; L differs per quad) and a pull per corner.
  void AddTo(Residuals& r, bool batched, const ceres::LossFunction* loss) {
    const int n = int(x.size() / 6) - 1;
    PqBatch* batch = batched ? static_cast<PqBatch*>(r.Own(std::make_unique<PqBatch>(-1.0)))
                             : nullptr;
    for (int i = 0; i < n; ++i) {
      double* blocks[4] = {P(i, 0), P(i + 1, 0), P(i + 1, 1), P(i, 1)};
      if (batched) {
        r.Add(batch, batch->Push(PqDiagonal(1.0 + 0.01 * i)), loss, blocks, 4);
      } else {
        r.Add(MakePqDiagonal(1.0 + 0.01 * i), loss, blocks, 4);
      }
    }
    for (size_t v = 0; v < x.size() / 3; ++v) {
      double* block = &x[3 * v];
      r.Add(new ceres::AutoDiffCostFunction<Pull, 3, 3>(new Pull{block[0], block[1], block[2]}),
            nullptr, &block, 1);
    }
  }
  // r = 0.1 (p − target): keeps the strip where it was.
  struct Pull {
    template <typename T>
    bool operator()(const T* p, T* r) const {
      for (int k = 0; k < 3; ++k) r[k] = T(0.1) * (p[k] - T(target[k]));
      return true;
    }
    double target[3];
  };
};

TEST(Batch, LeanSolveAndCeresSolveBatchElementsAsCostObjects) {
  const ceres::ScaledLoss loss(nullptr, 10.0, ceres::DO_NOT_TAKE_OWNERSHIP);
  Strip a(30), b(30), c(30);
  Residuals ra, rb, rc;
  a.AddTo(ra, true, &loss);
  b.AddTo(rb, false, &loss);
  c.AddTo(rc, true, &loss);
  for (int i = 0; i < int(ra.residuals().size()); ++i) EXPECT_EQ(ra.Cost(i), rb.Cost(i));

  ceres::Solver::Options options;
  // LeanSolve's inexact steps (CG ended by eta = 0.1, Nash and Sofer's test
  // as in Ceres) take ~50 iterations to the optimum a direct solve reaches.
  options.max_num_iterations = 100;
  const SolveSummary lean_batched = LeanSolve(options, ra, nullptr);
  const SolveSummary lean_objects = LeanSolve(options, rb, nullptr);
  ASSERT_TRUE(lean_batched.usable);
  EXPECT_EQ(a.x, b.x);  // the same bits
  EXPECT_EQ(lean_batched.final_cost, lean_objects.final_cost);
  EXPECT_LT(lean_batched.final_cost, 1e-3 * lean_batched.initial_cost + 1e-12);

  // Ceres on the batched list (MakeProblem views the elements) starts from
  // the same cost (up to the order of its sum: LeanSolve sums by thread) and
  // reaches the same optimal cost.
  const std::unique_ptr<ceres::Problem> problem = rc.MakeProblem();
  ceres::Solver::Summary summary;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.function_tolerance = 1e-14;
  ceres::Solve(options, problem.get(), &summary);
  ASSERT_TRUE(summary.IsSolutionUsable());
  EXPECT_DOUBLE_EQ(summary.initial_cost, lean_batched.initial_cost);
  EXPECT_NEAR(summary.final_cost, lean_batched.final_cost, 1e-6 * summary.initial_cost);
}

}  // namespace
}  // namespace archgeo
