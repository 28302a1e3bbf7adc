// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Least-squares solves of small dense systems (core/dense_solve.cpp). Each
// of Eigen's rank-revealing decompositions costs seconds of compile time in
// every translation unit that instantiates it; here they are compiled once,
// and share their column-pivoting QR.
#pragma once

#include <Eigen/Core>

namespace archgeo {

// min |A x − b| by column-pivoting Householder QR (A of full column rank).
Eigen::VectorXd SolveByQr(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

// The minimum-norm solution of min |A x − b| (complete orthogonal
// decomposition; Eigen's default rank threshold).
Eigen::VectorXd SolveMinimumNorm(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

// The least-squares solution by the thin SVD (Jacobi), singular values
// below `threshold` times the largest taken as zero.
Eigen::VectorXd SolveBySvd(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double threshold);

}  // namespace archgeo
