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
  std::unique_ptr<ReferenceSurface> reference;  // canonical frame
  std::unique_ptr<MeshModel> model;             // the last level's
};

// Solves `spec`'s problem on `mesh` (file units; the spec's `mesh` key only
// names it in messages) against `reference` (null: `mesh`, the design
// surface, for a net the problem made from it (Solution::on_design), else the
// net itself).
// `stop` (may be null): LoopOptions::stop; a stop also ends multiresolution
// before its next level. Throws InputError for unsuitable input.
std::unique_ptr<Solution> Solve(const ProblemSpec& spec, const Mesh& mesh, const Mesh* reference,
                                const ProgressSink& progress,
                                const std::atomic<bool>* stop = nullptr);

}  // namespace archgeo
