// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/lean_solve.h"

#include "core/clock.h"
#include "core/lean_kernels.h"
#include "core/normal_cholesky.h"
#include "core/normal_equations.h"
#include "core/parallel_parts.h"
#include "core/solver_options.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <ceres/cost_function.h>
#include <ceres/loss_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/types.h>

namespace archgeo {
namespace {

using Vector = Eigen::VectorXd;

// Ceres' loss corrector (Triggs et al. 1999, "Bundle adjustment — a modern
// synthesis", §4.3): scales r and J so that ½‖r̃‖² matches ρ to second order.
struct Corrector {
  double residual_scaling = 1, alpha_sq_norm = 0, sqrt_rho1 = 1;
  Corrector(double sq_norm, const double rho[3]) {
    sqrt_rho1 = std::sqrt(rho[1]);
    if (sq_norm == 0.0 || rho[2] <= 0.0) {
      residual_scaling = sqrt_rho1;
      return;
    }
    const double D = 1.0 + 2.0 * sq_norm * rho[2] / rho[1];
    const double alpha = 1.0 - std::sqrt(D);
    residual_scaling = sqrt_rho1 / (1 - alpha);
    alpha_sq_norm = alpha / sq_norm;
  }
};

// One thread's linearisation scratch and its sum Σ ρ, on cache lines of its
// own: another thread's writes to its sum must not evict this one's scratch
// pointers (false sharing).
struct alignas(64) Work {
  std::vector<double> residual, ambient, tangent;
  std::vector<double*> jacobians, tangents;
  std::vector<int> free;
  double total = 0;
};

class Lean {
 public:
  Lean(const Residuals& residuals, NormalPattern& pattern, int threads)
      : in_(residuals), s_(pattern), threads_(std::clamp(threads, 1, 256)),
        work_(size_t(threads_)) {
    if (!ReadNormalPattern(residuals, threads_, &s_)) s_.cholesky.reset();
    size_t rows = 0, scratch = 0, parameters = 0;
    for (size_t i = 0; i < residuals.residuals().size(); ++i) {
      const Residuals::Residual& r = residuals.residuals()[i];
      const int m = Rows(i);
      rows = std::max<size_t>(rows, m);
      parameters = std::max<size_t>(parameters, r.end - r.first);
      size_t need = 0;
      for (int a = r.first; a < r.end; ++a) {
        if (block(a) >= 0) need += size_t(m) * ambient(a);
      }
      scratch = std::max(scratch, need);
    }
    s_.hessian.Resize(size_t(s_.slots));
    size_t plus = 0;
    for (PatternBlock& b : s_.blocks) {
      b.plus = b.manifold ? int(plus) : -1;
      if (b.manifold) plus += size_t(b.ambient) * b.tangent;
    }
    s_.plus_jacobians.resize(plus);
    // Each buffer with 16 spare entries (≥ 64 bytes) at its end, so that no
    // two threads' buffers share a cache line.
    constexpr size_t kSpare = 16;
    for (Work& w : work_) {
      w.residual.resize(rows + kSpare);
      w.ambient.resize(scratch + kSpare);
      w.tangent.resize(scratch + kSpare);
      w.jacobians.resize(parameters + kSpare);
      w.tangents.resize(parameters + kSpare);
      w.free.resize(parameters + kSpare);
    }
    system_ = std::make_unique<NormalSystem>(s_, threads_);
  }

  const NormalSystem& system() const { return *system_; }

  // The free blocks' values, concatenated (to undo a rejected step).
  std::vector<double> Save() const {
    std::vector<double> x;
    for (const PatternBlock& b : s_.blocks) x.insert(x.end(), b.values, b.values + b.ambient);
    return x;
  }
  void Restore(const std::vector<double>& x) const {
    size_t at = 0;
    for (const PatternBlock& b : s_.blocks) {
      std::copy(x.begin() + long(at), x.begin() + long(at + b.ambient), b.values);
      at += b.ambient;
    }
  }
  // x ⊞ δ in place (manifold Plus per block).
  bool Step(const Vector& delta) {
    std::vector<double> moved;
    for (const PatternBlock& b : s_.blocks) {
      const double* d = delta.data() + b.offset;
      if (!b.manifold) {
        for (int k = 0; k < b.ambient; ++k) b.values[k] += d[k];
        continue;
      }
      moved.resize(b.ambient);
      if (!b.manifold->Plus(b.values, d, moved.data())) return false;
      std::copy(moved.begin(), moved.end(), b.values);
    }
    return true;
  }

