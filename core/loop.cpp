// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/loop.h"

#include <ceres/solver.h>
#include <glog/logging.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/clock.h"
#include "core/format_number.h"
#include "core/lean_solve.h"
#include "core/normal_equations.h"
#include "core/solver_options.h"

namespace archgeo {
namespace {

// "  name value" for each logged measure.
std::string MeasureText(const std::map<std::string, double>& measures) {
  std::string text;
  for (const auto& [name, value] : measures) text += "  " + name + " " + FormatNumber("%.4g", value);
  return text;
}

// One progress line per Ceres iteration; ends the solve when every
// per-iteration tolerance holds (and tells LeanSolve so before it linearises).
class IterationWatch : public EndingCallback {
 public:
  // watched: (measure, bound value, whether it is a Tolerance::bound); the
  // solve ends when all hold and at least one is not a bound.
  struct Watched {
    std::string measure;
    double value;
    bool bound;
  };
  // `where`: the round's event fields (kind, round, stage, goal and target);
  // each iteration adds its number, the goal's value and the time.
  IterationWatch(Model& model, const ProgressSink& sink, std::string label,
                 std::vector<Watched> watched, ProgressEvent where, Clock::time_point start,
                 const std::atomic<bool>* stop)
      : model_(model), sink_(sink), label_(std::move(label)), watched_(std::move(watched)),
        where_(std::move(where)), start_(start), stop_(stop) {}

  bool Ends() override {
    if (Stopping()) return true;
    measured_ = false;  // a new step
    const bool met = Met(nullptr);
    measured_ = true;
    return met;
  }

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    std::string values;
    const bool met = Met(&values);
    measured_ = false;
    if (sink_) {
      char line[256];
      std::snprintf(line, sizeof line, "%s  iter %3d  cost %.6e%s  |gradient| %.2e  |step| %.2e  %.3f s",
                    label_.c_str(), s.iteration, s.cost, values.c_str(), s.gradient_max_norm,
                    s.step_norm, s.cumulative_time_in_seconds);
      ProgressEvent event = where_;
      event.kind = ProgressEvent::Kind::kIteration;
      event.line = line;
      event.iteration = s.iteration;
      for (const Watched& w : watched_) {  // measured per iteration: cheap
        if (!w.bound && w.measure == event.measure) event.value = model_.Measure(w.measure);
      }
      event.elapsed = SecondsSince(start_);
      sink_(event);
    }
    return met || Stopping() ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

 private:
  bool Stopping() const { return stop_ && stop_->load(); }

  // Whether every watched measure holds at the current values (" name value"
  // of each goal into `values`; a bound is measured only once the goals
  // hold). The state changed since the last report, unless Ends measured
  // this same step just before it.
  bool Met(std::string* values) {
    if (!measured_) model_.StateChanged();
    bool goals = false, met = true;
    for (const Watched& w : watched_) {
      if (w.bound) continue;
      const double value = model_.Measure(w.measure);
      if (values) *values += "  " + w.measure + " " + FormatNumber("%.3e", value);
      goals = true;
      met = met && value <= w.value;
    }
    if (!goals || !met) return false;
    for (const Watched& w : watched_) {
      if (w.bound && model_.Measure(w.measure) > w.value) return false;
    }
    return true;
  }

