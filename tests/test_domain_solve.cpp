// Domain decomposition (core/domain_solve.h): the parts are independent in
// pass 1, the band pass reaches the global optimum of a locally coupled
// problem, the problem's constant blocks are left as they were, and
// planar_quads solved in domains meets its tolerance with the displacement of
// the global solve.
#include <gtest/gtest.h>

#include <ceres/ceres.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "core/domain_solve.h"
#include "mesh/generators.h"
#include "mesh/metrics.h"
#include "mesh/similarity.h"
#include "problems/solve.h"

namespace archgeo {
namespace {

// r = w (x − y) for one scalar, or w (x − target).
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

// A membrane on an n × n grid: data terms pull each value to a rough target,
// differences tie neighbours (a 2-D graph like a mesh's normal equations).
struct Membrane {
  int n;
  std::vector<double> x;
  ceres::Problem problem;
  explicit Membrane(int size) : n(size), x(size * size, 0.0) {
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const double target = std::sin(0.7 * i) * std::cos(1.3 * j) + ((i * 7 + j * 3) % 5) * 0.1;
        problem.AddResidualBlock(new ceres::AutoDiffCostFunction<Data, 1, 1>(new Data{0.5, target}),
                                 nullptr, &x[i * n + j]);
        if (i + 1 < n) {
          problem.AddResidualBlock(
              new ceres::AutoDiffCostFunction<Difference, 1, 1, 1>(new Difference{1.0}), nullptr,
              &x[i * n + j], &x[(i + 1) * n + j]);
        }
        if (j + 1 < n) {
          problem.AddResidualBlock(
              new ceres::AutoDiffCostFunction<Difference, 1, 1, 1>(new Difference{1.0}), nullptr,
              &x[i * n + j], &x[i * n + j + 1]);
        }
      }
    }
  }
};

ceres::Solver::Options Options() {
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  o.function_tolerance = 1e-14;
  o.gradient_tolerance = 1e-14;
  o.parameter_tolerance = 1e-14;
  o.max_num_iterations = 20;
  return o;
}

TEST(DomainSolve, SmallProblemsAreSolvedGlobally) {
  EXPECT_EQ(DomainParts(1000, 0), 0);
  EXPECT_EQ(DomainParts(4000, 1000), 0);
  EXPECT_EQ(DomainParts(4001, 1000), 5);
  Membrane m(10);
  const DomainSolveSummary s = DomainSolve(Options(), {1000, 1, 0}, &m.problem);
  EXPECT_EQ(s.parts, 0);
  EXPECT_TRUE(s.usable);
}

TEST(DomainSolve, PartsAndBandReachTheGlobalOptimum) {
  Membrane global(40), domains(40);
  const DomainSolveSummary g = DomainSolve(Options(), {0, 1, 0}, &global.problem);
  ASSERT_EQ(g.parts, 0);
  const DomainSolveSummary d = DomainSolve(Options(), {100, 1, 0}, &domains.problem);
  EXPECT_EQ(d.parts, 16);  // 1600 variables, about 100 per part
  EXPECT_TRUE(d.usable);
  EXPECT_GE(d.final_cost, g.final_cost * (1 - 1e-12));
  // Pass 1 alone (no band pass) leaves the separator where it started.
  Membrane parts_only(40);
  const DomainSolveSummary p = DomainSolve(Options(), {100, -1, 0}, &parts_only.problem);
  EXPECT_GT(p.final_cost, 1.1 * g.final_cost);
  // The band pass closes most of the gap: parts of 10 × 10 cells with a
  // coupling that decays over about two cells.
  std::printf("optimum %.4f, parts and band %.4f, parts alone %.4f\n", g.final_cost,
              d.final_cost, p.final_cost);
  EXPECT_LT(d.final_cost - g.final_cost, 0.25 * (p.final_cost - g.final_cost));
  EXPECT_LE(d.final_cost, 1.03 * g.final_cost);
  double worst = 0, worst_parts = 0;
  for (size_t k = 0; k < global.x.size(); ++k) {
    worst = std::max(worst, std::abs(domains.x[k] - global.x[k]));
    worst_parts = std::max(worst_parts, std::abs(parts_only.x[k] - global.x[k]));
  }
  std::printf("largest error: parts and band %.4f, parts alone %.4f\n", worst, worst_parts);
  EXPECT_LT(worst, 0.5 * worst_parts);
}

TEST(DomainSolve, ConstantBlocksStayConstantAndTheRestIsRestored) {
  Membrane m(30);
  m.problem.SetParameterBlockConstant(&m.x[0]);
  m.x[0] = 5;
  DomainSolve(Options(), {50, 1, 0}, &m.problem);
  EXPECT_EQ(m.x[0], 5);
  EXPECT_TRUE(m.problem.IsParameterBlockConstant(&m.x[0]));
  for (size_t k = 1; k < m.x.size(); ++k) {
    EXPECT_FALSE(m.problem.IsParameterBlockConstant(&m.x[k])) << k;
  }
}

double MaxDisplacement(const Mesh& a, const Mesh& b) {
  double worst = 0;
  for (auto v : a.vertices()) {
    worst = std::max(worst, std::sqrt(CGAL::squared_distance(a.point(v), b.point(v))));
  }
  return worst;
}

TEST(DomainSolve, PlanarQuadsInDomainsMatchesTheGlobalSolve) {
  Mesh input = QuadGrid(40, 40, RoofSurface, 0.05, 3);
  ToCanonical(CanonicalFrame(input), input);
  auto run = [&](const std::string& yaml) {
    Mesh mesh = input;
    const ProblemSpec spec = ParseSpec("problem: planar_quads\n" + yaml);
    return Solve(spec, mesh, &input, {});
  };
  const auto global = run("");
  const auto domains = run("solver: {domain_size: 2000}\n");
  ASSERT_TRUE(global->loop.usable);
  ASSERT_TRUE(domains->loop.usable);
  EXPECT_EQ(global->loop.domains, 0);
  EXPECT_GE(domains->loop.domains, 5);
  const double tolerance = 1e-3;
  EXPECT_TRUE(domains->loop.tolerances.at("tolerance.pq_normalized_max"));
  EXPECT_LE(ComputeMetrics(domains->output, nullptr, nullptr).pq_normalized_max, tolerance);
  const double moved_global = MaxDisplacement(global->output, input);
  const double moved_domains = MaxDisplacement(domains->output, input);
  std::printf("max displacement: global %.4f, domains %.4f (rounds %d / %d)\n", moved_global, moved_domains, global->loop.rounds, domains->loop.rounds);
  EXPECT_LE(moved_domains, 1.1 * moved_global);
  EXPECT_GE(moved_domains, 0.9 * moved_global);
}

}  // namespace
}  // namespace archgeo
