// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// LeanSolve (core/lean_solve.h): Levenberg–Marquardt with block-Jacobi PCG on
// the assembled normal equations reaches Ceres' optimum on a linear and on a
// non-linear problem with a manifold and a robust loss, keeps constant blocks,
// obeys callbacks (with finite gradient norms), gives the same bits for the
// same number of threads, refuses the options it does not implement, and
// planar_quads solved with it meets its tolerance with the displacement of
// Ceres' direct solve.
#include <gtest/gtest.h>

#include <ceres/ceres.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <filesystem>
#include <fstream>
#include <string>
#include <memory>
#include <type_traits>
#include <vector>

#include "core/lean_solve.h"
#include "core/lean_kernels.h"
#include "core/normal_cholesky.h"
#include "core/normal_equations.h"
#include "generators/generators.h"
#include "analysis/metrics.h"
#include "mesh/similarity.h"
#include "problems/runtime/solve.h"
#include "tests/scratch_dir.h"
#include "tests/shell.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

// r = w (x − y), or w (x − target).
struct Difference {
  template <typename T>
  bool operator()(const T* x, const T* y, T* r) const {
    r[0] = T(w) * (x[0] - y[0]);
    return true;
  }
  double w;
};
struct Data {
  template <typename T>
  bool operator()(const T* x, T* r) const {
    r[0] = T(w) * (x[0] - target);
    return true;
  }
  double w, target;
};

// Adds `cost` over `blocks` to `residuals`.
void Add(Residuals& residuals, ceres::CostFunction* cost, const ceres::LossFunction* loss,
         std::vector<double*> blocks) {
  residuals.Add(cost, loss, blocks.data(), int(blocks.size()));
}

// A membrane on an n × n grid: data terms pull each value to a rough target,
// differences tie neighbours (a 2-D graph like a mesh's normal equations).
struct Membrane {
  int n;
  std::vector<double> x;
  Residuals residuals;
  // by_term: all data terms first, then all differences (as a round adds
  // its terms one after another); else cell by cell.
  double data = 0.5;  // the data terms' weight (small: a stiffer membrane)
  explicit Membrane(int size, bool by_term = false, double data_weight = 0.5)
      : n(size), x(size * size, 0.0), data(data_weight) {
    AddTo(residuals, by_term);
  }
  // The membrane's residual blocks over `x`, into `r` (in the same order).
  void AddTo(Residuals& r, bool by_term = false) {
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const double target = std::sin(0.7 * i) * std::cos(1.3 * j) + ((i * 7 + j * 3) % 5) * 0.1;
        Add(r, new ceres::AutoDiffCostFunction<Data, 1, 1>(new Data{data, target}), nullptr,
            {&x[i * n + j]});
        if (!by_term) AddDifferences(r, i, j);
      }
    }
    for (int i = 0; i < n && by_term; ++i) {
      for (int j = 0; j < n; ++j) AddDifferences(r, i, j);
    }
  }
  void AddDifferences(Residuals& r, int i, int j) {
    if (i + 1 < n) {
      Add(r, new ceres::AutoDiffCostFunction<Difference, 1, 1, 1>(new Difference{1.0}), nullptr,
          {&x[i * n + j], &x[(i + 1) * n + j]});
    }
    if (j + 1 < n) {
      Add(r, new ceres::AutoDiffCostFunction<Difference, 1, 1, 1>(new Difference{1.0}), nullptr,
          {&x[i * n + j], &x[i * n + j + 1]});
    }
  }
};

// Signed distance of point p to the plane n·x = d, with n on the unit sphere.
struct PlaneDistance {
  template <typename T>
  bool operator()(const T* n, const T* d, T* r) const {
    r[0] = n[0] * T(p[0]) + n[1] * T(p[1]) + n[2] * T(p[2]) - d[0];
    return true;
  }
  double p[3];
};

// Points near the plane z = 0.3 + 0.2 x − 0.1 y, two of them far off (the
// robust loss discounts them), fitted from a tilted start.
struct PlaneFit {
  double normal[3] = {0.3, -0.2, 0.93};
  double offset = 0;
  Residuals residuals;
  PlaneFit() {
    for (int i = 0; i < 12; ++i) {
      for (int j = 0; j < 12; ++j) {
        const double x = i * 0.1, y = j * 0.1;
        double z = 0.3 + 0.2 * x - 0.1 * y + 0.01 * std::sin(3.0 * i + 5.0 * j);
        if ((i == 3 && j == 4) || (i == 9 && j == 1)) z += 2.0;
        auto* cost = new ceres::AutoDiffCostFunction<PlaneDistance, 1, 3, 1>(
            new PlaneDistance{{x, y, z}});
        Add(residuals, cost,
            residuals.Own(
                new ceres::ScaledLoss(new ceres::CauchyLoss(0.05), 3.0, ceres::TAKE_OWNERSHIP)),
            {normal, &offset});
      }
    }
    const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    for (double& c : normal) c /= length;
    residuals.SetManifold(normal, new ceres::SphereManifold<3>());
  }
};

ceres::Solver::Options Tight() {
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  o.function_tolerance = 1e-15;
  o.gradient_tolerance = 1e-15;
  o.parameter_tolerance = 1e-15;
  o.max_num_iterations = 200;
  o.eta = 1e-10;
  o.max_linear_solver_iterations = 2000;
  return o;
}

// The residuals hand Ceres the same problem: its size, its manifolds and
// constant blocks, and per residual the cost Ceres evaluates.
TEST(LeanSolve, ResidualsGiveCeresTheSameProblem) {
  PlaneFit fit;
  fit.residuals.SetConstant(&fit.offset);
  double unread = 0;
  fit.residuals.SetManifold(&unread, new ceres::SphereManifold<3>());  // no residual reads it
  EXPECT_FALSE(fit.residuals.Has(&unread));
  const std::unique_ptr<ceres::Problem> problem = fit.residuals.MakeProblem();
  EXPECT_EQ(problem->NumResiduals(), fit.residuals.NumResiduals());
  EXPECT_EQ(problem->NumParameters(), fit.residuals.NumParameters());
  EXPECT_EQ(fit.residuals.NumParameters(), 4);
  EXPECT_EQ(fit.residuals.FreeTangentSize(), 2);  // the normal on the sphere; the offset fixed
  EXPECT_EQ(problem->ParameterBlockTangentSize(fit.normal), 2);
  EXPECT_TRUE(problem->IsParameterBlockConstant(&fit.offset));
  std::vector<ceres::ResidualBlockId> ids;
  problem->GetResidualBlocks(&ids);
  ASSERT_EQ(ids.size(), fit.residuals.residuals().size());
  double total = 0, ceres_total = 0;
  for (size_t i = 0; i < ids.size(); ++i) {
    double cost = 0;
    ASSERT_TRUE(problem->EvaluateResidualBlock(ids[i], true, &cost, nullptr, nullptr));
    EXPECT_NEAR(fit.residuals.Cost(int(i)), cost, 1e-15 * std::max(1.0, cost)) << i;
    total += fit.residuals.Cost(int(i));
  }
  problem->Evaluate(ceres::Problem::EvaluateOptions(), &ceres_total, nullptr, nullptr, nullptr);
  EXPECT_NEAR(total, ceres_total, 1e-12 * ceres_total);
  EXPECT_GT(total, 0.1);  // the outliers (Cauchy-discounted) and the tilted start
}