  Model& model_;
  const ProgressSink& sink_;
  std::string label_;
  std::vector<Watched> watched_;
  ProgressEvent where_;
  Clock::time_point start_;
  bool measured_ = false;  // Ends measured the current step
  const std::atomic<bool>* stop_;
};

// ½ Σ w r² per objective part and in total, at the current state.
std::map<std::string, double> Objective(const Residuals& residuals) {
  std::vector<double> parts(residuals.parts().size(), 0.0);
  std::vector<bool> used(parts.size(), false);
  std::vector<double> scratch;
  for (size_t i = 0; i < residuals.residuals().size(); ++i) {
    const int part = residuals.residuals()[i].part();
    scratch.resize(std::max<size_t>(scratch.size(), size_t(residuals.residuals()[i].rows())));
    parts[size_t(part)] += residuals.Cost(int(i), scratch.data());
    used[size_t(part)] = true;
  }
  std::map<std::string, double> objective;
  double total = 0;
  for (size_t k = 0; k < parts.size(); ++k) {
    if (!used[k]) continue;
    objective[residuals.parts()[k]] = parts[k];
    total += parts[k];
  }
  objective["total"] = total;
  return objective;
}

double Bound(const Settings& s, const Tolerance& t) { return s.Number(t.key); }

// Whether a residual of `residuals` counts under one of the parts `names`.
bool AnyPart(const Residuals& residuals, const std::vector<std::string>& names) {
  std::vector<bool> named(residuals.parts().size(), false);
  for (size_t k = 0; k < named.size(); ++k) {
    named[k] = std::find(names.begin(), names.end(), residuals.parts()[k]) != names.end();
  }
  for (const Residuals::Residual& r : residuals.residuals()) {
    if (named[size_t(r.part())]) return true;
  }
  return false;
}

}  // namespace

nlohmann::json RoundJson(const RoundLog& r) {
  nlohmann::json j = {{"stage", r.stage},         {"round", r.round}, {"valid", r.valid},
                      {"invalid", r.invalid},
                      {"iterations", r.iterations}, {"cost", r.cost},
                      {"weight_scale", r.weight_scale}, {"max_move", r.max_move},
                      {"clamped_vertices", r.clamped}, {"undone", r.undone},
                      {"seconds", r.seconds}};
  for (const auto& [name, value] : r.measures) j["measures"][name] = value;
  return j;
}

namespace {

// What a stage's settings make of it before its first round.
struct StagePlan {
  std::vector<Tolerance> active;  // tolerances with a bound > 0
  bool stopping = false;          // one of them ends the stage when all hold
  int rounds = 0;
  double factor = 1;              // continuation factor of the weights
  double band = -1;               // tolerance band of continued terms (< 0: none)
  double rest_move = 0;
  double guard = 0;
};

// The rounds of every stage of a problem (core/loop.h): one object per
// RunLoop, its state what carries from round to round and stage to stage.
class Loop {
 public:
  Loop(const ProblemDecl& declaration, const LoopOptions& options, Model& model)
      : s_(*options.settings), options_(options), model_(model), base_(SolverOptions(s_)),
        stages_(declaration.stages(s_)), time_limit_(s_.Number("schedule.max_seconds")) {
    how_.pcg_above = int(s_.Integer("solver.pcg_above"));
    how_.lean = s_.String("solver.back_end") == "lean";
    how_.ordering = s_.String("solver.ordering") == "metis" ? CholeskyOrdering::kMetis
                                                            : CholeskyOrdering::kAmd;
    how_.pcg_function_tolerance = s_.Number("solver.pcg_function_tolerance");
    how_.subset_parts = SubsetParts(s_);
    for (const Stage& stage : stages_) {
      for (const Tolerance& t : stage.tolerances) {
        if (t.bound) all_bounds_.push_back(t);
      }
    }
  }

  LoopResult Run() {
    result_.weight_scale = scale_;
    LogInput();
    last_valid_ = model_.SaveState();
    for (const Stage& stage : stages_) {
      if (!RunStage(stage)) return result_;
      if (result_.stopped) break;
    }
    KeepLastValid();
    for (const Stage& stage : stages_) {
      for (const Tolerance& t : stage.tolerances) {
        const double bound = Bound(s_, t);
        result_.tolerances[t.key] = bound <= 0 || model_.Measure(t.measure) <= bound;
      }
    }
    if (built_) result_.objective = Objective(residuals_);
    return result_;
  }

 private:
  // Round 0: the input's measures.
  void LogInput() {
    RoundLog input;
    input.stage = "input";
    for (const Stage& stage : stages_) {
      for (const std::string& m : stage.logged) input.measures[m] = model_.Measure(m);
    }
    result_.log.push_back(input);
    if (options_.progress) options_.progress("round  0 (input)" + MeasureText(input.measures));
  }

