// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the lowest eigenpairs of K φ = λ B φ (spectral/laplacian.h) by
// shift-invert Lanczos (Spectra's SymEigsShiftSolver) on a sparse LDLᵀ
// factorisation (Eigen's SimplicialLDLT) of the symmetric
// A = B^{-1/2} K B^{-1/2} shifted just below 0; no dense matrix is formed.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace archgeo {

struct Eigenpairs {
  Eigen::VectorXd values;   // ascending, λ_0 ≈ 0 first
  Eigen::MatrixXd vectors;  // column k: φ_k, B-orthonormal (φ_kᵀ B φ_k = 1)
};

// The `count` lowest eigenpairs (count < the number of rows). Throws
// std::runtime_error when the factorisation or the Lanczos iteration fails.
Eigenpairs LowestEigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                            const Eigen::VectorXd& mass, int count);

}  // namespace archgeo