// The residual list's mapped lists (core/mapped_list.h) keep every value
// while they grow (the pages move), are fitted and are cleared and filled
// again.
TEST(LeanSolve, MappedListsKeepTheirValuesThroughGrowthAndFit) {
  MappedList<int> list;
  const int n = 3'000'000;  // 12 MB: the mapping grows and moves ~12 times
  for (int k = 0; k < n; ++k) list.push_back(k * 7);
  ASSERT_EQ(list.size(), size_t(n));
  bool same = true;
  for (int k = 0; k < n; ++k) same = same && list[size_t(k)] == k * 7;
  EXPECT_TRUE(same);
  list.Fit();
  EXPECT_EQ(list.back(), (n - 1) * 7);
  list.clear();
  EXPECT_TRUE(list.empty());
  for (int k = 0; k < 1000; ++k) list.push_back(-k);
  list.Fit();  // shrinks the mapping to one page
  for (int k = 0; k < 5000; ++k) list.push_back(k);
  EXPECT_EQ(list.size(), 6000u);
  EXPECT_EQ(list[999], -999);
  EXPECT_EQ(list[1000], 0);
  EXPECT_EQ(list.back(), 4999);
  list.clear();
  list.Fit();  // no mapping at all
  list.push_back(5);
  EXPECT_EQ(list[0], 5);
  MappedList<int> moved = std::move(list);
  EXPECT_TRUE(list.empty());
  EXPECT_EQ(moved[0], 5);
  MappedList<double> h;  // as J^T J: sized, never initialised
  h.Resize(100000);
  EXPECT_EQ(h.size(), 100000u);
  EXPECT_EQ(h[99999], 0.0);  // a page never written
}

// Each residual keeps its own loss and objective part in its 24 bytes, with
// losses added in turn (as proximity adds its two weights vertex by vertex).
TEST(LeanSolve, EachResidualKeepsItsLossAndPart) {
  Residuals residuals;
  const ceres::LossFunction* losses[2] = {
      residuals.Own(new ceres::ScaledLoss(nullptr, 2.0, ceres::TAKE_OWNERSHIP)),
      residuals.Own(new ceres::CauchyLoss(1.0))};
  const int parts[2] = {residuals.Part("a"), residuals.Part("b")};
  std::vector<double> x(300, 1.0);
  for (int k = 0; k < 300; ++k) {
    double* block = &x[size_t(k)];
    residuals.Add(new ceres::AutoDiffCostFunction<Data, 1, 1>(new Data{1.0, 0.0}),
                  k % 3 == 2 ? nullptr : losses[k % 3], &block, 1, parts[k % 2]);
  }
  for (int k = 0; k < 300; ++k) {
    const Residuals::Residual& r = residuals.residuals()[size_t(k)];
    EXPECT_EQ(residuals.Loss(r.loss()), k % 3 == 2 ? nullptr : losses[k % 3]) << k;
    EXPECT_EQ(r.part(), parts[k % 2]) << k;
  }
  EXPECT_NE(parts[0], parts[1]);
}

TEST(LeanSolve, ReachesCeresOptimumOnALinearProblem) {
  Membrane ceres_side(30), lean_side(30);
  ceres::Solver::Summary reference;
  ceres::Solve(Tight(), ceres_side.residuals.MakeProblem().get(), &reference);
  const SolveSummary lean = LeanSolve(Tight(), lean_side.residuals);
  ASSERT_TRUE(lean.usable) << lean.message;
  EXPECT_TRUE(lean.pcg);
  EXPECT_GT(lean.cg_iterations, 0);
  EXPECT_LT(lean.final_cost, 0.8 * lean.initial_cost);  // 35.8 -> 27.5
  EXPECT_NEAR(lean.final_cost, reference.final_cost, 1e-9 * reference.final_cost);
  double worst = 0;
  for (size_t k = 0; k < lean_side.x.size(); ++k)
    worst = std::max(worst, std::abs(lean_side.x[k] - ceres_side.x[k]));
  EXPECT_LT(worst, 1e-6);
}

TEST(LeanSolve, ReachesCeresOptimumWithAManifoldAndARobustLoss) {
  PlaneFit ceres_side, lean_side;
  ceres::Solver::Summary reference;
  ceres::Solve(Tight(), ceres_side.residuals.MakeProblem().get(), &reference);
  ASSERT_TRUE(reference.IsSolutionUsable());
  const SolveSummary lean = LeanSolve(Tight(), lean_side.residuals);
  ASSERT_TRUE(lean.usable) << lean.message;
  EXPECT_NEAR(lean.final_cost, reference.final_cost, 1e-8 * reference.initial_cost);
  EXPECT_NEAR(lean.initial_cost, reference.initial_cost, 1e-12 * reference.initial_cost);
  // The normal stays on the sphere and matches Ceres' (up to sign: both start
  // on the same side).
  const double* n = lean_side.normal;
  EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-12);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(n[k], ceres_side.normal[k], 1e-6) << k;
  EXPECT_NEAR(lean_side.offset, ceres_side.offset, 1e-6);
  // The robust loss kept the outliers out: the plane's slope is 0.2 / −0.1.
  EXPECT_NEAR(-n[0] / n[2], 0.2, 0.01);
  EXPECT_NEAR(-n[1] / n[2], -0.1, 0.01);
}

TEST(LeanSolve, ConstantBlocksStayConstant) {
  Membrane m(20);
  m.x[0] = 5;
  m.residuals.SetConstant(&m.x[0]);
  const SolveSummary s = LeanSolve(Tight(), m.residuals);
  ASSERT_TRUE(s.usable);
  EXPECT_EQ(m.x[0], 5);
  EXPECT_GT(m.x[1], 0.5);  // its neighbour is pulled towards it
}

// Ends the solve after `after` iterations.
struct StopAfter : ceres::IterationCallback {
  int after, seen = 0;
  explicit StopAfter(int a) : after(a) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    ++seen;
    return s.iteration >= after ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }
};

TEST(LeanSolve, ACallbackEndsTheSolve) {
  PlaneFit fit;
  StopAfter stop(1);
  ceres::Solver::Options o = Tight();
  o.callbacks.push_back(&stop);
  const SolveSummary s = LeanSolve(o, fit.residuals);
  EXPECT_TRUE(s.terminated_by_callback);
  EXPECT_EQ(s.iterations, 1);
  EXPECT_EQ(stop.seen, 2);  // iteration 0 and 1
}

// Knows before LeanSolve linearises that the step it is at ends the solve
// (the step reported as iteration `at`); records the reported gradients.
struct EndAt : EndingCallback {
  int at, reports = 0;
  std::vector<double> gradient;
  explicit EndAt(int a) : at(a) {}
  bool Ends() override { return reports >= at; }  // the coming report is iteration `reports`
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    ++reports;
    gradient.push_back(s.gradient_max_norm);
    return s.iteration >= at ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }
};

// A step that ends the solve is not linearised again: its report carries the
// model's gradient there (finite), and the result is that of a callback that
// ends it after the linearisation; so is a step that meets the function
// tolerance.
TEST(LeanSolve, AStepThatEndsTheSolveIsNotLinearisedAgain) {
  PlaneFit ended, stopped;
  EndAt end(2);
  StopAfter stop(2);
  ceres::Solver::Options o = Tight();
  o.callbacks.push_back(&end);
  const SolveSummary a = LeanSolve(o, ended.residuals);
  o.callbacks = {&stop};
  const SolveSummary b = LeanSolve(o, stopped.residuals);
  EXPECT_TRUE(a.terminated_by_callback);
  EXPECT_EQ(a.iterations, 2);
  ASSERT_EQ(end.gradient.size(), 3u);
  for (double g : end.gradient) EXPECT_TRUE(std::isfinite(g)) << g;
  EXPECT_EQ(b.iterations, 2);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(ended.normal[k], stopped.normal[k]);
  EXPECT_EQ(ended.offset, stopped.offset);
  EXPECT_DOUBLE_EQ(a.final_cost, b.final_cost);

  PlaneFit loose;
  EndAt never(1000);
  o = Tight();
  o.function_tolerance = 1e-2;
  o.callbacks.push_back(&never);
  const SolveSummary c = LeanSolve(o, loose.residuals);
  EXPECT_FALSE(c.terminated_by_callback);
  ASSERT_GE(never.gradient.size(), 2u);
  for (double g : never.gradient) EXPECT_TRUE(std::isfinite(g)) << g;
  EXPECT_LT(c.final_cost, c.initial_cost);
}