  // ½ Σ ρ(‖r‖²) at the current values; false if a block fails to evaluate.
  // The T parts of the visiting order (each a part of the mesh with every
  // term), each summed on its own, then added in order.
  bool Cost(double* cost) {
    const size_t n = s_.visit.size();
    std::vector<char> good(size_t(threads_), 1);
    *cost = SumParts(threads_, [&](int t) {
      double* scratch = work_[size_t(t)].residual.data();
      double total = 0;
      for (size_t p = PartStart(n, threads_, t), end = PartStart(n, threads_, t + 1); p < end;
           ++p) {
        const double c = in_.Cost(s_.visit[p], scratch);
        if (std::isnan(c)) {
          good[size_t(t)] = 0;
          return 0.0;
        }
        total += c;
      }
      return total;
    });
    for (char g : good) {
      if (!g) return false;
    }
    return std::isfinite(*cost);
  }

  // The cost, the gradient g = J^T r and H = J^T J (slots) at the current
  // values.
  bool Linearise(double* cost, Vector* gradient) {
    for (PatternBlock& b : s_.blocks) {
      if (!b.manifold) continue;
      if (!b.manifold->PlusJacobian(b.values, s_.plus_jacobians.data() + b.plus)) return false;
    }
    // H and g in one copy: the pattern's first T runs of residuals read no
    // block in common (a thread each), then its last run.
    double* H = s_.hessian.data();
    const size_t slots = size_t(s_.slots);
    ForParts(threads_, [&](int t) {
      std::fill(H + PartStart(slots, threads_, t), H + PartStart(slots, threads_, t + 1), 0.0);
    });
    gradient_.setZero(s_.tangent);
    std::vector<char> good(size_t(threads_), 1);
    for (Work& w : work_) w.total = 0;
    ForParts(threads_, [&](int t) {
      Work& w = work_[size_t(t)];
      bool ok = true;  // written to good[t] once: they share a cache line
      for (int p = s_.RunStart(t); p < s_.run_end[size_t(t)] && ok; ++p) {
        ok = Accumulate(size_t(s_.visit[size_t(p)]), &w);
      }
      good[size_t(t)] = ok;
    });
    for (char g : good) {
      if (!g) return false;
    }
    double runs = work_[0].total;
    for (int t = 1; t < threads_; ++t) runs += work_[size_t(t)].total;
    Work& last = work_[0];
    last.total = 0;
    bool ok = true;
    for (int p = s_.RunStart(threads_); p < s_.run_end[size_t(threads_)] && ok; ++p) {
      ok = Accumulate(size_t(s_.visit[size_t(p)]), &last);
    }
    if (!ok) return false;
    *gradient = gradient_;
    *cost = 0.5 * (runs + last.total);
    return std::isfinite(*cost) && gradient->allFinite();
  }

  double ParameterNorm() const {
    double sq = 0;
    for (const PatternBlock& b : s_.blocks) {
      sq += Eigen::Map<const Vector>(b.values, b.ambient).squaredNorm();
    }
    return std::sqrt(sq);
  }

