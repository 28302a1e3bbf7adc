// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/normal_equations.h"

#include <algorithm>
#include <utility>

#include <ceres/manifold.h>

#include "core/halves.h"

namespace archgeo {

namespace {

int TangentSize(const Residuals::Block& b) {
  return b.manifold ? b.manifold->TangentSize() : b.size;
}

// NormalPattern::structure: the residuals' count and ends and every
// parameter's block, hashed in four interleaved lanes (multiply, xor-shift;
// one chain would wait on each multiply) and mixed by splitmix64's finaliser.
uint64_t Mix(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
uint64_t Structure(const Residuals& in) {
  uint64_t lane[4] = {1, 2, 3, 4};
  const auto add = [&](int k, uint64_t x) {
    lane[k] = (lane[k] ^ x) * 0x9E3779B97F4A7C15ull;
    lane[k] ^= lane[k] >> 29;
  };
  const MappedList<Residuals::Residual>& residuals = in.residuals();
  for (size_t k = 0; k < residuals.size(); ++k) add(int(k & 3), uint64_t(residuals[k].end));
  const MappedList<int>& block_of = in.block_of();
  for (size_t a = 0; a < block_of.size(); ++a) add(int(a & 3), uint64_t(uint32_t(block_of[a])));
  uint64_t h = Mix(residuals.size());
  for (uint64_t x : lane) h = Mix(h ^ x);
  return h;
}

// Renews `s`'s manifolds from `in` if the structure is `s`'s; false (and
// `s` partly renewed) if not.
bool Renew(const Residuals& in, NormalPattern& s) {
  if (in.residuals().size() != s.pairs.size() || in.blocks().size() != s.free.size()) return false;
  // The free blocks in order, and the constant ones, as before...
  size_t constant = 0;
  for (size_t k = 0; k < in.blocks().size(); ++k) {
    const Residuals::Block& b = in.blocks()[k];
    if (b.constant != (s.free[k] < 0)) return false;
    if (b.constant) {
      if (s.constant[constant++] != b.values) return false;
      continue;
    }
    PatternBlock& p = s.blocks[size_t(s.free[k])];
    if (p.values != b.values || p.ambient != b.size || p.tangent != TangentSize(b)) return false;
    p.manifold = b.manifold;
  }
  // ...and every residual reading the same blocks.
  return Structure(in) == s.structure;
}

// The residuals' visiting order and its runs (NormalPattern::visit): cut
// by their first free block at the block below which half of them start
// (the blocks are numbered by first use, so the cut runs across the mesh);
// a residual reading a block that residuals of both sides read goes to the
// run after them. Each run goes chunk by chunk of the mesh, and keeps the
// residuals' order (term by term) within a chunk.
void Partition(const Residuals& in, NormalPattern& s) {
  const int n = int(in.residuals().size());
  const int blocks = int(s.blocks.size());
  const auto each_block = [&](int k, auto&& f) {
    const Residuals::Residual& r = in.residuals()[size_t(k)];
    for (int a = r.first; a < r.end; ++a) {
      const int b = s.free[size_t(in.block_of()[size_t(a)])];
      if (b >= 0) f(b);
    }
  };
  // The first free block of each residual, and the block below which half
  // of them start.
  std::vector<int> key(n, 0), count(blocks + 1, 0);
  for (int k = 0; k < n; ++k) {
    int first = blocks;
    each_block(k, [&](int b) { first = std::min(first, b); });
    key[k] = first;
    ++count[first];
  }
  int cut = 0;
  for (int below = 0; cut < blocks && 2 * (below + count[cut]) <= n; ++cut) below += count[cut];
  // Which half reads each block: bit 1 the first, bit 2 the second.
  std::vector<unsigned char> read_by(blocks, 0);
  for (int k = 0; k < n; ++k) {
    each_block(k, [&](int b) { read_by[b] |= key[k] < cut ? 1 : 2; });
  }
  // Runs: the first half's residuals that read no block of both halves, the
  // second half's, then those that do, each in the residuals' order.
  std::vector<unsigned char> run(n);
  for (int k = 0; k < n; ++k) {
    bool shared = false;
    each_block(k, [&](int b) { shared = shared || read_by[b] == 3; });
    run[k] = shared ? 2 : key[k] < cut ? 0 : 1;
  }
  // Within a run, chunk by chunk (kVisitChunk), each in the residuals' order.
  const int chunks = blocks / kVisitChunk + 1;
  std::vector<int> start(size_t(3 * chunks) + 1, 0);
  const auto bucket = [&](int k) { return run[k] * chunks + key[k] / kVisitChunk; };
  for (int k = 0; k < n; ++k) ++start[size_t(bucket(k)) + 1];
  for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  s.visit.assign(n, 0);
  for (int k = 0; k < n; ++k) s.visit[size_t(start[size_t(bucket(k))]++)] = k;
  s.split[0] = start[size_t(chunks) - 1];
  s.split[1] = start[size_t(2 * chunks) - 1];
}

}  // namespace

bool ReadNormalPattern(const Residuals& in, NormalPattern* pattern) {
  if (!pattern->pairs.empty() && Renew(in, *pattern)) return true;
  *pattern = NormalPattern();
  NormalPattern& s = *pattern;
  // Free blocks in order of first use (as Residuals keeps them); -1: constant.
  s.free.assign(in.blocks().size(), -1);
  s.blocks.reserve(in.blocks().size());
  for (size_t k = 0; k < in.blocks().size(); ++k) {
    const Residuals::Block& b = in.blocks()[k];
    if (b.constant) {
      s.constant.push_back(b.values);
      continue;
    }
    s.free[k] = int(s.blocks.size());
    PatternBlock block;
    block.values = b.values;
    block.ambient = b.size;
    block.tangent = TangentSize(b);
    block.manifold = b.manifold;
    block.offset = s.tangent;
    s.tangent += block.tangent;
    s.blocks.push_back(std::move(block));
  }
  s.structure = Structure(in);
  const MappedList<Residuals::Residual>& residuals = in.residuals();
  const auto block = [&](int a) { return s.free[size_t(in.block_of()[size_t(a)])]; };
  // Slots: the diagonal, then block row by block row its upper pairs (so a
  // row's slots lie together for the product).
  const int n = int(s.blocks.size());
  s.diagonal.resize(n);
  for (int b = 0; b < n; ++b) {
    s.diagonal[b] = s.slots;
    s.slots += s.blocks[b].tangent * s.blocks[b].tangent;
  }
  s.diagonal_slots = s.slots;
  // Free pairs per residual (the order Linearise walks them), numbered, and
  // each under its lower block: (upper block, pair number) in the order
  // Linearise walks them, so a row's columns come in order of first use.
  // Two halves of the residuals, one per thread where there are two: the
  // second's pairs go after the first's, under each block.
  const size_t middle = residuals.size() / 2;
  // start(k) for each residual k in [from, to), then f(p, q) for each of its
  // free pairs.
  const auto each_pair = [&](size_t from, size_t to, auto&& start, auto&& f) {
    for (size_t k = from; k < to; ++k) {
      start(k);
      const Residuals::Residual& r = residuals[k];
      for (int a = r.first; a < r.end; ++a) {
        const int p = block(a);
        if (p < 0) continue;
        for (int b = a + 1; b < r.end; ++b) {
          const int q = block(b);
          if (q >= 0 && p != q) f(p, q);
        }
      }
    }
  };
  s.pairs.resize(residuals.size());
  std::vector<int> count[2] = {std::vector<int>(n + 1, 0), std::vector<int>(n + 1, 0)};
  int half_pairs[2] = {0, 0};
  ForHalves(middle, residuals.size(), [&](int t, size_t from, size_t to) {
    int pairs = 0;
    std::vector<int>& c = count[t];
    each_pair(from, to, [](size_t) {}, [&](int p, int q) {
      ++c[std::min(p, q)];
      ++pairs;
    });
    half_pairs[t] = pairs;
  });
  const int pair_count = half_pairs[0] + half_pairs[1];
  std::vector<int> lower_start(n + 1, 0);
  for (int b = 0; b < n; ++b) {
    const int first = count[0][b], second = count[1][b];
    count[0][b] = lower_start[b];          // where the first half's pairs under b go
    count[1][b] = lower_start[b] + first;  // and the second's
    lower_start[b + 1] = lower_start[b] + first + second;
  }
  std::vector<std::pair<int, int>> upper(static_cast<size_t>(pair_count));  // (upper, pair)
  ForHalves(middle, residuals.size(), [&](int t, size_t from, size_t to) {
    std::vector<int>& fill = count[t];
    int at = t == 0 ? 0 : half_pairs[0];
    each_pair(from, to, [&](size_t k) { s.pairs[k] = at; }, [&](int p, int q) {
      upper[size_t(fill[std::min(p, q)]++)] = {std::max(p, q), at++};
    });
  });
  // Slots, row by row: a row's distinct upper blocks, in order of first use.
  // The rows in two halves (by pairs), one per thread where there are two;
  // the second half's slots and columns are numbered from 0, then moved past
  // the first's.
  s.pair_slot.assign(size_t(pair_count), -1);
  const int half = int(std::upper_bound(lower_start.begin(), lower_start.end(), pair_count / 2) -
                       lower_start.begin()) - 1;
  struct Rows {
    int from, to, slots;
    std::vector<int> row_start, column, slot;
  } rows[2] = {{0, std::max(half, 0), s.slots, {}, {}, {}},
               {std::max(half, 0), n, 0, {}, {}, {}}};
  const auto lay_out = [&](Rows& part) {
    std::vector<int> mark(n, -1), position(n, 0);
    for (int i = part.from; i < part.to; ++i) {
      for (int e = lower_start[i]; e < lower_start[i + 1]; ++e) {
        const auto [j, at] = upper[size_t(e)];
        if (mark[j] != i) {
          mark[j] = i;
          position[j] = part.slots;
          part.column.push_back(j);
          part.slot.push_back(part.slots);
          part.slots += s.blocks[i].tangent * s.blocks[j].tangent;
        }
        s.pair_slot[size_t(at)] = position[j];
      }
      part.row_start.push_back(int(part.column.size()));
    }
  };
  ForHalves(0, 0, [&](int t, size_t, size_t) { lay_out(rows[t]); });
  const int moved = rows[0].slots;
  for (int i = rows[1].from; i < rows[1].to; ++i) {
    for (int e = lower_start[i]; e < lower_start[i + 1]; ++e) {
      s.pair_slot[size_t(upper[size_t(e)].second)] += moved;
    }
  }
  s.slots = rows[0].slots + rows[1].slots;
  s.row_start.assign(1, 0);
  s.row_start.insert(s.row_start.end(), rows[0].row_start.begin(), rows[0].row_start.end());
  const int columns = int(rows[0].column.size());
  for (int r : rows[1].row_start) s.row_start.push_back(columns + r);
  s.column = std::move(rows[0].column);
  s.column.insert(s.column.end(), rows[1].column.begin(), rows[1].column.end());
  s.slot = std::move(rows[0].slot);
  for (int slot : rows[1].slot) s.slot.push_back(slot + moved);
  s.column.shrink_to_fit();
  s.slot.shrink_to_fit();
  Partition(in, s);
  return false;
}

}  // namespace archgeo