// Records every report.
struct Reports : EndingCallback {
  int end_at;
  std::vector<ceres::IterationSummary> seen;
  explicit Reports(int at = 1000) : end_at(at) {}
  bool Ends() override { return int(seen.size()) >= end_at; }
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    seen.push_back(s);
    return ceres::SOLVER_CONTINUE;
  }
};

// The gradient at the current values, ∇ ½Σρ, by Ceres (max norm, 2-norm).
std::pair<double, double> CeresGradient(const Residuals& residuals) {
  const std::unique_ptr<ceres::Problem> problem = residuals.MakeProblem();
  std::vector<double> g;
  double cost = 0;
  EXPECT_TRUE(problem->Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, &g, nullptr));
  const Eigen::Map<const Eigen::VectorXd> v(g.data(), long(g.size()));
  return {v.lpNorm<Eigen::Infinity>(), v.norm()};
}

// Callbacks see finite gradient norms at every report, the gradient at the
// iteration's point: after an accepted step that LeanSolve linearises, the
// gradient there; at a step that ends the solve, the model's, which on a
// linear problem is the gradient there too. Also the rest of the summary
// (lean_solve.h lists it).
TEST(LeanSolve, CallbacksSeeTheGradientAtEveryReport) {
  Membrane m(20);
  Reports reports(2);  // ends at the second step
  ceres::Solver::Options o = Tight();
  o.eta = 1e-3;
  o.initial_trust_region_radius = 10;  // damped: the first steps are not the optimum
  o.callbacks.push_back(&reports);
  const SolveSummary s = LeanSolve(o, m.residuals);
  ASSERT_TRUE(s.usable) << s.message;
  ASSERT_EQ(reports.seen.size(), 3u);
  const ceres::IterationSummary& last = reports.seen.back();
  const auto [max_norm, norm] = CeresGradient(m.residuals);
  EXPECT_GT(norm, 1e-6);  // not at the optimum: a gradient to compare
  EXPECT_NEAR(last.gradient_max_norm, max_norm, 1e-9 * max_norm);
  EXPECT_NEAR(last.gradient_norm, norm, 1e-9 * norm);
  int cg = 0;
  for (const ceres::IterationSummary& it : reports.seen) {
    EXPECT_TRUE(std::isfinite(it.gradient_max_norm) && std::isfinite(it.gradient_norm));
    EXPECT_GT(it.gradient_norm, 0.0);
    EXPECT_GE(it.cumulative_time_in_seconds, it.iteration_time_in_seconds);
    cg += it.linear_solver_iterations;
    if (it.iteration == 0) continue;
    EXPECT_TRUE(it.step_is_valid && it.step_is_successful);
    EXPECT_GT(it.relative_decrease, o.min_relative_decrease);
    EXPECT_GT(it.step_norm, 0.0);
    EXPECT_GT(it.cost_change, 0.0);
    EXPECT_EQ(it.eta, o.eta);
    EXPECT_GT(it.linear_solver_iterations, 0);
  }
  EXPECT_EQ(cg, s.cg_iterations);
  EXPECT_DOUBLE_EQ(last.cost, s.final_cost);

  // After a step LeanSolve linearises: the gradient there, by Ceres.
  Membrane n(20);
  Reports one(1000);
  StopAfter stop(1);
  o.callbacks = {&one, &stop};
  LeanSolve(o, n.residuals);
  ASSERT_EQ(one.seen.size(), 2u);
  const auto [max_1, norm_1] = CeresGradient(n.residuals);
  EXPECT_NEAR(one.seen[1].gradient_max_norm, max_1, 1e-9 * max_1);
  EXPECT_NEAR(one.seen[1].gradient_norm, norm_1, 1e-9 * norm_1);
}

// The loop builds its residuals every round: the pattern of J^T J is kept
// while the structure stays, with the new round's costs, and the solve from
// it is the solve from a fresh pattern.
TEST(LeanSolve, ThePatternIsReusedWhileTheStructureStays) {
  Membrane fresh(12), kept(12);
  NormalPattern pattern;
  EXPECT_FALSE(ReadNormalPattern(kept.residuals, 2, &pattern));
  const int first_slots = pattern.slots;
  const std::vector<int> first_pair_slot = pattern.pair_slot;
  const size_t first_blocks = pattern.blocks.size();
  Residuals again;
  kept.AddTo(again);
  EXPECT_TRUE(ReadNormalPattern(again, 2, &pattern));
  EXPECT_EQ(pattern.slots, first_slots);
  EXPECT_EQ(pattern.pair_slot, first_pair_slot);

  ASSERT_TRUE(LeanSolve(Tight(), again, &pattern).usable);
  ASSERT_TRUE(LeanSolve(Tight(), fresh.residuals).usable);
  EXPECT_EQ(kept.x, fresh.x);

  Residuals changed;  // one block held constant: another structure
  kept.AddTo(changed);
  changed.SetConstant(&kept.x[5]);
  EXPECT_FALSE(ReadNormalPattern(changed, 2, &pattern));
  EXPECT_EQ(pattern.blocks.size() + 1, first_blocks);
  EXPECT_EQ(pattern.constant.size(), 1u);

  // The same blocks, residuals and sizes, but the second residual reads its
  // blocks the other way round: another structure.
  double x[3] = {0, 1, 2};
  const auto two = [&](Residuals& r, bool swap) {
    Add(r, new ceres::AutoDiffCostFunction<Difference, 1, 1, 1>(new Difference{1.0}), nullptr,
        {&x[0], &x[1]});
    Add(r, new ceres::AutoDiffCostFunction<Difference, 1, 1, 1>(new Difference{1.0}), nullptr,
        {swap ? &x[2] : &x[1], swap ? &x[1] : &x[2]});
  };
  Residuals straight, swapped;
  two(straight, false);
  two(swapped, true);
  EXPECT_FALSE(ReadNormalPattern(straight, 2, &pattern));
  EXPECT_FALSE(ReadNormalPattern(swapped, 2, &pattern));
  EXPECT_TRUE(ReadNormalPattern(swapped, 2, &pattern));
}

