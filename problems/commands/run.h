// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — one `archgeo solve` run: read the spec's files, solve the problem
// in the canonical frame (level by level with multiresolution) through the
// one loop, measure before and after, write the outputs atomically.
#pragma once

#include <atomic>
#include <string>

#include <nlohmann/json.hpp>

#include "core/progress.h"
#include "problems/spec/spec.h"

namespace archgeo {

// The version of the JSON report's layout (docs/report.schema.json):
// raised whenever a key changes meaning or moves.
inline constexpr int kReportSchemaVersion = 1;

struct RunResult {
  // 0: a valid result, every tolerance met; 4: a valid result written, a
  // tolerance missed; 5: the result written, with panels that cannot be
  // built as they were in the input (analysis/validity.h); 3: no usable or
  // no valid result, nothing written (bad input throws InputError: exit 2).
  int exit_code = 0;
  nlohmann::json report;   // the JSON run report (also written to output.report)
  std::string summary;     // human-readable summary for the terminal
  bool stopped = false;    // the stop request ended the solve: nothing was written
};

// Throws InputError for bad input (nothing is written then).
RunResult RunSpec(const ProblemSpec& spec, const ProgressSink& progress);

// Meshes in memory instead of the spec's files (the public API, python/):
// problems/runtime/mesh_inputs.h. `stop` (may be null): when it turns true
// the solve ends after the current iteration with the last valid state
// (core/loop.h, LoopOptions::stop), which is measured and reported (exit 0
// or 4 as usual, "stop": "stopped by request") but not written: the
// outputs stay as they were, as when `archgeo solve` is interrupted.
struct MeshInputs;
RunResult RunSpec(const ProblemSpec& spec, const ProgressSink& progress, const MeshInputs& meshes,
                  const std::atomic<bool>* stop = nullptr);

// One solve of `session` (problems/runtime/session.h) as RunSpec runs the
// spec: the same validity checks, measures, report, exit codes and outputs
// of the spec; the mesh solved is the session's start, measured against its
// reference (the first mesh when none was given, once the session has
// solved). A result that is written (exit 0, 4, 5) becomes the start of the
// next solve (SolveSession::Keep: session.start() is then that result).
// Throws InputError.
class SolveSession;
RunResult RunSession(SolveSession& session, const ProgressSink& progress,
                     const std::atomic<bool>* stop = nullptr);

// `archgeo measure`: metrics of `mesh_path`, against `reference_path` if not
// empty (displacement too when the vertex counts agree). `arrays`: the report
// gets "arrays" as output.arrays gives a solve's (per-face planarity, the
// per-vertex displacement from a reference with the mesh's vertices).
// Throws InputError.
RunResult MeasureFiles(const std::string& mesh_path, const std::string& reference_path,
                       bool all = false, bool arrays = false);

}  // namespace archgeo
