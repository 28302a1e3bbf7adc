// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo CLI — a run's progress on a terminal as one line rewritten in
// place (carriage return, erase to the end): the stage and round k of at
// most n, the iteration, the goal tolerance's measure against its target,
// the seconds so far and an estimate of the rest. Notes (stage messages)
// take the line until the next event. Iterations redraw at most ten times a
// second, each round's first always. Nothing scrolls; Clear() before the
// summary is printed.
#pragma once

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/progress.h"

namespace archgeo {

class ProgressLine {
 public:
  explicit ProgressLine(std::FILE* terminal) : out_(terminal) {}
  ~ProgressLine() { Clear(); }
  void Show(const ProgressEvent& event);
  void Clear();

 private:
  std::string Text(const ProgressEvent& event) const;
  std::string Estimate(const ProgressEvent& event) const;
  void Track(const ProgressEvent& event);
  int Width() const;

  std::FILE* out_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_draw_{};
  std::string drawn_stage_;  // the round of the last iteration drawn
  int drawn_round_ = -1;
  // The stage being estimated: its goal and time at its start and at the
  // end of its last finished round.
  std::string stage_;
  int seen_round_ = 0, rounds_done_ = 0;
  double start_value_ = NAN, last_value_ = NAN;
  double start_elapsed_ = 0, last_elapsed_ = 0;
};

}  // namespace archgeo