// The residuals' visiting order for T threads: every residual once; the
// first T runs (a thread each) read no free block in common; the last run,
// after them, holds the residuals that straddle the cuts, few of them.
TEST(LeanSolve, TheThreadsRunsShareNoBlock) {
  Membrane m(40);
  for (int threads : {1, 2, 3, 4}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    NormalPattern pattern;
    ReadNormalPattern(m.residuals, threads, &pattern);
    const int n = int(pattern.pairs.size());
    ASSERT_EQ(pattern.threads, threads);
    ASSERT_EQ(pattern.run_end.size(), size_t(threads) + 1);
    ASSERT_EQ(pattern.run_end.back(), n);
    std::vector<int> sorted = pattern.visit;
    std::sort(sorted.begin(), sorted.end());
    std::vector<int> all(n);
    for (int k = 0; k < n; ++k) all[k] = k;
    EXPECT_EQ(sorted, all);
    std::vector<int> run_of(pattern.blocks.size(), -1);
    int shared = 0;
    for (int run = 0; run < threads; ++run) {
      for (int p = pattern.RunStart(run); p < pattern.run_end[size_t(run)]; ++p) {
        const Residuals::Residual& r = m.residuals.residuals()[size_t(pattern.visit[p])];
        for (int a = r.first; a < r.end; ++a) {
          const int b = pattern.free[size_t(m.residuals.block_of()[size_t(a)])];
          if (b < 0) continue;
          shared += run_of[b] >= 0 && run_of[b] != run;
          run_of[b] = run;
        }
      }
    }
    EXPECT_EQ(shared, 0);
    // 40 × 40 values, 4,720 residuals: each thread's run about 1/T of them,
    // the rows along the T − 1 cuts after them.
    for (int run = 0; run < threads; ++run) {
      EXPECT_NEAR(pattern.run_end[size_t(run)] - pattern.RunStart(run), n / threads, n / 20);
    }
    EXPECT_LE(n - pattern.run_end[size_t(threads) - 1], (threads - 1) * n / 20);
    if (threads > 1) {
      EXPECT_GT(n - pattern.run_end[size_t(threads) - 1], 0);
    }
  }
  // Another thread count on a kept pattern: the same slots, another order.
  NormalPattern kept;
  ReadNormalPattern(m.residuals, 2, &kept);
  const std::vector<int> slots = kept.pair_slot;
  EXPECT_TRUE(ReadNormalPattern(m.residuals, 4, &kept));
  EXPECT_EQ(kept.threads, 4);
  EXPECT_EQ(kept.run_end.size(), 5u);
  EXPECT_EQ(kept.pair_slot, slots);
  NormalPattern fresh;
  ReadNormalPattern(m.residuals, 4, &fresh);
  EXPECT_EQ(kept.visit, fresh.visit);
  EXPECT_EQ(fresh.pair_slot, slots);  // the layout does not depend on the threads
  EXPECT_EQ(fresh.slot, kept.slot);
  EXPECT_EQ(fresh.column, kept.column);
  EXPECT_EQ(fresh.row_start, kept.row_start);
}

// Within each run the residuals go chunk by chunk of kVisitChunk blocks (by
// their first free block), in their own order (term by term) within a chunk.
TEST(LeanSolve, EachRunVisitsTheMeshChunkByChunkTermByTerm) {
  Membrane m(100, /*by_term=*/true);  // 10,000 blocks: 10 chunks
  NormalPattern pattern;
  ReadNormalPattern(m.residuals, 2, &pattern);
  const auto chunk = [&](int k) {
    const Residuals::Residual& r = m.residuals.residuals()[size_t(k)];
    int first = int(pattern.blocks.size());
    for (int a = r.first; a < r.end; ++a) {
      first = std::min(first, pattern.free[size_t(m.residuals.block_of()[size_t(a)])]);
    }
    return first / kVisitChunk;
  };
  int chunks_seen = 0;
  for (int run = 0, p = 0; run < 3; ++run) {
    for (int begin = p; p < pattern.run_end[size_t(run)]; ++p) {
      if (p == begin) continue;
      const int a = pattern.visit[size_t(p - 1)], b = pattern.visit[size_t(p)];
      ASSERT_LE(chunk(a), chunk(b)) << "run " << run << " position " << p;
      if (chunk(a) == chunk(b)) {
        ASSERT_LT(a, b) << "run " << run << " position " << p;
      } else {
        ++chunks_seen;
      }
    }
  }
  EXPECT_GE(chunks_seen, 8);  // the two halves: ~5 chunks each
}

// Blocks and residuals larger than the unrolled products' sizes (a 6-vector,
// a point on the 5-sphere, 5 rows per residual) take the general products:
// LeanSolve reaches Ceres' optimum.
struct Rows5 {
  template <typename T>
  bool operator()(const T* x, T* r) const {
    for (int i = 0; i < 5; ++i) {
      r[i] = T(-b[i]);
      for (int j = 0; j < 6; ++j) r[i] += T(a[i][j]) * x[j];
    }
    return true;
  }
  double a[5][6], b[5];
};
TEST(LeanSolve, LargeBlocksReachCeresOptimum) {
  struct Problem {
    double c[6] = {0, 0, 0, 0, 0, 0};
    double u[6] = {1, 0, 0, 0, 0, 0};
    Residuals residuals;
    Problem() {
      for (int k = 0; k < 4; ++k) {
        for (double* x : {c, u}) {
          auto* f = new Rows5;
          for (int i = 0; i < 5; ++i) {
            for (int j = 0; j < 6; ++j) f->a[i][j] = std::sin(1.0 + 7 * k + 3 * i + 2.0 * j + (x == u));
            f->b[i] = std::cos(2.0 * k + i);
          }
          Add(residuals, new ceres::AutoDiffCostFunction<Rows5, 5, 6>(f), nullptr, {x});
        }
      }
      residuals.SetManifold(u, new ceres::SphereManifold<6>());
    }
  };
  Problem ceres_side, lean_side;
  ceres::Solver::Summary reference;
  ceres::Solve(Tight(), ceres_side.residuals.MakeProblem().get(), &reference);
  ASSERT_TRUE(reference.IsSolutionUsable());
  const SolveSummary lean = LeanSolve(Tight(), lean_side.residuals);
  ASSERT_TRUE(lean.usable) << lean.message;
  EXPECT_LT(lean.final_cost, 0.8 * lean.initial_cost);  // 14.5 -> 10.5
  EXPECT_NEAR(lean.final_cost, reference.final_cost, 1e-9 * reference.initial_cost);
  for (int k = 0; k < 6; ++k) {
    EXPECT_NEAR(lean_side.c[k], ceres_side.c[k], 1e-6) << k;
    EXPECT_NEAR(lean_side.u[k], ceres_side.u[k], 1e-6) << k;
  }
}

// r = A x − b over one block of N values (N rows).
template <int N>
struct Square {
  template <typename T>
  bool operator()(const T* x, T* r) const {
    for (int i = 0; i < N; ++i) {
      r[i] = T(-b[i]);
      for (int j = 0; j < N; ++j) r[i] += T(a[i][j]) * x[j];
    }
    return true;
  }
  double a[N][N], b[N];
};

// The preconditioner is each block's (H_ii + D_i)⁻¹: where the normal
// equations are block-diagonal (blocks of 1 to 6 values, each scaled
// differently and coupled inside), preconditioned CG solves each LM step in
// its first step; Nash and Sofer's test, which compares a step's decrease of
// the model with the decrease so far, ends it at the second. With the
// identity instead: 224 CG steps in 5 LM steps.
TEST(LeanSolve, BlockJacobiSolvesIndependentBlocksInOneStepEach) {
  double x1[1] = {0}, x2[2] = {0, 0}, x3[3] = {0, 0, 0}, x4[4] = {0, 0, 0, 0};
  double x6[6] = {0, 0, 0, 0, 0, 0};
  Residuals residuals;
  const auto add = [&](auto functor, double* x, double scale) {
    constexpr int n = sizeof(functor->b) / sizeof(double);
    for (int i = 0; i < n; ++i) {
      functor->b[i] = std::cos(1.0 + 2 * i) * scale;
      for (int j = 0; j < n; ++j) {
        functor->a[i][j] = scale * ((i == j ? 2.0 : 0.0) + 0.4 * std::sin(1.0 + 3 * i + 5.0 * j));
      }
    }
    using F = std::remove_pointer_t<decltype(functor)>;
    Add(residuals, new ceres::AutoDiffCostFunction<F, n, n>(functor), nullptr, {x});
  };
  add(new Square<1>, x1, 0.01);
  add(new Square<2>, x2, 30.0);
  add(new Square<3>, x3, 1.0);
  add(new Square<4>, x4, 300.0);
  add(new Square<6>, x6, 0.1);  // wider than the stack-sized inverse
  ceres::Solver::Options o = Tight();
  o.eta = 1e-12;
  const SolveSummary lean = LeanSolve(o, residuals);
  ASSERT_TRUE(lean.usable) << lean.message;
  ASSERT_GT(lean.iterations, 0);
  EXPECT_EQ(lean.cg_iterations, 2 * lean.iterations);
  EXPECT_LT(lean.final_cost, 1e-12 * lean.initial_cost);  // A x = b: every residual 0
}

