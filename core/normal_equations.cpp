#include "core/normal_equations.h"

#include <algorithm>
#include <unordered_map>

namespace archgeo {

namespace {

// Renews `s`'s costs, losses and manifolds from `problem` if the structure
// is `s`'s; false (and `s` partly renewed) if not.
bool Renew(ceres::Problem& problem, const std::vector<ceres::ResidualBlockId>& ids,
           NormalPattern& s) {
  if (ids.size() != s.residuals.size() ||
      size_t(problem.NumParameterBlocks()) != s.blocks.size() + s.constant.size()) {
    return false;
  }
  std::vector<double*> read;
  for (size_t k = 0; k < ids.size(); ++k) {
    PatternResidual& r = s.residuals[k];
    problem.GetParameterBlocksForResidualBlock(ids[k], &read);
    if (int(read.size()) != r.end - r.first ||
        !std::equal(read.begin(), read.end(), s.values.begin() + r.first)) {
      return false;
    }
    r.cost = problem.GetCostFunctionForResidualBlock(ids[k]);
    r.loss = problem.GetLossFunctionForResidualBlock(ids[k]);
    r.rows = r.cost->num_residuals();
  }
  // Every block below is read by a residual above, so the problem has it.
  for (PatternBlock& b : s.blocks) {
    if (problem.IsParameterBlockConstant(b.values) ||
        problem.ParameterBlockSize(b.values) != b.ambient ||
        problem.ParameterBlockTangentSize(b.values) != b.tangent) {
      return false;
    }
    b.manifold = problem.GetManifold(b.values);
  }
  for (const double* c : s.constant) {
    if (!problem.IsParameterBlockConstant(const_cast<double*>(c))) return false;
  }
  return true;
}

}  // namespace

bool ReadNormalPattern(ceres::Problem& problem, NormalPattern* pattern) {
  std::vector<ceres::ResidualBlockId> ids;
  problem.GetResidualBlocks(&ids);
  if (!pattern->residuals.empty() && Renew(problem, ids, *pattern)) return true;
  *pattern = NormalPattern();
  NormalPattern& s = *pattern;
  std::unordered_map<const double*, int> index(2 * size_t(problem.NumParameterBlocks()));
  s.residuals.reserve(ids.size());
  s.values.reserve(4 * ids.size());
  s.block.reserve(4 * ids.size());
  std::vector<double*> read;
  for (ceres::ResidualBlockId id : ids) {
    problem.GetParameterBlocksForResidualBlock(id, &read);
    PatternResidual r;
    r.cost = problem.GetCostFunctionForResidualBlock(id);
    r.loss = problem.GetLossFunctionForResidualBlock(id);
    r.rows = r.cost->num_residuals();
    r.first = int(s.values.size());
    for (double* b : read) {
      s.values.push_back(b);
      auto [it, added] = index.emplace(b, -1);  // -1: constant
      if (added && problem.IsParameterBlockConstant(b)) {
        s.constant.push_back(b);
      } else if (added) {
        it->second = int(s.blocks.size());
        PatternBlock block;
        block.values = b;
        block.ambient = problem.ParameterBlockSize(b);
        block.tangent = problem.ParameterBlockTangentSize(b);
        block.manifold = problem.GetManifold(b);
        block.offset = s.tangent;
        s.tangent += block.tangent;
        s.blocks.push_back(std::move(block));
      }
      s.block.push_back(it->second);
    }
    r.end = int(s.values.size());
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
  return false;
}

}  // namespace archgeo
