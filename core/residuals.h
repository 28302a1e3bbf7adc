// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — one round's residual blocks as the problem layer adds them: the
// cost functions, the weighted losses they share, the parameter blocks they
// read (in order of first use, with their manifolds and constant flags), and
// the objective part each residual counts under.
//
// Both solvers read it. LeanSolve (core/lean_solve.h) reads it directly, so a
// large round never builds a ceres::Problem (building and freeing one every
// round is a large share of a large round's time); a small round hands Ceres
// the equivalent problem (MakeProblem), which borrows everything from here.
// It owns every cost, loss and manifold added to it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include <ceres/cost_function.h>
#include <ceres/problem.h>

#include "core/batch.h"
#include "core/mapped_list.h"

namespace ceres {
class LossFunction;
class Manifold;
}  // namespace ceres

namespace archgeo {

class Residuals {
 public:
  struct Block {
    double* values = nullptr;
    int size = 0;
    const ceres::Manifold* manifold = nullptr;  // nullptr: Euclidean
    bool constant = false;
  };
  struct Residual {  // 24 bytes: there are ~30 per quad
    union {
      ceres::CostFunction* cost = nullptr;  // when element < 0 (owned)
      const Batch* batch;                   // else: its element `element`
    };
    int element = -1;
    int first = 0;  // its parameter blocks in values() / block_of(): [first, end)
    int end = 0;
    uint32_t loss_part = 0;  // loss << 8 | part

    // Its loss, Residuals::Loss(loss()) (0: none, ½‖r‖²), and its objective part.
    int loss() const { return int(loss_part >> 8); }
    int part() const { return int(loss_part & 255); }

    int rows() const { return element < 0 ? cost->num_residuals() : batch->num_residuals(); }
    bool Evaluate(double const* const* values, double* residuals, double** jacobians) const {
      return element < 0 ? cost->Evaluate(values, residuals, jacobians)
                         : batch->Evaluate(element, values, residuals, jacobians);
    }
  };
  static_assert(sizeof(Residual) == 24);

  Residuals();
  ~Residuals();
  Residuals(const Residuals&) = delete;
  Residuals& operator=(const Residuals&) = delete;

  // Deletes every residual, loss and manifold and forgets every block; keeps
  // the capacity (the loop's next round has the same size).
  void Clear();
  // A hint: the blocks of `width` doubles at base + k·width (k < count),
  // e.g. every vertex position, are found by their address, not hashed
  // (hashing them is a large share of a round's build). Until Clear.
  void AddressRange(const double* base, int count, int width);
  // Takes ownership of `loss` (nullptr stays nullptr) and returns it, for
  // any number of residuals to share.
  const ceres::LossFunction* Own(ceres::LossFunction* loss);
  // The index of the objective part `name` (added on first use).
  int Part(const std::string& name);
  // Adds the residual block `cost` (owned from here on) over `count` blocks,
  // counted under `part`. CHECKs what Ceres would: distinct blocks, each of
  // the size the cost declares and the size it had before.
  void Add(ceres::CostFunction* cost, const ceres::LossFunction* loss, double* const* blocks,
           int count, int part = 0);
  // Takes ownership of `batch` (until Clear) and returns it.
  Batch* Own(std::unique_ptr<Batch> batch);
  // Adds element `element` of an owned batch as a residual block, as above.
  void Add(const Batch* batch, int element, const ceres::LossFunction* loss,
           double* const* blocks, int count, int part = 0);
  // Releases the spare capacity the lists grew by (up to half of them) once a
  // round's residuals are all added; Clear keeps the fitted capacity for the
  // next round of the same size.
  void Fit();
  bool Has(const double* block) const { return Find(block) >= 0; }
  // Sets the manifold (owned from here on) of a block a residual reads that
  // has none yet; deletes `manifold` otherwise.
  void SetManifold(double* block, ceres::Manifold* manifold);
  void SetConstant(const double* block);  // CHECKs that a residual reads it

  const MappedList<Residual>& residuals() const { return residuals_; }
  const std::vector<Block>& blocks() const { return blocks_; }
  double* const* values() const { return values_.data(); }  // per residual parameter
  const MappedList<int>& block_of() const { return block_of_; }  // per residual parameter
  const std::vector<std::string>& parts() const { return parts_; }
  // The loss function of a residual's loss() (nullptr: none).
  const ceres::LossFunction* Loss(int loss) const { return loss_of_[size_t(loss)]; }
  int NumResiduals() const { return rows_; }  // scalar residuals
  int NumParameters() const;                  // every block's size, constant ones too
  int FreeTangentSize() const;                // the variables the solve moves

  // ½ ρ(‖r‖²) of residual `i` at the current values (NaN if it fails to
  // evaluate); `scratch`, if given, holds its residual vector (at least
  // rows() doubles) instead of an allocation.
  double Cost(int i, double* scratch = nullptr) const;
  // The same problem for ceres::Solve: the residuals in this order, then the
  // manifolds and constant blocks. It borrows costs, losses and manifolds
  // (and views of batch elements kept here until Clear); this list must
  // outlive it. `ids`, if given, receives each residual's block id in the
  // problem (e.g. for Ceres' SUBSET preconditioner).
  std::unique_ptr<ceres::Problem> MakeProblem(
      std::vector<ceres::ResidualBlockId>* ids = nullptr) const;

 private:
  struct Range {
    const double* base;
    size_t count;
    int width;
    std::vector<int> id;  // per block of the range: its index in blocks_, or -1
  };
  // The block index of `block` (-1: none); its slot in a range, if in one.
  int Find(const double* block) const;
  int* RangeSlot(const double* block, int size);
  // Appends the residual `r` (with `loss` and `part`) over `blocks` of `sizes`.
  void Append(Residual r, const ceres::LossFunction* loss, int part,
              const std::vector<int32_t>& sizes, double* const* blocks, int count);

  std::vector<Range> ranges_;
  MappedList<Residual> residuals_;  // the long lists: mapped (core/mapped_list.h)
  std::vector<Block> blocks_;
  MappedList<double*> values_;
  MappedList<int> block_of_;
  std::unordered_map<const double*, int> index_;
  std::vector<std::string> parts_;
  std::vector<std::unique_ptr<ceres::LossFunction>> losses_;
  std::vector<const ceres::LossFunction*> loss_of_{nullptr};  // Residual::loss() → loss
  std::unordered_map<const ceres::LossFunction*, uint32_t> loss_index_{{nullptr, 0}};
  uint32_t last_loss_ = 0;  // the last one added (terms add runs of one loss)
  std::vector<std::unique_ptr<ceres::Manifold>> manifolds_;
  std::vector<std::unique_ptr<Batch>> batches_;
  mutable std::vector<std::unique_ptr<ceres::CostFunction>> views_;  // MakeProblem's
  int rows_ = 0;
};

}  // namespace archgeo
