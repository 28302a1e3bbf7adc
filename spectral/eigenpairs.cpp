// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "spectral/eigenpairs.h"

#include <Spectra/SymEigsShiftSolver.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include <Eigen/SparseCholesky>

namespace archgeo {
namespace {

// y = (A − σI)⁻¹ x by a sparse LDLᵀ factorisation: the operator Spectra's
// shift-invert mode applies.
class ShiftInvertLdlt {
 public:
  using Scalar = double;
  explicit ShiftInvertLdlt(const Eigen::SparseMatrix<double>& a) : a_(a) {}
  Eigen::Index rows() const { return a_.rows(); }
  Eigen::Index cols() const { return a_.cols(); }
  void set_shift(double sigma) {
    Eigen::SparseMatrix<double> identity(a_.rows(), a_.cols());
    identity.setIdentity();
    ldlt_.compute(a_ - sigma * identity);
    if (ldlt_.info() != Eigen::Success) {
      throw std::runtime_error("the shifted Laplacian could not be factorised");
    }
  }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Eigen::VectorXd> x(x_in, a_.rows());
    Eigen::Map<Eigen::VectorXd> y(y_out, a_.rows());
    y = ldlt_.solve(x);
  }

 private:
  const Eigen::SparseMatrix<double>& a_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
};

}  // namespace

Eigenpairs LowestEigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                            const Eigen::VectorXd& mass, int count) {
  const int n = int(stiffness.rows());
  if (count < 1 || count >= n) {
    throw std::invalid_argument("asked for " + std::to_string(count) + " eigenpairs of " +
                                std::to_string(n) + " vertices");
  }
  const Eigen::VectorXd scale = mass.cwiseSqrt().cwiseInverse();  // B^{-1/2}
  const Eigen::SparseMatrix<double> a = scale.asDiagonal() * stiffness * scale.asDiagonal();
  // Just below the smallest eigenvalue (0): A − σI is positive definite.
  const double sigma = -1e-8 * a.diagonal().mean();
  ShiftInvertLdlt op(a);
  // A few more than asked: Lanczos converges on the wanted end first, but the
  // last members of a degenerate cluster (2l+1 on a sphere) can come late.
  const int wanted = std::min(n - 1, count + 8);
  const int subspace = std::min(n, std::max(2 * wanted + 1, wanted + 20));
  Spectra::SymEigsShiftSolver<ShiftInvertLdlt> eigs(op, wanted, subspace, sigma);
  eigs.init();
  eigs.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10);
  if (eigs.info() != Spectra::CompInfo::Successful) {
    throw std::runtime_error("the Lanczos iteration did not converge for " +
                             std::to_string(wanted) + " eigenpairs");
  }
  // Spectra returns them from the largest transformed value, i.e. ascending λ
  // after the shift-invert; sort to be sure.
  const Eigen::VectorXd values = eigs.eigenvalues();
  const Eigen::MatrixXd vectors = eigs.eigenvectors();
  std::vector<int> order(values.size());
  for (int k = 0; k < int(order.size()); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](int x, int y) { return values[x] < values[y]; });
  Eigenpairs out;
  out.values.resize(count);
  out.vectors.resize(n, count);
  for (int k = 0; k < count; ++k) {
    out.values[k] = values[order[k]];
    out.vectors.col(k) = scale.asDiagonal() * vectors.col(order[k]);  // φ = B^{-1/2} ψ
  }
  return out;
}

}  // namespace archgeo