  StagePlan Plan(const Stage& stage) {
    StagePlan plan;
    for (const Tolerance& t : stage.tolerances) {
      if (Bound(s_, t) > 0) plan.active.push_back(t);
    }
    for (const Tolerance& t : plan.active) plan.stopping = plan.stopping || t.stops;
    // A stage marked skip_if_met whose tolerances (one of them stopping)
    // already hold runs no round.
    bool met_at_start = stage.skip_if_met && plan.stopping;
    for (const Tolerance& t : plan.active) {
      met_at_start = met_at_start && model_.Measure(t.measure) <= Bound(s_, t);
    }
    plan.rounds = met_at_start ? 0 : int(s_.Integer(stage.rounds_key));
    if (plan.rounds > 0 && stage.runs && !stage.runs(model_.hooks())) plan.rounds = 0;
    if (met_at_start) {
      result_.stop = "tolerances met before " + (stage.name.empty() ? std::string("the first round")
                                                                    : stage.name + " round 1");
    }
    plan.factor = stage.factor_key.empty() ? 1.0 : s_.Number(stage.factor_key);
    const Tolerance* goal = nullptr;
    for (const Tolerance& t : plan.active) {
      if (!t.bound && !goal) goal = &t;
    }
    plan.band = stage.band_key.empty() ? -1.0
                : goal == nullptr      ? 0.0
                                       : s_.Number(stage.band_key) * Bound(s_, *goal);
    plan.rest_move = stage.rest_move_key.empty() ? stage.rest_move : s_.Number(stage.rest_move_key);
    plan.guard = stage.guard_key.empty() ? 0.0 : s_.Number(stage.guard_key);
    return plan;
  }

  // Whether a term that reads the projection onto the reference is on.
  bool Projecting() const {
    for (const TermSpec* t : options_.terms) {
      if (t->needs_projection && s_.Number("terms." + std::string(t->name) + ".weight") > 0) {
        return true;
      }
    }
    return false;
  }

  // The stage's rounds; false when a round gave no usable state (the loop
  // ends with result_.usable false).
  bool RunStage(const Stage& stage) {
    const StagePlan plan = Plan(stage);
    const bool projecting = Projecting();
    // Best round (keep_best) and patience bookkeeping.
    best_ = stage.keep_best.empty() ? 0 : model_.Measure(stage.keep_best);
    best_state_.clear();
    if (!stage.keep_best.empty()) best_state_ = model_.SaveState();
    best_round_ = round_number_;
    patience_best_ = stage.patience_measure.empty() ? 0 : model_.Measure(stage.patience_measure);
    if (stage.patience_valid && !Rejected(plan.active).empty()) {
      patience_best_ = std::numeric_limits<double>::infinity();  // no valid value yet
    }
    last_gain_ = 0;
    valid_rounds_ = 0;
    if (stage.start_scale > 0 && plan.rounds > 0) scale_ = stage.start_scale;
    for (int k = 1; k <= plan.rounds; ++k) {
      if (time_limit_ > 0 && SecondsSince(start_) >= time_limit_) {
        result_.stop = "schedule.max_seconds reached";
        break;
      }
      const RoundEnd end = Round(stage, plan, k, projecting);
      if (end == RoundEnd::kUnusable) return false;
      if (end == RoundEnd::kStop) break;
      if (k == plan.rounds) result_.stop = "rounds exhausted (" + stage.rounds_key + ")";
    }
    result_.output_round = round_number_;
    if (!stage.keep_best.empty() && best_round_ != round_number_) {
      model_.RestoreState(best_state_);  // the best round (or the stage's start)
      model_.StateChanged();
      result_.output_round = best_round_;
    }
    return true;
  }

  enum class RoundEnd { kNext, kStop, kUnusable };

  bool Stopping() const { return options_.stop && options_.stop->load(); }

