// archgeo — the `solver:` section of a problem spec, mapped onto
// ceres::Solver::Options.
#pragma once

#include <string>
#include <vector>

#include <ceres/solver.h>

namespace archgeo {

// Every key of the `solver:` YAML section (see docs in problems/spec.h).
struct SolverSettings {
  std::string linear_solver = "sparse_normal_cholesky";  // | dense_qr | dense_normal_cholesky | cgnr | iterative_schur
  std::string sparse_library = "suite_sparse";           // | eigen_sparse
  std::string trust_region = "levenberg_marquardt";      // | dogleg
  std::string preconditioner = "jacobi";                 // for cgnr / iterative_schur: jacobi | identity
  int max_iterations = 50;          // per outer iteration (Ceres iterations)
  int outer_iterations = 12;        // re-projection / continuation rounds, at most
  double function_tolerance = 1e-10;
  double gradient_tolerance = 1e-14;
  double parameter_tolerance = 1e-10;
  int threads = 2;
};

// The accepted names of a string key of SolverSettings ("linear_solver",
// "sparse_library", "trust_region", "preconditioner"), for the spec parser.
std::vector<std::string> SolverChoices(const std::string& key);

// Throws std::invalid_argument naming the bad value (the spec parser wraps it
// with file/line/key).
ceres::Solver::Options ToCeresOptions(const SolverSettings& settings);

// Configures OpenMP and BLAS threading once per process: Debian's CHOLMOD
// hard-codes 4 OpenMP threads, which on 2 cores is ~3x slower than letting
// the runtime adapt (omp_set_dynamic(1)). An OMP_DYNAMIC environment
// variable, if set, is left in charge.
void ConfigureThreading();

// Path of the shared library that provides the BLAS dgemm_ symbol in this
// process (e.g. ".../openblas-pthread/libblas.so.3"), for reports and benchmarks.
std::string BlasLibrary();

}  // namespace archgeo