// Records every report's cost and cost change.
struct Costs : ceres::IterationCallback {
  std::vector<double> cost, change;
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    cost.push_back(s.cost);
    change.push_back(s.cost_change);
    return ceres::SOLVER_CONTINUE;
  }
};

// One Gauss–Newton step on a stiff membrane (data weight 0.03: a 2-D
// Laplacian, where CG's residual falls slowly long after the model's
// decrease has settled). Nash and Sofer's test with eta = 0.1 ends CG after
// 22 steps, with 97.5% of the exact step's decrease; the residual test
// ‖b − Aδ‖ ≤ eta ‖b‖ used before took 46 steps (for 99.99%).
TEST(LeanSolve, ConjugateGradientsEndWhenTheModelDecreaseSettles) {
  Membrane exact(40, false, 0.03), one(40, false, 0.03);
  ceres::Solver::Summary reference;
  ceres::Solve(Tight(), exact.residuals.MakeProblem().get(), &reference);
  ceres::Solver::Options o = Tight();
  o.eta = 0.1;
  o.max_num_iterations = 1;
  o.initial_trust_region_radius = 1e12;  // no damping to speak of
  const SolveSummary step = LeanSolve(o, one.residuals);
  ASSERT_TRUE(step.usable) << step.message;
  const double fraction =
      (step.initial_cost - step.final_cost) / (step.initial_cost - reference.final_cost);
  EXPECT_GT(fraction, 0.95);
  EXPECT_LE(step.cg_iterations, 30);
  // At least min_linear_solver_iterations steps, as in Ceres.
  Membrane longer(40, false, 0.03);
  o.min_linear_solver_iterations = 35;
  EXPECT_EQ(LeanSolve(o, longer.residuals).cg_iterations, 35);
}

// A PCG round is re-projected and re-linearised by the next one: LeanSolve
// also ends where the next cost change, extrapolated from the last two
// (Δ_k² / Δ_(k−1)), is below the function tolerance, without the step that
// would only confirm it (in the tail: a step that changed the cost by at
// most a tenth). The plane fit's changes: 1.38, 0.61, 0.0168, 2.5e-5 (a
// tenth of the cost left is 6.5e-3), then a confirming step that 1e-4
// does not need.
TEST(LeanSolve, TheFunctionToleranceEndsWhereTheNextChangeWouldMeetIt) {
  PlaneFit loose, tight;
  Costs ended, further;
  ceres::Solver::Options o = Tight();
  o.eta = 0.1;
  const double tolerance = 1e-4;
  o.function_tolerance = tolerance;
  o.callbacks.push_back(&ended);
  const SolveSummary s = LeanSolve(o, loose.residuals);
  ASSERT_TRUE(s.usable) << s.message;
  const size_t k = ended.change.size() - 1;  // the last step
  ASSERT_GE(k, 3u);
  EXPECT_EQ(s.iterations, int(k));
  // Not its own change but the extrapolated one ended it ...
  EXPECT_GT(ended.change[k], tolerance * ended.cost[k - 1]);
  EXPECT_LE(ended.change[k], 0.1 * ended.cost[k]);
  EXPECT_LE(ended.change[k] * ended.change[k] / ended.change[k - 1], tolerance * ended.cost[k]);
  // ... and rightly: the same solve with a tighter tolerance takes that
  // step, and it changes the cost by less than the tolerance.
  o.function_tolerance = 1e-8;
  o.callbacks = {&further};
  LeanSolve(o, tight.residuals);
  ASSERT_GT(further.change.size(), k + 1);
  EXPECT_DOUBLE_EQ(further.cost[k], ended.cost[k]);  // (summed in another order)
  EXPECT_LT(further.change[k + 1], tolerance * further.cost[k]);
}

// The extrapolated next change ends a solve only in the tail, where a step
// changes the cost by no more than the cost left. A far start whose first
// step removes nearly all of its cost (a stiff term met at once, as a
// random start's feature constraints in the wave) gives a rate that would
// predict a next change of nothing after the second step (which still
// removes most of the plane fit's cost) and end the fit there, short of
// its optimum.
TEST(LeanSolve, AFarStartsFirstDropDoesNotEndTheSolve) {
  PlaneFit ceres_side, lean_side;
  double far_ceres = 1000, far_lean = 1000;  // pulled to 0 with weight 1000
  Add(ceres_side.residuals, new ceres::AutoDiffCostFunction<Data, 1, 1>(new Data{1000, 0}),
      nullptr, {&far_ceres});
  Add(lean_side.residuals, new ceres::AutoDiffCostFunction<Data, 1, 1>(new Data{1000, 0}),
      nullptr, {&far_lean});
  ceres::Solver::Options o = Tight();
  o.function_tolerance = 1e-4;
  o.initial_trust_region_radius = 1e16;  // the first step meets the stiff term
  ceres::Solver::Summary reference;
  ceres::Solve(o, ceres_side.residuals.MakeProblem().get(), &reference);
  Costs costs;
  o.callbacks.push_back(&costs);
  const SolveSummary lean = LeanSolve(o, lean_side.residuals, nullptr, LeanStep::kCholesky);
  ASSERT_TRUE(lean.usable) << lean.message;
  ASSERT_GE(costs.change.size(), 3u);
  EXPECT_LT(costs.change[2], 1e-6 * costs.change[1]);  // the first drop (step 1) ...
  EXPECT_GT(lean.iterations, 2);                        // ... does not end it at step 2
  EXPECT_NEAR(lean.final_cost, reference.final_cost, 1e-3 * reference.final_cost);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(lean_side.normal[k], ceres_side.normal[k], 1e-3) << k;
}

ceres::Solver::Options Threads(ceres::Solver::Options o, int threads) {
  o.num_threads = threads;
  return o;
}

// The same number of threads gives the same bits, run to run: each of 1, 2
// and 4 threads twice (OpenMP runs 4 threads on any number of cores, so the
// parallel assembly, products and sums run here), on a membrane large enough
// for residuals along every cut and on the plane fit (a manifold, a loss).
TEST(LeanSolve, EachThreadCountGivesTheSameBitsEveryRun) {
  for (int threads : {1, 2, 4}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    Membrane first(40, false, 0.03), second(40, false, 0.03);
    ceres::Solver::Options o = Threads(Tight(), threads);
    o.eta = 0.1;  // inexact steps: the sums' order shows in the result
    o.max_num_iterations = 10;
    const SolveSummary a = LeanSolve(o, first.residuals);
    const SolveSummary b = LeanSolve(o, second.residuals);
    ASSERT_TRUE(a.usable && b.usable);
    EXPECT_EQ(first.x, second.x);
    EXPECT_EQ(a.final_cost, b.final_cost);
    EXPECT_EQ(a.cg_iterations, b.cg_iterations);
    PlaneFit one, two;
    ASSERT_TRUE(LeanSolve(o, one.residuals).usable);
    ASSERT_TRUE(LeanSolve(o, two.residuals).usable);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(one.normal[k], two.normal[k]);
    EXPECT_EQ(one.offset, two.offset);
  }
}