 private:
  // The free block of residual parameter `parameter` (-1: constant).
  int block(int parameter) const { return s_.free[size_t(in_.block_of()[size_t(parameter)])]; }
  int ambient(int parameter) const { return s_.blocks[size_t(block(parameter))].ambient; }
  // One residual block into the sums: ρ, its corrected tangent Jacobians,
  // g += J̃ᵀ r̃ and every J̃_aᵀ J̃_b into its slot.
  bool Accumulate(size_t index, Work* k) {
    const Residuals::Residual& in = in_.residuals()[index];
    const ceres::LossFunction* loss = in_.Loss(in.loss());
    const int rows = in.rows();
    const int m = in.end - in.first;
    double** jacobians = k->jacobians.data();
    double** tangents = k->tangents.data();
    int* free = k->free.data();  // its parameters' free blocks (-1: constant)
    size_t used = 0;
    for (int a = 0; a < m; ++a) {
      free[a] = block(in.first + a);
      jacobians[a] = tangents[a] = nullptr;
      if (free[a] < 0) continue;
      jacobians[a] = k->ambient.data() + used;
      tangents[a] = k->tangent.data() + used;
      used += size_t(rows) * s_.blocks[size_t(free[a])].ambient;
    }
    if (!in.Evaluate(in_.values() + in.first, k->residual.data(), jacobians)) return false;
    Eigen::Map<Vector> res(k->residual.data(), rows);
    const double sq = res.squaredNorm();
    double rho[3] = {sq, 1.0, 0.0};
    if (loss) loss->Evaluate(sq, rho);
    k->total += rho[0];
    if (sq == 0.0 && AllZero(jacobians, free, m, rows)) return true;  // e.g. an idle barrier
    const Corrector corrector(sq, rho);
    // Tangent Jacobians, corrected: J̃ = √ρ' (J − α/‖r‖² r rᵀ J).
    for (int a = 0; a < m; ++a) {
      const int i = free[a];
      if (i < 0) continue;
      const PatternBlock& b = s_.blocks[i];
      if (b.manifold) {
        TangentProduct(jacobians[a], s_.plus_jacobians.data() + b.plus, rows, b.ambient,
                       b.tangent, tangents[a]);
      } else {
        tangents[a] = jacobians[a];  // tangent = ambient: in place
      }
      double* T = tangents[a];
      const int t = b.tangent;
      if (corrector.alpha_sq_norm != 0.0) {
        for (int c = 0; c < t; ++c) {
          double dot = 0;
          for (int r = 0; r < rows; ++r) dot += res[r] * T[r * t + c];
          for (int r = 0; r < rows; ++r) T[r * t + c] -= corrector.alpha_sq_norm * res[r] * dot;
        }
      }
      if (corrector.sqrt_rho1 != 1.0) {
        for (int e = 0; e < rows * t; ++e) T[e] *= corrector.sqrt_rho1;
      }
    }
    if (corrector.residual_scaling != 1.0) res *= corrector.residual_scaling;
    double* H = s_.hessian.data();
    double* g = gradient_.data();
    int pair = s_.pairs[index];
    for (int a = 0; a < m; ++a) {
      const int i = free[a];
      if (i < 0) continue;
      const PatternBlock& bi = s_.blocks[i];
      AddTransposeProduct(tangents[a], res.data(), rows, bi.tangent, 1,
                          g + bi.offset);
      AddTransposeProduct(tangents[a], tangents[a], rows, bi.tangent, bi.tangent,
                          H + s_.diagonal[i]);
      for (int c = a + 1; c < m; ++c) {
        const int j = free[c];
        if (j < 0 || j == i) continue;
        const PatternBlock& bj = s_.blocks[j];
        if (i < j) {
          AddTransposeProduct(tangents[a], tangents[c], rows, bi.tangent, bj.tangent,
                              H + s_.pair_slot[pair]);
        } else {
          AddTransposeProduct(tangents[c], tangents[a], rows, bj.tangent, bi.tangent,
                              H + s_.pair_slot[pair]);
        }
        ++pair;
      }
    }
    return true;
  }

  // Whether every Jacobian of a residual whose parameters are in the free
  // blocks `free` is zero: it adds nothing to g or H.
  bool AllZero(double* const* jacobians, const int* free, int m, int rows) const {
    for (int a = 0; a < m; ++a) {
      if (!jacobians[a]) continue;
      const double* J = jacobians[a];
      for (int e = 0, n = rows * s_.blocks[size_t(free[a])].ambient; e < n; ++e) {
        if (J[e] != 0.0) return false;
      }
    }
    return true;
  }
  int Rows(size_t i) const { return in_.residuals()[i].rows(); }

