#include "core/normal_equations.h"

#include <algorithm>

#include <ceres/manifold.h>

namespace archgeo {

namespace {

int TangentSize(const Residuals::Block& b) {
  return b.manifold ? b.manifold->TangentSize() : b.size;
}

// Renews `s`'s manifolds from `in` if the structure is `s`'s; false (and
// `s` partly renewed) if not.
bool Renew(const Residuals& in, NormalPattern& s) {
  const std::vector<Residuals::Residual>& residuals = in.residuals();
  if (residuals.size() != s.residuals.size() ||
      in.blocks().size() != s.blocks.size() + s.constant.size() ||
      in.block_of().size() != s.block.size()) {
    return false;
  }
  for (size_t k = 0; k < residuals.size(); ++k) {
    const PatternResidual& r = s.residuals[k];
    if (residuals[k].first != r.first || residuals[k].end != r.end) return false;
  }
  // The free blocks in order, and the constant ones, as before...
  std::vector<int> free_index(in.blocks().size(), -1);
  size_t free = 0, constant = 0;
  for (size_t k = 0; k < in.blocks().size(); ++k) {
    const Residuals::Block& b = in.blocks()[k];
    if (b.constant) {
      if (constant == s.constant.size() || s.constant[constant++] != b.values) return false;
      continue;
    }
    if (free == s.blocks.size()) return false;
    PatternBlock& p = s.blocks[free];
    if (p.values != b.values || p.ambient != b.size || p.tangent != TangentSize(b)) return false;
    p.manifold = b.manifold;
    free_index[k] = int(free++);
  }
  // ...and every residual reading the same blocks.
  for (size_t a = 0; a < s.block.size(); ++a) {
    if (s.block[a] != free_index[size_t(in.block_of()[a])]) return false;
  }
  return true;
}

// The residuals' visiting order and its runs (NormalPattern::visit): cut
// by their first free block at the block below which half of them start
// (the blocks are numbered by first use, so the cut runs across the mesh);
// a residual reading a block that residuals of both sides read goes to the
// run after them. Each run keeps the residuals' order (term by term).
void Partition(NormalPattern& s) {
  const int n = int(s.residuals.size());
  const int blocks = int(s.blocks.size());
  const auto each_block = [&](int k, auto&& f) {
    for (int a = s.residuals[k].first; a < s.residuals[k].end; ++a) {
      if (s.block[a] >= 0) f(s.block[a]);
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
  s.visit.clear();
  s.visit.reserve(n);
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < n; ++k) {
      if (run[k] == r) s.visit.push_back(k);
    }
    if (r < 2) s.split[r] = int(s.visit.size());
  }
}

}  // namespace

bool ReadNormalPattern(const Residuals& in, NormalPattern* pattern) {
  if (!pattern->residuals.empty() && Renew(in, *pattern)) return true;
  *pattern = NormalPattern();
  NormalPattern& s = *pattern;
  // Free blocks in order of first use (as Residuals keeps them); -1: constant.
  std::vector<int> free_index(in.blocks().size(), -1);
  s.blocks.reserve(in.blocks().size());
  for (size_t k = 0; k < in.blocks().size(); ++k) {
    const Residuals::Block& b = in.blocks()[k];
    if (b.constant) {
      s.constant.push_back(b.values);
      continue;
    }
    free_index[k] = int(s.blocks.size());
    PatternBlock block;
    block.values = b.values;
    block.ambient = b.size;
    block.tangent = TangentSize(b);
    block.manifold = b.manifold;
    block.offset = s.tangent;
    s.tangent += block.tangent;
    s.blocks.push_back(std::move(block));
  }
  const std::vector<Residuals::Residual>& residuals = in.residuals();
  const size_t parameters = residuals.empty() ? 0 : size_t(residuals.back().end);
  s.block.resize(parameters);
  for (size_t a = 0; a < parameters; ++a) s.block[a] = free_index[in.block_of()[a]];
  s.residuals.reserve(residuals.size());
  for (const Residuals::Residual& from : residuals) {
    PatternResidual r;
    r.first = from.first;
    r.end = from.end;
    s.residuals.push_back(r);
  }
  // Slots: the diagonal, then block row by block row its upper pairs (so a
  // row's slots lie together for the product).
  const int n = int(s.blocks.size());
  s.diagonal.resize(n);
  for (int b = 0; b < n; ++b) {
    s.diagonal[b] = s.slots;
    s.slots += s.blocks[b].tangent * s.blocks[b].tangent;
  }
  s.diagonal_slots = s.slots;
  // Free pairs per residual (the order Linearise walks them), and which
  // residuals read each block.
  std::vector<int> incident_start(n + 1, 0);
  int pair_count = 0;
  for (PatternResidual& r : s.residuals) {
    r.pairs = pair_count;
    for (int a = r.first; a < r.end; ++a) {
      if (s.block[a] >= 0) ++incident_start[s.block[a] + 1];
      for (int b = a + 1; b < r.end; ++b) {
        pair_count += s.block[a] >= 0 && s.block[b] >= 0 && s.block[a] != s.block[b];
      }
    }
  }
  for (int b = 0; b < n; ++b) incident_start[b + 1] += incident_start[b];
  std::vector<int> incident(incident_start[n]);
  std::vector<int> fill(incident_start.begin(), incident_start.end() - 1);
  for (size_t r = 0; r < s.residuals.size(); ++r) {
    for (int a = s.residuals[r].first; a < s.residuals[r].end; ++a) {
      if (s.block[a] >= 0) incident[fill[s.block[a]]++] = int(r);
    }
  }
  s.pair_slot.assign(pair_count, -1);
  s.row_start.assign(1, 0);
  std::vector<int> mark(n, -1), position(n, 0);
  for (int i = 0; i < n; ++i) {
    for (int k = incident_start[i]; k < incident_start[i + 1]; ++k) {
      const PatternResidual& r = s.residuals[incident[k]];
      int pair = r.pairs;
      for (int a = r.first; a < r.end; ++a) {
        for (int b = a + 1; b < r.end; ++b) {
          const int p = s.block[a], q = s.block[b];
          if (p < 0 || q < 0 || p == q) continue;
          const int at = pair++;
          if (std::min(p, q) != i) continue;
          const int j = std::max(p, q);
          if (mark[j] != i) {
            mark[j] = i;
            position[j] = s.slots;
            s.column.push_back(j);
            s.slot.push_back(s.slots);
            s.slots += s.blocks[i].tangent * s.blocks[j].tangent;
          }
          s.pair_slot[at] = position[j];
        }
      }
    }
    s.row_start.push_back(int(s.column.size()));
  }
  s.column.shrink_to_fit();
  s.slot.shrink_to_fit();
  Partition(s);
  return false;
}

}  // namespace archgeo
