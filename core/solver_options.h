// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the `solver:` section of a spec: ceres::Solver::Options by
// Ceres' own option names (lower case in YAML, e.g. `linear_solver_type:
// sparse_normal_cholesky`), converted with ceres::StringTo*. Every choice
// Ceres offers and this build of it supports is accepted; a combination
// Ceres rejects (e.g. dogleg with an iterative linear solver) is an input
// error naming the keys, before any work.
#pragma once

#include <string>
#include <vector>

#include <ceres/solver.h>

#include "core/settings.h"

namespace archgeo {

// The solver keys ("solver.<ceres option name>") with archgeo's defaults.
std::vector<Key> SolverKeys();

// The Ceres options of `settings` (logging off; callbacks are the loop's).
// Throws InputError naming the offending key(s) for an invalid combination.
ceres::Solver::Options SolverOptions(const Settings& settings);

// The objective parts of solver.subset_preconditioner_parts (comma-separated
// names, blanks dropped).
std::vector<std::string> SubsetParts(const Settings& settings);

// Configures OpenMP and BLAS threading once per process: Debian's CHOLMOD
// hard-codes 4 OpenMP threads, which on 2 cores is ~3x slower than letting
// the runtime adapt (omp_set_dynamic(1)). OpenBLAS (pthreads build) runs
// on one thread: its spinning worker threads compete with Ceres' and
// CHOLMOD's for the cores. OMP_DYNAMIC and OPENBLAS_NUM_THREADS, if set,
// are left in charge.
void ConfigureThreading();

// libgomp reads OMP_WAIT_POLICY once, as it is loaded, before main. Unset,
// its idle threads spin after every parallel region, on cores the solve, the
// linear solver's threads or another process need; archgeo's regions are
// many and short. Called first in a program's main: unless the user chose a
// policy, the process starts once more (same arguments) with the passive one;
// if that fails it goes on as it is.
void StartWithPassiveOpenMpWaits(char** argv);

// In its scope archgeo's own OpenMP loops get the threads they ask for:
// libgomp's dynamic adjustment (above) subtracts the load average, which
// counts this process itself, and so would leave LeanSolve one thread on 2
// cores. Not for scopes that call CHOLMOD. OMP_DYNAMIC, if set, stays in
// charge.
class FullTeams {
 public:
  FullTeams();
  ~FullTeams();
  FullTeams(const FullTeams&) = delete;
  FullTeams& operator=(const FullTeams&) = delete;

 private:
  int previous_;
};

// Path of the shared library that provides the BLAS dgemm_ symbol in this
// process (e.g. ".../openblas-pthread/libblas.so.3"), for reports and benchmarks.
std::string BlasLibrary();

// The kernels OpenBLAS runs (its core name, e.g. "SkylakeX", "Prescott" for
// its generic ones), or "" when another BLAS serves dgemm_.
std::string BlasKernels();

}  // namespace archgeo