  // Round k of the stage: its step or Ceres solve, then the round's log row
  // and the stage's stop criteria.
  RoundEnd Round(const Stage& stage, const StagePlan& plan, int k, bool projecting) {
    const auto round_start = Clock::now();
    ++round_number_;
    if (stage.before_round) stage.before_round(model_.hooks());
    const double undo_before = stage.undo_if_worse.empty() ? 0 : model_.Measure(stage.undo_if_worse);
    const double change_before =
        stage.rest_change_measure.empty() ? 0 : model_.Measure(stage.rest_change_measure);
    const auto projection_start = Clock::now();
    model_.BeginRound(projecting);
    if (projecting) result_.seconds["projection"] += SecondsSince(projection_start);
    const std::string label = (stage.name.empty() ? std::string() : stage.name + " ") +
                              "round " + FormatNumber("%2.0f", round_number_);
    std::vector<double> before;
    const StepResult step = stage.step ? Step(stage, &before) : Solve(stage, plan, k, label, &before);
    if (!step.usable || !model_.Finite()) {
      result_.usable = false;
      result_.message = step.usable ? "the solver produced non-finite values" : step.message;
      return RoundEnd::kUnusable;
    }
    RoundLog row = Log(stage, plan, step, before, undo_before);
    row.seconds = SecondsSince(round_start);
    result_.weight_scale = row.weight_scale;
    result_.log.push_back(row);
    Report(label, row, Where(stage, plan, k));
    if (Stopping()) {
      result_.stopped = true;
      result_.stop = "stopped by request";
      return RoundEnd::kStop;
    }
    if (row.undone) return RoundEnd::kStop;
    return Continue(stage, plan, k, row, step, change_before) ? RoundEnd::kNext : RoundEnd::kStop;
  }

  // A round that is not a Ceres solve.
  StepResult Step(const Stage& stage, std::vector<double>* before) {
    *before = model_.SaveState();
    StepResult step = stage.step(model_.hooks());
    model_.StateChanged();
    result_.rounds = round_number_;
    result_.iterations += step.iterations;
    return step;
  }

  // The terms of the round with their weights (continued terms scaled).
  std::vector<ActiveTerm> Terms(const Stage& stage, const StagePlan& plan) const {
    std::vector<ActiveTerm> terms;
    for (const TermSpec* t : options_.terms) {
      const std::string name = t->name;
      if (!stage.terms.empty() &&
          std::find(stage.terms.begin(), stage.terms.end(), name) == stage.terms.end()) {
        continue;
      }
      const bool continued =
          std::find(stage.continued.begin(), stage.continued.end(), name) != stage.continued.end();
      const double w = s_.Number("terms." + name + ".weight") * (continued ? scale_ : 1.0);
      if (w > 0) terms.push_back({t, w, continued ? plan.band : -1.0});
    }
    return terms;
  }

  // Builds the round's residuals and solves them (Ceres or LeanSolve).
  StepResult Solve(const Stage& stage, const StagePlan& plan, int k, const std::string& label,
                   std::vector<double>* before) {
    const auto build_start = Clock::now();
    residuals_.Clear();
    model_.Build(Terms(stage, plan), k, residuals_);
    residuals_.Fit();
    result_.seconds["build"] += SecondsSince(build_start);
    built_ = true;
    *before = model_.SaveState();

    ceres::Solver::Options solver = base_;
    if (stage.max_iterations > 0) {
      solver.max_num_iterations = std::min(solver.max_num_iterations, stage.max_iterations);
    }
    if (time_limit_ > 0) {
      solver.max_solver_time_in_seconds = std::min(solver.max_solver_time_in_seconds,
                                                   std::max(0.0, time_limit_ - SecondsSince(start_)));
    }
    std::vector<IterationWatch::Watched> watched;
    for (const Tolerance& t : plan.active) {
      if (t.per_iteration) watched.push_back({t.measure, Bound(s_, t), t.bound});
    }
    IterationWatch watch(model_, options_.progress, label, watched, Where(stage, plan, k), start_,
                         options_.stop);
    if (options_.progress || !watched.empty() || options_.stop) {
      solver.callbacks.push_back(&watch);
      solver.update_state_every_iteration = true;
    }
    SolveSummary summary;
    if (residuals_.NumResiduals() > 0) {
      CheckSolverFits(solver);
      summary = SolveRound(solver, how_, residuals_, pattern_);
    }
    model_.StateChanged();
    return Account(summary);
  }

