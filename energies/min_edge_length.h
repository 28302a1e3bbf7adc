// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Edges that do not collapse: a one-sided (hinge) barrier per edge (a, b):
//
//   r = max(0, ℓ_min − ‖b − a‖) / ℓ_min,
//   ℓ_min = min(f · L̄, max(φ · L̄, ½ ‖b₀ − a₀‖))
//
//   [validity of a built mesh: an edge shrunk to nothing is a degenerate panel
//    (Shi 2014 and Zadravec 2010 objectives can be met by collapsing edges;
//    see analysis/validity.h "short_edges")]
//
// ‖b₀ − a₀‖ is the edge's length at the start of the solve, L̄ the input's
// mean edge length (1 in the canonical frame the terms see) and f a fraction
// (terms.min_edge_length.fraction), φ ≤ f a floor (terms.min_edge_length.floor,
// 0 by default; conjugate_layout's 0.12: the net it made has no edges of
// its own to inherit). The validity check flags an edge shorter
// than a tenth of L̄ and than half its input length; with the default
// f = 0.2 every edge the barrier keeps is valid (an edge of the input shorter
// than 0.4 L̄ keeps half its length, a longer one at least 0.2 L̄) while
// edges may still shrink a lot where the goal asks for it. The residual is
// zero while the edge is longer than ℓ_min, so the term acts only on edges
// about to collapse.
//
// Units / normalisation: r is relative to ℓ_min, unit-free; the weight should
// be large against the goal terms (e.g. 1e3) so that it acts as a constraint.
//
// Singular configurations: ‖b − a‖ is regularised as sqrt(‖b − a‖² + ε²)
// with ε = 1e-9 so that a collapsed edge still has a finite Jacobian. The
// hinge is not differentiable at ‖b − a‖ = ℓ_min (one-sided derivative);
// never returns false.
//
// Invariances: rigid motions (r unchanged); uniform scaling with ℓ_min scaled
// alike (r unchanged).
#ifndef ARCHGEO_ENERGIES_MIN_EDGE_LENGTH_H_
#define ARCHGEO_ENERGIES_MIN_EDGE_LENGTH_H_

#include <Eigen/Core>

#include "energies/autodiff.h"

namespace archgeo {

struct MinEdgeLength {
  using Shape = CostShape<1, 3, 3>;

  explicit MinEdgeLength(double min_length) : min_length(min_length) {}

  // a, b: 3 doubles each; residual: 1 double.
  template <typename T>
  bool operator()(const T* a_ptr, const T* b_ptr, T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> a(a_ptr), b(b_ptr);
    const T length = sqrt((b - a).squaredNorm() + T(1e-18));
    const T gap = (T(min_length) - length) / T(min_length);
    residual[0] = gap > T(0) ? gap : T(0);
    return true;
  }

  double min_length;
  // max(gap, 0): where the residual is 0 its derivatives are 0 too (its
  // batch differentiates only the elements that are not idle).
  static constexpr bool kFlatWhereZero = true;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_MIN_EDGE_LENGTH_H_
