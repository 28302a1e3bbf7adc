// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the one solve loop. Every problem runs here:
//
//   for each stage of the declaration:
//     no round if it is skip_if_met and its tolerances already hold
//     for each round (at most the stage's rounds):
//       before-round hook; re-project onto the reference (if a term needs it)
//       build the Ceres problem from the active terms (weights × continuation)
//       solve (one progress line per Ceres iteration; a per-iteration
//         tolerance ends the solve the moment it holds)
//       check the solution (usable, finite); after-round hook (e.g. guard)
//       measure; log the round; undo a round that made `undo_if_worse` worse
//       stop on tolerances met, rest, a stall (patience); else continue (continuation)
//   restore the best round if the stage keeps the best
//
// The loop knows no mesh type: it works through a Model (problems/runtime/model.h
// implements it over the CGAL store, the reference and the measures).
#pragma once

#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/problem.h"
#include "core/progress.h"
#include "core/residuals.h"
#include "core/settings.h"
#include "core/term.h"


namespace archgeo {

struct NormalPattern;  // core/normal_equations.h

// A term as the loop activates it for one round.
struct ActiveTerm {
  const TermSpec* spec = nullptr;
  double weight = 0;  // settings weight × continuation scale
  double band = -1;  // tolerance band (< 0: none)
};

class Model {
 public:
  virtual ~Model() = default;

  // Start of a round: snapshots ("previous" positions), vertex normals and,
  // if `project`, the projection onto the reference.
  virtual void BeginRound(bool project) = 0;
  // Adds the residuals of `terms` (in order; consecutive terms on the same
  // element set are added element by element) to `residuals`, each under its
  // objective part (term name or part name); makes fixed vertices constant
  // and unit blocks spherical.
  virtual void Build(const std::vector<ActiveTerm>& terms, int round, Residuals& residuals) = 0;
  // After a round: grows the guard weight (block "guard_weight", read by the
  // displacement_guard term) of the vertices beyond half the bound
  // (`bound_relative` × the bounding-box diagonal) and clamps vertices beyond
  // it; returns how many were clamped.
  virtual int Guard(double bound_relative) = 0;

  // The value of a measure on the current state (cached until it changes).
  virtual double Measure(const std::string& name) = 0;
  virtual void StateChanged() = 0;  // invalidates the measure cache

  // Every variable (positions and blocks), to restore a round.
  virtual std::vector<double> SaveState() const = 0;
  virtual void RestoreState(const std::vector<double>& state) = 0;
  // Largest vertex move between two saved states (canonical lengths).
  virtual double MaxMove(const std::vector<double>& a, const std::vector<double>& b) const = 0;
  virtual bool Finite() const = 0;
  // The cheap validity checks of the current state against the start of the
  // solve (analysis/validity.h without the self-intersection test): "" when
  // valid, else the failed checks.
  virtual std::string Invalid() = 0;

  virtual HookContext& hooks() = 0;
};

// One round of the log (the report's "rounds").
struct RoundLog {
  std::string stage;
  int round = 0;       // 1-based over the whole run
  int iterations = 0;  // Ceres iterations
  double cost = 0;     // Ceres' final cost (½ Σ w r²)
  double weight_scale = 1;
  double max_move = 0;  // canonical lengths (input mean edge length = 1)
  int clamped = 0;      // vertices put back by the guard
  bool undone = false;
  bool valid = true;    // the state after the round passes the validity checks
  std::string invalid;  // else: which checks failed
  double seconds = 0;
  std::map<std::string, double> measures;
};

struct LoopResult {
  bool usable = true;   // false: Ceres found no usable solution (message says why)
  std::string message;
  int variables = 0, residuals = 0;
  int rounds = 0, iterations = 0;
  int pcg_rounds = 0;     // rounds solved by LeanSolve (solver.pcg_above)
  int cg_iterations = 0;  // their conjugate-gradient steps
  int cholesky_rounds = 0;  // rounds solved by LeanSolve's Cholesky steps (solver.back_end)
  // Orderings and symbolic factorisations those rounds made: one per new
  // structure of the residuals (0 when a kept pattern, LoopOptions::pattern,
  // fits every round).
  int cholesky_analyses = 0;
  // Those rounds' numeric factorisations (one per step, rejected steps
  // included), their floating-point operations summed and the nonzeros of
  // the largest factor: CHOLMOD's counts.
  int cholesky_factorisations = 0;
  double cholesky_flops = 0, cholesky_factor_nonzeros = 0;
  std::map<std::string, double> objective;  // ½ Σ w r² per part and "total", final state
  std::map<std::string, double> seconds;    // "solver" (Ceres or PCG), "linear_solver", "jacobian",
                                            // "residual", "projection"
  std::map<std::string, bool> tolerances;   // per tolerance key: met at the end
  std::vector<RoundLog> log;                // log[0]: the input (round 0)
  int output_round = 0;                     // the round whose state is the output
  std::string stop;                         // why the last stage ended
  bool stalled = false;                     // a stage ended by its stall rule (patience)
  // Per bound (Tolerance::bound) key: the lowest value of its measure among
  // the rounds that met every goal tolerance of their stage but broke the
  // bound (what the goals needed); absent if no round did.
  std::map<std::string, double> bound_needs;
  bool restored_valid = false;              // the last round was invalid: the output is
                                            // the last valid round (output_round)
  bool stopped = false;                     // LoopOptions::stop ended the run
  double weight_scale = 1;                  // the continuation's scale in the last round run
  double trust_region_radius = 0;           // LeanSolve's at the end of the last round it
                                            // solved (0: none)
};

struct LoopOptions {
  const Settings* settings = nullptr;  // the problem's settings (weights, schedule, solver)
  std::vector<const TermSpec*> terms;  // the problem's terms, in residual order
  ProgressSink progress;
  // When set and true (another thread, a signal handler or the progress sink
  // may set it), the solve ends after the current Ceres iteration, no further
  // round or stage runs, and the output is the last valid state (as
  // validity.keep_last_valid, whatever its value). Null: never stops.
  const std::atomic<bool>* stop = nullptr;
  // The pattern of J^T J and its Cholesky analysis (core/normal_equations.h),
  // kept beyond this run when given (a session's re-solves on the same
  // store: while the residuals keep their structure, no run analyses it
  // again). Null: the run's own.
  NormalPattern* pattern = nullptr;
  // The continuation's scale of the weights at the start (Stage::continued):
  // 1 for a solve from its input; a session's re-solve starts at the scale
  // its last solve ended with (LoopResult::weight_scale).
  double weight_scale = 1;
};

// Runs `declaration` on `model`. Never throws for a failed solve (see
// LoopResult::usable); throws InputError for settings Ceres rejects.
LoopResult RunLoop(const ProblemDecl& declaration, const LoopOptions& options, Model& model);

// The JSON of a round log row.
nlohmann::json RoundJson(const RoundLog& row);

}  // namespace archgeo