// 1, 2 and 4 threads sum in different orders, to the same optimum: within a
// tight tolerance of each other and of Ceres' direct solve.
TEST(LeanSolve, ThreadCountsReachCeresOptimum) {
  Membrane reference(40, false, 0.03);
  ceres::Solver::Summary direct;
  ceres::Solve(Tight(), reference.residuals.MakeProblem().get(), &direct);
  ASSERT_TRUE(direct.IsSolutionUsable());
  std::vector<std::vector<double>> x;
  for (int threads : {1, 2, 4}) {
    Membrane m(40, false, 0.03);
    const SolveSummary s = LeanSolve(Threads(Tight(), threads), m.residuals);
    ASSERT_TRUE(s.usable) << s.message;
    EXPECT_NEAR(s.final_cost, direct.final_cost, 1e-10 * direct.final_cost) << threads;
    double worst = 0;
    for (size_t k = 0; k < m.x.size(); ++k) {
      worst = std::max(worst, std::abs(m.x[k] - reference.x[k]));
    }
    EXPECT_LT(worst, 1e-7) << threads;
    x.push_back(m.x);
  }
  for (size_t t = 1; t < x.size(); ++t) {
    double worst = 0;
    for (size_t k = 0; k < x[0].size(); ++k) worst = std::max(worst, std::abs(x[t][k] - x[0][k]));
    EXPECT_LT(worst, 1e-7) << t;
  }
}

// The product (H + D) x in T parts, each into a vector of its own, equals
// the dense product, for every T (each part's rows and their transposed
// columns counted once).
TEST(LeanSolve, TheProductInPartsIsTheDenseProduct) {
  Membrane m(30);
  for (int threads : {1, 2, 3, 4, 7}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    NormalPattern pattern;
    ceres::Solver::Options o = Threads(Tight(), threads);
    o.max_num_iterations = 0;
    ASSERT_TRUE(LeanSolve(o, m.residuals, &pattern).usable);  // H at the start
    const int n = pattern.tangent;
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
    for (size_t i = 0; i < pattern.blocks.size(); ++i) {
      const PatternBlock& b = pattern.blocks[i];
      dense(b.offset, b.offset) = pattern.hessian[size_t(pattern.diagonal[i])];
      for (int k = pattern.row_start[i]; k < pattern.row_start[i + 1]; ++k) {
        const PatternBlock& c = pattern.blocks[size_t(pattern.column[size_t(k)])];
        dense(b.offset, c.offset) = dense(c.offset, b.offset) =
            pattern.hessian[size_t(pattern.slot[size_t(k)])];
      }
    }
    Eigen::VectorXd x(n), damping(n), y;
    for (int k = 0; k < n; ++k) {
      x[k] = std::sin(0.3 * k + 1.0);
      damping[k] = 0.1 + 0.01 * k;
    }
    NormalSystem(pattern, threads).Multiply(damping, x, &y);
    const Eigen::VectorXd expected = dense * x + damping.cwiseProduct(x);
    EXPECT_LT((y - expected).lpNorm<Eigen::Infinity>(), 1e-12 * expected.lpNorm<Eigen::Infinity>());
  }
}

TEST(LeanSolve, SolveRoundUsesPcgOnlyAboveTheThreshold) {
  Membrane a(10), b(10), c(10);
  RoundSolver how;
  how.pcg_function_tolerance = 1e-4;
  EXPECT_FALSE(SolveRound(Tight(), how, a.residuals).pcg);
  how.pcg_above = 100;
  EXPECT_FALSE(UsesLeanSolve(how.pcg_above, b.residuals));
  EXPECT_FALSE(SolveRound(Tight(), how, b.residuals).pcg);  // 100 variables: not above
  how.pcg_above = 99;
  EXPECT_TRUE(UsesLeanSolve(how.pcg_above, c.residuals));
  EXPECT_TRUE(SolveRound(Tight(), how, c.residuals).pcg);
}

// LeanSolve refuses the options that ask for another algorithm: it solves
// nothing and names the option; it solves with every other.
TEST(LeanSolve, RefusesOptionsItDoesNotImplement) {
  const auto refused = [](const std::function<void(ceres::Solver::Options&)>& set,
                          const std::string& option) {
    SCOPED_TRACE(option);
    Membrane m(10);
    ceres::Solver::Options o = Tight();
    set(o);
    EXPECT_EQ(LeanSolveRefuses(o), option);
    const SolveSummary s = LeanSolve(o, m.residuals);
    EXPECT_FALSE(s.usable);
    EXPECT_EQ(s.message.rfind(option + ": ", 0), 0u) << s.message;
    EXPECT_EQ(s.iterations, 0);
    for (double v : m.x) EXPECT_EQ(v, 0.0);
  };
  refused([](auto& o) { o.trust_region_strategy_type = ceres::DOGLEG; },
          "trust_region_strategy_type");
  refused([](auto& o) { o.minimizer_type = ceres::LINE_SEARCH; }, "minimizer_type");
  refused([](auto& o) { o.use_nonmonotonic_steps = true; }, "use_nonmonotonic_steps");
  refused([](auto& o) { o.use_inner_iterations = true; }, "use_inner_iterations");
  refused([](auto& o) { o.preconditioner_type = ceres::IDENTITY; }, "preconditioner_type");
  refused([](auto& o) { o.preconditioner_type = ceres::SUBSET; }, "preconditioner_type");
  // Ignored (documented): another linear solver, no Jacobi scaling.
  Membrane m(10);
  ceres::Solver::Options o = Tight();
  o.linear_solver_type = ceres::CGNR;
  o.jacobi_scaling = false;
  EXPECT_EQ(LeanSolveRefuses(o), "");
  EXPECT_TRUE(LeanSolve(o, m.residuals).usable);
}

// LeanStep::kCholesky: each step one sparse Cholesky factorisation of the
// damped normal equations (core/normal_cholesky.h), no CG step. It reaches
// Ceres' optimum on the linear membrane, on the plane fit (a manifold and a
// robust loss) and with blocks of 6; on the linear problem its exact steps
// need a handful of iterations where PCG's inexact ones need many more.
TEST(LeanSolve, CholeskyStepsReachCeresOptimum) {
  Membrane ceres_side(30), lean_side(30), pcg_side(30);
  ceres::Solver::Summary reference;
  ceres::Solve(Tight(), ceres_side.residuals.MakeProblem().get(), &reference);
  const SolveSummary lean = LeanSolve(Tight(), lean_side.residuals, nullptr, LeanStep::kCholesky);
  ASSERT_TRUE(lean.usable) << lean.message;
  EXPECT_TRUE(lean.cholesky);
  EXPECT_FALSE(lean.pcg);
  EXPECT_EQ(lean.cg_iterations, 0);
  EXPECT_NEAR(lean.final_cost, reference.final_cost, 1e-12 * reference.final_cost);
  double worst = 0;
  for (size_t k = 0; k < lean_side.x.size(); ++k)
    worst = std::max(worst, std::abs(lean_side.x[k] - ceres_side.x[k]));
  EXPECT_LT(worst, 1e-8);
  ceres::Solver::Options loose = Tight();
  loose.eta = 0.1;
  const SolveSummary pcg = LeanSolve(loose, pcg_side.residuals);
  EXPECT_LE(lean.iterations, 4);
  EXPECT_LT(lean.iterations, pcg.iterations);

  PlaneFit fit_ceres, fit_lean;
  ceres::Solve(Tight(), fit_ceres.residuals.MakeProblem().get(), &reference);
  const SolveSummary fit = LeanSolve(Tight(), fit_lean.residuals, nullptr, LeanStep::kCholesky);
  ASSERT_TRUE(fit.usable) << fit.message;
  EXPECT_NEAR(fit.final_cost, reference.final_cost, 1e-10 * reference.initial_cost);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(fit_lean.normal[k], fit_ceres.normal[k], 1e-7) << k;
}