  const Residuals& in_;
  NormalPattern& s_;
  int threads_;
  std::vector<Work> work_;  // one per thread
  Vector gradient_;  // g = J^T r
  std::unique_ptr<NormalSystem> system_;
};

}  // namespace

SolveSummary LeanSolve(const ceres::Solver::Options& options, const Residuals& residuals,
                       NormalPattern* pattern, LeanStep step, CholeskyOrdering ordering) {
  const FullTeams teams;  // no CHOLMOD here
  const auto start = Clock::now();
  SolveSummary out;
  const bool direct = step == LeanStep::kCholesky;
  out.pcg = !direct;
  out.cholesky = direct;
  std::string why;
  const std::string refused = LeanSolveRefuses(options, &why);
  if (!refused.empty()) {
    out.usable = false;
    out.message = refused + ": " + why;
    return out;
  }
  NormalPattern own;
  Lean lean(residuals, pattern ? *pattern : own, options.num_threads);
  const NormalSystem& system = lean.system();
  NormalPattern& kept = pattern ? *pattern : own;
  double cost = 0;
  Vector gradient;
  auto t = Clock::now();
  if (!lean.Linearise(&cost, &gradient)) {
    out.usable = false;
    out.message = "a residual block failed to evaluate at the start";
    return out;
  }
  out.jacobian_seconds += SecondsSince(t);
  out.initial_cost = out.final_cost = cost;
  double radius = options.initial_trust_region_radius, decrease_factor = 2.0;
  double last_change = 0;  // the cost change of the last accepted step
  Vector delta;
  double model_max_norm = 0, model_norm = 0;  // of the model's gradient at the step
  // The report of an iteration (see lean_solve.h for its fields): `it` holds
  // what the step filled in, the gradient norms included unless `g` is given.
  auto report = [&](ceres::IterationSummary it, const Vector* g) {
    it.cost = cost;
    if (g) {
      it.gradient_max_norm = g->lpNorm<Eigen::Infinity>();
      it.gradient_norm = g->norm();
    }
    it.trust_region_radius = radius;
    it.cumulative_time_in_seconds = SecondsSince(start);
    for (ceres::IterationCallback* callback : options.callbacks) {
      const ceres::CallbackReturnType r = (*callback)(it);
      if (r == ceres::SOLVER_TERMINATE_SUCCESSFULLY) {
        out.terminated_by_callback = true;
        return true;
      }
      if (r == ceres::SOLVER_ABORT) {
        out.usable = false;
        out.message = "a callback aborted the solve";
        return true;
      }
    }
    return false;
  };
  {
    ceres::IterationSummary zero;
    zero.iteration_time_in_seconds = SecondsSince(start);
    if (report(zero, &gradient)) {
      out.seconds = SecondsSince(start);
      return out;
    }
  }
  if (gradient.lpNorm<Eigen::Infinity>() <= options.gradient_tolerance) {
    out.seconds = SecondsSince(start);
    return out;
  }
  for (int iteration = 1; iteration <= options.max_num_iterations; ++iteration) {
    if (SecondsSince(start) >= options.max_solver_time_in_seconds) break;
    const auto iteration_start = Clock::now();
    out.iterations = iteration;
    ceres::IterationSummary it;
    it.iteration = iteration;
    it.eta = options.eta;
    t = Clock::now();
    const Vector diagonal = system.Diagonal().cwiseMax(options.min_lm_diagonal).cwiseMin(
        options.max_lm_diagonal);
    const Vector damping = diagonal / radius;
    bool solved = true;
    if (direct) {
      // Not positive definite: no step; it is rejected and the damping
      // grows, as after Ceres' linear solver failure.
      if (!kept.cholesky || kept.cholesky->ordering() != ordering) {
        kept.cholesky = std::make_shared<NormalCholesky>(kept, ordering);
        ++out.analyses;
      }
      solved = kept.cholesky->Solve(kept, damping, gradient, &delta);
      ++out.factorisations;
      out.factor_flops += kept.cholesky->FactorFlops();
      out.factor_nonzeros = std::max(out.factor_nonzeros, kept.cholesky->FactorNonzeros());
      if (!solved) delta.setZero(gradient.size());
    } else {
      it.linear_solver_iterations =
          system.Solve(damping, gradient, options.eta, options.min_linear_solver_iterations,
                       options.max_linear_solver_iterations, &delta);
    }
    out.cg_iterations += it.linear_solver_iterations;
    const double model_change =
        system.ModelChange(gradient, delta, &model_max_norm, &model_norm);
    it.step_solver_time_in_seconds = SecondsSince(t);
    out.linear_solver_seconds += it.step_solver_time_in_seconds;
    it.step_norm = delta.norm();
    const std::vector<double> before = lean.Save();
    const double x_norm = lean.ParameterNorm();
    double new_cost = 0;
    t = Clock::now();
    it.step_is_valid = solved && model_change < 0.0 && lean.Step(delta) && lean.Cost(&new_cost);
    out.residual_seconds += SecondsSince(t);
    const double rho = it.step_is_valid ? (cost - new_cost) / -model_change : -1.0;
    if (it.step_is_valid) it.relative_decrease = rho;
    const bool small_step = solved && delta.norm() <= options.parameter_tolerance *
                                                          (x_norm + options.parameter_tolerance);
    if (it.step_is_valid && rho > options.min_relative_decrease) {
      it.step_is_successful = true;
      it.cost_change = cost - new_cost;
      cost = new_cost;
      radius = std::min(options.max_trust_region_radius,
                        radius / std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3)));
      decrease_factor = 2.0;
      // A step that ends the solve is not linearised again. It ends where
      // its change, or the next one extrapolated from the last two (Δ_k² /
      // Δ_(k−1): the changes falling geometrically), is below the function
      // tolerance: the iteration that would only confirm it is not taken.
      // Only in the tail, where the step changed the cost by at most a
      // tenth of what is left: a far start's first step removes nearly all
      // of its cost (a stiff term met at once), and its rate would predict a
      // next change of nothing after a second step that still removes much
      // of the rest.
      const double change = it.cost_change;
      const bool tail = last_change > 0 && change <= 0.1 * cost;
      const double next_change = tail ? change * change / last_change : change;
      bool ends = change <= options.function_tolerance * (cost + change) ||
                  next_change <= options.function_tolerance * cost || small_step;
      last_change = change;
      for (ceres::IterationCallback* callback : options.callbacks) {
        auto* ending = dynamic_cast<EndingCallback*>(callback);
        ends = ends || (ending && ending->Ends());
      }
      if (ends) {
        // Reported with the model's gradient at the step, g + JᵀJ δ.
        it.gradient_max_norm = model_max_norm;
        it.gradient_norm = model_norm;
        it.iteration_time_in_seconds = SecondsSince(iteration_start);
        report(it, nullptr);
        break;
      }
      t = Clock::now();
      if (!lean.Linearise(&cost, &gradient)) {
        out.usable = false;
        out.message = "a residual block failed to evaluate";
        break;
      }
      out.jacobian_seconds += SecondsSince(t);
      it.iteration_time_in_seconds = SecondsSince(iteration_start);
      if (report(it, &gradient)) break;
      if (gradient.lpNorm<Eigen::Infinity>() <= options.gradient_tolerance) break;
    } else {
      lean.Restore(before);
      radius /= decrease_factor;
      decrease_factor *= 2.0;
      it.iteration_time_in_seconds = SecondsSince(iteration_start);
      if (report(it, &gradient)) break;
      if (radius < options.min_trust_region_radius) break;
      if (small_step) break;
    }
  }
  out.trust_region_radius = radius;
  out.final_cost = cost;
  out.seconds = SecondsSince(start);
  return out;
}