  // A round LeanSolve solves refuses the options it does not implement, and
  // the SUBSET preconditioner needs residuals in its parts: input errors,
  // before any output is written.
  void CheckSolverFits(const ceres::Solver::Options& solver) const {
    const bool pcg = UsesLeanSolve(how_.pcg_above, residuals_);
    if (pcg) {
      std::string why;
      const std::string option = LeanSolveRefuses(solver, &why);
      if (!option.empty()) {
        throw s_.Error("solver." + option,
                       why + " (this round has " + std::to_string(residuals_.FreeTangentSize()) +
                           " variables, more than solver.pcg_above = " +
                           std::to_string(how_.pcg_above) +
                           ": set solver.pcg_above: 0 to solve every round with Ceres)");
      }
    }
    if (!pcg && solver.preconditioner_type == ceres::SUBSET && !AnyPart(residuals_, how_.subset_parts)) {
      throw s_.Error("solver.subset_preconditioner_parts",
                     "no residual of this round is in these parts (preconditioner_type: "
                     "subset needs them)");
    }
  }

  // The solve's counts and times into the result; its step.
  StepResult Account(const SolveSummary& summary) {
    result_.rounds = round_number_;
    result_.variables = residuals_.NumParameters();
    result_.residuals = residuals_.NumResiduals();
    if (summary.pcg) {
      ++result_.pcg_rounds;
      result_.cg_iterations += summary.cg_iterations;
    }
    result_.cholesky_rounds += summary.cholesky;
    result_.cholesky_analyses += summary.analyses;
    result_.cholesky_factorisations += summary.factorisations;
    result_.cholesky_flops += summary.factor_flops;
    result_.cholesky_factor_nonzeros =
        std::max(result_.cholesky_factor_nonzeros, summary.factor_nonzeros);
    if (summary.trust_region_radius > 0) result_.trust_region_radius = summary.trust_region_radius;
    StepResult step;
    step.iterations = summary.iterations;
    step.cost = summary.final_cost;
    result_.iterations += step.iterations;
    result_.seconds["solver"] += summary.seconds;  // ceres::Solve or LeanSolve
    result_.seconds["linear_solver"] += summary.linear_solver_seconds;
    result_.seconds["jacobian"] += summary.jacobian_seconds;
    result_.seconds["residual"] += summary.residual_seconds;
    if (!summary.usable) {
      step.usable = false;
      step.message = summary.message;
    }
    return step;
  }

  // The round's log row, after the guard, the stage's after_round and the
  // undo of a round that made undo_if_worse rise; records a valid state.
  RoundLog Log(const Stage& stage, const StagePlan& plan, const StepResult& step,
               const std::vector<double>& before, double undo_before) {
    RoundLog row;
    row.stage = stage.name;
    row.round = round_number_;
    row.iterations = step.iterations;
    row.cost = step.cost;
    row.weight_scale = scale_;
    if (plan.guard > 0) {
      row.clamped = model_.Guard(plan.guard);
      model_.StateChanged();
    }
    if (stage.after_round) {
      stage.after_round(model_.hooks());
      model_.StateChanged();
    }
    row.max_move = model_.MaxMove(before, model_.SaveState());
    for (const std::string& m : stage.logged) row.measures[m] = model_.Measure(m);
    if (!stage.undo_if_worse.empty() && model_.Measure(stage.undo_if_worse) > undo_before) {
      model_.RestoreState(before);
      model_.StateChanged();
      row.undone = true;
      result_.stop = "round undone: " + stage.undo_if_worse + " rose";
    }
    row.invalid = model_.Invalid();
    const std::string broken = BrokenBounds(plan.active);
    if (!broken.empty() && row.invalid.empty() && GoalsMet(plan.active)) {
      RecordNeeds(plan.active);
    }
    row.invalid += (row.invalid.empty() || broken.empty() ? "" : "; ") + broken;
    row.valid = row.invalid.empty();
    if (row.valid) {
      last_valid_ = model_.SaveState();
      last_valid_round_ = round_number_;
    }
    return row;
  }

  void Report(const std::string& label, const RoundLog& row, ProgressEvent event) const {
    if (!options_.progress) return;
    char line[160];
    std::snprintf(line, sizeof line, "%s done: %d iterations  cost %.6e  max move %.2e  %.2f s%s",
                  label.c_str(), row.iterations, row.cost, row.max_move, row.seconds,
                  row.undone ? "  UNDONE" : "");
    event.kind = ProgressEvent::Kind::kRound;
    event.line = line + MeasureText(row.measures) + (row.valid ? "" : "  INVALID");
    if (!event.measure.empty()) event.value = model_.Measure(event.measure);
    event.elapsed = SecondsSince(start_);
    options_.progress(event);
  }

