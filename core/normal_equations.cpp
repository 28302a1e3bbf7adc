// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/normal_equations.h"

#include <algorithm>
#include <utility>

#include <ceres/manifold.h>

#include "core/parallel_parts.h"

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

// The residuals' visiting order and its runs for `threads` threads
// (NormalPattern::visit): the residuals cut into `threads` ranges by their
// first free block, at the blocks below which 1/T, 2/T, … of them start (the
// blocks are numbered by first use, so each cut runs across the mesh); a
// residual reading a block that residuals of two ranges read goes to the
// last run, after them. Each run goes chunk by chunk of the mesh, and keeps
// the residuals' order (term by term) within a chunk.
void Partition(const Residuals& in, int threads, NormalPattern& s) {
  const int n = int(in.residuals().size());
  const int blocks = int(s.blocks.size());
  const auto each_block = [&](int k, auto&& f) {
    const Residuals::Residual& r = in.residuals()[size_t(k)];
    for (int a = r.first; a < r.end; ++a) {
      const int b = s.free[size_t(in.block_of()[size_t(a)])];
      if (b >= 0) f(b);
    }
  };
  // The first free block of each residual (`blocks`: none), and the cuts:
  // cut[t] the first block of range t, below which at most t/T of the
  // residuals start.
  std::vector<int> key(n, 0), count(blocks + 1, 0);
  for (int k = 0; k < n; ++k) {
    int first = blocks;
    each_block(k, [&](int b) { first = std::min(first, b); });
    key[k] = first;
    ++count[first];
  }
  std::vector<int> cut(size_t(threads), 0);
  long long below = 0;
  for (int t = 1, c = 0; t < threads; ++t) {
    for (; c < blocks && threads * (below + count[c]) <= (long long)(t) * n; ++c) below += count[c];
    cut[size_t(t)] = c;
  }
  const auto range = [&](int k) {
    return int(std::upper_bound(cut.begin() + 1, cut.end(), key[k]) - cut.begin()) - 1;
  };
  // Which range's residuals read each block: -1 none yet, -2 two or more.
  std::vector<int> owner(blocks, -1);
  for (int k = 0; k < n; ++k) {
    const int r = range(k);
    each_block(k, [&](int b) { owner[b] = owner[b] == -1 || owner[b] == r ? r : -2; });
  }
  // Runs: each range's residuals that read no block of another range, then
  // those that do (run `threads`), each in the residuals' order.
  std::vector<uint16_t> run(n);  // threads ≤ 256 (solver.num_threads)
  for (int k = 0; k < n; ++k) {
    bool shared = false;
    each_block(k, [&](int b) { shared = shared || owner[b] == -2; });
    run[k] = uint16_t(shared ? threads : range(k));
  }
  // Within a run, chunk by chunk (kVisitChunk), each in the residuals' order.
  const int chunks = blocks / kVisitChunk + 1;
  std::vector<int> start(size_t((threads + 1) * chunks) + 1, 0);
  const auto bucket = [&](int k) { return run[k] * chunks + key[k] / kVisitChunk; };
  for (int k = 0; k < n; ++k) ++start[size_t(bucket(k)) + 1];
  for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  s.visit.assign(n, 0);
  for (int k = 0; k < n; ++k) s.visit[size_t(start[size_t(bucket(k))]++)] = k;
  s.threads = threads;
  s.run_end.assign(size_t(threads) + 1, n);
  for (int t = 0; t < threads; ++t) s.run_end[size_t(t)] = start[size_t((t + 1) * chunks) - 1];
}

}  // namespace

