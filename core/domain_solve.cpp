#include "core/domain_solve.h"

#include <metis.h>

#include <algorithm>
#include <chrono>
#include <unordered_map>
#include <vector>

namespace archgeo {
namespace {

using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The free parameter blocks and, per residual, the free blocks it reads
// (compressed rows), with the transpose (per block, its residuals).
struct Incidence {
  std::vector<double*> blocks;
  std::vector<int> sizes;                       // tangent size per block
  std::vector<int> residual_start, residual_blocks;  // residual -> blocks
  std::vector<int> block_start, block_residuals;     // block -> residuals
};

// Blocks are numbered in the order the residuals first read them (the
// problem's own block order follows memory addresses, which differ from run
// to run; the parts must not).
Incidence Collect(const ceres::Problem& problem) {
  Incidence g;
  std::unordered_map<const double*, int> index;
  std::vector<ceres::ResidualBlockId> residuals;
  problem.GetResidualBlocks(&residuals);
  std::vector<double*> read;
  g.residual_start.push_back(0);
  for (ceres::ResidualBlockId r : residuals) {
    problem.GetParameterBlocksForResidualBlock(r, &read);
    const size_t before = g.residual_blocks.size();
    for (double* b : read) {
      if (problem.IsParameterBlockConstant(b)) continue;
      auto [it, added] = index.emplace(b, int(g.blocks.size()));
      if (added) {
        g.blocks.push_back(b);
        g.sizes.push_back(problem.ParameterBlockTangentSize(b));
      }
      g.residual_blocks.push_back(it->second);
    }
    if (g.residual_blocks.size() > before) g.residual_start.push_back(int(g.residual_blocks.size()));
  }
  // Transpose.
  const int n = int(g.blocks.size());
  g.block_start.assign(n + 1, 0);
  for (int b : g.residual_blocks) ++g.block_start[b + 1];
  for (int i = 0; i < n; ++i) g.block_start[i + 1] += g.block_start[i];
  g.block_residuals.resize(g.residual_blocks.size());
  std::vector<int> fill(g.block_start.begin(), g.block_start.end() - 1);
  for (size_t r = 0; r + 1 < g.residual_start.size(); ++r) {
    for (int k = g.residual_start[r]; k < g.residual_start[r + 1]; ++k) {
      g.block_residuals[fill[g.residual_blocks[k]]++] = int(r);
    }
  }
  return g;
}

// Adjacency of the blocks (two blocks adjacent when a residual reads both),
// compressed rows as METIS reads them.
void Adjacency(const Incidence& g, std::vector<idx_t>* start, std::vector<idx_t>* adjacent) {
  const int n = int(g.blocks.size());
  std::vector<int> mark(n, -1);
  start->assign(1, 0);
  adjacent->clear();
  for (int b = 0; b < n; ++b) {
    mark[b] = b;
    for (int k = g.block_start[b]; k < g.block_start[b + 1]; ++k) {
      const int r = g.block_residuals[k];
      for (int j = g.residual_start[r]; j < g.residual_start[r + 1]; ++j) {
        const int c = g.residual_blocks[j];
        if (mark[c] != b) {
          mark[c] = b;
          adjacent->push_back(c);
        }
      }
    }
    start->push_back(idx_t(adjacent->size()));
  }
}

// Accumulates one pass's Ceres summary.
void Add(const ceres::Solver::Summary& s, DomainSolveSummary* out) {
  out->iterations += std::max(0, int(s.iterations.size()) - 1);
  out->seconds += std::max(0.0, s.total_time_in_seconds);
  out->linear_solver_seconds += std::max(0.0, s.linear_solver_time_in_seconds);
  out->jacobian_seconds += std::max(0.0, s.jacobian_evaluation_time_in_seconds);
  out->residual_seconds += std::max(0.0, s.residual_evaluation_time_in_seconds);
  out->final_cost = s.final_cost;
  if (!s.IsSolutionUsable()) {
    out->usable = false;
    out->message = s.message;
  }
  out->terminated_by_callback = s.termination_type == ceres::USER_SUCCESS;
}

// One Ceres solve with the blocks `held` constant (restored afterwards).
void SolveHolding(const ceres::Solver::Options& options, const Incidence& g,
                  const std::vector<char>& held, ceres::Problem* problem, DomainSolveSummary* out) {
  for (size_t b = 0; b < g.blocks.size(); ++b) {
    if (held[b]) problem->SetParameterBlockConstant(g.blocks[b]);
  }
  ceres::Solver::Summary summary;
  ceres::Solve(options, problem, &summary);
  for (size_t b = 0; b < g.blocks.size(); ++b) {
    if (held[b]) problem->SetParameterBlockVariable(g.blocks[b]);
  }
  Add(summary, out);
}

}  // namespace

int DomainParts(int variables, int size) {
  if (size <= 0 || variables <= 4LL * size) return 0;
  return int((variables + size - 1) / size);
}

DomainSolveSummary DomainSolve(const ceres::Solver::Options& global_options,
                               const DomainOptions& domains, ceres::Problem* problem) {
  const int band_rings = domains.band_rings;
  DomainSolveSummary out;
  if (DomainParts(problem->NumParameters(), domains.size) == 0) {  // small (or off): no graph
    ceres::Solver::Summary summary;
    ceres::Solve(global_options, problem, &summary);
    Add(summary, &out);
    return out;
  }
  const auto partition_start = Clock::now();
  const Incidence g = Collect(*problem);
  int variables = 0;
  for (int size : g.sizes) variables += size;
  idx_t parts = DomainParts(variables, domains.size);
  std::vector<idx_t> part(g.blocks.size(), 0);
  if (parts > 0) {
    std::vector<idx_t> start, adjacent, weight(g.sizes.begin(), g.sizes.end());
    Adjacency(g, &start, &adjacent);
    idx_t vertices = idx_t(g.blocks.size()), constraints = 1, cut = 0;
    idx_t metis_options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(metis_options);
    metis_options[METIS_OPTION_NUMBERING] = 0;
    metis_options[METIS_OPTION_SEED] = 1;  // the same parts on every run
    if (METIS_PartGraphKway(&vertices, &constraints, start.data(), adjacent.data(), weight.data(),
                            nullptr, nullptr, &parts, nullptr, nullptr, metis_options, &cut,
                            part.data()) != METIS_OK) {
      parts = 0;  // METIS failed (out of memory): one global solve
    }
  }
  out.partition_seconds = Since(partition_start);
  if (parts <= 0) {
    ceres::Solver::Summary summary;
    ceres::Solve(global_options, problem, &summary);
    Add(summary, &out);
    return out;
  }
  out.parts = int(parts);
  // A pass is one step of an alternating scheme: solving it to the last digit
  // is wasted (on 100k quads the second and third Ceres iterations of a pass
  // changed the cost by < 1e-4 relative).
  ceres::Solver::Options options = global_options;
  options.function_tolerance = std::max(options.function_tolerance, domains.function_tolerance);

  // Pass 1: the separator (every block of a residual that reads two parts)
  // held, the parts free.
  const int n = int(g.blocks.size());
  std::vector<char> separator(n, 0);
  for (size_t r = 0; r + 1 < g.residual_start.size(); ++r) {
    const int first = g.residual_start[r], end = g.residual_start[r + 1];
    bool straddles = false;
    for (int k = first + 1; k < end && !straddles; ++k) {
      straddles = part[g.residual_blocks[k]] != part[g.residual_blocks[first]];
    }
    if (!straddles) continue;
    for (int k = first; k < end; ++k) separator[g.residual_blocks[k]] = 1;
  }
  SolveHolding(options, g, separator, problem, &out);
  if (!out.usable || out.terminated_by_callback || band_rings < 0) {
    ceres::Problem::EvaluateOptions all;
    problem->Evaluate(all, &out.final_cost, nullptr, nullptr, nullptr);
    return out;
  }

  // Pass 2: the separator grown by band_rings steps free, the rest held.
  std::vector<char> band = separator;
  std::vector<int> front;
  for (int b = 0; b < n; ++b) {
    if (band[b]) front.push_back(b);
  }
  for (int ring = 0; ring < band_rings; ++ring) {
    std::vector<int> next;
    for (int b : front) {
      for (int k = g.block_start[b]; k < g.block_start[b + 1]; ++k) {
        const int r = g.block_residuals[k];
        for (int j = g.residual_start[r]; j < g.residual_start[r + 1]; ++j) {
          const int c = g.residual_blocks[j];
          if (!band[c]) {
            band[c] = 1;
            next.push_back(c);
          }
        }
      }
    }
    front.swap(next);
  }
  std::vector<char> held(n);
  for (int b = 0; b < n; ++b) held[b] = !band[b];
  SolveHolding(options, g, held, problem, &out);
  ceres::Problem::EvaluateOptions all;
  problem->Evaluate(all, &out.final_cost, nullptr, nullptr, nullptr);
  return out;
}

}  // namespace archgeo
