// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the block pattern of a round's normal equations J^T J,
// as core/lean_solve.h assembles them: the free parameter blocks (with their
// manifolds), the residual blocks (cost, loss, the blocks they read), and one
// dense tangent × tangent slot per diagonal block and per pair of free blocks
// that a residual reads together (upper triangle; a row's slots lie together).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/residuals.h"

namespace archgeo {

struct PatternBlock {
  double* values = nullptr;
  int ambient = 0, tangent = 0;
  int offset = 0;  // into the tangent vector
  int plus = -1;  // with a manifold: its Plus Jacobian at NormalPattern::plus_jacobians[plus]
  const ceres::Manifold* manifold = nullptr;  // nullptr: Euclidean
};

// The residuals are visited a chunk of this many blocks at a time (by their
// first free block), in their own order (term by term) within a chunk: the
// chunk's slots of H stay in cache while each term adds to them, and each
// term's code runs over many residuals at once.
constexpr int kVisitChunk = 1024;

// The structure of a round's residuals as the PCG solver reads it (their
// costs, losses and the blocks they read stay in the Residuals), and the
// block pattern of J^T J.
class NormalCholesky;

struct NormalPattern {
  std::vector<PatternBlock> blocks;  // free blocks
  std::vector<int> free;             // per Residuals block: its free block, or -1 (constant)
  std::vector<int> pairs;            // per residual: its first slot in pair_slot
  std::vector<int> pair_slot;        // per residual, per free pair (a < b): slot offset
  std::vector<int> diagonal;         // per block: its diagonal slot offset
  // The off-diagonal slots of each block row i: H_ij for j > i, stored
  // row × column, in slot order.
  std::vector<int> row_start, column, slot;
  int tangent = 0, slots = 0;
  int diagonal_slots = 0;  // the diagonal slots come first: [0, diagonal_slots)
  std::vector<const double*> constant;  // the constant blocks the residuals read
  // A 64-bit hash of which blocks each residual reads (Residuals::block_of
  // and every residual's first parameter): the structure a later round's
  // residuals must have for ReadNormalPattern to reuse this one.
  uint64_t structure = 0;
  // The order the solver visits the residuals in to assemble H and g, in
  // `threads` + 1 runs. The residuals are cut into `threads` ranges by their
  // first free block (about as many residuals in each); run t < threads
  // holds the residuals of range t that read only blocks no other range's
  // residuals read, so the runs write disjoint parts of H and g, one thread
  // each, without a second copy; the last run holds the residuals that
  // straddle two ranges and goes after them, in its fixed order. Run t is
  // visit[RunStart(t), run_end[t]). Each run visits a chunk of kVisitChunk
  // blocks at a time (by the residuals' first free block), term by term
  // within it.
  std::vector<int> visit;
  int threads = 0;
  std::vector<int> run_end;  // threads + 1 entries
  int RunStart(int t) const { return t == 0 ? 0 : run_end[size_t(t) - 1]; }
  // H, kept with the pattern, so that a round of the same structure reuses
  // the pages instead of faulting in 8·slots fresh bytes (mapped, so that
  // the first linearisation's zeroing, on every thread, faults them in, not
  // a serial value-initialisation before it).
  MappedList<double> hessian;
  // The manifold blocks' Plus Jacobians (ambient × tangent, row-major) at the
  // current values.
  std::vector<double> plus_jacobians;
  // The sparse Cholesky factorisation's analysis of H (core/normal_cholesky.h),
  // made by the first direct step on this structure and kept with it.
  std::shared_ptr<NormalCholesky> cholesky;
};

// Reads `residuals` into `pattern` (constant blocks stay out of the
// pattern), with the visiting order for `threads` ≥ 1 threads (at most
// 256). When `pattern` holds the pattern of residuals of the same structure — the same number of residual blocks, reading the same parameter
// blocks (by hash, NormalPattern::structure), the same blocks free and
// constant in the same order, of the same sizes — only the manifolds are read
// anew (and the visiting order, if for another number of threads); the loop
// builds its residuals every round with that structure. Returns whether it
// was reused. The slots' layout does not depend on `threads`.
bool ReadNormalPattern(const Residuals& residuals, int threads, NormalPattern* pattern);

}  // namespace archgeo