// The ordering and symbolic analysis are made once per structure: kept in
// the NormalPattern for the next solve of the same structure, dropped when
// the structure changes.
TEST(LeanSolve, CholeskyAnalysisIsKeptWithThePattern) {
  Membrane a(12), c(13);
  NormalPattern pattern;
  ASSERT_TRUE(LeanSolve(Tight(), a.residuals, &pattern, LeanStep::kCholesky).usable);
  const NormalCholesky* first = pattern.cholesky.get();
  ASSERT_NE(first, nullptr);
  const std::vector<double> solved = a.x;
  std::fill(a.x.begin(), a.x.end(), 0.0);  // the next round: the same blocks, anew
  ASSERT_TRUE(LeanSolve(Tight(), a.residuals, &pattern, LeanStep::kCholesky).usable);
  EXPECT_EQ(pattern.cholesky.get(), first);
  for (size_t k = 0; k < a.x.size(); ++k) EXPECT_NEAR(a.x[k], solved[k], 1e-12);
  const SolveSummary other = LeanSolve(Tight(), c.residuals, &pattern, LeanStep::kCholesky);
  ASSERT_TRUE(other.usable);
  ASSERT_NE(pattern.cholesky, nullptr);
  EXPECT_LT(other.final_cost, other.initial_cost);
}

// The summary counts each numeric factorisation (one per step, rejected
// steps included) with CHOLMOD's flops of it, and the factor's nonzeros: a
// solve's flops are its factorisations times the analysis' count, and the
// factor holds at least the diagonal and H's upper triangle.
TEST(LeanSolve, SummaryCountsFactorisationsAndTheirFlops) {
  Membrane m(12);
  NormalPattern pattern;
  const SolveSummary s = LeanSolve(Tight(), m.residuals, &pattern, LeanStep::kCholesky);
  ASSERT_TRUE(s.usable) << s.message;
  ASSERT_NE(pattern.cholesky, nullptr);
  EXPECT_GT(s.iterations, 0);
  EXPECT_EQ(s.factorisations, s.iterations);
  EXPECT_NEAR(s.factor_flops, s.factorisations * pattern.cholesky->FactorFlops(),
              1e-12 * s.factor_flops);
  EXPECT_EQ(s.factor_nonzeros, pattern.cholesky->FactorNonzeros());
  EXPECT_GE(s.factor_nonzeros, double(m.x.size()));
  const SolveSummary pcg = LeanSolve(Tight(), m.residuals, &pattern, LeanStep::kPcg);
  EXPECT_EQ(pcg.factorisations, 0);
  EXPECT_EQ(pcg.factor_flops, 0.0);
}

// solver.ordering metis: the analysis orders by METIS' nested dissection,
// whose factorisation of a 120 × 120 membrane takes fewer flops than AMD's
// (1.6e7 against 2.1e7), and the steps reach the same optimum.
TEST(LeanSolve, MetisOrderingTakesFewerFlopsAndReachesTheSameOptimum) {
  Membrane amd_side(120), metis_side(120);
  NormalPattern amd_pattern, metis_pattern;
  const SolveSummary amd = LeanSolve(Tight(), amd_side.residuals, &amd_pattern,
                                     LeanStep::kCholesky, CholeskyOrdering::kAmd);
  const SolveSummary metis = LeanSolve(Tight(), metis_side.residuals, &metis_pattern,
                                       LeanStep::kCholesky, CholeskyOrdering::kMetis);
  ASSERT_TRUE(amd.usable && metis.usable);
  ASSERT_EQ(metis_pattern.cholesky->used(), CholeskyOrdering::kMetis);
  EXPECT_EQ(amd_pattern.cholesky->used(), CholeskyOrdering::kAmd);
  EXPECT_LT(metis_pattern.cholesky->FactorFlops(), 0.9 * amd_pattern.cholesky->FactorFlops());
  EXPECT_NEAR(metis.final_cost, amd.final_cost, 1e-12 * amd.final_cost);
  for (size_t k = 0; k < amd_side.x.size(); ++k) EXPECT_NEAR(metis_side.x[k], amd_side.x[k], 1e-9);
}

// With how.lean (solver.back_end: lean) a round goes to LeanSolve's Cholesky
// steps when the options ask for nothing else; an option it does not
// implement (dogleg, a dense or iterative linear solver, another sparse
// library) sends the round to Ceres, which solves it.
TEST(LeanSolve, SolveRoundTakesCholeskyStepsUnlessAnOptionAsksForCeres) {
  RoundSolver how;
  how.lean = true;
  Membrane a(10);
  const SolveSummary lean = SolveRound(Tight(), how, a.residuals);
  EXPECT_TRUE(lean.cholesky);
  EXPECT_FALSE(lean.pcg);
  for (const auto& set : std::vector<std::function<void(ceres::Solver::Options&)>>{
           [](auto& o) { o.trust_region_strategy_type = ceres::DOGLEG; },
           [](auto& o) { o.linear_solver_type = ceres::DENSE_QR; },
           [](auto& o) { o.linear_solver_type = ceres::CGNR; },
           [](auto& o) { o.sparse_linear_algebra_library_type = ceres::EIGEN_SPARSE; },
           [](auto& o) { o.max_num_refinement_iterations = 2; }}) {
    Membrane m(10);
    ceres::Solver::Options o = Tight();
    set(o);
    EXPECT_FALSE(LeanCholeskyTakes(o));
    const SolveSummary s = SolveRound(o, how, m.residuals);
    EXPECT_TRUE(s.usable) << s.message;
    EXPECT_FALSE(s.cholesky);
    EXPECT_NEAR(s.final_cost, lean.final_cost, 1e-6 * lean.final_cost);
  }
}

class LeanSolveCli : public ScratchDirTest {};

