// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/normal_cholesky.h"

#include <algorithm>
#include <utility>
#include <vector>

#include <omp.h>
#include <suitesparse/cholmod.h>

#include "core/normal_equations.h"

namespace archgeo {

struct NormalCholesky::Impl {
  cholmod_common common;
  cholmod_sparse* matrix = nullptr;  // upper triangle, CSC, sorted
  cholmod_factor* factor = nullptr;
  cholmod_dense* rhs = nullptr;
  std::vector<int> source;    // per stored scalar: its entry in the pattern's hessian
  std::vector<int> diagonal;  // per tangent coordinate: its stored diagonal scalar
};

namespace {

// CHOLMOD's OpenMP teams adapt to the cores (core/solver_options.h,
// ConfigureThreading) also inside LeanSolve's FullTeams scope.
class DynamicTeams {
 public:
  DynamicTeams() : previous_(omp_get_dynamic()) { omp_set_dynamic(1); }
  ~DynamicTeams() { omp_set_dynamic(previous_); }

 private:
  int previous_;
};

}  // namespace

NormalCholesky::NormalCholesky(const NormalPattern& p, CholeskyOrdering ordering)
    : impl_(std::make_unique<Impl>()), ordering_(ordering), used_(ordering) {
  Impl& m = *impl_;
  const int blocks = int(p.blocks.size());
  // The off-diagonal slots by block column: (row block, slot) with row < column.
  std::vector<std::vector<std::pair<int, int>>> above(static_cast<size_t>(blocks));
  for (int i = 0; i < blocks; ++i) {
    for (int k = p.row_start[size_t(i)]; k < p.row_start[size_t(i) + 1]; ++k) {
      above[size_t(p.column[size_t(k)])].emplace_back(i, p.slot[size_t(k)]);
    }
  }
  std::vector<int> column_start{0}, rows;
  m.diagonal.resize(size_t(p.tangent));
  for (int j = 0; j < blocks; ++j) {
    std::sort(above[size_t(j)].begin(), above[size_t(j)].end());
    const PatternBlock& bj = p.blocks[size_t(j)];
    for (int c = 0; c < bj.tangent; ++c) {
      for (const auto& [i, slot] : above[size_t(j)]) {
        const PatternBlock& bi = p.blocks[size_t(i)];
        for (int r = 0; r < bi.tangent; ++r) {
          rows.push_back(bi.offset + r);
          m.source.push_back(slot + r * bj.tangent + c);
        }
      }
      for (int r = 0; r <= c; ++r) {
        rows.push_back(bj.offset + r);
        m.source.push_back(p.diagonal[size_t(j)] + r * bj.tangent + c);
      }
      m.diagonal[size_t(bj.offset + c)] = int(rows.size()) - 1;
      column_start.push_back(int(rows.size()));
    }
  }
  cholmod_start(&m.common);
  m.common.supernodal = CHOLMOD_SUPERNODAL;
  m.common.quick_return_if_not_posdef = 1;
  // Supernodes amalgamated more than CHOLMOD's defaults (nrelax 4/16/48,
  // zrelax 0.8/0.1/0.05): fewer and larger dense blocks, at the price of
  // some explicit zeros in the factor. Each supernode costs CHOLMOD's
  // numeric factorisation a few OpenMP regions, and each region a team
  // barrier with a system call, more than the arithmetic of a small
  // supernode; larger ones also give the BLAS larger products. The
  // figures that chose these values: docs/performance.md, "The factor's
  // supernodes".
  m.common.nrelax[0] = 24;
  m.common.nrelax[1] = 96;
  m.common.nrelax[2] = 192;
  m.common.zrelax[0] = 0.9;
  m.common.zrelax[1] = 0.3;
  m.common.zrelax[2] = 0.15;
  m.common.print = 0;  // a matrix that is not positive definite is the caller's to handle
  if (ordering == CholeskyOrdering::kMetis) {
    m.common.nmethods = 1;
    m.common.method[0].ordering = CHOLMOD_METIS;
  }
  const size_t n = size_t(p.tangent);
  m.matrix = cholmod_allocate_sparse(n, n, rows.size(), /*sorted=*/1, /*packed=*/1,
                                     /*stype=*/1, CHOLMOD_REAL, &m.common);
  std::copy(column_start.begin(), column_start.end(), static_cast<int*>(m.matrix->p));
  std::copy(rows.begin(), rows.end(), static_cast<int*>(m.matrix->i));
  m.rhs = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, &m.common);
  const DynamicTeams teams;
  m.factor = cholmod_analyze(m.matrix, &m.common);
  if (!m.factor && ordering == CholeskyOrdering::kMetis) {
    m.common.nmethods = 0;  // CHOLMOD's default: AMD
    used_ = CholeskyOrdering::kAmd;
    m.factor = cholmod_analyze(m.matrix, &m.common);
  }
}

double NormalCholesky::FactorFlops() const { return impl_->common.fl; }

double NormalCholesky::FactorNonzeros() const { return impl_->common.lnz; }

NormalCholesky::~NormalCholesky() {
  Impl& m = *impl_;
  cholmod_free_factor(&m.factor, &m.common);
  cholmod_free_dense(&m.rhs, &m.common);
  cholmod_free_sparse(&m.matrix, &m.common);
  cholmod_finish(&m.common);
}

bool NormalCholesky::Solve(const NormalPattern& p, const Eigen::VectorXd& damping,
                           const Eigen::VectorXd& gradient, Eigen::VectorXd* delta) {
  Impl& m = *impl_;
  if (!m.factor) return false;
  double* x = static_cast<double*>(m.matrix->x);
  const double* h = p.hessian.data();
  for (size_t k = 0; k < m.source.size(); ++k) x[k] = h[m.source[k]];
  for (size_t c = 0; c < m.diagonal.size(); ++c) x[m.diagonal[c]] += damping[long(c)];
  const DynamicTeams teams;
  if (!cholmod_factorize(m.matrix, m.factor, &m.common) ||
      m.common.status != CHOLMOD_OK) {
    return false;
  }
  double* b = static_cast<double*>(m.rhs->x);
  for (long k = 0; k < gradient.size(); ++k) b[k] = -gradient[k];
  cholmod_dense* solution = cholmod_solve(CHOLMOD_A, m.factor, m.rhs, &m.common);
  if (!solution) return false;
  delta->resize(gradient.size());
  std::copy_n(static_cast<const double*>(solution->x), gradient.size(), delta->data());
  cholmod_free_dense(&solution, &m.common);
  return true;
}

}  // namespace archgeo