  // Round k of `stage`: the fields every event of the round carries.
  ProgressEvent Where(const Stage& stage, const StagePlan& plan, int k) const {
    ProgressEvent event;
    event.stage = stage.name;
    event.round = round_number_;
    event.stage_round = k;
    event.stage_rounds = plan.rounds;
    for (const Tolerance& t : plan.active) {
      if (t.bound) continue;
      event.measure = t.measure;
      event.target = Bound(s_, t);
      break;
    }
    return event;
  }

  // After a round: keep the best, then the stop criteria (patience, the
  // tolerances, the step's own end, rest); continues the weights where a
  // tolerance is not met. False: the stage ends.
  bool Continue(const Stage& stage, const StagePlan& plan, int k, const RoundLog& row,
                const StepResult& step, double change_before) {
    if (!stage.keep_best.empty() && row.valid) {
      const double value = model_.Measure(stage.keep_best);
      if (value < best_) {
        best_ = value;
        best_state_ = model_.SaveState();
        best_round_ = round_number_;
      }
    }
    if (stage.ends) {
      const std::string reason = stage.ends(model_.hooks());
      if (!reason.empty()) {
        result_.stop = reason;
        return false;
      }
    }
    if (!stage.patience_measure.empty() && Stalled(stage, k, row)) return false;
    bool met = !plan.active.empty();
    for (const Tolerance& t : plan.active) met = met && model_.Measure(t.measure) <= Bound(s_, t);
    if (plan.stopping && met) {
      result_.stop = "tolerances met";
      return false;
    }
    if (!step.stop.empty()) {  // a step that reached its own end
      result_.stop = step.stop;
      return false;
    }
    if (stage.restart_on_goals) {
      if (!GoalsMet(plan.active)) {
        scale_ *= plan.factor;
      } else if (stage.start_scale > 0) {
        scale_ = stage.start_scale;
      }
    } else if (!plan.active.empty() && !met) {
      scale_ *= plan.factor;  // continuation
    }
    if (plan.stopping) return true;
    if (plan.rest_move > 0 && row.max_move < plan.rest_move) {
      result_.stop = "at rest (max move below " + FormatNumber("%g", plan.rest_move) + ")";
      return false;
    }
    if (!stage.rest_change_measure.empty()) {
      const double now = model_.Measure(stage.rest_change_measure);
      if (std::abs(now - change_before) <= s_.Number(stage.rest_change_key) * std::abs(change_before)) {
        result_.stop = "at rest (" + stage.rest_change_measure + " settled)";
        return false;
      }
    }
    return true;
  }

  // The stall rule (Stage::patience_*): whether `patience_rounds` rounds in a
  // row, up to round k of the stage, have not lowered the lowest measure so
  // far by the fraction; records the reason.
  bool Stalled(const Stage& stage, int k, const RoundLog& row) {
    const double fraction = s_.Number(stage.patience_key);
    const int rounds = stage.patience_rounds_key.empty()
                           ? stage.patience_rounds
                           : int(s_.Integer(stage.patience_rounds_key));
    if (row.valid) ++valid_rounds_;
    const int position = stage.patience_counts_valid ? valid_rounds_ : k;
    if (!stage.patience_valid || row.valid) {
      const double value = model_.Measure(stage.patience_measure);
      if (value < patience_best_ - fraction * std::abs(patience_best_) ||
          (std::isinf(patience_best_) && std::isfinite(value))) {
        last_gain_ = position;
      }
      patience_best_ = std::min(patience_best_, value);
    }
    if (!(fraction > 0) || rounds <= 0 || position - last_gain_ < rounds) return false;
    result_.stalled = true;
    result_.stop = "stalled: no gain in " + std::string(stage.patience_valid ? "the best valid " : "") +
                   stage.patience_measure + " (" + FormatNumber("%.4g", patience_best_) + ") by more than " +
                   FormatNumber("%g", 100 * fraction) + "% in " + std::to_string(rounds) + " rounds";
    return true;
  }

