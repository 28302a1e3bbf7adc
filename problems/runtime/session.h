// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — a solve kept for solving again (the public API's archgeo::Session):
// after the first solve the spec, the store (positions and every block, in
// the canonical frame of the first mesh), the model with its element sets,
// the reference surface and LeanSolve's pattern of J^T J with its Cholesky
// analysis (core/normal_equations.h) stay. Between solves vertices move
// (file units) and term weights change; the next solve starts from the last
// solution with those moves, as a solve of that mesh would (the model
// restarts there: original positions, blocks' `init`, validity's start) but
// against the session's reference, in its frame, and with the continuation
// of the weights and the trust region where the last solve left them
// (`continuation.start` set to the scale it ended with, where the problem
// has that key: a solve near a planar state needs the weights that made it
// planar, not the rounds that grew them from 1; and
// `solver.initial_trust_region_radius` to LeanSolve's radius at its end).
// While the residuals
// keep their structure (the same fixed vertices, the same terms on) no
// pattern is read and no ordering or symbolic factorisation made again.
//
// What it takes: a problem that solves the mesh it is given (no net of its
// own, e.g. hnet's diagonal net or relayout: auto) without multiresolution;
// anything else is an InputError.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "core/normal_equations.h"
#include "core/progress.h"
#include "mesh/surface_mesh.h"
#include "problems/runtime/solve.h"
#include "problems/spec/spec.h"

namespace archgeo {

class SolveSession {
 public:
  // `mesh` (file units) and the spec's problem; `reference` (may be null:
  // `mesh` itself) is the surface every solve stays close to. Throws
  // InputError for what a session does not take (above) and for `mesh`'s
  // unsuitability, as Solve.
  SolveSession(ProblemSpec spec, Mesh mesh, std::unique_ptr<Mesh> reference);
  ~SolveSession();

  const ProblemSpec& spec() const { return spec_; }
  // The mesh the next solve starts from (file units): the first mesh, then
  // the last kept result (Keep) with the moves since.
  const Mesh& start() const { return start_; }
  // The reference given, or null (the first mesh is the reference).
  const Mesh* reference() const { return reference_.get(); }
  // The first mesh (the reference when none was given).
  const Mesh& first() const { return first_; }
  // Whether a solve has run (the next one is warm).
  bool solved() const { return solution_ != nullptr; }

  // Puts vertex ids[i] (0-based, the mesh's order) at positions[i] (file
  // units) for the next solve. A fixed vertex stays there; a free one starts
  // there. Throws InputError (key "vertex") for an index out of range or a
  // non-finite position; nothing moves then. CHECKs the sizes agree.
  void Move(const std::vector<long long>& ids, const std::vector<Vec3>& positions);
  // Sets `terms.<term>.weight` for the next solves (the key's range).
  // Throws InputError (key "terms") for a term the problem does not have or
  // a weight out of range.
  void SetWeight(const std::string& term, double weight);
  // The value of `terms.<term>.weight` now (InputError as SetWeight).
  double Weight(const std::string& term) const;

  // Solves: the first call as Solve (problems/runtime/solve.h), each later
  // one from start(). The solution stays the session's until the next call.
  Solution& Run(const ProgressSink& progress, const std::atomic<bool>* stop);
  // After Run: `kept` makes its output the start of the next solve (a result
  // that is usable and written); otherwise the next solve starts again from
  // where this one started.
  void Keep(bool kept);

 private:
  Solution& Resolve(const ProgressSink& progress, const std::atomic<bool>* stop);
  const Key& WeightKey(const std::string& term) const;  // InputError if none

  ProblemSpec spec_;
  Mesh first_;
  std::unique_ptr<Mesh> reference_;
  Mesh start_;               // file units
  Mesh canonical_start_;     // start_ in the session's frame (the store's state at Run)
  std::vector<double> start_state_;  // the store's variables at the start of the last Run
  NormalPattern pattern_;    // kept across solves (LoopOptions::pattern)
  std::unique_ptr<Solution> solution_;
};

}  // namespace archgeo
