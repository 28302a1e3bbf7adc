// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — many residual blocks of one cost functor type, one per element,
// evaluated by one object: a term adds its elements to a batch instead of
// allocating a ceres::CostFunction per element. At 100k quads a planar_quads
// round has ~1.7M residual blocks; one cost object each (the functor, the
// CostFunction with its vector of block sizes, a band wrapper) took ~300 MB
// and most of each round's build in allocations.
//
// A batch element evaluates to exactly what the corresponding
// ceres::AutoDiffCostFunction (wrapped in a ToleranceBand when band ≥ 0)
// returns: the same functor call, the same automatic differentiation.
#pragma once

#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <vector>

#include <ceres/autodiff_cost_function.h>
#include <ceres/cost_function.h>

#include "core/tolerance_band.h"

namespace archgeo {

class Batch {
 public:
  // rows: residuals per element; sizes: its parameter blocks' sizes; band:
  // a tolerance band applied to every element's scalar residual (< 0: none).
  Batch(int rows, std::vector<int32_t> sizes, double band);
  virtual ~Batch() = default;
  Batch(const Batch&) = delete;
  Batch& operator=(const Batch&) = delete;

  // Releases spare capacity once every element is added.
  virtual void Fit() = 0;
  int num_residuals() const { return rows_; }
  const std::vector<int32_t>& parameter_block_sizes() const { return sizes_; }

  // ceres::CostFunction::Evaluate of element `element`.
  bool Evaluate(int element, double const* const* parameters, double* residuals,
                double** jacobians) const {
    if (!EvaluateElement(element, parameters, residuals, jacobians)) return false;
    if (band_ >= 0) ApplyToleranceBand(band_, sizes_, residuals, jacobians);
    return true;
  }

 protected:
  virtual bool EvaluateElement(int element, double const* const* parameters, double* residuals,
                               double** jacobians) const = 0;

 private:
  int rows_;
  std::vector<int32_t> sizes_;
  double band_;
};

// Whether `Functor` declares `static constexpr bool kFlatWhereZero = true`:
// where its residuals are all 0, so are their derivatives (a one-sided
// barrier max(gap, 0), idle on most elements). Its batch then evaluates an
// element in doubles first and differentiates it only where it is not 0.
template <class Functor, class = void>
struct FlatWhereZero : std::false_type {};
template <class Functor>
struct FlatWhereZero<Functor, std::void_t<decltype(Functor::kFlatWhereZero)>>
    : std::bool_constant<Functor::kFlatWhereZero> {};

// The elements of ceres::AutoDiffCostFunction<Functor, kResiduals, Ns...>:
// one functor each.
template <class Functor, int kResiduals, int... Ns>
class AutoDiffBatch final : public Batch {
 public:
  using Dims = ceres::internal::StaticParameterDims<Ns...>;
  explicit AutoDiffBatch(double band) : Batch(kResiduals, {Ns...}, band) {}
  // The type's key (one address per instantiation).
  static const void* Key() {
    static const char key = 0;
    return &key;
  }
  int Push(const Functor& functor) {
    functors_.push_back(functor);
    return int(functors_.size()) - 1;
  }
  void Fit() override { functors_.shrink_to_fit(); }

 private:
  bool EvaluateElement(int element, double const* const* parameters, double* residuals,
                       double** jacobians) const override {
    const Functor& f = functors_[size_t(element)];
    if (!jacobians) return ceres::internal::VariadicEvaluate<Dims>(f, parameters, residuals);
    if constexpr (FlatWhereZero<Functor>::value) {
      if (!ceres::internal::VariadicEvaluate<Dims>(f, parameters, residuals)) return false;
      if (std::all_of(residuals, residuals + kResiduals, [](double r) { return r == 0.0; })) {
        const std::vector<int32_t>& sizes = parameter_block_sizes();
        for (size_t b = 0; b < sizes.size(); ++b) {
          if (jacobians[b]) std::fill(jacobians[b], jacobians[b] + kResiduals * sizes[b], 0.0);
        }
        return true;
      }
    }
    return ceres::internal::AutoDifferentiate<kResiduals, Dims>(f, parameters, kResiduals,
                                                                residuals, jacobians);
  }
  std::vector<Functor> functors_;
};

// The batch type of an AutoDiffCostFunction type.
template <class Cost>
struct BatchOf;
template <class Functor, int kResiduals, int... Ns>
struct BatchOf<ceres::AutoDiffCostFunction<Functor, kResiduals, Ns...>> {
  using type = AutoDiffBatch<Functor, kResiduals, Ns...>;
  using functor = Functor;
  static constexpr size_t kBlocks = sizeof...(Ns);
};

// One element of a batch as a ceres::CostFunction (borrowing the batch), for
// a ceres::Problem and for wrappers.
class BatchElement final : public ceres::CostFunction {
 public:
  BatchElement(const Batch& batch, int element);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  const Batch& batch_;
  int element_;
};

}  // namespace archgeo
