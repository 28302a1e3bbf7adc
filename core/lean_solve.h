// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — Levenberg–Marquardt on hand-assembled normal equations with a
// preconditioned conjugate-gradient step, for problems too large for one
// sparse Cholesky factorisation.
//
// Why (README, "Speed", measured on the planar_quads problem of a 10k-quad
// roof, 60,603 variables): one CHOLMOD factorisation of J^T J + μD takes
// 0.50–0.58 s whatever the ordering (AMD, METIS, nested dissection; 4.5–6.6
// GFlop, the factor has 10–12M entries), and it grows ~n^1.5. Conjugate
// gradients on the same matrix with a block-Jacobi preconditioner reach 99.6%
// of the step's model decrease in 16–32 iterations (0.02–0.05 s), and each
// iteration costs ~n. Ceres' own CGNR works on J rather than J^T J and was
// slower than its direct solve (32k quads: 93 s against 40 s). So this solver:
//   - reads the round's residuals (core/residuals.h: Ceres cost functions,
//     losses, manifolds) without a ceres::Problem: the energies stay the
//     autodiff functors of energies/;
//   - fixes the block pattern of J^T J once (and keeps it for the next
//     round while the structure stays), and each iteration accumulates
//     every residual block's J_a^T J_b into its slot (no J is stored);
//   - solves (J^T J + μ diag(J^T J)) δ = −J^T r by block-Jacobi PCG (an
//     inexact Newton step), ending as Ceres' conjugate gradients do in its
//     Levenberg–Marquardt: when the quadratic model's relative decrease,
//     times the step count, falls below `eta` (Nash & Sofer's test), after
//     at least min_ and at most max_linear_solver_iterations steps;
//   - steps and adapts μ as Ceres' Levenberg–Marquardt strategy does, with its
//     tolerances (function, gradient, parameter), iteration and time limits,
//     and iteration callbacks (so a per-iteration tolerance ends the solve);
//     the function tolerance also ends it where the next cost change,
//     extrapolated from the last two (Δ_k² / Δ_(k−1)), would be below it.
// Losses are applied with Ceres' corrector (Triggs et al.): the same cost.
#pragma once

#include <string>

#include <ceres/solver.h>

#include "core/residuals.h"

namespace archgeo {

struct NormalPattern;

struct SolveSummary {
  bool pcg = false;    // solved by LeanSolve (else by ceres::Solve)
  int iterations = 0;  // accepted and rejected steps, as Ceres counts them
  int cg_iterations = 0;
  double seconds = 0, linear_solver_seconds = 0, jacobian_seconds = 0, residual_seconds = 0;
  double initial_cost = 0, final_cost = 0;  // ½ Σ ρ(‖r‖²)
  bool usable = true;
  std::string message;
  bool terminated_by_callback = false;
};

// An iteration callback that can tell, at an accepted step and before
// LeanSolve linearises there, that it will end the solve at this step (e.g.
// its tolerances hold at the current values). LeanSolve then reports the
// step without that linearisation (gradient norms NaN: not evaluated).
class EndingCallback : public ceres::IterationCallback {
 public:
  virtual bool Ends() = 0;
};

// Minimises the sum of `residuals` from the values in their parameter blocks
// (which hold the result on return). Reads from `options`: max_num_iterations,
// max_solver_time_in_seconds, function/gradient/parameter_tolerance,
// min_relative_decrease, initial/max/min_trust_region_radius,
// min/max_lm_diagonal, eta, min/max_linear_solver_iterations, callbacks.
// `pattern`, if given, keeps the pattern of J^T J from one call to the next
// and is reused while the problem's structure stays (core/normal_equations.h).
SolveSummary LeanSolve(const ceres::Solver::Options& options, const Residuals& residuals,
                       NormalPattern* pattern = nullptr);

// One round's solve: LeanSolve with function_tolerance raised to at least
// `pcg_function_tolerance` when pcg_above > 0 and the problem has more than
// pcg_above free variables (solver.pcg_above), else ceres::Solve on
// residuals.MakeProblem().
SolveSummary SolveRound(const ceres::Solver::Options& options, int pcg_above,
                        double pcg_function_tolerance, const Residuals& residuals,
                        NormalPattern* pattern = nullptr);

}  // namespace archgeo
