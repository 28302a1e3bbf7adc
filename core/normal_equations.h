// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the block pattern of a round's normal equations J^T J,
// as core/lean_solve.h assembles them: the free parameter blocks (with their
// manifolds), the residual blocks (cost, loss, the blocks they read), and one
// dense tangent × tangent slot per diagonal block and per pair of free blocks
// that a residual reads together (upper triangle; a row's slots lie together).
#pragma once

#include <cstdint>
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
// term's code runs over many residuals at once. 100k quads: with the
// fixed-size products of core/lean_solve.cpp, a linearisation 12–25% faster
// than term by term over the whole mesh (either change alone ≤ 5%; chunks
// of 512 to 4,096 blocks alike); residual by residual in block order it was
// 40–60% slower.
constexpr int kVisitChunk = 1024;

// The structure of a round's residuals as the PCG solver reads it (their
// costs, losses and the blocks they read stay in the Residuals), and the
// block pattern of J^T J.
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
  // three runs: visit[0, split[0]) and visit[split[0], split[1]) read no free
  // block in common, so two threads write H and g at once without a second
  // copy; visit[split[1], end) reads blocks of both and goes after them.
  // Each run visits a chunk of kVisitChunk blocks at a time (by the
  // residuals' first free block), term by term within it.
  std::vector<int> visit;
  int split[2] = {0, 0};
  // H, kept with the pattern, so that a round of the same structure reuses
  // the pages instead of faulting in 8·slots fresh bytes (920 MB at 1M
  // quads; mapped, so that the first linearisation's zeroing on two threads
  // faults them in, not a serial value-initialisation before it).
  MappedList<double> hessian;
  // The manifold blocks' Plus Jacobians (ambient × tangent, row-major) at the
  // current values.
  std::vector<double> plus_jacobians;
};

// Reads `residuals` into `pattern` (constant blocks stay out of the
// pattern). When `pattern` holds the pattern of residuals of the same
// structure — the same number of residual blocks, reading the same parameter
// blocks (by hash, NormalPattern::structure), the same blocks free and
// constant in the same order, of the same sizes — only the manifolds are read
// anew; the loop builds its residuals every round with that structure.
// Returns whether it was reused.
bool ReadNormalPattern(const Residuals& residuals, NormalPattern* pattern);

}  // namespace archgeo