bool ReadNormalPattern(const Residuals& in, int threads, NormalPattern* pattern) {
  threads = std::clamp(threads, 1, 256);
  if (!pattern->pairs.empty() && Renew(in, *pattern)) {
    if (pattern->threads != threads) Partition(in, threads, *pattern);
    return true;
  }
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
  // The residuals in `parts` parts, a thread each: a part's pairs go after
  // the earlier parts' under each block, so the layout is that of one part,
  // whatever their number (at most 16: each holds a count per block).
  const int parts = std::min(threads, 16);
  const size_t m = residuals.size();
  const auto part_start = [&](int t) { return PartStart(m, parts, t); };
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
  s.pairs.resize(m);
  std::vector<std::vector<int>> count(static_cast<size_t>(parts), std::vector<int>(n + 1, 0));
  std::vector<int> part_pairs(static_cast<size_t>(parts) + 1, 0);  // then: each part's first pair
  ForParts(parts, [&](int t) {
    int pairs = 0;
    std::vector<int>& c = count[size_t(t)];
    each_pair(part_start(t), part_start(t + 1), [](size_t) {}, [&](int p, int q) {
      ++c[std::min(p, q)];
      ++pairs;
    });
    part_pairs[size_t(t) + 1] = pairs;
  });
  for (int t = 0; t < parts; ++t) part_pairs[size_t(t) + 1] += part_pairs[size_t(t)];
  const int pair_count = part_pairs[size_t(parts)];
  std::vector<int> lower_start(n + 1, 0);
  for (int b = 0; b < n; ++b) {
    int at = lower_start[b];
    for (std::vector<int>& c : count) {  // where each part's pairs under b go
      const int mine = c[b];
      c[b] = at;
      at += mine;
    }
    lower_start[b + 1] = at;
  }
  std::vector<std::pair<int, int>> upper(static_cast<size_t>(pair_count));  // (upper, pair)
  ForParts(parts, [&](int t) {
    std::vector<int>& fill = count[size_t(t)];
    int at = part_pairs[size_t(t)];
    each_pair(part_start(t), part_start(t + 1), [&](size_t k) { s.pairs[k] = at; },
              [&](int p, int q) {
                upper[size_t(fill[std::min(p, q)]++)] = {std::max(p, q), at++};
              });
  });
  count.clear();
  // Slots, row by row: a row's distinct upper blocks, in order of first use.
  // The rows in `parts` parts (by pairs), a thread each; each part's slots
  // are numbered from 0, then moved past the earlier parts'.
  s.pair_slot.assign(size_t(pair_count), -1);
  struct Rows {
    int from = 0, to = 0, slots = 0;
    std::vector<int> row_start, column, slot;
  };
  std::vector<Rows> rows(static_cast<size_t>(parts));
  // The first row of part t: the row of the pair t/T of the way through.
  const auto row_at = [&](int t) {
    if (t == parts) return n;
    const int pairs = int(PartStart(size_t(pair_count), parts, t));
    return std::max(int(std::upper_bound(lower_start.begin(), lower_start.end(), pairs) -
                        lower_start.begin()) - 1, 0);
  };
  for (int t = 0; t < parts; ++t) {
    rows[size_t(t)].from = t == 0 ? 0 : row_at(t);
    rows[size_t(t)].to = row_at(t + 1);
  }
  rows[0].slots = s.slots;  // after the diagonal
  ForParts(parts, [&](int t) {
    Rows& part = rows[size_t(t)];
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
  });
  s.row_start.assign(1, 0);
  s.column.clear();
  s.slot.clear();
  int moved = 0;
  for (int t = 0; t < parts; ++t) {
    const Rows& part = rows[size_t(t)];
    if (t > 0) {
      for (int i = part.from; i < part.to; ++i) {
        for (int e = lower_start[i]; e < lower_start[i + 1]; ++e) {
          s.pair_slot[size_t(upper[size_t(e)].second)] += moved;
        }
      }
    }
    const int columns = int(s.column.size());
    for (int r : part.row_start) s.row_start.push_back(columns + r);
    s.column.insert(s.column.end(), part.column.begin(), part.column.end());
    for (int slot : part.slot) s.slot.push_back(slot + moved);
    moved = t == 0 ? part.slots : moved + part.slots;
  }
  s.slots = moved;
  s.column.shrink_to_fit();
  s.slot.shrink_to_fit();
  Partition(in, threads, s);
  return false;
}

}  // namespace archgeo
