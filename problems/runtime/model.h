// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the problem layer under the one loop (core/loop.h): a Model over
// the variable store (mesh/store.h), the reference surface and the measures,
// and the HookContext a problem declaration's hooks see.
//
// Terms reach the store through a TermContext (core/term.h) per term; the
// element sets they act on come from mesh/elements.h or from the problem
// (HookContext::SetElements), narrowed by `terms.<t>.select`.
#pragma once

#include <functional>
#include <future>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include <glog/logging.h>
#include <nlohmann/json.hpp>

#include "core/loop.h"
#include "analysis/validity.h"
#include "core/problem.h"
#include "energies/grid_shared.h"
#include "mesh/similarity.h"
#include "mesh/store.h"
#include "mesh/surface_mesh.h"

namespace ceres {
class Manifold;
}  // namespace ceres

namespace archgeo {

class ReferenceSurface;
class MeshModel;
struct FieldResult;     // problems/declarations/field_pipeline.h
struct LevelSetResult;  // problems/declarations/field_pipeline.h

// The net a problem optimises when that is not the input mesh itself (hnet:
// a diagonal net of the input, geometry/diagonal_net.h; principal_symmetric: the
// input with its quads split). The run then measures, solves and writes this
// net; displacements from its vertices' input positions. Without a `reference`
// it is its own reference, or the input for a net made from it (on_design).
struct WorkingNet {
  bool derived = false;      // false: the problem works on the input itself
  Mesh mesh;                 // the net, in file units (when derived)
  std::vector<int> source;   // per net vertex: its input vertex index (when derived)
  nlohmann::json details = nlohmann::json::object();  // the report's "net" entry (if not empty)
  std::string headline;      // for the terminal ("" or lines ending in '\n')
};

// A problem's own data for one run (carried across multiresolution levels):
// one struct per problem, derived from this, reached through
// HookContext::State.
struct ProblemState {
  virtual ~ProblemState() = default;
};

// What a problem's hooks see. One per run.
class HookContext {
 public:
  Store* store = nullptr;             // the current level's store (canonical frame)
  const Mesh* input = nullptr;        // the mesh as read (hook `net`), then the net
                                      // solved, file units
  WorkingNet net;                     // set by the `net` hook
  Similarity frame;                   // file units -> canonical
  const ReferenceSurface* reference = nullptr;  // canonical frame
  const Settings* settings = nullptr;
  std::vector<bool> fixed;            // per vertex: hard-fixed (init may add)
  int level = 0;                      // multiresolution level
  ProgressSink progress;
  MeshModel* model = nullptr;
  const LoopResult* loop = nullptr;   // the last level's loop, for `finish`
  long version = 0;                   // changes whenever the state (positions, blocks) does

  nlohmann::json details = nlohmann::json::object();  // the report's problem entries
  std::string headline;               // lines for the terminal
  // A goal of the problem's own that the result missed, where no tolerance
  // key measures it (e.g. wave_quads: the complex is not a valid quad
  // complex): "" or one line; the run then ends with exit 4 and this line.
  std::string missed;

  // Results a problem leaves for the problem that nests it (problems/
  // field_pipeline.h), for its `write` hook and for tests; null until set.
  std::shared_ptr<const FieldResult> field;          // conjugate_field (finish)
  std::shared_ptr<const LevelSetResult> level_sets;  // level_sets (finish), conjugate_layout (net)
  // What the grid problem shares with its terms (TermContext::grid).
  GridShared grid;

  // For `write`: the output in file units and the staged file per output key.
  const Mesh* output = nullptr;
  std::map<std::string, std::string> temporaries;

  // Input checks a hook left running on another thread (they only read the
  // input): each gives what it records (details, headline, a progress line).
  std::vector<std::future<std::function<void(HookContext&)>>> checks;
  // Records the finished checks in order, up to the first unfinished one
  // (every one, waiting for it, if `wait`). The model records at the start of
  // each round, Solve after the last.
  void RecordChecks(bool wait);

