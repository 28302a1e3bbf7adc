// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the one way to add an autodiff residual. An energy's functor
// (energies/<name>.h) declares its shape,
//
//   struct PqDiagonal {
//     using Shape = CostShape<1, 3, 3, 3, 3>;  // 1 residual; 4 blocks of 3
//     template <typename T> bool operator()(const T* b0, ..., T* residual) const;
//   };
//
// and its .cpp instantiates the derivatives once (ARCHGEO_AUTODIFF(PqDiagonal),
// energies/autodiff_impl.h). Then
//   - a term adds one residual per element with AddAutoDiff(context,
//     functor, blocks): the elements of one functor type share one
//     evaluator per round (core/batch.h), not a cost object each;
//   - a test or a benchmark gets a ceres::CostFunction with
//     MakeAutoDiff(functor).
// Both evaluate the functor on doubles, or on ceres::Jet with one dual
// number per parameter (forward-mode automatic differentiation, as
// ceres::AutoDiffCostFunction does): the same values to the last bit.
//
// This header is light (no Ceres): energy headers and tests include it; the
// derivatives are compiled only where ARCHGEO_AUTODIFF instantiates them.
#pragma once

#include <array>
#include <cstddef>

namespace ceres {
class CostFunction;
}  // namespace ceres

namespace archgeo {

class TermContext;

// The shape of a cost functor: kResiduals residuals over parameter blocks
// of sizes kSizes... (in the order of operator()'s arguments).
template <int kResiduals, int... kSizes>
struct CostShape {
  static_assert(kResiduals > 0 && sizeof...(kSizes) > 0, "a residual reads at least one block");
  static constexpr int kNumResiduals = kResiduals;
  static constexpr size_t kNumBlocks = sizeof...(kSizes);
  static constexpr int kNumParameters = (kSizes + ...);
  static constexpr std::array<int, sizeof...(kSizes)> kBlockSizes = {kSizes...};
};

// The parameter blocks of one residual of functor F.
template <class F>
using BlocksOf = std::array<double*, F::Shape::kNumBlocks>;

// A new cost function of `functor` (the caller takes ownership).
template <class F>
ceres::CostFunction* MakeAutoDiff(const F& functor);

// Functors over a vertex and its ring, a number of 3-blocks known only at
// run time, take (T const* const* blocks, T* residuals) and declare
// `static constexpr int kResiduals`, `kStride` (the Jet width of one pass
// of Ceres' dynamic autodiff) and `int NumBlocks() const`: a new cost
// function of `functor` over NumBlocks() blocks of 3.
template <class F>
ceres::CostFunction* MakeStarAutoDiff(const F& functor);

// Adds the residual `functor` over `blocks` to the context's round, as
// context.Add(MakeAutoDiff(functor), blocks, part, weight) would (within a
// tolerance band of half-width `band` when band ≥ 0: core/tolerance_band.h),
// without a cost object: the elements of one functor type and band share
// one evaluator this round.
template <class F>
void AddAutoDiff(TermContext& context, const F& functor, const BlocksOf<F>& blocks,
                 double band = -1, const char* part = nullptr, double weight = -1);

}  // namespace archgeo
