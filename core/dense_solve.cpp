// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/dense_solve.h"

#include <Eigen/QR>
#include <Eigen/SVD>

namespace archgeo {

Eigen::VectorXd SolveByQr(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  return Eigen::ColPivHouseholderQR<Eigen::MatrixXd>(A).solve(b);
}

Eigen::VectorXd SolveMinimumNorm(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  return A.completeOrthogonalDecomposition().solve(b);
}

Eigen::VectorXd SolveBySvd(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double threshold) {
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeThinU | Eigen::ComputeThinV);
  svd.setThreshold(threshold);
  return svd.solve(b);
}

}  // namespace archgeo
