#include "problems/solver_options.h"

#include <dlfcn.h>
#include <omp.h>

#include <stdexcept>

namespace archgeo {

ceres::Solver::Options ToCeresOptions(const SolverSettings& s) {
  ceres::Solver::Options o;
  if (s.linear_solver == "sparse_normal_cholesky") {
    o.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  } else if (s.linear_solver == "dense_qr") {
    o.linear_solver_type = ceres::DENSE_QR;
  } else if (s.linear_solver == "dense_normal_cholesky") {
    o.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
  } else if (s.linear_solver == "cgnr") {
    o.linear_solver_type = ceres::CGNR;
  } else if (s.linear_solver == "iterative_schur") {
    o.linear_solver_type = ceres::ITERATIVE_SCHUR;
  } else {
    throw std::invalid_argument("unknown linear_solver '" + s.linear_solver +
                                "' (sparse_normal_cholesky, dense_qr, dense_normal_cholesky, cgnr, "
                                "iterative_schur)");
  }
  if (s.sparse_library == "suite_sparse") {
    o.sparse_linear_algebra_library_type = ceres::SUITE_SPARSE;
  } else if (s.sparse_library == "eigen_sparse") {
    o.sparse_linear_algebra_library_type = ceres::EIGEN_SPARSE;
  } else {
    throw std::invalid_argument("unknown sparse_library '" + s.sparse_library +
                                "' (suite_sparse, eigen_sparse)");
  }
  if (s.trust_region == "levenberg_marquardt") {
    o.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  } else if (s.trust_region == "dogleg") {
    o.trust_region_strategy_type = ceres::DOGLEG;
  } else {
    throw std::invalid_argument("unknown trust_region '" + s.trust_region +
                                "' (levenberg_marquardt, dogleg)");
  }
  if (s.preconditioner == "jacobi") {
    o.preconditioner_type = ceres::JACOBI;
  } else if (s.preconditioner == "identity") {
    o.preconditioner_type = ceres::IDENTITY;
  } else {
    throw std::invalid_argument("unknown preconditioner '" + s.preconditioner +
                                "' (jacobi, identity)");
  }
  if (s.max_iterations < 1) throw std::invalid_argument("max_iterations must be >= 1");
  if (s.threads < 1) throw std::invalid_argument("threads must be >= 1");
  for (double t : {s.function_tolerance, s.gradient_tolerance, s.parameter_tolerance}) {
    if (!(t >= 0)) throw std::invalid_argument("tolerances must be >= 0");
  }
  o.max_num_iterations = s.max_iterations;
  o.function_tolerance = s.function_tolerance;
  o.gradient_tolerance = s.gradient_tolerance;
  o.parameter_tolerance = s.parameter_tolerance;
  o.num_threads = s.threads;
  o.logging_type = ceres::SILENT;
  o.minimizer_progress_to_stdout = false;
  return o;
}

void ConfigureThreading() {
  // Let libgomp shrink CHOLMOD's hard-coded 4-thread teams to the cores we have.
  omp_set_dynamic(1);
}

std::string BlasLibrary() {
  // Looked up at run time: the BLAS is a dependency of CHOLMOD, not of ours.
  void* symbol = dlsym(RTLD_DEFAULT, "dgemm_");
  Dl_info info;
  if (symbol && dladdr(symbol, &info) && info.dli_fname) {
    char resolved[4096];
    if (realpath(info.dli_fname, resolved)) return resolved;
    return info.dli_fname;
  }
  return "unknown";
}

}  // namespace archgeo