std::string LeanSolveRefuses(const ceres::Solver::Options& o, std::string* why) {
  std::string name, reason;
  if (o.minimizer_type != ceres::TRUST_REGION) {
    name = "minimizer_type";
    reason = "LeanSolve is a trust-region (Levenberg-Marquardt) solver, not a line search";
  } else if (o.trust_region_strategy_type != ceres::LEVENBERG_MARQUARDT) {
    name = "trust_region_strategy_type";
    reason = "LeanSolve steps by Levenberg-Marquardt only, not by dogleg";
  } else if (o.use_nonmonotonic_steps) {
    name = "use_nonmonotonic_steps";
    reason = "LeanSolve accepts only steps that lower the cost";
  } else if (o.use_inner_iterations) {
    name = "use_inner_iterations";
    reason = "LeanSolve has no inner iterations";
  } else if (o.preconditioner_type != ceres::JACOBI) {
    name = "preconditioner_type";
    std::string type = ceres::PreconditionerTypeToString(o.preconditioner_type);
    for (char& c : type) c = char(std::tolower(static_cast<unsigned char>(c)));
    reason = "LeanSolve's conjugate gradients are preconditioned by block Jacobi (jacobi) only, "
             "not " + type;
  }
  if (why) *why = reason;
  return name;
}

