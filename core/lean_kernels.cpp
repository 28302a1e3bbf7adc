// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/lean_kernels.h"

#include <algorithm>

#include <Eigen/Cholesky>

#include "core/parallel_parts.h"

namespace archgeo {
namespace {

using Vector = Eigen::VectorXd;

// out = (H + diag(D))⁻¹ for one n × n diagonal block H (row-major) of the
// normal equations, by Cholesky; the identity where H + diag(D) is not
// positive definite. Square: a dynamic-size matrix type, with room for at
// most kMaxUnrolled rows on the stack where the block fits (no heap
// allocation; the same arithmetic as on the heap, to the last bit).
template <class Square>
void InvertDamped(const double* H, const double* D, double* out, int n) {
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor,
                             Square::MaxRowsAtCompileTime, Square::MaxColsAtCompileTime>;
  Square Hii = Eigen::Map<const Rows>(H, n, n);
  Hii.diagonal() += Eigen::Map<const Eigen::VectorXd>(D, n);
  const Eigen::LLT<Square> llt(Hii);
  Square inv = Square::Identity(n, n);
  if (llt.info() == Eigen::Success) inv = llt.solve(inv);
  Eigen::Map<Rows>(out, n, n) = inv;
}

}  // namespace

NormalSystem::NormalSystem(const NormalPattern& pattern, int threads)
    : s_(pattern), threads_(std::clamp(threads, 1, 256)) {
  // The product's parts: part t starts at the first block row past t/T of
  // the off-diagonal slots.
  const int n = int(s_.blocks.size());
  row_part_.assign(size_t(threads_) + 1, n);
  row_part_[0] = 0;
  for (int t = 1; t < threads_; ++t) {
    const int slots = int(PartStart(size_t(s_.row_start[size_t(n)]), threads_, t));
    const int row = int(std::lower_bound(s_.row_start.begin(), s_.row_start.end(), slots) -
                        s_.row_start.begin());
    row_part_[size_t(t)] = std::min(row, n);
  }
  spare_.resize(size_t(threads_ - 1));
}

void NormalSystem::Multiply(const Vector& damping, const Vector& x, Vector* y) const {
  const double* H = s_.hessian.data();
  const int n = s_.tangent;
  // Part t writes y_i and y_j (j > i) of its rows i only: from the offset
  // of its first row on.
  const auto first = [&](int t) {
    const int row = row_part_[size_t(t)];
    return row < int(s_.blocks.size()) ? s_.blocks[size_t(row)].offset : n;
  };
  y->resize(n);
  ForParts(threads_, [&](int t) {
    double* out = y->data();
    if (t == 0) {
      y->noalias() = damping.cwiseProduct(x);
    } else {
      Vector& spare = spare_[size_t(t) - 1];
      spare.resize(n);
      spare.segment(first(t), n - first(t)).setZero();
      out = spare.data();
    }
    for (int i = row_part_[size_t(t)]; i < row_part_[size_t(t) + 1]; ++i) {
      const PatternBlock& bi = s_.blocks[size_t(i)];
      double* yi = out + bi.offset;
      const double* xi = x.data() + bi.offset;
      AddProduct<false>(H + s_.diagonal[size_t(i)], bi.tangent, bi.tangent, xi, yi);
      for (int k = s_.row_start[size_t(i)]; k < s_.row_start[size_t(i) + 1]; ++k) {
        const PatternBlock& bj = s_.blocks[size_t(s_.column[size_t(k)])];
        AddProduct<false>(H + s_.slot[size_t(k)], bi.tangent, bj.tangent, x.data() + bj.offset,
                          yi);
        AddProduct<true>(H + s_.slot[size_t(k)], bi.tangent, bj.tangent, xi, out + bj.offset);
      }
    }
  });
  if (threads_ == 1) return;
  // y += part 1 + part 2 + …, entry by entry in that order; the entries in
  // T parts.
  ForParts(threads_, [&](int part) {
    const int begin = int(PartStart(size_t(n), threads_, part));
    const int end = int(PartStart(size_t(n), threads_, part + 1));
    for (int t = 1; t < threads_; ++t) {
      const int from = std::max(begin, first(t));
      if (from >= end) continue;
      y->segment(from, end - from) += spare_[size_t(t) - 1].segment(from, end - from);
    }
  });
}

Vector NormalSystem::Diagonal() const {
  Vector d(s_.tangent);
  for (size_t i = 0; i < s_.blocks.size(); ++i) {
    const PatternBlock& b = s_.blocks[i];
    for (int c = 0; c < b.tangent; ++c) {
      d[b.offset + c] = s_.hessian[size_t(s_.diagonal[i] + c * b.tangent + c)];
    }
  }
  return d;
}

int NormalSystem::Solve(const Vector& damping, const Vector& gradient, double eta,
                        int min_iterations, int max_iterations, Vector* delta) const {
  // Block-Jacobi preconditioner: every block's (H_ii + D_i)⁻¹, on the
  // stack where the block fits.
  const int blocks = int(s_.blocks.size());
  std::vector<double> inverse(size_t(s_.diagonal_slots));
  ForParts(threads_, [&](int t) {
    for (int i = int(PartStart(size_t(blocks), threads_, t)),
             end = int(PartStart(size_t(blocks), threads_, t + 1));
         i < end; ++i) {
      const PatternBlock& b = s_.blocks[size_t(i)];
      const double* H = s_.hessian.data() + s_.diagonal[size_t(i)];
      const double* D = damping.data() + b.offset;
      double* out = inverse.data() + s_.diagonal[size_t(i)];
      if (b.tangent <= kMaxUnrolled) {
        InvertDamped<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxUnrolled,
                                   kMaxUnrolled>>(H, D, out, b.tangent);
      } else {
        InvertDamped<Eigen::MatrixXd>(H, D, out, b.tangent);
      }
    }
  });
  // The vector work of a step in three passes over the T fixed parts of the
  // blocks, fused so that each vector streams from memory once per pass.
  const int n = s_.tangent;
  const auto block_start = [&](int t) { return int(PartStart(size_t(blocks), threads_, t)); };
  const auto offset = [&](int i) { return i < blocks ? s_.blocks[size_t(i)].offset : n; };
  delta->setZero(n);
  Vector r = -gradient, z(n), p(n), q(n);
  // z = M⁻¹ r on part t's blocks; returns their r·z (M⁻¹ is positive
  // definite: r·z > 0 unless r = 0).
  const auto precondition = [&](int t) {
    double sum = 0;
    for (int i = block_start(t); i < block_start(t + 1); ++i) {
      const PatternBlock& b = s_.blocks[size_t(i)];
      const double* ri = r.data() + b.offset;
      double* zi = z.data() + b.offset;
      std::fill(zi, zi + b.tangent, 0.0);
      AddProduct<false>(inverse.data() + s_.diagonal[size_t(i)], b.tangent, b.tangent, ri, zi);
      for (int c = 0; c < b.tangent; ++c) sum += ri[c] * zi[c];
    }
    return sum;
  };
  double rz = SumParts(threads_, precondition);
  p = z;
  double model = 0;  // Q at δ
  int k = 0;
  while (k < max_iterations && rz > 0) {
    Multiply(damping, p, &q);
    const double pq = SumParts(threads_, [&](int t) {
      const int a = offset(block_start(t)), e = offset(block_start(t + 1));
      return p.segment(a, e - a).dot(q.segment(a, e - a));
    });
    if (!(pq > 0.0)) break;
    const double alpha = rz / pq;
    const double next_rz = SumParts(threads_, [&](int t) {
      const int a = offset(block_start(t)), e = offset(block_start(t + 1));
      delta->segment(a, e - a) += alpha * p.segment(a, e - a);
      r.segment(a, e - a) -= alpha * q.segment(a, e - a);
      return precondition(t);
    });
    ++k;
    const double next = model - alpha * rz;
    if (k >= min_iterations && k * (next - model) / next < eta) break;
    model = next;
    const double beta = next_rz / rz;
    rz = next_rz;
    ForParts(threads_, [&](int t) {
      const int a = offset(block_start(t)), e = offset(block_start(t + 1));
      p.segment(a, e - a) = z.segment(a, e - a) + beta * p.segment(a, e - a);
    });
  }
  return k;
}

double NormalSystem::ModelChange(const Vector& gradient, const Vector& delta, double* max_norm,
                                 double* norm) const {
  Vector Hd(s_.tangent);
  Multiply(Vector::Zero(s_.tangent), delta, &Hd);
  const double change = gradient.dot(delta) + 0.5 * delta.dot(Hd);
  Hd += gradient;  // the model's gradient
  if (max_norm) *max_norm = Hd.lpNorm<Eigen::Infinity>();
  if (norm) *norm = Hd.norm();
  return change;
}

}  // namespace archgeo
