// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/runtime/session.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/clock.h"
#include "core/input_error.h"
#include "core/solver_options.h"

namespace archgeo {

SolveSession::SolveSession(ProblemSpec spec, Mesh mesh, std::unique_ptr<Mesh> reference)
    : spec_(std::move(spec)), first_(std::move(mesh)), reference_(std::move(reference)) {
  CHECK(spec_.declaration) << "SolveSession: the spec has no problem (use ReadSpec)";
  const ProblemDecl& d = *spec_.declaration;
  const Settings& s = spec_.settings;
  SolverOptions(s);  // a combination Ceres rejects fails before any work
  if (d.makes_input) {
    throw s.Error("problem", "a session re-solves a mesh it is given; " + d.name +
                                 " makes its own net (solve it with Solve)");
  }
  if (s.Integer("multiresolution.levels") > 0) {
    throw s.Error("multiresolution.levels",
                  "a session solves one level (its store keeps the mesh's topology): set "
                  "multiresolution.levels: 0");
  }
  start_ = first_;
}

SolveSession::~SolveSession() = default;

void SolveSession::Move(const std::vector<long long>& ids, const std::vector<Vec3>& positions) {
  CHECK_EQ(ids.size(), positions.size()) << "SolveSession::Move: one position per vertex";
  const long long n = (long long)start_.number_of_vertices();
  for (size_t i = 0; i < ids.size(); ++i) {  // every one checked before any moves
    if (ids[i] < 0 || ids[i] >= n) {
      throw InputError("<session>", 0, "vertex",
                       "vertex index " + std::to_string(ids[i]) + " out of range: the mesh has " +
                           std::to_string(n) + " vertices");
    }
    const Vec3& p = positions[i];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      throw InputError("<session>", 0, "vertex",
                       "vertex " + std::to_string(ids[i]) + ": the new position is not finite");
    }
  }
  for (size_t i = 0; i < ids.size(); ++i) {
    const VertexIndex vertex{VertexIndex::size_type(ids[i])};
    start_.point(vertex) = ToPoint(positions[i]);
    if (solution_) {
      solution_->store->mesh().point(vertex) =
          ToPoint(solution_->frame.ToCanonical(positions[i]));
    }
  }
}

const Key& SolveSession::WeightKey(const std::string& term) const {
  const Key* k = spec_.settings.schema().Find("terms." + term + ".weight");
  if (k == nullptr) {
    std::string names;
    for (const TermUse& use : spec_.declaration->terms) {
      names += (names.empty() ? "" : ", ") + use.term;
    }
    throw InputError("<session>", 0, "terms",
                     "'" + term + "' is not a term of " + spec_.declaration->name +
                         " (its terms: " + names + ")");
  }
  return *k;
}

double SolveSession::Weight(const std::string& term) const {
  return spec_.settings.Number(WeightKey(term).name);
}

void SolveSession::SetWeight(const std::string& term, double weight) {
  const Key& k = WeightKey(term);
  if (!(weight >= k.lo && weight <= k.hi)) {
    char text[160];
    std::snprintf(text, sizeof text, "%g is out of range [%g, %g]", weight, k.lo, k.hi);
    throw InputError("<session>", 0, k.name, k.name + ": " + text);
  }
  spec_.settings.Set(k.name, weight, Origin{"<session>", 0});
}

Solution& SolveSession::Run(const ProgressSink& progress, const std::atomic<bool>* stop) {
  if (solution_) return Resolve(progress, stop);
  first_ = start_;  // with the moves made before the first solve
  std::unique_ptr<Solution> sol =
      Solve(spec_, first_, reference_.get(), progress, stop, &pattern_);
  if (sol->net.derived) {
    throw spec_.settings.Error(
        "problem", "a session re-solves the mesh it is given; " + spec_.declaration->name +
                       " solved a net of its own here (" +
                       sol->net.details.value("net", std::string("a derived net")) +
                       "): solve it with Solve");
  }
  canonical_start_ = first_;
  ToCanonical(sol->frame, canonical_start_);
  solution_ = std::move(sol);
  start_state_.clear();  // the first solve's start is first_
  return *solution_;
}

