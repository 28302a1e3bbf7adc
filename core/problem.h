// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — a problem is a declaration: the terms it composes (with default
// weights), its own settings, the stages of its schedule (rounds, tolerance
// stops, continuation, rest rules, undo, keep-best), the measures it logs,
// and a few hooks for what is specific to its paper (e.g. the H-net step 2
// between the rounds of Shi's step 3). One loop (core/loop.h) runs every
// declaration; problems/declarations/<name>.cpp holds one, listed in problems/declarations/registry.cpp.
#pragma once

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/settings.h"
#include "core/term.h"

namespace archgeo {

// A term in a problem, with its defaults there.
struct TermUse {
  std::string term;      // registered name (energies/registry.cpp)
  double weight = 0;     // default weight; 0 = off unless the spec gives one
  std::map<std::string, Value> options;  // defaults of the term's options here
  std::string elements;  // default element set ("" = the term's own)
  bool implicit = false; // part of the problem's mechanics (e.g. displacement_guard):
                         // a spec that lists `terms` does not turn it off
};

// A stop criterion: the stage ends once every tolerance of it holds.
struct Tolerance {
  std::string measure;  // a measure (lower is better)
  std::string key;      // the setting holding the bound; a bound ≤ 0 turns it off
  bool per_iteration = false;  // also checked after every Ceres iteration: the
                               // solve ends the moment the tolerance holds
  bool stops = true;    // false: it only drives continuation (the stage runs on)
  // A bound (a constraint, e.g. the deviation from the design surface): it
  // does not end the stage, but the stage's tolerances are met only while it
  // holds, and a round that breaks it is rejected like an invalid one (never
  // the output: keep_best, keep_last_valid and patience skip it).
  bool bound = false;
};

class HookContext;  // defined by the problem layer (problems/runtime/model.h)
using Hook = std::function<void(HookContext&)>;

// A round that is not a Ceres solve (e.g. the iterations of a force-directed
// method): what it reports to the loop.
struct StepResult {
  bool usable = true;
  std::string message;  // why not usable
  int iterations = 0;
  double cost = 0;
  // Non-empty: the step reached its own end (e.g. a force-directed method
  // that stalled); the stage ends after this round, with this as the reason.
  std::string stop;
};

struct Stage {
  std::string name;                // shown in progress lines and the round log
  std::vector<std::string> terms;  // the terms active in this stage (empty: all)
  std::string rounds_key;          // setting: rounds at most
  std::vector<Tolerance> tolerances;
  // The stage runs no round when its tolerances (one of them stopping)
  // already hold before its first round: for a refinement stage that only
  // serves the tolerances (hnet's step 3). Other stages run at least one
  // round, since their terms may serve goals no tolerance measures.
  bool skip_if_met = false;
  // Continuation on the penalty weight: after a round that misses a
  // tolerance, the weights of `continued` terms are multiplied by the value of
  // `factor_key`; terms that support a band get band = value of `band_key` ×
  // the bound of the first tolerance. The scale carries over to later stages.
  std::vector<std::string> continued;
  std::string factor_key, band_key;
  // > 0: the continued weights start the stage at this scale instead of the
  // one the stage before ended with.
  double start_scale = 0;
  // For a stage whose hooks move the target after each round that meets the
  // goals (band tightening): the weights grow only after a round that misses
  // a goal (a tolerance that is not a bound), and start again at
  // start_scale after one that meets them, whatever bound it breaks.
  bool restart_on_goals = false;
  // Without an active tolerance: the stage ends when a round moves no vertex
  // by more than `rest_move` (canonical frame, mean edge length 1; or the
  // value of `rest_move_key`), or changes `rest_change_measure` by less than
  // the fraction `rest_change_key`.
  double rest_move = 0;
  std::string rest_move_key;
  std::string rest_change_measure, rest_change_key;
  // Stall: the stage ends when `patience_rounds` rounds in a row (or the
  // value of `patience_rounds_key`) have not lowered the lowest
  // `patience_measure` so far by the fraction `patience_key` (0 = off). With
  // `patience_valid`, only a round that passes the validity checks counts (a
  // stage that keeps its best valid round gains nothing from an invalid one).
  std::string patience_measure, patience_key, patience_rounds_key;
  int patience_rounds = 0;
  bool patience_valid = false;
  // Only rounds that could be the output (valid, every bound held) count
  // towards the patience rounds (a stage whose first rounds are beyond a
  // bound by design).
  bool patience_counts_valid = false;
  // The output is the state after the round with the lowest value of this
  // measure (the input counts as round 0).
  std::string keep_best;
  // A round after which this measure is larger than before it is undone
  // (positions and blocks restored) and ends the stage.
  std::string undo_if_worse;
  // Bound on every vertex's distance from its input position, as a fraction
  // of the bounding-box diagonal (the value of `guard_key`; 0 = none): a
  // vertex beyond half the bound gets an anchor to its input position
  // (weight 1, ×10 per further round), a vertex beyond the bound is put back
  // inside it unless it is a vertex of a polygon (see problems/runtime/model.h).
  std::string guard_key;
  // Solver iterations per round at most (0: solver.max_num_iterations); a
  // stage whose rounds re-aim each round (a level that follows the worst
  // element) gains more from more, shorter rounds.
  int max_iterations = 0;
  std::vector<std::string> logged;  // measures in the round log and progress lines
  Hook before_round, after_round;
  // If set: asked before the stage's first round; false: the stage runs no
  // round (the stop of the stage before stands).
  std::function<bool(HookContext&)> runs;
  // If set: asked after each round (after keep-best); a reason ends the
  // stage with it as the stop.
  std::function<std::string(HookContext&)> ends;
  // If set, a round runs this instead of building and solving a Ceres problem
  // from the terms.
  std::function<StepResult(HookContext&)> step;
};

// A stage of one round that records what the `net` hook made, without a
// solve: the schedule of a problem whose net is its result (subdivide,
// remesh, the quads of the charts). `stop` is the report's stop reason.
inline Stage ResultWithoutSolve(const std::string& name, const std::string& stop) {
  Stage s;
  s.name = name;
  s.rounds_key = "schedule.outer_iterations";
  s.step = [stop](HookContext&) {
    StepResult r;
    r.stop = stop;
    return r;
  };
  return s;
}

enum class InputKind {
  kAny,
  kTriangles,      // every face a triangle
  kHasPolygons,    // at least one face with more than three sides
  kQuads,          // every face a quad
  kInteriorEdge,   // at least one interior edge
};

struct ProblemDecl {
  std::string name;
  std::string summary;  // one line
  std::string paper;
  InputKind input = InputKind::kAny;
  bool makes_input = false;  // no `mesh` file: the `net` hook makes the net from the
                             // settings (e.g. a grid on a parametric surface)
  std::vector<TermUse> terms;  // in the order their residuals are added
  std::vector<Key> keys;       // the problem's own settings
  std::map<std::string, Value> defaults;  // its defaults of common keys (e.g.
                                          // "schedule.outer_iterations")
  std::vector<BlockDecl> blocks;  // blocks the problem owns (read by its terms)
  // The stages, given the settings (e.g. no keep-best with design handles).
  std::function<std::vector<Stage>(const Settings&)> stages;
  std::set<std::string> analyses;  // report sections: "planarity", "smoothness", "hnet"
  std::vector<std::string> output_keys;  // extra `output.<key>` files it writes
  // The per-face quantity of the face colours and pictures: the one the
  // problem lowers (a name of problems/report/colors.h), unless
  // `state_colors` is set.
  std::string colors = "planarity";
  // A per-face quantity that needs the problem's state (its variables, its
  // labels): values(c, true) the input's (kept by the problem at init),
  // values(c, false) the current state's; one per face index.
  struct StateColors {
    std::string name, label, units;
    std::function<std::vector<double>(HookContext&, bool input)> values;
  } state_colors;
  // The problem's own measures (besides problems/runtime/measures.h).
  std::map<std::string, std::function<double(HookContext&)>> measures;
  // After the spec is read: checks across keys (throw Settings::Error).
  std::function<void(const Settings&)> check;
  // Hooks (optional), all in the problem layer:
  Hook net;     // replace the working net (hnet: a diagonal net of the input)
  Hook init;    // per solve (and multiresolution level), after blocks are initialised
  Hook finish;  // after the last stage: details and headline for the report
  Hook write;   // write the extra outputs
  // Optional: the problem's own hard validity checks of the current state
  // (after every round and on the result, beside analysis/validity.h): ""
  // when valid, else one line per failed check. E.g. a grid sliding on its
  // surface checks its faces against the surface normal.
  std::function<std::string(HookContext&)> invalid;
};

}  // namespace archgeo
