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

#include "core/lean_solve.h"
#include "core/normal_equations.h"
#include "core/solver_options.h"

namespace archgeo {
namespace {

using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string Format(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// "  name value" for each logged measure.
std::string MeasureText(const std::map<std::string, double>& measures) {
  std::string text;
  for (const auto& [name, value] : measures) text += "  " + name + " " + Format("%.4g", value);
  return text;
}

// One progress line per Ceres iteration; ends the solve when every
// per-iteration tolerance holds (and tells LeanSolve so before it linearises).
class IterationWatch : public EndingCallback {
 public:
  IterationWatch(Model& model, const ProgressSink& sink, std::string label,
                 std::vector<std::pair<std::string, double>> watched)
      : model_(model), sink_(sink), label_(std::move(label)), watched_(std::move(watched)) {}

  bool Ends() override {
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
      sink_(line);
    }
    return met ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

 private:
  // Whether every watched measure holds at the current values (" name value"
  // of each into `values`). The state changed since the last report, unless
  // Ends measured this same step just before it.
  bool Met(std::string* values) {
    if (!measured_) model_.StateChanged();
    bool met = !watched_.empty();
    for (const auto& [measure, bound] : watched_) {
      const double value = model_.Measure(measure);
      if (values) *values += "  " + measure + " " + Format("%.3e", value);
      met = met && value <= bound;
    }
    return met;
  }

  Model& model_;
  const ProgressSink& sink_;
  std::string label_;
  std::vector<std::pair<std::string, double>> watched_;
  bool measured_ = false;  // Ends measured the current step
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

LoopResult RunLoop(const ProblemDecl& declaration, const LoopOptions& options, Model& model) {
  CHECK(options.settings) << "RunLoop: no settings";
  const Settings& s = *options.settings;
  const ceres::Solver::Options base = SolverOptions(s);
  RoundSolver how;
  how.pcg_above = int(s.Integer("solver.pcg_above"));
  how.pcg_function_tolerance = s.Number("solver.pcg_function_tolerance");
  how.subset_parts = SubsetParts(s);
  const std::vector<Stage> stages = declaration.stages(s);
  const double time_limit = s.Number("schedule.max_seconds");
  const auto start = Clock::now();

  LoopResult result;
  RoundLog input;
  input.stage = "input";
  for (const Stage& stage : stages) {
    for (const std::string& m : stage.logged) input.measures[m] = model.Measure(m);
  }
  result.log.push_back(input);
  if (options.progress) options.progress("round  0 (input)" + MeasureText(input.measures));

  double scale = 1;  // continuation, carried from stage to stage
  // The last state that passed the validity checks (round 0: the input).
  std::vector<double> last_valid = model.SaveState();
  int last_valid_round = 0;
  Residuals residuals;  // the last round's
  bool built = false;
  NormalPattern pattern;  // PCG rounds' pattern of J^T J, reused while it fits
  int round_number = 0;
  for (const Stage& stage : stages) {
    std::vector<Tolerance> active;
    for (const Tolerance& t : stage.tolerances) {
      if (Bound(s, t) > 0) active.push_back(t);
    }
    bool stopping_tolerance = false;
    for (const Tolerance& t : active) stopping_tolerance = stopping_tolerance || t.stops;
    // A stage marked skip_if_met whose tolerances (one of them stopping)
    // already hold runs no round.
    bool met_at_start = stage.skip_if_met && stopping_tolerance;
    for (const Tolerance& t : active) {
      met_at_start = met_at_start && model.Measure(t.measure) <= Bound(s, t);
    }
    const int rounds = met_at_start ? 0 : int(s.Integer(stage.rounds_key));
    if (met_at_start) {
      result.stop = "tolerances met before " +
                    (stage.name.empty() ? std::string("the first round") : stage.name + " round 1");
    }
    const double factor = stage.factor_key.empty() ? 1.0 : s.Number(stage.factor_key);
    // The tolerance band of continued terms (< 0: none).
    const double band = stage.band_key.empty()
                            ? -1.0
                            : active.empty() ? 0.0 : s.Number(stage.band_key) * Bound(s, active.front());
    const double rest_move =
        stage.rest_move_key.empty() ? stage.rest_move : s.Number(stage.rest_move_key);
    const double guard = stage.guard_key.empty() ? 0.0 : s.Number(stage.guard_key);
    const bool projecting = [&] {
      for (const TermSpec* t : options.terms) {
        if (t->needs_projection && s.Number("terms." + std::string(t->name) + ".weight") > 0) {
          return true;
        }
      }
      return false;
    }();

    // Best round (keep_best) and patience bookkeeping.
    double best = stage.keep_best.empty() ? 0 : model.Measure(stage.keep_best);
    std::vector<double> best_state;
    if (!stage.keep_best.empty()) best_state = model.SaveState();
    int best_round = round_number;
    double patience_best = stage.patience_measure.empty() ? 0 : model.Measure(stage.patience_measure);
    int last_gain = 0;

    for (int k = 1; k <= rounds; ++k) {
      if (time_limit > 0 && Since(start) >= time_limit) {
        result.stop = "schedule.max_seconds reached";
        break;
      }
      const auto round_start = Clock::now();
      ++round_number;
      if (stage.before_round) stage.before_round(model.hooks());
      const double undo_before =
          stage.undo_if_worse.empty() ? 0 : model.Measure(stage.undo_if_worse);
      const double change_before =
          stage.rest_change_measure.empty() ? 0 : model.Measure(stage.rest_change_measure);

      const auto projection_start = Clock::now();
      model.BeginRound(projecting);
      if (projecting) result.seconds["projection"] += Since(projection_start);

      const std::string label =
          (stage.name.empty() ? std::string() : stage.name + " ") + "round " +
          Format("%2.0f", round_number);
      std::vector<double> before;
      StepResult step;
      if (stage.step) {
        // A round that is not a Ceres solve.
        before = model.SaveState();
        step = stage.step(model.hooks());
        model.StateChanged();
        result.rounds = round_number;
        result.iterations += step.iterations;
      } else {
        std::vector<ActiveTerm> terms;
        for (const TermSpec* t : options.terms) {
          const std::string name = t->name;
          if (!stage.terms.empty() &&
              std::find(stage.terms.begin(), stage.terms.end(), name) == stage.terms.end()) {
            continue;
          }
          const bool continued = std::find(stage.continued.begin(), stage.continued.end(),
                                           name) != stage.continued.end();
          const double w = s.Number("terms." + name + ".weight") * (continued ? scale : 1.0);
          if (w > 0) terms.push_back({t, w, continued ? band : -1.0});
        }
        const auto build_start = Clock::now();
        residuals.Clear();
        model.Build(terms, k, residuals);
        residuals.Fit();
        result.seconds["build"] += Since(build_start);
        built = true;
        before = model.SaveState();

        ceres::Solver::Options solver = base;
        if (time_limit > 0) {
          solver.max_solver_time_in_seconds = std::min(
              solver.max_solver_time_in_seconds, std::max(0.0, time_limit - Since(start)));
        }
        std::vector<std::pair<std::string, double>> watched;
        for (const Tolerance& t : active) {
          if (t.per_iteration) watched.push_back({t.measure, Bound(s, t)});
        }
        IterationWatch watch(model, options.progress, label, watched);
        if (options.progress || !watched.empty()) {
          solver.callbacks.push_back(&watch);
          solver.update_state_every_iteration = true;
        }
        SolveSummary summary;
        if (residuals.NumResiduals() > 0) {
          // A round LeanSolve solves refuses the options it does not
          // implement: an input error, before any output is written.
          if (UsesLeanSolve(how.pcg_above, residuals)) {
            std::string why;
            const std::string option = LeanSolveRefuses(solver, &why);
            if (!option.empty()) {
              throw s.Error("solver." + option,
                            why + " (this round has " +
                                std::to_string(residuals.FreeTangentSize()) +
                                " variables, more than solver.pcg_above = " +
                                std::to_string(how.pcg_above) +
                                ": set solver.pcg_above: 0 to solve every round with Ceres)");
            }
          }
          if (!UsesLeanSolve(how.pcg_above, residuals) &&
              solver.preconditioner_type == ceres::SUBSET &&
              !AnyPart(residuals, how.subset_parts)) {
            throw s.Error("solver.subset_preconditioner_parts",
                          "no residual of this round is in these parts (preconditioner_type: "
                          "subset needs them)");
          }
          summary = SolveRound(solver, how, residuals, &pattern);
        }
        model.StateChanged();

        result.rounds = round_number;
        result.variables = residuals.NumParameters();
        result.residuals = residuals.NumResiduals();
        if (summary.pcg) {
          ++result.pcg_rounds;
          result.cg_iterations += summary.cg_iterations;
        }
        step.iterations = summary.iterations;
        step.cost = summary.final_cost;
        result.iterations += step.iterations;
        result.seconds["solver"] += summary.seconds;  // ceres::Solve or LeanSolve
        result.seconds["linear_solver"] += summary.linear_solver_seconds;
        result.seconds["jacobian"] += summary.jacobian_seconds;
        result.seconds["residual"] += summary.residual_seconds;
        if (!summary.usable) {
          step.usable = false;
          step.message = summary.message;
        }
      }
      if (!step.usable || !model.Finite()) {
        result.usable = false;
        result.message = step.usable ? "the solver produced non-finite values" : step.message;
        return result;
      }

      RoundLog row;
      row.stage = stage.name;
      row.round = round_number;
      row.iterations = step.iterations;
      row.cost = step.cost;
      row.weight_scale = scale;
      if (guard > 0) {
        row.clamped = model.Guard(guard);
        model.StateChanged();
      }
      if (stage.after_round) {
        stage.after_round(model.hooks());
        model.StateChanged();
      }
      row.max_move = model.MaxMove(before, model.SaveState());
      for (const std::string& m : stage.logged) row.measures[m] = model.Measure(m);
      bool stop = false;
      if (!stage.undo_if_worse.empty() && model.Measure(stage.undo_if_worse) > undo_before) {
        model.RestoreState(before);
        model.StateChanged();
        row.undone = true;
        result.stop = "round undone: " + stage.undo_if_worse + " rose";
        stop = true;
      }
      row.invalid = model.Invalid();
      row.valid = row.invalid.empty();
      if (row.valid) {
        last_valid = model.SaveState();
        last_valid_round = round_number;
      }
      row.seconds = Since(round_start);
      result.log.push_back(row);
      if (options.progress) {
        char line[160];
        std::snprintf(line, sizeof line, "%s done: %d iterations  cost %.6e  max move %.2e  %.2f s%s",
                      label.c_str(), row.iterations, row.cost, row.max_move, row.seconds,
                      row.undone ? "  UNDONE" : "");
        options.progress(line + MeasureText(row.measures) + (row.valid ? "" : "  INVALID"));
      }
      if (stop) break;

      if (!stage.keep_best.empty() && row.valid) {
        const double value = model.Measure(stage.keep_best);
        if (value < best) {
          best = value;
          best_state = model.SaveState();
          best_round = round_number;
        }
      }
      if (!stage.patience_measure.empty()) {
        const double value = model.Measure(stage.patience_measure);
        const double fraction = s.Number(stage.patience_key);
        if (value < patience_best - fraction * patience_best) last_gain = k;
        patience_best = std::min(patience_best, value);
        if (fraction > 0 && k - last_gain >= stage.patience_rounds) {
          result.stop = "no gain in " + stage.patience_measure + " for " +
                        std::to_string(stage.patience_rounds) + " rounds";
          break;
        }
      }
      bool met = !active.empty();
      for (const Tolerance& t : active) met = met && model.Measure(t.measure) <= Bound(s, t);
      if (stopping_tolerance && met) {
        result.stop = "tolerances met";
        break;
      }
      if (!step.stop.empty()) {  // a step that reached its own end
        result.stop = step.stop;
        break;
      }
      if (!active.empty() && !met) scale *= factor;  // continuation
      if (!stopping_tolerance) {
        if (rest_move > 0 && row.max_move < rest_move) {
          result.stop = "at rest (max move below " + Format("%g", rest_move) + ")";
          break;
        }
        if (!stage.rest_change_measure.empty()) {
          const double now = model.Measure(stage.rest_change_measure);
          if (std::abs(now - change_before) <=
              s.Number(stage.rest_change_key) * std::abs(change_before)) {
            result.stop = "at rest (" + stage.rest_change_measure + " settled)";
            break;
          }
        }
      }
      if (k == rounds) result.stop = "rounds exhausted (" + stage.rounds_key + ")";
    }
    result.output_round = round_number;
    if (!stage.keep_best.empty() && best_round != round_number) {
      model.RestoreState(best_state);  // the best round (or the stage's start)
      model.StateChanged();
      result.output_round = best_round;
    }
  }
  // An invalid final state gives way to the last valid round after the input.
  const Key* keep = s.schema().Find("validity.keep_last_valid");
  if (keep && s.Bool("validity.keep_last_valid") && !model.Invalid().empty() &&
      last_valid_round > 0) {
    model.RestoreState(last_valid);
    model.StateChanged();
    result.output_round = last_valid_round;
    result.restored_valid = true;
    result.stop += "; the last round was invalid: the output is round " +
                   std::to_string(last_valid_round) + ", the last valid one";
  }
  for (const Stage& stage : stages) {
    for (const Tolerance& t : stage.tolerances) {
      const double bound = Bound(s, t);
      result.tolerances[t.key] = bound <= 0 || model.Measure(t.measure) <= bound;
    }
  }
  if (built) result.objective = Objective(residuals);
  return result;
}

}  // namespace archgeo
