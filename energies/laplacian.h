// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Laplacian (umbrella-operator) smoothing of a vertex v with neighbours
// w_1 … w_n — the YAML term `laplacian`, one 3-vector residual per vertex:
//
//   r = ( Σ_j c_j (w_j − v) / Σ_j c_j ) / L
//
//   [Gebreiter 2012, §10.1 "Laplacian smoothing, which places vertices at the
//    barycentres of their neighbours"; §11.2.2 edge-length variation
//    "remedied by Laplacian smoothing"; Taubin 1995, umbrella operator]
//
// With uniform weights c_j = 1 (uniform weights) r is the vector from v to the
// barycentre of its neighbours, over L: r = 0 iff v is at the barycentre.
// With other constant weights (cotangent weights) r points to the
// weighted barycentre; the cotangent weights frozen at the start of a round
// (energies/mean_curvature_flow.h CotangentWeights) give the linearised
// mean-curvature flow of Desbrun et al. 1999 / the minimal-surface iteration
// of Pinkall and Polthier 1993.
//
// Units / normalisation: L = 1/inv_length is a fixed length chosen by the
// builder (the mean edge length), so r is unit-free. Ceres minimises ½Σ‖r‖².
// Dividing by Σ c_j makes r independent of the weights' overall scale.
//
// Singular configurations: none; r is affine in the positions (Jacobian
// blocks −I/L for v, c_j/(Σc) I/L for w_j). Never returns false.
//
// Invariances: translation; rotation (r → R r, ‖r‖ unchanged); uniform
// scaling x → s x with inv_length → inv_length / s (r unchanged); any order of
// the neighbours (with their weights).
#ifndef ARCHGEO_ENERGIES_LAPLACIAN_H_
#define ARCHGEO_ENERGIES_LAPLACIAN_H_

#include <vector>

#include <Eigen/Core>

namespace archgeo {

// Functor over a vertex star (MakeStarAutoDiff): parameters[0] = v,
// parameters[j] = w_j (j = 1 … n), 3 doubles each; 3 residuals.
struct Laplacian {
  static constexpr int kResiduals = 3;
  static constexpr int kStride = 12;
  int NumBlocks() const { return int(weights.size()) + 1; }

  // weights: c_1 … c_n (n ≥ 1, Σ c_j > 0); inv_length: 1/L.
  Laplacian(const std::vector<double>& weights, double inv_length)
      : weights(weights), inv_length(inv_length) {
    double sum = 0.0;
    for (double c : weights) sum += c;
    scale = inv_length / sum;
  }

  template <typename T>
  bool operator()(T const* const* parameters, T* residual_ptr) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> v(parameters[0]);
    Vec3 sum = Vec3::Zero();
    for (size_t j = 0; j < weights.size(); ++j) {
      sum += T(weights[j]) * (Eigen::Map<const Vec3>(parameters[j + 1]) - v);
    }
    Eigen::Map<Vec3> residual(residual_ptr);
    residual = sum * T(scale);
    return true;
  }

  std::vector<double> weights;
  double inv_length;
  double scale;  // inv_length / Σ c_j
};

// The functor after checking its input (CHECKs: n ≥ 1, every c_j finite,
// Σ c_j > 0 (individual cotangent weights may be negative); inv_length finite
// and > 0). Uniform weights: std::vector<double>(n, 1.0).
Laplacian CheckedLaplacian(const std::vector<double>& weights, double inv_length);

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_LAPLACIAN_H_
