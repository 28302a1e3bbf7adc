// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/lean_solve.h"

#include "core/halves.h"
#include "core/normal_equations.h"
#include "core/solver_options.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include <omp.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <ceres/cost_function.h>
#include <ceres/loss_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>

namespace archgeo {
namespace {

using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using Vector = Eigen::VectorXd;

// y += M x (or Mᵀ x) for a row-major rows × cols block; 3 × 3 unrolled.
template <bool kTranspose>
inline void AddProduct(const double* M, int rows, int cols, const double* x, double* y) {
  if (rows == 3 && cols == 3) {
    using M3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
    Eigen::Map<const M3> m(M);
    if (kTranspose) {
      Eigen::Map<Eigen::Vector3d>(y).noalias() += m.transpose() * Eigen::Map<const Eigen::Vector3d>(x);
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
constexpr auto kTransposeProducts =
    KernelTable<TransposeProductOf>(std::make_integer_sequence<int, kMax * kMax * kMax>());
constexpr auto kTangentProducts =
    KernelTable<TangentProductOf>(std::make_integer_sequence<int, kMax * kMax * kMax>());
inline bool Fits(int rows, int a, int b) { return rows <= kMax && a <= kMax && b <= kMax; }
inline int KernelIndex(int rows, int a, int b) { return ((rows - 1) * kMax + a - 1) * kMax + b - 1; }

// C += Aᵀ B (see AddTransposeProductAny), unrolled where the sizes fit the table.
inline void AddTransposeProduct(const double* A, const double* B, int rows, int a, int b,
                                double* C) {
  if (Fits(rows, a, b)) return kTransposeProducts[size_t(KernelIndex(rows, a, b))](A, B, C);
  AddTransposeProductAny(A, B, rows, a, b, C);
}
// T = J P (see TangentProductAny), unrolled where the sizes fit the table.
inline void TangentProduct(const double* J, const double* P, int rows, int a, int t, double* T) {
  if (Fits(rows, a, t)) return kTangentProducts[size_t(KernelIndex(rows, a, t))](J, P, T);
  TangentProductAny(J, P, rows, a, t, T);
}

// The sums {a, b} of body(first, end) over the two fixed halves of [0, n),
// each half's then added (ForHalves: the same sums on one thread).
template <class Body>
std::array<double, 2> SumHalves(size_t split, size_t n, const Body& body) {
  std::array<double, 2> half[2] = {{0, 0}, {0, 0}};
  ForHalves(split, n, [&](int t, size_t first, size_t end) { half[t] = body(first, end); });
  return {half[0][0] + half[1][0], half[0][1] + half[1][1]};
}

// Ceres' loss corrector (Triggs et al. 1999, "Bundle adjustment — a modern
// synthesis", §4.3): scales r and J so that ½‖r̃‖² matches ρ to second order.
struct Corrector {
  double residual_scaling = 1, alpha_sq_norm = 0, sqrt_rho1 = 1;
  Corrector(double sq_norm, const double rho[3]) {
    sqrt_rho1 = std::sqrt(rho[1]);
    if (sq_norm == 0.0 || rho[2] <= 0.0) {
      residual_scaling = sqrt_rho1;
      return;
    }
    const double D = 1.0 + 2.0 * sq_norm * rho[2] / rho[1];
    const double alpha = 1.0 - std::sqrt(D);
    residual_scaling = sqrt_rho1 / (1 - alpha);
    alpha_sq_norm = alpha / sq_norm;
  }
};

// out = (H + diag(D))⁻¹ for one n × n diagonal block H (row-major) of the
// normal equations, by Cholesky; the identity where H + diag(D) is not
// positive definite. Square: a dynamic-size matrix type, with room for at
// most kMax rows on the stack where the block fits (no heap allocation; the
// same arithmetic as on the heap, to the last bit).
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

// One thread's linearisation scratch and its sum Σ ρ, on cache lines of its
// own: the other thread's writes to its sum must not evict this one's
// scratch pointers (false sharing, which cost up to 70% of the linearisation
// depending on where the stack happened to put the two).
struct alignas(64) Work {
  std::vector<double> residual, ambient, tangent;
  std::vector<double*> jacobians, tangents;
  std::vector<int> free;
  double total = 0;
};

class Lean {
 public:
  Lean(const Residuals& residuals, NormalPattern& pattern) : in_(residuals), s_(pattern) {
    ReadNormalPattern(residuals, &s_);
    size_t rows = 0, scratch = 0, parameters = 0;
    for (size_t i = 0; i < residuals.residuals().size(); ++i) {
      const Residuals::Residual& r = residuals.residuals()[i];
      const int m = Rows(i);
      rows = std::max<size_t>(rows, m);
      parameters = std::max<size_t>(parameters, r.end - r.first);
      size_t need = 0;
      for (int a = r.first; a < r.end; ++a) {
        if (block(a) >= 0) need += size_t(m) * ambient(a);
      }
      scratch = std::max(scratch, need);
    }
    s_.hessian.Resize(size_t(s_.slots));
    size_t plus = 0;
    for (PatternBlock& b : s_.blocks) {
      b.plus = b.manifold ? int(plus) : -1;
      if (b.manifold) plus += size_t(b.ambient) * b.tangent;
    }
    s_.plus_jacobians.resize(plus);
    // Each buffer with 16 spare entries (≥ 64 bytes) at its end, so that no
    // two threads' buffers share a cache line.
    constexpr size_t kSpare = 16;
    for (int t = 0; t < 2; ++t) {
      Work* w = t == 0 ? &work_ : &second_;
      w->residual.resize(rows + kSpare);
      w->ambient.resize(scratch + kSpare);
      w->tangent.resize(scratch + kSpare);
      w->jacobians.resize(parameters + kSpare);
      w->tangents.resize(parameters + kSpare);
      w->free.resize(parameters + kSpare);
    }
    // The product's halves: the first block row past half the off-diagonal slots.
    const int n = int(s_.blocks.size());
    split_ = int(std::lower_bound(s_.row_start.begin(), s_.row_start.end(), s_.row_start[n] / 2) -
                 s_.row_start.begin());
    split_ = std::min(split_, n);
  }

  // The free blocks' values, concatenated (to undo a rejected step).
  std::vector<double> Save() const {
    std::vector<double> x;
    for (const PatternBlock& b : s_.blocks) x.insert(x.end(), b.values, b.values + b.ambient);
    return x;
  }
  void Restore(const std::vector<double>& x) const {
    size_t at = 0;
    for (const PatternBlock& b : s_.blocks) {
      std::copy(x.begin() + long(at), x.begin() + long(at + b.ambient), b.values);
      at += b.ambient;
    }
  }
  // x ⊞ δ in place (manifold Plus per block).
  bool Step(const Vector& delta) {
    std::vector<double> moved;
    for (const PatternBlock& b : s_.blocks) {
      const double* d = delta.data() + b.offset;
      if (!b.manifold) {
        for (int k = 0; k < b.ambient; ++k) b.values[k] += d[k];
        continue;
      }
      moved.resize(b.ambient);
      if (!b.manifold->Plus(b.values, d, moved.data())) return false;
      std::copy(moved.begin(), moved.end(), b.values);
    }
    return true;
  }

  // ½ Σ ρ(‖r‖²) at the current values; false if a block fails to evaluate.
  // The two halves of the visiting order (each a part of the mesh with
  // every term), each summed on its own, then added: two threads where there
  // are, and the same sum on one.
  bool Cost(double* cost) {
    const size_t n = s_.visit.size();
    double sum[2] = {0, 0};
    bool good[2] = {true, true};
    ForHalves(n / 2, n, [&](int t, size_t first, size_t end) {
      double* scratch = (t == 0 ? work_ : second_).residual.data();
      double total = 0;
      for (size_t p = first; p < end; ++p) {
        const double c = in_.Cost(s_.visit[p], scratch);
        if (std::isnan(c)) {
          good[t] = false;
          return;
        }
        total += c;
      }
      sum[t] = total;
    });
    if (!good[0] || !good[1]) return false;
    *cost = sum[0] + sum[1];
    return std::isfinite(*cost);
  }

  // The cost, the gradient g = J^T r and H = J^T J (slots) at the current
  // values.
  bool Linearise(double* cost, Vector* gradient) {
    for (PatternBlock& b : s_.blocks) {
      if (!b.manifold) continue;
      if (!b.manifold->PlusJacobian(b.values, s_.plus_jacobians.data() + b.plus)) return false;
    }
    // H and g in one copy: the pattern's first two runs of residuals read
    // no block in common (two threads where there are, and the same sums on
    // one), then its third run.
    double* H = s_.hessian.data();
    ForHalves(s_.slots / 2, s_.slots, [&](int, size_t first, size_t end) {
      std::fill(H + first, H + end, 0.0);
    });
    gradient_.setZero(s_.tangent);
    bool good[2] = {true, true};
    work_.total = second_.total = 0;
    ForHalves(size_t(s_.split[0]), size_t(s_.split[1]), [&](int t, size_t first, size_t end) {
      Work& w = t == 0 ? work_ : second_;
      bool ok = true;  // written to good[t] once: the two share a cache line
      for (size_t p = first; p < end && ok; ++p) ok = Accumulate(s_.visit[p], &w);
      good[t] = ok;
    });
    if (!good[0] || !good[1]) return false;
    const double halves = work_.total + second_.total;
    work_.total = 0;
    for (size_t p = size_t(s_.split[1]); p < s_.visit.size() && good[0]; ++p) {
      good[0] = Accumulate(s_.visit[p], &work_);
    }
    if (!good[0]) return false;
    *gradient = gradient_;
    *cost = 0.5 * (halves + work_.total);
    return std::isfinite(*cost) && gradient->allFinite();
  }

  // y = (H + diag(damping)) x. One pass over the stored upper triangle, in
  // slot order: each off-diagonal slot H_ij adds H_ij x_j to y_i and
  // H_ijᵀ x_i to y_j, so H streams from memory once (the product is bound
  // by that traffic, not by arithmetic). Two fixed halves of the block rows
  // (by slots), each into its own y, then summed: two threads where there
  // are, and the same sums on one.
  void Multiply(const Vector& damping, const Vector& x, Vector* y) const {
    const int n = int(s_.blocks.size());
    const double* H = s_.hessian.data();
    spare_.resize(s_.tangent);
    ForHalves(size_t(split_), size_t(n), [&](int t, size_t first, size_t end) {
      double* out = t == 0 ? y->data() : spare_.data();
      if (t == 0) {
        y->noalias() = damping.cwiseProduct(x);
      } else {
        spare_.setZero();
      }
      for (size_t i = first; i < end; ++i) {
        const PatternBlock& bi = s_.blocks[i];
        double* yi = out + bi.offset;
        const double* xi = x.data() + bi.offset;
        AddProduct<false>(H + s_.diagonal[i], bi.tangent, bi.tangent, xi, yi);
        for (int k = s_.row_start[i]; k < s_.row_start[i + 1]; ++k) {
          const PatternBlock& bj = s_.blocks[s_.column[k]];
          AddProduct<false>(H + s_.slot[k], bi.tangent, bj.tangent, x.data() + bj.offset, yi);
          AddProduct<true>(H + s_.slot[k], bi.tangent, bj.tangent, xi, out + bj.offset);
        }
      }
    });
    ForHalves(size_t(s_.tangent) / 2, size_t(s_.tangent), [&](int, size_t first, size_t end) {
      y->segment(first, end - first) += spare_.segment(first, end - first);
    });
  }

  // The diagonal of H.
  Vector Diagonal() const {
    Vector d(s_.tangent);
    for (size_t i = 0; i < s_.blocks.size(); ++i) {
      const PatternBlock& b = s_.blocks[i];
      d.segment(b.offset, b.tangent) = Slot(s_.diagonal[i], b.tangent, b.tangent).diagonal();
    }
    return d;
  }

  // Solves (H + diag(damping)) δ = −g by block-Jacobi PCG, from δ = 0, for
  // at least `min_iterations` and at most `max_iterations` steps; returns the
  // steps taken. It stops as Ceres' conjugate gradients do inside its
  // Levenberg–Marquardt (Nash & Sofer 1990, "Assessing a search direction
  // within a truncated-Newton method"): at step k once
  // k (Q_k − Q_(k−1)) / Q_k < eta, Q the quadratic model δᵀAδ − 2bᵀδ
  // (A = H + diag(damping), b = −g), which each step lowers by α rᵀz. The
  // residual ‖b − Aδ‖, the test used before, keeps falling slowly long after
  // the model's decrease has stalled: on 100k-quad roofs the last steps of a
  // round took 76–185 CG steps each for a cost change of 1e-4.
  int Solve(const Vector& damping, const Vector& gradient, double eta, int min_iterations,
            int max_iterations, Vector* delta) const {
    // PatternBlock-Jacobi preconditioner: every block's (H_ii + D_i)⁻¹ (the identity
    // where that is not positive definite). Heap-allocated matrices for
    // every block (three each) cost 0.10–0.14 s of the 100k roof's 2.2 s of CG.
    const int blocks = int(s_.blocks.size());
    std::vector<double> inverse(s_.diagonal_slots);
#pragma omp parallel for schedule(static, 256)
    for (int i = 0; i < blocks; ++i) {
      const PatternBlock& b = s_.blocks[i];
      const double* H = s_.hessian.data() + s_.diagonal[i];
      const double* D = damping.data() + b.offset;
      double* out = inverse.data() + s_.diagonal[i];
      if (b.tangent <= kMax) {
        InvertDamped<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMax, kMax>>(
            H, D, out, b.tangent);
      } else {
        InvertDamped<Eigen::MatrixXd>(H, D, out, b.tangent);
      }
    }
    // The vector work of a step in three passes over the two fixed halves
    // of the blocks (two threads where there are, and the same sums on one),
    // fused so that each vector streams from memory once per pass.
    const int n = s_.tangent;
    const size_t half = size_t(blocks / 2);
    const auto offset = [&](size_t i) { return i < size_t(blocks) ? size_t(s_.blocks[i].offset) : size_t(n); };
    delta->setZero(n);
    Vector r = -gradient, z(n), p(n), q(n);
    // z = M⁻¹ r on blocks [first, end); returns their r·z (M⁻¹ is positive
    // definite: r·z > 0 unless r = 0).
    const auto precondition = [&](size_t first, size_t end) {
      std::array<double, 2> sum = {0, 0};
      for (size_t i = first; i < end; ++i) {
        const PatternBlock& b = s_.blocks[i];
        const double* ri = r.data() + b.offset;
        double* zi = z.data() + b.offset;
        std::fill(zi, zi + b.tangent, 0.0);
        AddProduct<false>(inverse.data() + s_.diagonal[i], b.tangent, b.tangent, ri, zi);
        for (int c = 0; c < b.tangent; ++c) sum[0] += ri[c] * zi[c];
      }
      return sum;
    };
    std::array<double, 2> sums = SumHalves(half, size_t(blocks), precondition);
    p = z;
    double rz = sums[0];
    double model = 0;  // Q at δ
    int k = 0;
    while (k < max_iterations && rz > 0) {
      Multiply(damping, p, &q);
      const double pq = SumHalves(half, size_t(blocks), [&](size_t first, size_t end) {
        const size_t a = offset(first), e = offset(end);
        return std::array<double, 2>{p.segment(a, e - a).dot(q.segment(a, e - a)), 0.0};
      })[0];
      if (!(pq > 0.0)) break;
      const double alpha = rz / pq;
      sums = SumHalves(half, size_t(blocks), [&](size_t first, size_t end) {
        const size_t a = offset(first), e = offset(end);
        delta->segment(a, e - a) += alpha * p.segment(a, e - a);
        r.segment(a, e - a) -= alpha * q.segment(a, e - a);
        return precondition(first, end);
      });
      ++k;
      const double next = model - alpha * rz;
      if (k >= min_iterations && k * (next - model) / next < eta) break;
      model = next;
      const double beta = sums[0] / rz;
      rz = sums[0];
      ForHalves(half, size_t(blocks), [&](int, size_t first, size_t end) {
        const size_t a = offset(first), e = offset(end);
        p.segment(a, e - a) = z.segment(a, e - a) + beta * p.segment(a, e - a);
      });
    }
    return k;
  }

  // ½ δᵀ H δ + gᵀ δ (the model's change).
  double ModelChange(const Vector& gradient, const Vector& delta) const {
    Vector Hd(s_.tangent);
    Multiply(Vector::Zero(s_.tangent), delta, &Hd);
    return gradient.dot(delta) + 0.5 * delta.dot(Hd);
  }

  double ParameterNorm() const {
    double sq = 0;
    for (const PatternBlock& b : s_.blocks) {
      sq += Eigen::Map<const Vector>(b.values, b.ambient).squaredNorm();
    }
    return std::sqrt(sq);
  }

 private:
  // The free block of residual parameter `parameter` (-1: constant).
  int block(int parameter) const { return s_.free[size_t(in_.block_of()[size_t(parameter)])]; }
  int ambient(int parameter) const { return s_.blocks[size_t(block(parameter))].ambient; }
  // One residual block into the sums: ρ, its corrected tangent Jacobians,
  // g += J̃ᵀ r̃ and every J̃_aᵀ J̃_b into its slot.
  bool Accumulate(size_t index, Work* k) {
    const Residuals::Residual& in = in_.residuals()[index];
    const ceres::LossFunction* loss = in_.Loss(in.loss());
    const int rows = in.rows();
    const int m = in.end - in.first;
    double** jacobians = k->jacobians.data();
    double** tangents = k->tangents.data();
    int* free = k->free.data();  // its parameters' free blocks (-1: constant)
    size_t used = 0;
    for (int a = 0; a < m; ++a) {
      free[a] = block(in.first + a);
      jacobians[a] = tangents[a] = nullptr;
      if (free[a] < 0) continue;
      jacobians[a] = k->ambient.data() + used;
      tangents[a] = k->tangent.data() + used;
      used += size_t(rows) * s_.blocks[size_t(free[a])].ambient;
    }
    if (!in.Evaluate(in_.values() + in.first, k->residual.data(), jacobians)) return false;
    Eigen::Map<Vector> res(k->residual.data(), rows);
    const double sq = res.squaredNorm();
    double rho[3] = {sq, 1.0, 0.0};
    if (loss) loss->Evaluate(sq, rho);
    k->total += rho[0];
    if (sq == 0.0 && AllZero(jacobians, free, m, rows)) return true;  // e.g. an idle barrier
    const Corrector corrector(sq, rho);
    // Tangent Jacobians, corrected: J̃ = √ρ' (J − α/‖r‖² r rᵀ J).
    for (int a = 0; a < m; ++a) {
      const int i = free[a];
      if (i < 0) continue;
      const PatternBlock& b = s_.blocks[i];
      if (b.manifold) {
        TangentProduct(jacobians[a], s_.plus_jacobians.data() + b.plus, rows, b.ambient,
                       b.tangent, tangents[a]);
      } else {
        tangents[a] = jacobians[a];  // tangent = ambient: in place
      }
      double* T = tangents[a];
      const int t = b.tangent;
      if (corrector.alpha_sq_norm != 0.0) {
        for (int c = 0; c < t; ++c) {
          double dot = 0;
          for (int r = 0; r < rows; ++r) dot += res[r] * T[r * t + c];
          for (int r = 0; r < rows; ++r) T[r * t + c] -= corrector.alpha_sq_norm * res[r] * dot;
        }
      }
      if (corrector.sqrt_rho1 != 1.0) {
        for (int e = 0; e < rows * t; ++e) T[e] *= corrector.sqrt_rho1;
      }
    }
    if (corrector.residual_scaling != 1.0) res *= corrector.residual_scaling;
    double* H = s_.hessian.data();
    double* g = gradient_.data();
    int pair = s_.pairs[index];
    for (int a = 0; a < m; ++a) {
      const int i = free[a];
      if (i < 0) continue;
      const PatternBlock& bi = s_.blocks[i];
      AddTransposeProduct(tangents[a], res.data(), rows, bi.tangent, 1,
                          g + bi.offset);
      AddTransposeProduct(tangents[a], tangents[a], rows, bi.tangent, bi.tangent,
                          H + s_.diagonal[i]);
      for (int c = a + 1; c < m; ++c) {
        const int j = free[c];
        if (j < 0 || j == i) continue;
        const PatternBlock& bj = s_.blocks[j];
        if (i < j) {
          AddTransposeProduct(tangents[a], tangents[c], rows, bi.tangent, bj.tangent,
                              H + s_.pair_slot[pair]);
        } else {
          AddTransposeProduct(tangents[c], tangents[a], rows, bj.tangent, bi.tangent,
                              H + s_.pair_slot[pair]);
        }
        ++pair;
      }
    }
    return true;
  }

  // Whether every Jacobian of a residual whose parameters are in the free
  // blocks `free` is zero: it adds nothing to g or H.
  bool AllZero(double* const* jacobians, const int* free, int m, int rows) const {
    for (int a = 0; a < m; ++a) {
      if (!jacobians[a]) continue;
      const double* J = jacobians[a];
      for (int e = 0, n = rows * s_.blocks[size_t(free[a])].ambient; e < n; ++e) {
        if (J[e] != 0.0) return false;
      }
    }
    return true;
  }
  int Rows(size_t i) const { return in_.residuals()[i].rows(); }
  Eigen::Map<const RowMatrix> Slot(int offset, int rows, int cols) const {
    return Eigen::Map<const RowMatrix>(s_.hessian.data() + offset, rows, cols);
  }

  const Residuals& in_;
  NormalPattern& s_;
  Work work_, second_;
  Vector gradient_;  // g = J^T r
  int split_ = 0;
  mutable Vector spare_;  // the product's second half
};

}  // namespace

SolveSummary LeanSolve(const ceres::Solver::Options& options, const Residuals& residuals,
                       NormalPattern* pattern) {
  const FullTeams teams;  // no CHOLMOD here
  const auto start = Clock::now();
  SolveSummary out;
  out.pcg = true;
  NormalPattern own;
  Lean lean(residuals, pattern ? *pattern : own);
  double cost = 0;
  Vector gradient;
  auto t = Clock::now();
  if (!lean.Linearise(&cost, &gradient)) {
    out.usable = false;
    out.message = "a residual block failed to evaluate at the start";
    return out;
  }
  out.jacobian_seconds += Since(t);
  out.initial_cost = out.final_cost = cost;
  double radius = options.initial_trust_region_radius, decrease_factor = 2.0;
  double last_change = 0;  // the cost change of the last accepted step
  Vector delta;
  auto report = [&](int iteration, double step_norm, bool success, double change) {
    ceres::IterationSummary it;
    it.iteration = iteration;
    it.cost = cost;
    it.cost_change = change;
    it.gradient_max_norm = gradient.lpNorm<Eigen::Infinity>();
    it.gradient_norm = gradient.norm();
    it.step_norm = step_norm;
    it.step_is_valid = it.step_is_successful = success;
    it.trust_region_radius = radius;
    it.cumulative_time_in_seconds = Since(start);
    for (ceres::IterationCallback* callback : options.callbacks) {
      const ceres::CallbackReturnType r = (*callback)(it);
      if (r == ceres::SOLVER_TERMINATE_SUCCESSFULLY) {
        out.terminated_by_callback = true;
        return true;
      }
      if (r == ceres::SOLVER_ABORT) {
        out.usable = false;
        out.message = "a callback aborted the solve";
        return true;
      }
    }
    return false;
  };
  if (report(0, 0.0, true, 0.0)) {
    out.seconds = Since(start);
    return out;
  }
  if (gradient.lpNorm<Eigen::Infinity>() <= options.gradient_tolerance) {
    out.seconds = Since(start);
    return out;
  }
  for (int iteration = 1; iteration <= options.max_num_iterations; ++iteration) {
    if (Since(start) >= options.max_solver_time_in_seconds) break;
    out.iterations = iteration;
    t = Clock::now();
    const Vector diagonal = lean.Diagonal().cwiseMax(options.min_lm_diagonal).cwiseMin(
        options.max_lm_diagonal);
    const Vector damping = diagonal / radius;
    out.cg_iterations += lean.Solve(damping, gradient, options.eta,
                                    options.min_linear_solver_iterations,
                                    options.max_linear_solver_iterations, &delta);
    const double model_change = lean.ModelChange(gradient, delta);
    out.linear_solver_seconds += Since(t);
    const std::vector<double> before = lean.Save();
    const double x_norm = lean.ParameterNorm();
    double new_cost = 0;
    t = Clock::now();
    const bool valid = model_change < 0.0 && lean.Step(delta) && lean.Cost(&new_cost);
    out.residual_seconds += Since(t);
    const double rho = valid ? (cost - new_cost) / -model_change : -1.0;
    const bool small_step =
        delta.norm() <= options.parameter_tolerance * (x_norm + options.parameter_tolerance);
    if (valid && rho > options.min_relative_decrease) {
      const double change = cost - new_cost;
      cost = new_cost;
      radius = std::min(options.max_trust_region_radius,
                        radius / std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3)));
      decrease_factor = 2.0;
      // A step that ends the solve is not linearised again. It ends where
      // its change, or the next one extrapolated from the last two (Δ_k² /
      // Δ_(k−1): the changes falling geometrically), is below the function
      // tolerance: the iteration that would only confirm it is not taken.
      const double next_change = last_change > 0 ? change * change / last_change : change;
      bool ends = change <= options.function_tolerance * (cost + change) ||
                  next_change <= options.function_tolerance * cost || small_step;
      last_change = change;
      for (ceres::IterationCallback* callback : options.callbacks) {
        auto* ending = dynamic_cast<EndingCallback*>(callback);
        ends = ends || (ending && ending->Ends());
      }
      if (ends) {
        gradient.setConstant(std::numeric_limits<double>::quiet_NaN());
        report(iteration, delta.norm(), true, change);
        break;
      }
      t = Clock::now();
      if (!lean.Linearise(&cost, &gradient)) {
        out.usable = false;
        out.message = "a residual block failed to evaluate";
        break;
      }
      out.jacobian_seconds += Since(t);
      if (report(iteration, delta.norm(), true, change)) break;
      if (gradient.lpNorm<Eigen::Infinity>() <= options.gradient_tolerance) break;
    } else {
      lean.Restore(before);
      radius /= decrease_factor;
      decrease_factor *= 2.0;
      if (report(iteration, delta.norm(), false, 0.0)) break;
      if (radius < options.min_trust_region_radius) break;
      if (small_step) break;
    }
  }
  out.final_cost = cost;
  out.seconds = Since(start);
  return out;
}

SolveSummary SolveRound(const ceres::Solver::Options& options, int pcg_above,
                        double pcg_function_tolerance, const Residuals& residuals,
                        NormalPattern* pattern) {
  if (pcg_above > 0 && residuals.FreeTangentSize() > pcg_above) {
    ceres::Solver::Options lean = options;
    lean.function_tolerance = std::max(options.function_tolerance, pcg_function_tolerance);
    return LeanSolve(lean, residuals, pattern);
  }
  const std::unique_ptr<ceres::Problem> problem = residuals.MakeProblem();
  ceres::Solver::Summary summary;
  ceres::Solve(options, problem.get(), &summary);
  SolveSummary out;
  out.iterations = std::max(0, int(summary.iterations.size()) - 1);
  out.seconds = std::max(0.0, summary.total_time_in_seconds);
  out.linear_solver_seconds = std::max(0.0, summary.linear_solver_time_in_seconds);
  out.jacobian_seconds = std::max(0.0, summary.jacobian_evaluation_time_in_seconds);
  out.residual_seconds = std::max(0.0, summary.residual_evaluation_time_in_seconds);
  out.initial_cost = summary.initial_cost;
  out.final_cost = summary.final_cost;
  out.usable = summary.IsSolutionUsable();
  if (!out.usable) out.message = summary.message;
  out.terminated_by_callback = summary.termination_type == ceres::USER_SUCCESS;
  return out;
}

}  // namespace archgeo
