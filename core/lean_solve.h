// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — LeanSolve: Levenberg–Marquardt on hand-assembled normal
// equations, each step either one sparse Cholesky factorisation (CHOLMOD,
// core/normal_cholesky.h: an exact step, as Ceres' sparse_normal_cholesky
// takes, without Ceres' per-solve set-up and Jacobian storage) or, for
// problems too large for one factorisation per step (a factorisation grows
// ~n^1.5 in time and memory; a CG step costs ~n), a block-Jacobi
// preconditioned conjugate-gradient step.
//   - It reads the round's residuals (core/residuals.h: Ceres cost
//     functions, losses, manifolds) without a ceres::Problem: the energies
//     stay the autodiff functors of energies/.
//   - It fixes the block pattern of JᵀJ once (core/normal_equations.h; kept
//     for the next round while the structure stays), and each iteration
//     accumulates every residual block's J_aᵀ J_b into its slot (no J is
//     stored).
//   - It solves (JᵀJ + μ diag(JᵀJ)) δ = −Jᵀr exactly (LeanStep::kCholesky:
//     a numeric factorisation per step; a matrix that is not positive
//     definite gives no step, which is rejected), or by block-Jacobi PCG
//     (core/lean_kernels.h), an inexact Newton step ended by Nash and
//     Sofer's test as Ceres' conjugate gradients end inside its
//     Levenberg–Marquardt, after at least min_ and at most
//     max_linear_solver_iterations steps.
//   - It steps and adapts μ as Ceres' Levenberg–Marquardt strategy does,
//     with its tolerances (function, gradient, parameter), iteration and
//     time limits and iteration callbacks (so a per-iteration tolerance ends
//     the solve); the function tolerance also ends it where the next cost
//     change, extrapolated from the last two (Δ_k² / Δ_(k−1)), would be
//     below it, once a step changes the cost by at most a tenth of what is
//     left.
//   - Losses are applied with Ceres' corrector (Triggs et al.): the same cost.
//   - It runs on options.num_threads = T threads (core/parallel_parts.h):
//     the residuals are cut into T ranges of the mesh whose blocks no other
//     range reads, assembled in parallel, then the residuals that straddle
//     two ranges in a fixed order; every product and dot product runs in T
//     fixed parts whose results are added in part order. The same T gives
//     the same bits, run to run and on any number of cores; another T sums
//     in another order (the last bits differ).
//
// Options. Read: max_num_iterations, max_solver_time_in_seconds,
// num_threads, function/gradient/parameter_tolerance, min_relative_decrease,
// initial/max/min_trust_region_radius, min/max_lm_diagonal, eta,
// min/max_linear_solver_iterations, callbacks. Refused (LeanSolveRefuses;
// LeanSolve then solves nothing and reports the option): minimizer_type
// other than trust_region, trust_region_strategy_type other than
// levenberg_marquardt, use_nonmonotonic_steps, use_inner_iterations,
// preconditioner_type other than jacobi. Every other option is ignored: the
// linear solver, its libraries and factorisation options (LeanSolve's
// linear solver is its PCG or CHOLMOD's supernodal Cholesky, by `step`;
// SolveRound sends a round whose options ask for another to Ceres:
// LeanCholeskyTakes), jacobi_scaling (the LM step with μ diag(JᵀJ)
// and a block-Jacobi preconditioner does not change under a scaling of the
// columns, which is what jacobi_scaling does, but for the min/max_lm_diagonal
// clamps), max_num_consecutive_invalid_
// steps (an invalid step, one whose cost fails to evaluate, is rejected and
// the radius shrinks until min_trust_region_radius ends the solve), and the
// options that only apply with a refused one (dogleg_type, line_search_*,
// max_consecutive_nonmonotonic_steps, inner_iteration_tolerance).
//
// Iteration callbacks get a ceres::IterationSummary per iteration (0: the
// start) with, as Ceres fills them: iteration, cost, cost_change (0 for a
// rejected step), gradient_max_norm and gradient_norm (of Jᵀr at the
// iteration's point, in the tangent space), step_norm (‖δ‖, tangent),
// step_is_valid (the step lowers the model and its cost evaluates),
// step_is_successful (accepted), relative_decrease (actual / model
// decrease, for a valid step), trust_region_radius (after the step),
// eta, linear_solver_iterations (CG steps), step_solver_time_in_seconds
// (the CG solve), iteration_time_in_seconds and cumulative_time_in_seconds.
// One exception: a step that ends the solve (a tolerance met, or an
// EndingCallback's Ends) is not linearised again, so its gradient norms are
// those of the quadratic model's gradient at the step, g + JᵀJ δ (exact for
// a linear problem; finite always). Left at their defaults:
// step_is_nonmonotonic (false: LeanSolve is monotonic), step_size and the
// line_search_* counts (0: no line search). Iteration 0 has step_is_valid
// and step_is_successful false, as in Ceres.
//
// Why LeanSolve and not Ceres' own iterative solver. On the same noisy roofs
// (planar_quads, tolerance 1e-3, 2 threads, each run capped at 600 s, in one
// run on a shared 2-core machine; docs/performance.md, "Solver back ends"),
// LeanSolve reached the tolerance 3–10× sooner than
// Ceres' CGNR with its Jacobi preconditioner, in 10 Levenberg–Marquardt
// iterations against 27–29 and to the same quality, and CGNR with the
// SUBSET preconditioner (the planarity and barrier rows) did not reach it in
// 600 s at 100k quads and took about 600 s at 10k: it factorises the
// subset's QᵀQ every iteration, which costs about as much as the direct
// solve, and leaves the other terms out. CGNR applies JᵀJ through J and Jᵀ
// in each CG step (~30 residual blocks per quad); LeanSolve assembles JᵀJ
// once per iteration and each CG step streams its upper triangle, with the
// same block-Jacobi preconditioner. So LeanSolve's PCG is the back end of the
// rounds above solver.pcg_above (its Cholesky steps, with back_end lean, of
// the others; docs/performance.md has those figures):
//
//   quads    back end              wall s  rounds  iterations    δ_PQ,n max  exit
//   100x100  LeanSolve                8.2       5  10 (224 CG)   0.00058     0
//   100x100  Ceres cgnr + jacobi     23.9       5  27            0.00059     0
//   100x100  Ceres cgnr + subset    596.9       5  55            0.00039     0
//   317x317  LeanSolve               23.2       5  10 (181 CG)   0.00066     0
//   317x317  Ceres cgnr + jacobi    231.8       5  29            0.00074     0
//   317x317  Ceres cgnr + subset    679.2       1   6            0.091       4 (not met)
//
//   benchmarks/solver_backends.sh build/archgeo
#pragma once

