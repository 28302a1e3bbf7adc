// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the linear algebra of LeanSolve (core/lean_solve.h) on the
// normal equations it assembles (core/normal_equations.h):
//   - the small dense block products of one residual block's Jacobians
//     (AddTransposeProduct: C += Aᵀ B; TangentProduct: J through a
//     manifold's Plus Jacobian), unrolled for every size up to kMaxUnrolled;
//   - NormalSystem: the product (H + diag(D)) x over the stored upper
//     triangle of H = JᵀJ, and block-Jacobi preconditioned conjugate
//     gradients on it, ended by Nash and Sofer's test as Ceres ends its own.
// Every loop runs in T fixed parts (core/parallel_parts.h), T = the
// threads given, and every sum adds its parts in order: the same T gives
// the same bits.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/normal_equations.h"

namespace archgeo {

// y += M x (or Mᵀ x) for a row-major rows × cols block; 3 × 3 unrolled.
template <bool kTranspose>
inline void AddProduct(const double* M, int rows, int cols, const double* x, double* y) {
  if (rows == 3 && cols == 3) {
    using M3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
    Eigen::Map<const M3> m(M);
    if (kTranspose) {
      Eigen::Map<Eigen::Vector3d>(y).noalias() +=
          m.transpose() * Eigen::Map<const Eigen::Vector3d>(x);
    } else {
      Eigen::Map<Eigen::Vector3d>(y).noalias() += m * Eigen::Map<const Eigen::Vector3d>(x);
    }
    return;
  }
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      if (kTranspose) {
        y[c] += M[r * cols + c] * x[r];
      } else {
        y[r] += M[r * cols + c] * x[c];
      }
    }
  }
}

namespace kernels {

// C += Aᵀ B for row-major A (rows × a) and B (rows × b), C a × b: the tiny
// products of one residual's Jacobians. Each entry sums its rows first, then
// adds to C (so C is read and written once).
inline void AddTransposeProductAny(const double* A, const double* B, int rows, int a, int b,
                                   double* C) {
#pragma GCC unroll 4
  for (int i = 0; i < a; ++i) {
#pragma GCC unroll 4
    for (int j = 0; j < b; ++j) {
      double sum = 0;
#pragma GCC unroll 4
      for (int r = 0; r < rows; ++r) sum += A[r * a + i] * B[r * b + j];
      C[i * b + j] += sum;
    }
  }
}
template <int kRows, int kA, int kB>
void AddTransposeProductFixed(const double* A, const double* B, double* C) {
  AddTransposeProductAny(A, B, kRows, kA, kB, C);  // inlined with the sizes known
}
// T = J P for row-major J (rows × a) and P (a × t): a block's tangent
// Jacobian through its manifold's Plus Jacobian.
inline void TangentProductAny(const double* J, const double* P, int rows, int a, int t,
                              double* T) {
#pragma GCC unroll 4
  for (int r = 0; r < rows; ++r) {
#pragma GCC unroll 4
    for (int j = 0; j < t; ++j) {
      double sum = 0;
#pragma GCC unroll 4
      for (int k = 0; k < a; ++k) sum += J[r * a + k] * P[k * t + j];
      T[r * t + j] = sum;
    }
  }
}
template <int kRows, int kA, int kT>
void TangentProductFixed(const double* J, const double* P, double* T) {
  TangentProductAny(J, P, kRows, kA, kT, T);  // inlined with the sizes known
}

// The kernels above of every size up to kMax (rows and columns), indexed
// [rows − 1][a − 1][b − 1], so that a residual's products run unrolled
// (with the same sums as the loops: each entry over its rows in order).
constexpr int kMax = 4;
using Kernel = void (*)(const double*, const double*, double*);
template <template <int, int, int> class Of, int... I>
constexpr std::array<Kernel, sizeof...(I)> KernelTable(std::integer_sequence<int, I...>) {
  return {Of<I / (kMax * kMax) + 1, I / kMax % kMax + 1, I % kMax + 1>::kernel...};
}
template <int R, int A, int B>
struct TransposeProductOf {
  static constexpr Kernel kernel = &AddTransposeProductFixed<R, A, B>;
};
template <int R, int A, int T>
struct TangentProductOf {
  static constexpr Kernel kernel = &TangentProductFixed<R, A, T>;
};
inline constexpr auto kTransposeProducts =
    KernelTable<TransposeProductOf>(std::make_integer_sequence<int, kMax * kMax * kMax>());
inline constexpr auto kTangentProducts =
    KernelTable<TangentProductOf>(std::make_integer_sequence<int, kMax * kMax * kMax>());
inline bool Fits(int rows, int a, int b) { return rows <= kMax && a <= kMax && b <= kMax; }
inline int KernelIndex(int rows, int a, int b) {
  return ((rows - 1) * kMax + a - 1) * kMax + b - 1;
}

}  // namespace kernels

