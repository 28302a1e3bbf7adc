// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/residuals.h"

#include <cmath>
#include <limits>

#include <Eigen/Core>
#include <ceres/cost_function.h>
#include <ceres/loss_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <glog/logging.h>

namespace archgeo {

Residuals::Residuals() : parts_{""} {}

Residuals::~Residuals() { Clear(); }

void Residuals::Clear() {
  for (Residual& r : residuals_) {
    if (r.element < 0) delete r.cost;
  }
  residuals_.clear();
  blocks_.clear();
  values_.clear();
  block_of_.clear();
  index_.clear();
  ranges_.clear();
  parts_.assign(1, "");
  losses_.clear();
  loss_of_.assign(1, nullptr);
  loss_index_ = {{nullptr, 0}};
  last_loss_ = 0;
  manifolds_.clear();
  views_.clear();
  batches_.clear();
  rows_ = 0;
}

void Residuals::Fit() {
  residuals_.Fit();
  blocks_.shrink_to_fit();
  values_.Fit();
  block_of_.Fit();
  for (const std::unique_ptr<Batch>& b : batches_) b->Fit();
}

void Residuals::AddressRange(const double* base, int count, int width) {
  CHECK(base && count >= 0 && width > 0);
  ranges_.push_back({base, size_t(count), width, std::vector<int>(size_t(count), -1)});
}

namespace {

constexpr size_t kNone = size_t(-1);

// The index of `block` among the blocks of `range`, or kNone if it is not
// one of them.
template <class Range>
size_t IndexIn(const Range& range, const double* block) {
  if (block < range.base || block >= range.base + range.count * size_t(range.width)) return kNone;
  const size_t offset = size_t(block - range.base);
  return offset % size_t(range.width) == 0 ? offset / size_t(range.width) : kNone;
}

}  // namespace

int* Residuals::RangeSlot(const double* block, int size) {
  for (Range& r : ranges_) {
    const size_t k = IndexIn(r, block);
    if (k != kNone && r.width == size) return &r.id[k];
  }
  return nullptr;
}

int Residuals::Find(const double* block) const {
  for (const Range& r : ranges_) {
    const size_t k = IndexIn(r, block);
    if (k != kNone && r.id[k] >= 0) return r.id[k];
  }
  const auto it = index_.find(block);
  return it == index_.end() ? -1 : it->second;
}

const ceres::LossFunction* Residuals::Own(ceres::LossFunction* loss) {
  if (loss) losses_.emplace_back(loss);
  return loss;
}

int Residuals::Part(const std::string& name) {
  for (size_t k = 0; k < parts_.size(); ++k) {
    if (parts_[k] == name) return int(k);
  }
  parts_.push_back(name);
  return int(parts_.size()) - 1;
}

void Residuals::Add(ceres::CostFunction* cost, const ceres::LossFunction* loss,
                    double* const* blocks, int count, int part) {
  Residual r;
  r.cost = cost;
  Append(r, loss, part, cost->parameter_block_sizes(), blocks, count);
}

Batch* Residuals::Own(std::unique_ptr<Batch> batch) {
  batches_.push_back(std::move(batch));
  return batches_.back().get();
}

void Residuals::Add(const Batch* batch, int element, const ceres::LossFunction* loss,
                    double* const* blocks, int count, int part) {
  CHECK_GE(element, 0);
  Residual r;
  r.batch = batch;
  r.element = element;
  Append(r, loss, part, batch->parameter_block_sizes(), blocks, count);
}

void Residuals::Append(Residual r, const ceres::LossFunction* loss, int part,
                       const std::vector<int32_t>& sizes, double* const* blocks, int count) {
  CHECK_EQ(int(sizes.size()), count) << "a cost function over " << sizes.size()
                                     << " blocks added with " << count;
  CHECK(part >= 0 && part < 256) << "objective part " << part << ": at most 256";
  if (loss_of_[last_loss_] != loss) {
    const auto [it, added] = loss_index_.try_emplace(loss, uint32_t(loss_of_.size()));
    if (added) {
      CHECK_LT(loss_of_.size(), size_t(1) << 24) << "more than 2^24 loss functions";
      loss_of_.push_back(loss);
    }
    last_loss_ = it->second;
  }
  r.loss_part = last_loss_ << 8 | uint32_t(part);
  r.first = int(values_.size());
  for (int a = 0; a < count; ++a) {
    for (int b = 0; b < a; ++b) CHECK(blocks[a] != blocks[b]) << "a block read twice by one residual";
    int* slot = RangeSlot(blocks[a], sizes[a]);
    int id = slot ? *slot : -1;
    if (!slot) {
      const auto [it, added] = index_.try_emplace(blocks[a], int(blocks_.size()));
      id = added ? -1 : it->second;
    }
    if (id < 0) {
      id = int(blocks_.size());
      if (slot) *slot = id;
      blocks_.push_back({blocks[a], sizes[a], nullptr, false});
    }
    CHECK_EQ(blocks_[size_t(id)].size, sizes[a]) << "a block read with two sizes";
    values_.push_back(blocks[a]);
    block_of_.push_back(id);
  }
  r.end = int(values_.size());
  residuals_.push_back(r);
  rows_ += r.rows();
}

void Residuals::SetManifold(double* block, ceres::Manifold* manifold) {
  std::unique_ptr<ceres::Manifold> owned(manifold);
  const int id = Find(block);
  if (id < 0 || blocks_[size_t(id)].manifold) return;
  CHECK_EQ(manifold->AmbientSize(), blocks_[size_t(id)].size) << "a manifold of another size";
  blocks_[size_t(id)].manifold = manifold;
  manifolds_.push_back(std::move(owned));
}

void Residuals::SetConstant(const double* block) {
  const int id = Find(block);
  CHECK(id >= 0) << "SetConstant: no residual reads the block";
  blocks_[size_t(id)].constant = true;
}

int Residuals::NumParameters() const {
  int n = 0;
  for (const Block& b : blocks_) n += b.size;
  return n;
}

int Residuals::FreeTangentSize() const {
  int n = 0;
  for (const Block& b : blocks_) {
    if (!b.constant) n += b.manifold ? b.manifold->TangentSize() : b.size;
  }
  return n;
}

double Residuals::Cost(int i, double* scratch) const {
  const Residual& r = residuals_[size_t(i)];
  const int rows = r.rows();
  std::vector<double> own;
  if (!scratch) {
    own.resize(size_t(rows));
    scratch = own.data();
  }
  if (!r.Evaluate(values_.data() + r.first, scratch, nullptr)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const double sq = Eigen::Map<const Eigen::VectorXd>(scratch, rows).squaredNorm();
  const ceres::LossFunction* loss = Loss(r.loss());
  if (!loss) return 0.5 * sq;
  double rho[3];
  loss->Evaluate(sq, rho);
  return 0.5 * rho[0];
}

std::unique_ptr<ceres::Problem> Residuals::MakeProblem(
    std::vector<ceres::ResidualBlockId>* ids) const {
  ceres::Problem::Options options;
  options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  options.enable_fast_removal = false;
  auto problem = std::make_unique<ceres::Problem>(options);
  std::vector<double*> read;
  if (ids) ids->clear();
  for (const Residual& r : residuals_) {
    read.assign(values_.data() + r.first, values_.data() + r.end);
    ceres::CostFunction* cost = r.element < 0 ? r.cost : nullptr;
    if (!cost) {
      views_.push_back(std::make_unique<BatchElement>(*r.batch, r.element));
      cost = views_.back().get();
    }
    const ceres::ResidualBlockId id =
        problem->AddResidualBlock(cost, const_cast<ceres::LossFunction*>(Loss(r.loss())), read);
    if (ids) ids->push_back(id);
  }
  for (const Block& b : blocks_) {
    if (b.manifold) problem->SetManifold(b.values, const_cast<ceres::Manifold*>(b.manifold));
    if (b.constant) problem->SetParameterBlockConstant(b.values);
  }
  return problem;
}

}  // namespace archgeo
