// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo's automatic differentiation (energies/autodiff.h) and batches
// (core/batch.h): a functor's cost function and its batch element evaluate
// to the bits of ceres::AutoDiffCostFunction (inside a ToleranceBand when
// banded), and a residual list of batch elements gives LeanSolve and Ceres
// (MakeProblem) the same problem as one cost object per element.
#include <gtest/gtest.h>

#include <ceres/ceres.h>

#include <memory>
#include <random>
#include <vector>

#include "core/batch.h"
#include "core/lean_solve.h"
#include "core/residuals.h"
#include "core/tolerance_band.h"
#include "energies/autodiff_impl.h"
#include "energies/convexity.h"
#include "energies/dihedral_energy.h"
#include "energies/fairness.h"
#include "energies/pq_diagonal.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using PqCost = ceres::AutoDiffCostFunction<PqDiagonal, 1, 3, 3, 3, 3>;
using PqBatch = autodiff::FunctorBatch<PqDiagonal>;

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
      ceres::CostFunction* cost = new PqCost(new PqDiagonal(inv_length));
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

// MakeAutoDiff's cost function gives the bits of Ceres' for functors of
// several shapes (1 to 3 residuals, 3 to 4 blocks), Jacobians of some blocks
// left out.
TEST(AutoDiff, ACostFunctionGivesTheBitsOfCeres) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double target[3] = {0.1, -0.2, 0.3};
  const std::vector<std::pair<std::unique_ptr<ceres::CostFunction>,
                              std::unique_ptr<ceres::CostFunction>>>
      pairs = [&] {
        std::vector<std::pair<std::unique_ptr<ceres::CostFunction>,
                              std::unique_ptr<ceres::CostFunction>>>
            p;
        p.emplace_back(MakeAutoDiff(PqDiagonal(0.7)), new PqCost(new PqDiagonal(0.7)));
        p.emplace_back(MakeAutoDiff(Fairness(target, 1.3)),
                       new ceres::AutoDiffCostFunction<Fairness, 3, 3, 3, 3>(
                           new Fairness(target, 1.3)));
        p.emplace_back(MakeAutoDiff(DihedralTriTri(0.9, 0.4)),
                       new ceres::AutoDiffCostFunction<DihedralTriTri, 3, 3, 3, 3, 3>(
                           new DihedralTriTri(0.9, 0.4)));
        return p;
      }();
  for (const auto& [mine, theirs] : pairs) {
    ASSERT_EQ(mine->num_residuals(), theirs->num_residuals());
    ASSERT_EQ(mine->parameter_block_sizes(), theirs->parameter_block_sizes());
    const int rows = mine->num_residuals();
    const std::vector<int32_t>& sizes = mine->parameter_block_sizes();
    for (int trial = 0; trial < 10; ++trial) {
      std::vector<std::vector<double>> x;
      std::vector<const double*> blocks;
      for (int32_t s : sizes) {
        x.emplace_back(size_t(s));
        for (double& v : x.back()) v = u(random);
      }
      for (const auto& b : x) blocks.push_back(b.data());
      std::vector<std::vector<double>> jm, jt;
      std::vector<double*> pm, pt;
      for (size_t b = 0; b < sizes.size(); ++b) {
        jm.emplace_back(size_t(rows * sizes[b]), 7.0);
        jt.emplace_back(size_t(rows * sizes[b]), -7.0);
        const bool skip = (trial + int(b)) % 3 == 0;  // a block without Jacobian
        pm.push_back(skip ? nullptr : jm.back().data());
        pt.push_back(skip ? nullptr : jt.back().data());
      }
      std::vector<double> rm(static_cast<size_t>(rows)), rt(static_cast<size_t>(rows));
      ASSERT_TRUE(mine->Evaluate(blocks.data(), rm.data(), pm.data()));
      ASSERT_TRUE(theirs->Evaluate(blocks.data(), rt.data(), pt.data()));
      EXPECT_EQ(rm, rt);
      EXPECT_EQ(jm.size(), jt.size());
      for (size_t b = 0; b < sizes.size(); ++b) {
        if (pm[b]) {
          EXPECT_EQ(jm[b], jt[b]) << "block " << b;
        }
      }
      // Without Jacobians: the functor on doubles, on both sides (its value
      // may differ from the Jets' in the last bit: a Jet divides by
      // multiplying with the inverse).
      ASSERT_TRUE(mine->Evaluate(blocks.data(), rm.data(), nullptr));
      ASSERT_TRUE(theirs->Evaluate(blocks.data(), rt.data(), nullptr));
      EXPECT_EQ(rm, rt);
    }
  }
}

// A barrier (kFlatWhereZero) element is differentiated only where it is not
// idle: bit-equal residual and Jacobians to its AutoDiffCostFunction on idle
// corners (zero Jacobians written over garbage) and on violated ones.
TEST(Batch, AnIdleBarrierElementGivesTheBitsOfItsCostFunction) {
  using ConvexityCost = ceres::AutoDiffCostFunction<Convexity, 1, 3, 3, 3>;
  autodiff::FunctorBatch<Convexity> batch(-1.0);
  const double normal[3] = {0, 0, 1};
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int idle = 0, violated = 0;
  for (int k = 0; k < 40; ++k) {
    const double threshold = 0.05 * (k % 7);
    const int element = batch.Push(Convexity(normal, threshold));
    const std::unique_ptr<ceres::CostFunction> cost(
        new ConvexityCost(new Convexity(normal, threshold)));
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
        r.Add(MakeAutoDiff(PqDiagonal(1.0 + 0.01 * i)), loss, blocks, 4);
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
