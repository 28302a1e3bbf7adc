#include "problems/solver_options.h"

#include <dlfcn.h>
#include <omp.h>

#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace archgeo {

namespace {

template <typename E>
struct Named {
  const char* name;
  E value;
};

const Named<ceres::LinearSolverType> kLinearSolvers[] = {
    {"sparse_normal_cholesky", ceres::SPARSE_NORMAL_CHOLESKY},
    {"dense_qr", ceres::DENSE_QR},
    {"dense_normal_cholesky", ceres::DENSE_NORMAL_CHOLESKY},
    {"cgnr", ceres::CGNR},
    {"iterative_schur", ceres::ITERATIVE_SCHUR}};
const Named<ceres::SparseLinearAlgebraLibraryType> kSparseLibraries[] = {
    {"suite_sparse", ceres::SUITE_SPARSE}, {"eigen_sparse", ceres::EIGEN_SPARSE}};
const Named<ceres::TrustRegionStrategyType> kTrustRegions[] = {
    {"levenberg_marquardt", ceres::LEVENBERG_MARQUARDT}, {"dogleg", ceres::DOGLEG}};
const Named<ceres::PreconditionerType> kPreconditioners[] = {{"jacobi", ceres::JACOBI},
                                                             {"identity", ceres::IDENTITY}};

template <typename E, size_t N>
std::vector<std::string> Names(const Named<E> (&table)[N]) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.push_back(entry.name);
  return names;
}

template <typename E, size_t N>
E Lookup(const Named<E> (&table)[N], const std::string& key, const std::string& name) {
  for (const auto& entry : table) {
    if (name == entry.name) return entry.value;
  }
  std::string list;
  for (const std::string& n : Names(table)) list += (list.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown " + key + " '" + name + "' (" + list + ")");
}

}  // namespace

std::vector<std::string> SolverChoices(const std::string& key) {
  if (key == "linear_solver") return Names(kLinearSolvers);
  if (key == "sparse_library") return Names(kSparseLibraries);
  if (key == "trust_region") return Names(kTrustRegions);
  if (key == "preconditioner") return Names(kPreconditioners);
  return {};
}

ceres::Solver::Options ToCeresOptions(const SolverSettings& s) {
  ceres::Solver::Options o;
  o.linear_solver_type = Lookup(kLinearSolvers, "linear_solver", s.linear_solver);
  o.sparse_linear_algebra_library_type =
      Lookup(kSparseLibraries, "sparse_library", s.sparse_library);
  o.trust_region_strategy_type = Lookup(kTrustRegions, "trust_region", s.trust_region);
  o.preconditioner_type = Lookup(kPreconditioners, "preconditioner", s.preconditioner);
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
  // Let libgomp shrink CHOLMOD's hard-coded 4-thread teams to the cores we
  // have, unless the user decided with OMP_DYNAMIC.
  if (!std::getenv("OMP_DYNAMIC")) omp_set_dynamic(1);
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