bool LeanCholeskyTakes(const ceres::Solver::Options& o) {
  return LeanSolveRefuses(o).empty() && o.linear_solver_type == ceres::SPARSE_NORMAL_CHOLESKY &&
         o.sparse_linear_algebra_library_type == ceres::SUITE_SPARSE &&
         !o.use_mixed_precision_solves && o.max_num_refinement_iterations == 0 &&
         !o.dynamic_sparsity;
}

bool UsesLeanSolve(int pcg_above, const Residuals& residuals) {
  return pcg_above > 0 && residuals.FreeTangentSize() > pcg_above;
}

SolveSummary SolveRound(const ceres::Solver::Options& options, const RoundSolver& how,
                        const Residuals& residuals, NormalPattern* pattern) {
  if (UsesLeanSolve(how.pcg_above, residuals)) {
    ceres::Solver::Options lean = options;
    lean.function_tolerance = std::max(options.function_tolerance, how.pcg_function_tolerance);
    return LeanSolve(lean, residuals, pattern);
  }
  if (how.lean && LeanCholeskyTakes(options)) {
    return LeanSolve(options, residuals, pattern, LeanStep::kCholesky, how.ordering);
  }
  SolveSummary out;
  std::vector<ceres::ResidualBlockId> ids;
  const std::unique_ptr<ceres::Problem> problem = residuals.MakeProblem(&ids);
  ceres::Solver::Options ceres_options = options;
  if (options.preconditioner_type == ceres::SUBSET) {
    // Ceres' SUBSET preconditioner: the residual blocks of the named parts.
    std::vector<bool> in_subset(residuals.parts().size(), false);
    for (size_t k = 0; k < in_subset.size(); ++k) {
      in_subset[k] = std::find(how.subset_parts.begin(), how.subset_parts.end(),
                               residuals.parts()[k]) != how.subset_parts.end();
    }
    auto& subset = ceres_options.residual_blocks_for_subset_preconditioner;
    subset.clear();
    for (size_t i = 0; i < ids.size(); ++i) {
      if (in_subset[size_t(residuals.residuals()[i].part())]) subset.insert(ids[i]);
    }
    if (subset.empty()) {
      out.usable = false;
      out.message = "preconditioner_type subset: no residual block of the subset's parts";
      return out;
    }
  }
  ceres::Solver::Summary summary;
  ceres::Solve(ceres_options, problem.get(), &summary);
  out.iterations = std::max(0, int(summary.iterations.size()) - 1);
  out.seconds = std::max(0.0, summary.total_time_in_seconds);
  out.linear_solver_seconds = std::max(0.0, summary.linear_solver_time_in_seconds);
  out.jacobian_seconds = std::max(0.0, summary.jacobian_evaluation_time_in_seconds);
  out.residual_seconds = std::max(0.0, summary.residual_evaluation_time_in_seconds);
  out.initial_cost = summary.initial_cost;
  out.final_cost = summary.final_cost;
  out.usable = summary.IsSolutionUsable();
  if (!out.usable) out.message = summary.message;
  out.terminated_by_callback = summary.termination_type == ceres::USER_SUCCESS;
  return out;
}

}  // namespace archgeo