// Through the tool: a round that LeanSolve's PCG solves (solver.pcg_above=1)
// with an option it refuses is bad input: exit 2, the key named, no output
// written. The same options on a round Ceres solves are fine.
TEST_F(LeanSolveCli, RefusalIsExitTwoNamingTheKey) {
  const std::string tool = ARCHGEO_BINARY;
  const std::string roof = Path("roof.obj");
  ASSERT_EQ(Shell(tool + " generate " + roof + " --nu 8 --nv 6 --noise 0.05").code, 0);
  const std::string spec = std::string(ARCHGEO_SOURCE_DIR) + "/examples/planar_quads.yaml";
  const std::string run = tool + " solve " + spec + " --quiet --set mesh=" + roof +
                          " --set output.mesh=" + Path("out.ply") + " --set output.report=" +
                          Path("out.json") + " --set output.image=" + Path("out.png");
  for (const auto& [key, value] :
       {std::pair<std::string, std::string>{"trust_region_strategy_type", "dogleg"},
        {"minimizer_type", "line_search"},
        {"use_nonmonotonic_steps", "true"},
        {"use_inner_iterations", "true"},
        {"preconditioner_type", "identity"}}) {
    SCOPED_TRACE(key);
    const std::string set = " --set solver." + key + "=" + value;
    const Outcome lean = Shell(run + " --set solver.pcg_above=1" + set);
    EXPECT_EQ(lean.code, 2) << lean.output;
    EXPECT_NE(lean.output.find("solver." + key), std::string::npos) << lean.output;
    for (const char* out : {"out.ply", "out.json", "out.png"}) {
      EXPECT_FALSE(std::filesystem::exists(Path(out))) << out;
    }
    for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
      EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
    }
  }
  // Ceres' rounds (pcg_above=0): dogleg is Ceres' to take.
  const Outcome ceres = Shell(run + " --set solver.pcg_above=0 --set "
                              "solver.trust_region_strategy_type=dogleg");
  EXPECT_NE(ceres.code, 2) << ceres.output;
  EXPECT_TRUE(std::filesystem::exists(Path("out.ply")));
}

// Ceres' SUBSET preconditioner gets the residual blocks of the parts named
// in solver.subset_preconditioner_parts (planar_quads: the planarity terms
// and the barriers), and solves with them; a preconditioner with no block is
// refused before any work.
TEST_F(LeanSolveCli, CeresSubsetPreconditionerGetsTheNamedParts) {
  const std::string tool = ARCHGEO_BINARY;
  const std::string roof = Path("roof.obj");
  ASSERT_EQ(Shell(tool + " generate " + roof + " --nu 8 --nv 6 --noise 0.05").code, 0);
  const std::string spec = std::string(ARCHGEO_SOURCE_DIR) + "/examples/planar_quads.yaml";
  const std::string run = tool + " solve " + spec + " --quiet --set mesh=" + roof +
                          " --set output.mesh=" + Path("out.ply") + " --set output.report=" +
                          Path("out.json") + " --set output.image= --set solver.pcg_above=0" +
                          " --set solver.linear_solver_type=cgnr" +
                          " --set solver.preconditioner_type=subset";
  const Outcome subset = Shell(run);
  EXPECT_EQ(subset.code, 0) << subset.output;
  std::ifstream report(Path("out.json"));
  const nlohmann::json r = nlohmann::json::parse(report);
  EXPECT_LE(r["after"]["pq_normalized_max"].get<double>(), 1e-3);
  std::filesystem::remove(Path("out.ply"));
  const Outcome none = Shell(run + " --set solver.subset_preconditioner_parts=");
  EXPECT_EQ(none.code, 2) << none.output;
  EXPECT_NE(none.output.find("solver.subset_preconditioner_parts"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(Path("out.ply")));
}

// planar_quads solves its rounds by LeanSolve's Cholesky steps (the report's
// cholesky_rounds), and Ceres' with solver.back_end: ceres, both to the
// tolerance with the same planarity.
TEST_F(LeanSolveCli, PlanarQuadsRoundsAreLeanCholeskyUnlessBackEndCeres) {
  const std::string tool = ARCHGEO_BINARY;
  const std::string roof = Path("roof.obj");
  ASSERT_EQ(Shell(tool + " generate " + roof + " --nu 10 --nv 8 --noise 0.05").code, 0);
  const std::string spec = std::string(ARCHGEO_SOURCE_DIR) + "/examples/planar_quads.yaml";
  const auto run = [&](const std::string& set) {
    const Outcome out = Shell(tool + " solve " + spec + " --quiet --set mesh=" + roof +
                              " --set output.mesh=" + Path("out.ply") + " --set output.report=" +
                              Path("out.json") + " --set output.image=" + set);
    EXPECT_EQ(out.code, 0) << out.output;
    std::ifstream report(Path("out.json"));
    return nlohmann::json::parse(report);
  };
  const nlohmann::json lean = run("");
  const nlohmann::json ceres = run(" --set solver.back_end=ceres");
  EXPECT_EQ(lean["cholesky_rounds"].get<int>(), lean["iterations"]["outer"].get<int>());
  EXPECT_GT(lean["cholesky_rounds"].get<int>(), 0);
  EXPECT_EQ(ceres["cholesky_rounds"].get<int>(), 0);
  // One factorisation per step of every round, with its flops.
  const nlohmann::json& factored = lean["cholesky_factorisations"];
  EXPECT_EQ(factored["count"].get<int>(), lean["iterations"]["inner"].get<int>());
  EXPECT_GT(factored["gflop"].get<double>(), 0.0);
  EXPECT_GE(factored["largest_factor_nonzeros"].get<double>(), lean["variables"].get<double>());
  EXPECT_EQ(ceres["cholesky_factorisations"]["count"].get<int>(), 0);
  EXPECT_EQ(ceres["cholesky_factorisations"]["gflop"].get<double>(), 0.0);
  for (const nlohmann::json* r : {&lean, &ceres}) {
    EXPECT_LE((*r)["after"]["pq_normalized_max"].get<double>(), 1e-3);
  }
  EXPECT_NEAR(lean["after"]["pq_normalized_max"].get<double>(),
              ceres["after"]["pq_normalized_max"].get<double>(), 1e-4);
  const nlohmann::json dogleg = run(" --set solver.trust_region_strategy_type=dogleg");
  EXPECT_EQ(dogleg["cholesky_rounds"].get<int>(), 0);
}

double MaxDisplacement(const Mesh& a, const Mesh& b) {
  double worst = 0;
  for (auto v : a.vertices()) {
    worst = std::max(worst, std::sqrt(CGAL::squared_distance(a.point(v), b.point(v))));
  }
  return worst;
}

TEST(LeanSolve, PlanarQuadsWithPcgMatchesTheDirectSolve) {
  Mesh input = QuadGrid(40, 40, RoofSurface, 0.05, 3);
  ToCanonical(CanonicalFrame(input), input);
  auto run = [&](const std::string& yaml) {
    Mesh mesh = input;
    const ProblemSpec spec = ParseSpec("problem: planar_quads\n" + yaml);
    return Solve(spec, mesh, &input, {});
  };
  const auto direct = run("solver: {pcg_above: 0}\n");
  const auto pcg = run("solver: {pcg_above: 1000}\n");
  ASSERT_TRUE(direct->loop.usable);
  ASSERT_TRUE(pcg->loop.usable);
  EXPECT_EQ(direct->loop.pcg_rounds, 0);
  EXPECT_EQ(pcg->loop.pcg_rounds, pcg->loop.rounds);
  EXPECT_GT(pcg->loop.cg_iterations, pcg->loop.iterations);
  const double tolerance = 1e-3;
  EXPECT_TRUE(pcg->loop.tolerances.at("tolerance.pq_normalized_max"));
  const Metrics m = ComputeMetrics(pcg->output, nullptr, nullptr);
  EXPECT_LE(m.pq_normalized_max, tolerance);
  const double moved_direct = MaxDisplacement(direct->output, input);
  const double moved_pcg = MaxDisplacement(pcg->output, input);
  std::printf("max displacement: direct %.5f, pcg %.5f (rounds %d / %d, iterations %d / %d, CG %d)\n",
              moved_direct, moved_pcg, direct->loop.rounds, pcg->loop.rounds,
              direct->loop.iterations, pcg->loop.iterations, pcg->loop.cg_iterations);
  EXPECT_LE(moved_pcg, 1.1 * moved_direct);
  EXPECT_GE(moved_pcg, 0.9 * moved_direct);
}

}  // namespace
}  // namespace archgeo
