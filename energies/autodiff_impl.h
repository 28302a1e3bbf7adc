// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the definitions behind energies/autodiff.h. Include it only in
// an energy's .cpp, which instantiates each of its functors once:
//
//   ARCHGEO_AUTODIFF(PqDiagonal)
//
// Forward-mode automatic differentiation on ceres::Jet (Ceres' public dual
// numbers): parameter k of the residual's N = Σ sizes parameters is the Jet
// (x_k, e_k), the functor runs on Jets, and row i of block b's Jacobian is
// the infinitesimal part of residual i at the block's columns. That is what
// ceres::AutoDiffCostFunction computes, with the same Jet type: the same
// values to the last bit (tests/test_batch.cpp compares them).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include <ceres/cost_function.h>
#include <ceres/dynamic_autodiff_cost_function.h>
#include <ceres/jet.h>

#include "core/batch.h"
#include "core/term.h"
#include "energies/autodiff.h"

namespace archgeo {
namespace autodiff {

// The first of the residual's parameters that belongs to each block.
template <class Shape>
constexpr std::array<int, Shape::kNumBlocks> BlockOffsets() {
  std::array<int, Shape::kNumBlocks> offsets{};
  int sum = 0;
  for (size_t b = 0; b < Shape::kNumBlocks; ++b) {
    offsets[b] = sum;
    sum += Shape::kBlockSizes[b];
  }
  return offsets;
}

template <class F, class T, size_t... kBlock>
bool Call(const F& functor, T const* const* blocks, T* residuals, std::index_sequence<kBlock...>) {
  return functor(blocks[kBlock]..., residuals);
}

// ceres::CostFunction::Evaluate of `functor`.
template <class F>
bool Evaluate(const F& functor, double const* const* parameters, double* residuals,
              double** jacobians) {
  using Shape = typename F::Shape;
  constexpr auto kBlocks = std::make_index_sequence<Shape::kNumBlocks>{};
  if (!jacobians) return Call(functor, parameters, residuals, kBlocks);
  constexpr int kN = Shape::kNumParameters;
  constexpr std::array<int, Shape::kNumBlocks> kOffsets = BlockOffsets<Shape>();
  using Jet = ceres::Jet<double, kN>;
  Jet x[kN];
  const Jet* blocks[Shape::kNumBlocks];
  for (size_t b = 0; b < Shape::kNumBlocks; ++b) {
    for (int i = 0; i < Shape::kBlockSizes[b]; ++i) {
      x[kOffsets[b] + i] = Jet(parameters[b][i], kOffsets[b] + i);
    }
    blocks[b] = x + kOffsets[b];
  }
  Jet r[Shape::kNumResiduals];
  if (!Call(functor, blocks, r, kBlocks)) return false;
  for (int i = 0; i < Shape::kNumResiduals; ++i) residuals[i] = r[i].a;
  for (size_t b = 0; b < Shape::kNumBlocks; ++b) {
    if (!jacobians[b]) continue;
    const int size = Shape::kBlockSizes[b];
    for (int i = 0; i < Shape::kNumResiduals; ++i) {
      for (int j = 0; j < size; ++j) jacobians[b][i * size + j] = r[i].v[kOffsets[b] + j];
    }
  }
  return true;
}

template <class F>
std::vector<int32_t> BlockSizes() {
  const auto& sizes = F::Shape::kBlockSizes;
  return std::vector<int32_t>(sizes.begin(), sizes.end());
}

// Whether F declares `static constexpr bool kFlatWhereZero = true`: where its
// residuals are all 0, so are their derivatives (a one-sided barrier
// max(gap, 0), idle on most elements). Its batch then evaluates an element
// in doubles first and differentiates it only where it is not 0.
template <class F, class = void>
struct FlatWhereZero : std::false_type {};
template <class F>
struct FlatWhereZero<F, std::void_t<decltype(F::kFlatWhereZero)>>
    : std::bool_constant<F::kFlatWhereZero> {};

// The cost function of one functor.
template <class F>
class Cost final : public ceres::CostFunction {
 public:
  explicit Cost(const F& functor) : functor_(functor) {
    set_num_residuals(F::Shape::kNumResiduals);
    *mutable_parameter_block_sizes() = BlockSizes<F>();
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    return autodiff::Evaluate(functor_, parameters, residuals, jacobians);
  }

 private:
  F functor_;
};

// One functor per element, evaluated by one object (core/batch.h).
template <class F>
class FunctorBatch final : public Batch {
 public:
  explicit FunctorBatch(double band) : Batch(F::Shape::kNumResiduals, BlockSizes<F>(), band) {}
  // The type's key (one address per functor type).
  static const void* Key() {
    static const char key = 0;
    return &key;
  }
  int Push(const F& functor) {
    functors_.push_back(functor);
    return int(functors_.size()) - 1;
  }
  void Fit() override { functors_.shrink_to_fit(); }

 private:
  bool EvaluateElement(int element, double const* const* parameters, double* residuals,
                       double** jacobians) const override {
    const F& f = functors_[size_t(element)];
    constexpr int kRows = F::Shape::kNumResiduals;
    if constexpr (FlatWhereZero<F>::value) {
      if (jacobians) {
        if (!autodiff::Evaluate(f, parameters, residuals, nullptr)) return false;
        if (std::all_of(residuals, residuals + kRows, [](double r) { return r == 0.0; })) {
          for (size_t b = 0; b < F::Shape::kNumBlocks; ++b) {
            if (jacobians[b]) {
              std::fill(jacobians[b], jacobians[b] + kRows * F::Shape::kBlockSizes[b], 0.0);
            }
          }
          return true;
        }
      }
    }
    return autodiff::Evaluate(f, parameters, residuals, jacobians);
  }
  std::vector<F> functors_;
};

}  // namespace autodiff

template <class F>
ceres::CostFunction* MakeAutoDiff(const F& functor) {
  return new autodiff::Cost<F>(functor);
}

template <class F>
ceres::CostFunction* MakeStarAutoDiff(const F& functor) {
  auto* cost = new ceres::DynamicAutoDiffCostFunction<F, F::kStride>(new F(functor));
  for (int j = 0; j < functor.NumBlocks(); ++j) cost->AddParameterBlock(3);
  cost->SetNumResiduals(F::kResiduals);
  return cost;
}

template <class F>
void AddAutoDiff(TermContext& context, const F& functor, const BlocksOf<F>& blocks, double band,
                 const char* part, double weight) {
  using Kind = autodiff::FunctorBatch<F>;
  Batch* batch = context.FindBatch(Kind::Key(), band);
  if (!batch) batch = context.KeepBatch(Kind::Key(), band, std::make_unique<Kind>(band));
  const int element = static_cast<Kind*>(batch)->Push(functor);
  context.AddElement(*batch, element, blocks.data(), int(blocks.size()), part, weight);
}

}  // namespace archgeo

// Instantiates MakeAutoDiff for functor F (a name without commas: alias a
// template first), in F's energy .cpp.
#define ARCHGEO_AUTODIFF(F) template ceres::CostFunction* archgeo::MakeAutoDiff<F>(const F&);
// The same for a functor over a vertex star (MakeStarAutoDiff).
#define ARCHGEO_STAR_AUTODIFF(F) \
  template ceres::CostFunction* archgeo::MakeStarAutoDiff<F>(const F&);
