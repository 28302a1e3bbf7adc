// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the exact step of LeanSolve (core/lean_solve.h) for rounds of
// design size: (H + diag(D)) δ = −g by a sparse Cholesky factorisation
// (CHOLMOD, supernodal), H = JᵀJ as LeanSolve assembles it in the pattern's
// slots (core/normal_equations.h).
//   - The scalar pattern of H's upper triangle and its fill-reducing
//     ordering and symbolic factorisation (cholmod_analyze) are made once per
//     NormalPattern structure and kept for every iteration and every round
//     of that structure: an iteration costs one numeric factorisation and
//     two triangular solves.
//   - Each factorisation copies the slots' values into the matrix (a map from
//     every stored scalar to its slot entry, made with the pattern) and adds
//     the damping on the diagonal.
#pragma once

#include <memory>

#include <Eigen/Core>

namespace archgeo {

struct NormalPattern;

// The fill-reducing ordering of the factorisation (solver.ordering): CHOLMOD's
// approximate minimum degree, or METIS' nested dissection (fewer flops on
// large surface meshes, a costlier analysis).
enum class CholeskyOrdering { kAmd, kMetis };

class NormalCholesky {
 public:
  // Orders and analyses the upper triangle of `pattern`'s H.
  NormalCholesky(const NormalPattern& pattern, CholeskyOrdering ordering);
  // The ordering asked for, and the one the analysis used (AMD where this
  // CHOLMOD has no METIS).
  CholeskyOrdering ordering() const { return ordering_; }
  CholeskyOrdering used() const { return used_; }
  // Floating-point operations of one numeric factorisation (the analysis'
  // count, by the ordering it used).
  double FactorFlops() const;
  // Nonzeros of the factor L (the analysis' count, supernodal zeros included).
  double FactorNonzeros() const;
  ~NormalCholesky();
  NormalCholesky(const NormalCholesky&) = delete;
  NormalCholesky& operator=(const NormalCholesky&) = delete;

  // δ of (H + diag(damping)) δ = −gradient with H the pattern's current
  // hessian; false (δ untouched) when that matrix is not positive definite.
  bool Solve(const NormalPattern& pattern, const Eigen::VectorXd& damping,
             const Eigen::VectorXd& gradient, Eigen::VectorXd* delta);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  CholeskyOrdering ordering_, used_;
};

}  // namespace archgeo
