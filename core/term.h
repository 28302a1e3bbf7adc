// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — terms: an energy of energies/ registered once, with what it acts
// on, what it reads and how it is weighted, so that any problem (or a user's
// `problem: custom` spec) can compose it.
//
// A term is declared in its energy's .cpp (energies/<name>.cpp, next to the
// factory of its cost functor) as a `TermSpec` and listed once in
// energies/registry.cpp. Its `add` function is called once per element of the
// term's element set (core/elements.h) and adds that element's residual
// blocks through a TermContext; it sees positions, variable blocks, the
// reference projection and its own options, never the mesh type itself, so
// energies/ stays free of CGAL.
//
// Objective: Ceres minimises ½ Σ_terms w_t Σ_residuals ‖r‖²; w_t is the
// term's weight this round (its `weight` setting × continuation), applied as
// a ceres::ScaledLoss (optionally wrapping a robust loss, `terms.<t>.loss`).
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/blocks.h"
#include "core/elements.h"
#include "core/settings.h"

namespace ceres {
class CostFunction;
class Manifold;
}  // namespace ceres

namespace archgeo {

class Batch;
struct GridShared;  // energies/grid_shared.h

class TermContext;
using TermAdder = void (*)(TermContext& context, size_t element);
using TermHook = void (*)(TermContext& context);

struct TermSpec {
  const char* name = "";      // the YAML name = the file energies/<name>.h
  const char* summary = "";   // one line
  const char* paper = "";     // "[Zadravec 2010, §6, eq. 8]"
  const char* elements = "";  // default element set (mesh/elements.h names)
  std::vector<std::string> element_choices;  // other sets `terms.<t>.on` may name
  std::vector<BlockDecl> declares;  // blocks this term owns (initialised by `init`)
  std::vector<std::string> reads;   // blocks owned by other terms or the problem
  std::vector<Key> options;         // names relative to "terms.<name>." (besides weight, on,
                                    // select, loss, loss_scale)
  std::vector<std::string> parts;   // objective parts besides its own name
  const char* group = "";           // consecutive terms of one group on the same element set
                                    // are added element by element (residual order)
  const char* drives = "";          // the measure it drives to 0 (custom problems offer
                                    // tolerance.<measure> and continue the term's weight)
  bool barrier = false;             // a one-sided validity barrier (zero unless violated):
                                    // continued with the goal terms of its stage so that
                                    // it stays stronger than them
  bool needs_projection = false;    // reads the projection onto the reference
  bool supports_band = false;       // honours TermContext::band (continuation.band)
  TermAdder add = nullptr;
  TermHook init = nullptr;   // at the start of a solve (each multiresolution level):
                             // initial values of the blocks it declares
  TermHook begin = nullptr;  // at the start of every round, before `add`
  TermHook finish = nullptr; // after the round's residuals are added
};

// What a term's functions see. Implemented by the problem layer over the
// store (problems/runtime/model.h); all lengths in the canonical frame.
class TermContext {
 public:
  virtual ~TermContext() = default;

  const ElementSet* elements = nullptr;  // the term's (selected) elements
  double weight = 1;  // this round's weight (continuation included)
  double band = -1;   // tolerance band in residual units (< 0: the stage has none)
  int round = 1;      // 1-based round of the current stage

