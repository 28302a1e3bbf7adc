// archgeo — a Ceres solve by domain decomposition, for problems too large for
// one sparse Cholesky factorisation.
//
// Why: on a mesh the normal equations J^T J are a 2-D graph; a direct sparse
// Cholesky of it costs ~n^1.5 in time (the separators of nested dissection
// are ~√n wide and their dense blocks dominate) and its factor grows faster
// than n in memory (README, "Speed": 100k quads 3.8 GB, 1M quads 12.2 GB).
// Solving disjoint pieces costs ~n: every piece's factor is small.
//
// The solve is two passes of alternating Schwarz with every piece solved
// exactly (multiplicative Schwarz, two colours):
//   1. parts: the graph of the free parameter blocks (two blocks adjacent when
//      a residual reads both) is cut into parts of about `domain_size`
//      variables (METIS k-way, weights = tangent sizes). The blocks of every
//      residual that reads blocks of two parts (the separator) are held
//      constant; the rest falls into independent parts, so the normal
//      equations are block diagonal and one Ceres solve factorises the parts
//      one by one.
//   2. band: the separator and its neighbours up to `band_rings` graph steps
//      are free, everything else is held constant: the blocks that stood
//      still in pass 1 move with room on both sides.
// Each pass is an ordinary Ceres solve with the caller's options (its
// iteration callbacks too, so a per-iteration tolerance can end a pass; it
// then ends the whole solve). The decomposition is exact where it matters: a
// residual whose blocks are all held constant cannot change, so a face that
// met the tolerance in pass 1 and lies in the separator keeps its value in
// pass 2, and pass 2 re-solves every face that pass 1 could not move.
#pragma once

#include <string>

#include <ceres/problem.h>
#include <ceres/solver.h>

namespace archgeo {

struct DomainSolveSummary {
  int parts = 0;                // 0: one global solve (the problem was small)
  int iterations = 0;           // Ceres iterations of both passes
  double seconds = 0, linear_solver_seconds = 0, jacobian_seconds = 0, residual_seconds = 0;
  double partition_seconds = 0;  // graph + METIS
  double final_cost = 0;        // ½ Σ w r² of the whole problem at the end
  bool usable = true;
  std::string message;           // why not usable
  bool terminated_by_callback = false;  // a callback ended a pass (e.g. a tolerance held)
};

struct DomainOptions {
  int size = 0;         // variables per part; 0: one global solve
  int band_rings = 2;   // the band pass frees the separator and this many rings; < 0: no band pass
  double function_tolerance = 1e-4;  // per pass (at least the caller's)
};

// The number of parts for a problem with `variables` free variables: 0 (one
// global solve) unless size > 0 and variables > 4 × size.
int DomainParts(int variables, int size);

// Solves `problem` (as ceres::Solve would) by domain decomposition when
// DomainParts(the problem's free variables, domains.size) > 0, else by one
// Ceres solve with `options` unchanged. Parameter blocks that are constant on
// entry stay constant; the problem's constant/variable state is restored on
// return.
DomainSolveSummary DomainSolve(const ceres::Solver::Options& options, const DomainOptions& domains,
                               ceres::Problem* problem);

}  // namespace archgeo