Solution& SolveSession::Resolve(const ProgressSink& progress, const std::atomic<bool>* stop) {
  Solution& sol = *solution_;
  HookContext& hooks = sol.hooks;
  const ProblemDecl& d = *spec_.declaration;
  const auto start = Clock::now();
  // The store holds the last kept solution with the moves: that is the start.
  sol.input = start_;
  hooks.input = &sol.input;
  hooks.progress = progress;
  hooks.details = sol.input_details;
  hooks.headline = sol.input_headline;
  hooks.missed.clear();
  hooks.loop = nullptr;
  hooks.output = nullptr;
  hooks.temporaries.clear();
  canonical_start_ = sol.store->mesh();
  start_state_ = sol.store->Save();
  sol.model->Restart();
  LoopOptions options;
  options.settings = &spec_.settings;
  options.terms = TermsOf(d);
  options.progress = progress;
  options.stop = stop;
  options.pattern = &pattern_;
  options.weight_scale = ContinuationStart(spec_.settings);
  sol.loop = RunLoop(d, options, *sol.model);
  const Mesh& work = sol.store->mesh();
  sol.rounds = nlohmann::json::array();
  for (const RoundLog& row : sol.loop.log) {
    nlohmann::json j = RoundJson(row);
    j["level"] = 0;
    sol.rounds.push_back(j);
  }
  sol.levels = nlohmann::json::array({{{"level", 0},
                                       {"vertices", work.number_of_vertices()},
                                       {"faces", work.number_of_faces()},
                                       {"variables", sol.loop.variables},
                                       {"residuals", sol.loop.residuals},
                                       {"rounds", sol.loop.rounds},
                                       {"iterations", sol.loop.iterations},
                                       {"objective", sol.loop.objective},
                                       {"stop", sol.loop.stop},
                                       {"seconds", SecondsSince(start)}}});
  hooks.RecordChecks(true);
  hooks.loop = &sol.loop;
  if (sol.loop.usable && d.finish) d.finish(hooks);
  sol.details = hooks.details;
  sol.headline = hooks.headline;
  sol.output = InFileFrame(sol.input, work, canonical_start_, hooks.frame);
  hooks.output = &sol.output;
  return sol;
}

void SolveSession::Keep(bool kept) {
  CHECK(solution_) << "SolveSession::Keep before Run";
  if (kept) {
    start_ = solution_->output;
    // The next solve starts its continuation where this one ended (problems
    // without the key start each solve at 1).
    Settings& s = spec_.settings;
    if (const Key* k = s.schema().Find("continuation.start")) {
      s.Set(k->name, std::clamp(solution_->loop.weight_scale, k->lo, k->hi), Origin{"<session>", 0});
    }
    // And Levenberg–Marquardt's trust region where the last one left it
    // (LeanSolve's rounds): no steps rejected again to find its size.
    const double radius = solution_->loop.trust_region_radius;
    if (const Key* k = s.schema().Find("solver.initial_trust_region_radius"); k && radius > 0) {
      s.Set(k->name, std::clamp(radius, std::max(k->lo, 1e-6), k->hi), Origin{"<session>", 0});
    }
    return;
  }
  // Back to where the last solve started: its start mesh (file units) is
  // start_ still, and the store's state is restored (the first solve's start
  // is first_ in the frame).
  Store& store = *solution_->store;
  if (!start_state_.empty()) {
    store.Restore(start_state_);
  } else {
    Mesh& mesh = store.mesh();
    for (VertexIndex v : mesh.vertices()) mesh.point(v) = canonical_start_.point(v);
  }
  solution_->model->StateChanged();
}

}  // namespace archgeo