#include <string>
#include <vector>

#include <ceres/solver.h>

#include "core/normal_cholesky.h"
#include "core/residuals.h"

namespace archgeo {

struct NormalPattern;

struct SolveSummary {
  bool pcg = false;       // solved by LeanSolve with conjugate-gradient steps
  bool cholesky = false;  // solved by LeanSolve with sparse Cholesky steps
  int iterations = 0;  // accepted and rejected steps, as Ceres counts them
  int cg_iterations = 0;
  int analyses = 0;  // sparse Cholesky analyses made (ordering, symbolic factorisation)
  int factorisations = 0;          // numeric sparse Cholesky factorisations attempted
  double factor_flops = 0;         // their floating-point operations (CHOLMOD's count), summed
  double factor_nonzeros = 0;      // nonzeros of the largest factor L
  double seconds = 0, linear_solver_seconds = 0, jacobian_seconds = 0, residual_seconds = 0;
  double initial_cost = 0, final_cost = 0;  // ½ Σ ρ(‖r‖²)
  double trust_region_radius = 0;  // LeanSolve's at the end (0: Ceres solved it)
  bool usable = true;
  std::string message;
  bool terminated_by_callback = false;
};

// An iteration callback that can tell, at an accepted step and before
// LeanSolve linearises there, that it will end the solve at this step (e.g.
// its tolerances hold at the current values). LeanSolve then reports the
// step without that linearisation (gradient norms: the model's, see above).
class EndingCallback : public ceres::IterationCallback {
 public:
  virtual bool Ends() = 0;
};

// The option of `options` (by its Ceres name, e.g.
// "trust_region_strategy_type") that asks for an algorithm LeanSolve does
// not implement, with the reason in `why` if given; "" if none does.
std::string LeanSolveRefuses(const ceres::Solver::Options& options, std::string* why = nullptr);

// Minimises the sum of `residuals` from the values in their parameter blocks
// (which hold the result on return), with `options` as above; a refused
// option leaves everything as it was and returns usable = false, the
// option named in the message. `pattern`, if given, keeps the pattern of
// JᵀJ from one call to the next and is reused while the problem's
// structure stays (core/normal_equations.h).
enum class LeanStep { kPcg, kCholesky };
SolveSummary LeanSolve(const ceres::Solver::Options& options, const Residuals& residuals,
                       NormalPattern* pattern = nullptr, LeanStep step = LeanStep::kPcg,
                       CholeskyOrdering ordering = CholeskyOrdering::kAmd);

// Whether LeanSolve's Cholesky steps are the steps `options` ask for: no
// option LeanSolve refuses, and a sparse normal Cholesky of CHOLMOD in double
// precision, without iterative refinement or dynamic sparsity.
bool LeanCholeskyTakes(const ceres::Solver::Options& options);

// How the loop solves a round (solver.pcg_above, solver.pcg_function_tolerance,
// solver.subset_preconditioner_parts).
struct RoundSolver {
  int pcg_above = 0;                  // LeanSolve above this many free variables; 0: never
  bool lean = false;  // the other rounds by LeanSolve's Cholesky steps where LeanCholeskyTakes
  CholeskyOrdering ordering = CholeskyOrdering::kAmd;  // of those steps (solver.ordering)
  double pcg_function_tolerance = 0;  // LeanSolve's function tolerance at least this
  // With preconditioner_type subset (Ceres): the objective parts whose
  // residual blocks form Ceres' SUBSET preconditioner.
  std::vector<std::string> subset_parts;
};

// Whether SolveRound solves `residuals` by LeanSolve: pcg_above > 0 and more
// than pcg_above free variables.
bool UsesLeanSolve(int pcg_above, const Residuals& residuals);

// One round's solve: LeanSolve's PCG with function_tolerance raised to at
// least how.pcg_function_tolerance where UsesLeanSolve, else LeanSolve's
// Cholesky steps with how.lean where LeanCholeskyTakes, else ceres::Solve on
// residuals.MakeProblem() (with preconditioner_type subset: the subset of
// how.subset_parts; none of their blocks in the round: usable = false).
SolveSummary SolveRound(const ceres::Solver::Options& options, const RoundSolver& how,
                        const Residuals& residuals, NormalPattern* pattern = nullptr);

}  // namespace archgeo
