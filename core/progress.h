// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — a run's progress: one event per solver iteration, per round and
// per stage note, each with its log line and, for iterations and rounds,
// where the run stands (round k of at most n, the goal tolerance's measure
// against its target, seconds so far). The CLI shows them as one line on a
// terminal or as the log (--log); the API passes them on.
#pragma once

#include <cmath>
#include <functional>
#include <string>
#include <utility>

namespace archgeo {

struct ProgressEvent {
  enum class Kind { kNote, kIteration, kRound };
  Kind kind = Kind::kNote;
  std::string line;          // the log line (no trailing newline)
  std::string stage;         // the stage's name ("" for a problem's main stage)
  int round = 0;             // rounds so far over the run (this one included)
  int stage_round = 0;       // k of the stage's rounds (1-based)
  int stage_rounds = 0;      // the stage's most rounds (0: not known)
  int iteration = -1;        // the solver iteration within the round (kIteration)
  std::string measure;       // the stage's goal tolerance, e.g. "pq_normalized_max" ("": none)
  double value = NAN;        // its value at this event
  double target = NAN;       // the tolerance it must reach
  double elapsed = 0;        // seconds since the loop began

  ProgressEvent() = default;
  ProgressEvent(std::string text) : line(std::move(text)) {}  // NOLINT: a note from its line
  ProgressEvent(const char* text) : line(text) {}              // NOLINT
};

// Receives the events of a run; empty: no progress.
using ProgressSink = std::function<void(const ProgressEvent& event)>;

}  // namespace archgeo
