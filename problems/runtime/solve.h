// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — solving a problem on meshes in memory: the working net, the
// canonical frame, multiresolution levels and the one loop, without files.
// `archgeo solve` (problems/commands/run.h) adds reading, metrics, the report and the
// outputs; tests, benchmarks and the Python module call this directly.
#pragma once

#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "core/loop.h"
#include "geometry/reference.h"
#include "mesh/store.h"
#include "mesh/surface_mesh.h"
#include "problems/runtime/model.h"
#include "problems/spec/spec.h"

namespace archgeo {

struct Solution {
  HookContext hooks;      // the problem's hooks' view (points into this Solution;
                          // declared first, destroyed last)
  LoopResult loop;        // of the last level (rounds and iterations: all levels)
  WorkingNet net;         // the net solved, when derived from the input
  bool on_design = false;  // the net was made from the input surface (a layout: no
                           // net vertex is an input vertex): the input is the design
                           // surface, the reference without a `reference`
  Mesh input;             // the net solved, file units, as given
  Mesh output;            // the result, file units
  std::unique_ptr<Store> store;  // the last level's store (canonical frame: every block)
  Similarity frame;       // file units -> canonical
  nlohmann::json rounds = nlohmann::json::array();  // every level's round log
  nlohmann::json levels = nlohmann::json::array();  // one entry per level
  nlohmann::json details = nlohmann::json::object();  // the problem's report entries
  std::string headline;   // the problem's lines for the terminal
  // What the `net` hook and its input checks recorded (details and headline
  // before `finish`): a re-solve on the same net (problems/runtime/session.h)
  // starts from them.
  nlohmann::json input_details = nlohmann::json::object();
  std::string input_headline;
  std::unique_ptr<ReferenceSurface> reference;  // canonical frame
  std::unique_ptr<MeshModel> model;             // the last level's
};

// Solves `spec`'s problem on `mesh` (file units; the spec's `mesh` key only
// names it in messages) against `reference` (null: `mesh`, the design
// surface, for a net the problem made from it (Solution::on_design), else the
// net itself).
// `stop` (may be null): LoopOptions::stop; a stop also ends multiresolution
// before its next level. `pattern` (may be null): LoopOptions::pattern of
// the last level. Throws InputError for unsuitable input.
std::unique_ptr<Solution> Solve(const ProblemSpec& spec, const Mesh& mesh, const Mesh* reference,
                                const ProgressSink& progress,
                                const std::atomic<bool>* stop = nullptr,
                                NormalPattern* pattern = nullptr);

// LoopOptions::weight_scale of the settings: `continuation.start` where the
// problem has it, else 1.
double ContinuationStart(const Settings& settings);

// `solved` (canonical frame) in file units: on a copy of `input` (file
// units) when the topology is the input's, else rebuilt from positions and
// faces. A vertex of the input that did not move (its canonical position is
// bit for bit the one it started from, `start`) keeps its exact file
// coordinates: fixed supports do not drift by the rounding of the frame
// change.
Mesh InFileFrame(const Mesh& input, const Mesh& solved, const Mesh& start, const Similarity& frame);

}  // namespace archgeo
