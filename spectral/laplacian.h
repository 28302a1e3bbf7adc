// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the discrete Laplacians of spectral meshing (Gebreiter 2012,
// §4.1.5 and §6.1.3), on a triangle mesh given as plain arrays.
//
// Cotangent weights D_ij = (cot α_ij + cot β_ij) / 2 (the angles opposite
// edge ij). Both Laplacians are the generalised symmetric problem
//   K φ = λ B φ,   K_ij = −D_ij (i ≠ j),  K_ii = Σ_k D_ik,   B diagonal:
//   cotangent (§4.1.5): B = the lumped (barycentric) vertex areas, so λ
//     approximates the Laplace–Beltrami spectrum (l(l+1) on a unit sphere);
//   normalised (§6.1.3): B_ii = Σ_k D_ik, the eigenproblem of the thesis'
//     L = I − diag(Σ_k D_ik)⁻¹ D, whose eigenvalues lie in [0, 2].
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace archgeo {

enum class LaplacianKind { kCotangent, kNormalised };

struct Laplacian {
  Eigen::SparseMatrix<double> stiffness;  // K, symmetric, rows summing to 0
  Eigen::VectorXd mass;                   // the diagonal of B
};

// Throws std::invalid_argument when a vertex has no positive B (an isolated
// vertex, or cotangent weights summing to ≤ 0 for the normalised kind).
Laplacian BuildLaplacian(const std::vector<Eigen::Vector3d>& points,
                         const std::vector<std::array<int, 3>>& triangles, LaplacianKind kind);

}  // namespace archgeo