  virtual int NumVertices() const = 0;
  virtual double* Position(int v) = 0;
  virtual const double* Original(int v) const = 0;  // at the start of this solve
  virtual const double* Previous(int v) const = 0;  // at the start of this round
  // Unit vertex normal at the start of this round: the normalised sum of the
  // unit normals of the faces at v (0 for an isolated vertex).
  virtual const double* VertexNormal(int v) const = 0;
  virtual bool Fixed(int v) const = 0;
  // A variable block by element index (vertex, face or edge index, or the
  // index of a global block).
  virtual double* Block(std::string_view name, int index) = 0;
  // The closest point of the reference and its normal (surface) or tangent
  // (boundary curve), re-computed at the start of every round.
  virtual const double* ProjectedPoint(int v) const = 0;
  virtual const double* ProjectedDirection(int v) const = 0;
  virtual bool OnBoundaryCurve(int v) const = 0;
  // Another element set of the mesh (mesh/elements.h), e.g. "faces".
  virtual const ElementSet& Elements(const std::string& name) = 0;
  // What the grid problem shares with its terms (energies/grid_shared.h
  // SharedGrid): its surface and ideal edge length; the surface is null in
  // every other problem.
  virtual const GridShared& grid() const = 0;
  // Maps `width` values given in the file's units and axes (e.g. a load
  // direction or a length in a term option) to the canonical frame, as a
  // block of that FrameMap would be (kDirection rotates, kLength divides by
  // the input's mean edge length, kVector does both, ...).
  virtual void FromFile(FrameMap map, double* values, int width) const = 0;
  // Polylines in the canonical frame: those of the OBJ file (`l` records,
  // geometry/curves.h ReadPolylines) named by the term's option `option` (a
  // kInputPath), or, when that option is empty, the boundary loops of the
  // reference surface (longest first). Read once per solve; throws
  // InputError naming the option when there is no curve.
  struct Curve {
    std::vector<double> xyz;  // x y z per point; consecutive points distinct
    bool closed = false;      // the last point joins the first (not repeated)
  };
  virtual const std::vector<Curve>& Curves(const std::string& option) = 0;

  // The term's options ("terms.<name>.<option>").
  virtual const Settings& settings() const = 0;
  virtual const std::string& term_name() const = 0;
  // Number and Bool are read once per option and round (terms read them per
  // element).
  double Number(const std::string& option) const;
  long long Integer(const std::string& option) const;
  bool Bool(const std::string& option) const;
  const std::string& String(const std::string& option) const;

  // Adds the residual block `cost` over `blocks` with the term's weight (or
  // `weight` if ≥ 0), counted under `part` (default: the term's name). A
  // residual whose every block is constant (fixed vertices, constant blocks)
  // is dropped: it cannot change.
  virtual void Add(ceres::CostFunction* cost, const std::vector<double*>& blocks,
                   const char* part = nullptr, double weight = -1) = 0;
  // Batched residuals (energies/autodiff.h, AddAutoDiff): many elements of
  // one functor type share one evaluator per round instead of a cost object
  // each (core/batch.h). The batch kept this round under (key, band), or null.
  Batch* FindBatch(const void* key, double band) const;
  // Takes ownership of `batch` for this round's residuals under (key, band)
  // and returns it.
  Batch* KeepBatch(const void* key, double band, std::unique_ptr<Batch> batch);
  // Adds element `element` of a kept batch over `count` blocks, as Add does
  // (the weight, the part and the dropping of all-constant residuals alike).
  virtual void AddElement(const Batch& batch, int element, double* const* blocks, int count,
                          const char* part, double weight) = 0;
  // Optimises the 3-block on the unit sphere.
  virtual void SetUnit(double* block) = 0;
  // Optimises `block` on `manifold` (taking ownership), unless it already has
  // one (then `manifold` is deleted); e.g. a vertex bound to a curve.
  virtual void SetManifold(double* block, ceres::Manifold* manifold) = 0;

 protected:
  // Takes ownership of a batch for this round's residuals and returns it.
  virtual Batch* Keep(std::unique_ptr<Batch> batch) = 0;
  // This round's batches (forget them when the round's residuals go).
  struct Kept {
    const void* key;
    double band;
    Batch* batch;
  };
  std::vector<Kept> batches_;
  // Number and Bool options read this round (cleared with the batches).
  mutable std::vector<std::pair<std::string, double>> options_;

 private:
  double Option(const std::string& option, bool boolean) const;
};

}  // namespace archgeo