  // An invalid final state gives way to the last valid round after the input.
  // "key value > bound" for each bound of `active` the current state breaks.
  std::string BrokenBounds(const std::vector<Tolerance>& active) {
    std::string broken;
    for (const Tolerance& t : active) {
      if (!t.bound || Bound(s_, t) <= 0) continue;
      const double value = model_.Measure(t.measure);
      if (value <= Bound(s_, t)) continue;
      broken += (broken.empty() ? "" : "; ") + t.key + " broken (" + t.measure + " " +
                FormatNumber("%.4g", value) + " > " + FormatNumber("%.4g", Bound(s_, t)) + ")";
    }
    return broken;
  }

  // Whether every goal (not a bound) of `active` holds, and there is one.
  bool GoalsMet(const std::vector<Tolerance>& active) {
    bool goals = false;
    for (const Tolerance& t : active) {
      if (t.bound) continue;
      goals = true;
      if (model_.Measure(t.measure) > Bound(s_, t)) return false;
    }
    return goals;
  }

  // The goals hold but bounds break: what the goals needed of each bound.
  void RecordNeeds(const std::vector<Tolerance>& active) {
    for (const Tolerance& t : active) {
      if (!t.bound) continue;
      const double value = model_.Measure(t.measure);
      const auto it = result_.bound_needs.find(t.key);
      if (it == result_.bound_needs.end() || value < it->second) result_.bound_needs[t.key] = value;
    }
  }

  // Why the current state cannot be an output: the validity checks and the
  // bounds of `active` ("" if it can).
  std::string Rejected(const std::vector<Tolerance>& active) {
    const std::string invalid = model_.Invalid(), broken = BrokenBounds(active);
    return invalid + (invalid.empty() || broken.empty() ? "" : "; ") + broken;
  }

  // A final state that breaks a bound (and is otherwise valid) gives way to
  // the last round that held it, the input included.
  void KeepLastValid() {
    const Key* keep = s_.schema().Find("validity.keep_last_valid");
    const std::string invalid = model_.Invalid();
    const bool broken = !BrokenBounds(all_bounds_).empty();
    const bool keeping = result_.stopped || (keep && s_.Bool("validity.keep_last_valid"));
    if (!keeping || (invalid.empty() && !broken) ||
        (last_valid_round_ <= 0 && !result_.stopped && !(invalid.empty() && broken))) {
      return;
    }
    model_.RestoreState(last_valid_);
    model_.StateChanged();
    result_.output_round = last_valid_round_;
    result_.restored_valid = true;
    result_.stop += (invalid.empty() ? "; the last round broke a bound: the output is round "
                                     : "; the last round was invalid: the output is round ") +
                    std::to_string(last_valid_round_) + ", the last valid one";
  }

  const Settings& s_;
  const LoopOptions& options_;
  Model& model_;
  const ceres::Solver::Options base_;
  RoundSolver how_;
  const std::vector<Stage> stages_;
  const double time_limit_;
  std::vector<Tolerance> all_bounds_;  // of every stage
  const Clock::time_point start_ = Clock::now();
  LoopResult result_;
  double scale_ = options_.weight_scale;  // continuation, carried from stage to stage
  // The last state that passed the validity checks (round 0: the input).
  std::vector<double> last_valid_;
  int last_valid_round_ = 0;
  Residuals residuals_;  // the last round's
  bool built_ = false;
  NormalPattern own_pattern_;
  // LeanSolve's pattern of J^T J (and its Cholesky analysis), reused while it
  // fits: LoopOptions::pattern, else own_pattern_.
  NormalPattern* const pattern_ = options_.pattern ? options_.pattern : &own_pattern_;
  int round_number_ = 0;
  // The current stage's best round (keep_best) and patience.
  double best_ = 0;
  std::vector<double> best_state_;
  int best_round_ = 0;
  double patience_best_ = 0;
  int last_gain_ = 0;
  int valid_rounds_ = 0;  // of the current stage
};

}  // namespace

LoopResult RunLoop(const ProblemDecl& declaration, const LoopOptions& options, Model& model) {
  CHECK(options.settings) << "RunLoop: no settings";
  return Loop(declaration, options, model).Run();
}

}  // namespace archgeo
