// archgeo — what one solve reports: the builder's Solve returns it, and the
// pipelines' result structs extend it (problems/common_terms.h RecordSolve
// fills it from a Ceres summary).
#pragma once

#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace archgeo {

// What a builder's Solve reports. The generic run adds timing of its own,
// the metrics before and after, and the settings.
struct SolveOutcome {
  bool usable = true;   // false: Ceres found no usable solution (exit 3, nothing written)
  std::string message;  // Ceres' message when not usable
  int variables = 0, residuals = 0;
  int outer_iterations = 0, inner_iterations = 0;
  // ½ Σ w r² per term at the output (last linearisation) and "total",
  // in the canonical frame (unit mean edge length).
  std::map<std::string, double> objective;
  // Seconds spent in parts of the solve ("ceres", "linear_solver", ...).
  std::map<std::string, double> seconds;
  nlohmann::json details = nlohmann::json::object();  // builder-specific report entries
  std::string headline;  // one or more lines for the terminal, ending in '\n'
};

}  // namespace archgeo
