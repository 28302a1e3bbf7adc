// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "tools/progress_line.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

#include "core/format_number.h"

namespace archgeo {
namespace {

std::string Seconds(double s) { return s < 10 ? FormatNumber("%.1f s", s) : FormatNumber("%.0f s", s); }

}  // namespace

void ProgressLine::Show(const ProgressEvent& event) {
  Track(event);
  // Iterations redraw at most ten times a second, except a round's first;
  // rounds and notes always.
  const auto now = std::chrono::steady_clock::now();
  const bool new_round = event.stage != drawn_stage_ || event.stage_round != drawn_round_;
  if (event.kind == ProgressEvent::Kind::kIteration && shown_ && !new_round &&
      now - last_draw_ < std::chrono::milliseconds(100)) {
    return;
  }
  last_draw_ = now;
  if (event.kind == ProgressEvent::Kind::kIteration) {
    drawn_stage_ = event.stage;
    drawn_round_ = event.stage_round;
  }
  std::string text = Text(event);
  const size_t width = size_t(std::max(20, Width() - 1));
  if (text.size() > width) text = text.substr(0, width - 3) + "...";
  std::fprintf(out_, "\r\033[K%s", text.c_str());
  std::fflush(out_);
  shown_ = true;
}

void ProgressLine::Clear() {
  if (!shown_) return;
  std::fprintf(out_, "\r\033[K");
  std::fflush(out_);
  shown_ = false;
}

// The stage's goal at its start and at the end of its last round, for the
// estimate.
void ProgressLine::Track(const ProgressEvent& event) {
  if (event.kind == ProgressEvent::Kind::kNote) return;
  if (event.stage != stage_ || event.stage_round < seen_round_ || seen_round_ == 0) {
    stage_ = event.stage;
    start_elapsed_ = event.elapsed;
    start_value_ = event.value;
    rounds_done_ = 0;
  }
  seen_round_ = event.stage_round;
  if (std::isnan(start_value_)) start_value_ = event.value;
  if (event.kind != ProgressEvent::Kind::kRound) return;
  rounds_done_ = event.stage_round;
  last_value_ = event.value;
  last_elapsed_ = event.elapsed;
}

std::string ProgressLine::Text(const ProgressEvent& event) const {
  if (event.kind == ProgressEvent::Kind::kNote) return event.line;
  std::string text = event.stage.empty() ? "" : event.stage + " ";
  text += "round " + std::to_string(event.stage_round);
  if (event.stage_rounds > 0) text += "/" + std::to_string(event.stage_rounds);
  if (event.kind == ProgressEvent::Kind::kIteration) {
    text += "  iter " + std::to_string(event.iteration);
  } else {
    text += " done";
  }
  if (!event.measure.empty() && !std::isnan(event.value)) {
    text += "  " + event.measure + " " + FormatNumber("%.2e", event.value);
    if (!std::isnan(event.target)) text += " (goal " + FormatNumber("%.0e", event.target) + ")";
  }
  text += "  " + Seconds(event.elapsed);
  return text + Estimate(event);
}

// Rounds left at the stage's mean decrease of log(goal) per round so far
// (at most the stage's rounds left), times its mean seconds per round;
// without a decrease, the bound the stage's round limit gives.
std::string ProgressLine::Estimate(const ProgressEvent& event) const {
  if (rounds_done_ < 1 || event.stage_rounds <= 0) return "";
  const double per_round = (last_elapsed_ - start_elapsed_) / rounds_done_;
  const int most = event.stage_rounds - rounds_done_;
  const double value = last_value_, target = event.target;
  if (most <= 0 || !(per_round > 0) || !(value > target) || !(target > 0)) return "";
  const double rate = std::log(start_value_ / value) / rounds_done_;
  if (rate > 0) {
    const int left = std::min(most, int(std::ceil(std::log(value / target) / rate)));
    return "  ~" + Seconds(left * per_round) + " left";
  }
  return "  at most " + Seconds(most * per_round) + " left";
}

int ProgressLine::Width() const {
  winsize size{};
  if (ioctl(fileno(out_), TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
  return 80;
}

}  // namespace archgeo
