// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Transfer of the standing wave along an edge ij, 4 residuals:
//
//   r = P_ij f_j − C_ij f_i,   C_ij = R(α_ij) ⊗ R(β_ij),   R(a) = [cos a  −sin a; sin a  cos a]
//
//   [Gebreiter 2012, §8.3.1, E(f_0 … f_n) = Σ_ij (e1ᵀ f_j − c_ijᵀ f_i)² + …,
//    after Zhang et al. 2010, "Wave-based anisotropic quadrangulation"]
//
// f_i = (cos θ cos φ, cos θ sin φ, sin θ cos φ, sin θ sin φ) per vertex; the
// first-order Taylor step θ_j = θ_i + α_ij, φ_j = φ_i + β_ij with
// α_ij = ω_x X(e_ij)·(p_j − p_i), β_ij = ω_y Y(e_ij)·(p_j − p_i) and
// ω = 2π / size field gives f_j = C_ij f_i exactly; the thesis' c_ij is the
// first row of C_ij. All four rows are used: the first alone ties only the
// wave itself along each edge and leaves three of the four components free
// up to the two penalties (wave_norm, wave_product); with all four the
// quadratic part is a connection Laplacian, positive definite unless the
// field is exactly integrable. C_ij is orthogonal, so the reverse residual
// f_i − C_ji f_j has the same norm: one residual per edge.
//
// P_ij is the matching of the cross field across the edge: j's frame is
// relabelled into i's (i's θ at j is ±θ_j or ±φ_j, and i's φ the other), a
// signed permutation of f_j's components; cos θ cos φ is invariant under it,
// so the wave is one function across the field's singularities.
//
// Units: f and r are unit-free (|f| = 1). Singular configurations: none
// (linear). Invariances: a global phase shift of θ and φ (f_i → (R(a) ⊗
// R(b)) f_i for all i, with identity matchings) leaves r's norm unchanged.
#ifndef ARCHGEO_ENERGIES_WAVE_TRANSFER_H_
#define ARCHGEO_ENERGIES_WAVE_TRANSFER_H_

#include <array>

#include "energies/autodiff.h"

namespace archgeo {

struct WaveTransfer {
  using Shape = CostShape<4, 4, 4>;

  // α, β: phase advances (radians) from i to j in i's labels; source_theta,
  // source_phi ∈ {0, 1} (0: θ_j, 1: φ_j), signs ±1: i's θ at j is
  // sign_theta · (source_theta ? φ_j : θ_j), i's φ likewise. The two sources
  // differ.
  WaveTransfer(double alpha, double beta, int source_theta, double sign_theta, int source_phi,
               double sign_phi);

  // f_i, f_j: 4 doubles each; residual: 4.
  template <typename T>
  bool operator()(const T* fi, const T* fj, T* residual) const {
    for (int r = 0; r < 4; ++r) {
      T sum = T(p_sign[size_t(r)]) * fj[p_index[size_t(r)]];
      for (int c = 0; c < 4; ++c) sum -= T(C[size_t(4 * r + c)]) * fi[c];
      residual[r] = sum;
    }
    return true;
  }

  std::array<double, 16> C{};      // row-major
  std::array<int, 4> p_index{};    // (P f_j)[r] = p_sign[r] · f_j[p_index[r]]
  std::array<double, 4> p_sign{};
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_WAVE_TRANSFER_H_