// The largest block (rows and columns) whose products run unrolled.
constexpr int kMaxUnrolled = kernels::kMax;

// C += Aᵀ B for row-major A (rows × a), B (rows × b) and C (a × b); each
// entry sums its rows in order, then adds to C.
inline void AddTransposeProduct(const double* A, const double* B, int rows, int a, int b,
                                double* C) {
  using namespace kernels;
  if (Fits(rows, a, b)) return kTransposeProducts[size_t(KernelIndex(rows, a, b))](A, B, C);
  AddTransposeProductAny(A, B, rows, a, b, C);
}
// T = J P for row-major J (rows × a), P (a × t) and T (rows × t).
inline void TangentProduct(const double* J, const double* P, int rows, int a, int t, double* T) {
  using namespace kernels;
  if (Fits(rows, a, t)) return kTangentProducts[size_t(KernelIndex(rows, a, t))](J, P, T);
  TangentProductAny(J, P, rows, a, t, T);
}

// The assembled normal equations H = JᵀJ (the pattern's slots, in its
// `hessian`) as a linear operator, and their damped solve.
class NormalSystem {
 public:
  // `pattern` holds H (and must outlive this); `threads` ≥ 1 fixes the parts.
  NormalSystem(const NormalPattern& pattern, int threads);

  // y = (H + diag(damping)) x, y ≠ x. One pass over the stored upper
  // triangle, in slot order: each off-diagonal slot H_ij adds H_ij x_j to y_i
  // and H_ijᵀ x_i to y_j, so H streams from memory once (the product is
  // bound by that traffic, not by arithmetic). The block rows in T parts (by
  // slots), each into a vector of its own (part 0 into y), then added entry
  // by entry in part order.
  void Multiply(const Eigen::VectorXd& damping, const Eigen::VectorXd& x,
                Eigen::VectorXd* y) const;

  // The diagonal of H.
  Eigen::VectorXd Diagonal() const;

  // Solves (H + diag(damping)) δ = −g by block-Jacobi PCG from δ = 0, for
  // at least `min_iterations` and at most `max_iterations` steps; returns the
  // steps taken. The preconditioner is every diagonal block's
  // (H_ii + D_i)⁻¹ (the identity where that is not positive definite). It
  // stops as Ceres' conjugate gradients do inside its Levenberg–Marquardt
  // (Nash & Sofer 1990, "Assessing a search direction within a
  // truncated-Newton method"): at step k once k (Q_k − Q_(k−1)) / Q_k < eta,
  // Q the quadratic model δᵀAδ − 2bᵀδ (A = H + diag(damping), b = −g), which
  // each step lowers by α rᵀz. (The residual ‖b − Aδ‖ keeps falling slowly
  // long after the model's decrease has stalled.)
  int Solve(const Eigen::VectorXd& damping, const Eigen::VectorXd& gradient, double eta,
            int min_iterations, int max_iterations, Eigen::VectorXd* delta) const;

  // The model's change ½ δᵀHδ + gᵀδ, and in `max_norm` and `norm`, if
  // given, the max norm and the 2-norm of the model's gradient at δ, g + Hδ.
  double ModelChange(const Eigen::VectorXd& gradient, const Eigen::VectorXd& delta,
                     double* max_norm = nullptr, double* norm = nullptr) const;

 private:
  const NormalPattern& s_;
  int threads_;
  std::vector<int> row_part_;  // threads_ + 1: the product's parts of the block rows
  mutable std::vector<Eigen::VectorXd> spare_;  // parts 1 .. T − 1 of the product
};

}  // namespace archgeo