  // A problem-provided element set (replaces one of the same name).
  void SetElements(const std::string& name, ElementSet set);
  // A measure's value on the current state.
  double Measure(const std::string& name);
  // The problem's own data, created on first use. CHECKs that it is a T (a
  // problem has one state type).
  template <typename T>
  T& State() {
    static_assert(std::is_base_of_v<ProblemState, T>, "a problem's state derives from ProblemState");
    if (!state_) state_ = std::make_unique<T>();
    T* state = dynamic_cast<T*>(state_.get());
    CHECK(state != nullptr) << "the problem's state is not of the type asked for";
    return *state;
  }
  // The problem's own data (CHECKs that it exists and is a T).
  template <typename T>
  const T& State() const {
    const T* state = dynamic_cast<const T*>(state_.get());
    CHECK(state != nullptr) << "the problem has no state of the type asked for";
    return *state;
  }

 private:
  std::unique_ptr<ProblemState> state_;
};

class MeshModel : public Model {
 public:
  // `terms`: the declaration's terms (registered specs, residual order).
  // Declares every block the active terms and the declaration need, runs the
  // terms' `init` and then the declaration's `init` hook.
  MeshModel(const ProblemDecl& declaration, std::vector<const TermSpec*> terms,
            HookContext& hooks);
  ~MeshModel() override;

  // A new solve on the same store (a session's re-solve): the current state
  // becomes the start — the original positions (anchor, fairness relative to
  // the original), the validity checks' reference, the guard's box — and the
  // declaration's and the terms' `init` run again on blocks set to zero, as
  // for a new model. The element sets, the blocks' declarations and the
  // fixed vertices stay.
  void Restart();
  // The current positions become the original ones (anchor, fairness
  // relative to the original) for the rounds that follow; the validity
  // checks keep the start they were made against.
  void Rebase();

  void BeginRound(bool project) override;
  void Build(const std::vector<ActiveTerm>& terms, int round, Residuals& residuals) override;
  int Guard(double bound_relative) override;
  double Measure(const std::string& name) override;
  void StateChanged() override;
  std::vector<double> SaveState() const override;
  void RestoreState(const std::vector<double>& state) override;
  double MaxMove(const std::vector<double>& a, const std::vector<double>& b) const override;
  bool Finite() const override;
  std::string Invalid() override;
  HookContext& hooks() override { return hooks_; }

  void SetElements(const std::string& name, ElementSet set);
  // Holds one block of a variable block constant (e.g. a prescribed face of
  // a field, or the value that fixes a function's constant).
  void SetConstant(const std::string& block, int index);
  // One block of a variable block optimised on a manifold (`make` returns a
  // new one each round; the round's problem owns it), e.g. a grid vertex's
  // (u, v) on a side of its domain. A constant block stays constant.
  void SetManifold(const std::string& block, int index, std::function<ceres::Manifold*()> make);
  // The element set `name` (built on first use), narrowed by `select`.
  const ElementSet& Elements(const std::string& name);
  // The elements term `spec` acts on: its set `terms.<t>.on` narrowed by
  // `terms.<t>.select` (problems/spec/selection.h); cached for the solve.
  const ElementSet& Selected(const TermSpec& spec);

 private:
  class View;
  friend class View;
  void Start();  // the constructor's and Restart's start of a solve
  void ComputeVertexNormals();
  bool IsConstant(const double* block) const;

  const ProblemDecl& declaration_;
  std::vector<const TermSpec*> terms_;
  HookContext& hooks_;
  Store& store_;
  std::map<std::string, ElementSet> sets_;
  std::map<std::string, ElementSet> subsets_;          // per term name, if it selects some
  std::map<std::string, const ElementSet*> selected_;  // per term name: all of a set or its subset
  std::vector<double> original_, previous_, normals_;
  std::vector<double> projected_point_, projected_direction_;
  std::vector<char> on_curve_;  // per vertex (not vector<bool>: written in parallel)
  std::vector<bool> boundary_;
  double box_diagonal_ = 0;  // of the mesh at the start of the solve (the guard's unit)
  Mesh start_;               // the mesh at the start of the solve (validity's reference)
  std::set<const double*> constant_blocks_;  // blocks of constant (data) blocks
  std::set<const double*> constant_elements_;  // SetConstant's
  std::map<double*, std::function<ceres::Manifold*()>> manifolds_;  // SetManifold's
  std::map<std::string, double> cache_;
  std::map<std::string, std::unique_ptr<View>> views_;
};

// The validity limits of the settings (validity.* keys).
ValidityLimits LimitsOf(const Settings& settings);

// The terms of a declaration as registered specs (CHECKs each is registered).
std::vector<const TermSpec*> TermsOf(const ProblemDecl& declaration);

}  // namespace archgeo
