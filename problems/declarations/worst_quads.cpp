// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/declarations/worst_quads.h"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "problems/runtime/model.h"

namespace archgeo::problems {
namespace {

// Solver iterations per round of the stage: the level is re-aimed at the
// worst quad each round, so short rounds gain more than long ones.
constexpr int kWorstRoundIterations = 15;

struct WorstQuadsState : ProblemState {
  std::vector<double> start;  // every variable at the start of the solve
  bool restarted = false;     // the stage's first round has restored `start`
};

// Before each round of the stage: the first one starts from the input.
void RestartFromInput(HookContext& c) {
  WorstQuadsState& s = c.State<WorstQuadsState>();
  if (s.restarted) return;
  c.model->RestoreState(s.start);
  c.model->StateChanged();
  s.restarted = true;
}

}  // namespace

double WorstStagePq(HookContext& c) {
  return c.State<WorstQuadsState>().restarted ? c.Measure("pq_normalized_max")
                                              : std::numeric_limits<double>::infinity();
}

bool HasWorstQuadsStage(const Settings& settings) {
  return settings.schema().Find("relayout") && settings.String("relayout") == "never" &&
         settings.Number("tolerance.pq_normalized_max") > 0 &&
         settings.Number("terms.pq_worst.weight") > 0;
}

void KeepStartState(HookContext& c) {
  if (!HasWorstQuadsStage(*c.settings)) return;
  WorstQuadsState& s = c.State<WorstQuadsState>();
  s.start = c.model->SaveState();
  s.restarted = false;
}

Stage WorstQuadsStage(const Stage& first) {
  Stage s = first;
  s.name = "worst";
  s.skip_if_met = true;
  std::replace(s.terms.begin(), s.terms.end(), std::string("pq_diagonal"),
               std::string("pq_worst"));
  // The barriers keep the strength the first stage's continuation gave them
  // (its scale carries over; no further growth: no factor).
  s.continued = {"convexity", "min_edge_length"};
  s.factor_key.clear();
  s.band_key.clear();
  s.max_iterations = kWorstRoundIterations;
  s.before_round = &RestartFromInput;
  s.patience_measure = s.patience_measure.empty() ? "" : kWorstStagePq;
  return s;
}

}  // namespace archgeo::problems
