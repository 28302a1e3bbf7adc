// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Smoothness of the log sizes along an edge ij, 2 residuals:
//
//   r = (μ̃_i − μ̃_j^(i), η̃_i − η̃_j^(i))
//
//   [Gebreiter 2012, §8.1.4: "to counteract a phenomenon of rapid
//    oscillation ... a smoothing term is added"; after Zhang et al. 2010]
//
// Σ r² over the edges is the uniform (graph) Dirichlet energy of the log
// sizes, whose gradient is the umbrella Laplacian. μ̃_j^(i) is j's log size
// along i's X: μ̃_j or η̃_j by the cross field's matching across the edge.
// Units: unit-free (log sizes). Singular configurations: none (linear).
// Invariances: s̃ → s̃ + const.
#ifndef ARCHGEO_ENERGIES_SIZE_SMOOTHING_H_
#define ARCHGEO_ENERGIES_SIZE_SMOOTHING_H_

#include "energies/autodiff.h"

namespace archgeo {

struct SizeSmoothing {
  using Shape = CostShape<2, 2, 2>;

  // source_mu ∈ {0, 1}: i's μ̃ at j is s_j[source_mu], i's η̃ the other.
  explicit SizeSmoothing(int source_mu);

  // si, sj: (μ̃, η̃); residual: 2.
  template <typename T>
  bool operator()(const T* si, const T* sj, T* residual) const {
    residual[0] = si[0] - sj[source_mu];
    residual[1] = si[1] - sj[1 - source_mu];
    return true;
  }

  int source_mu = 0;
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_SIZE_SMOOTHING_H_
