// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/solver_options.h"

#include <dlfcn.h>
#include <unistd.h>
#include <omp.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <functional>

#include <ceres/problem.h>
#include <ceres/types.h>

namespace archgeo {
namespace {

std::string Lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}
std::string Upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// The lower-case names of an enum's values 0..last (its last enumerator in
// Ceres 2.1: converting an int beyond an enum's range is undefined), by
// Ceres' own *ToString, for the values `usable` accepts.
template <typename E>
std::vector<std::string> Names(const char* (*to_string)(E), E last,
                               const std::function<bool(E)>& usable = nullptr) {
  std::vector<std::string> names;
  for (int i = 0; i <= int(last); ++i) {
    const E e = static_cast<E>(i);
    const std::string name = to_string(e);
    if (name == "UNKNOWN" || (usable && !usable(e))) continue;
    names.push_back(Lower(name));
  }
  return names;
}

std::vector<std::string> SparseLibraries() {
  return Names<ceres::SparseLinearAlgebraLibraryType>(
      &ceres::SparseLinearAlgebraLibraryTypeToString, ceres::NO_SPARSE,
      [](ceres::SparseLinearAlgebraLibraryType t) {
        return t != ceres::NO_SPARSE && ceres::IsSparseLinearAlgebraLibraryTypeAvailable(t);
      });
}

std::vector<std::string> DenseLibraries() {
  return Names<ceres::DenseLinearAlgebraLibraryType>(
      &ceres::DenseLinearAlgebraLibraryTypeToString, ceres::CUDA,
      [](ceres::DenseLinearAlgebraLibraryType t) {
        return ceres::IsDenseLinearAlgebraLibraryTypeAvailable(t);
      });
}

template <typename E>
E Convert(const Settings& s, const std::string& key, bool (*from_string)(std::string, E*)) {
  E value;
  CHECK(from_string(Upper(s.String(key)), &value)) << key << ": " << s.String(key);
  return value;
}

}  // namespace

std::vector<Key> SolverKeys() {
  auto choice = [](std::string name, std::string fallback, std::vector<std::string> choices,
                   std::string doc) {
    return ChoiceKey("solver." + std::move(name), std::move(fallback), std::move(choices),
                     std::move(doc));
  };
  auto number = [](std::string name, double fallback, double lo, double hi, std::string doc) {
    return NumberKey("solver." + std::move(name), fallback, lo, hi, std::move(doc));
  };
  auto integer = [](std::string name, long long fallback, long long lo, long long hi,
                    std::string doc) {
    return IntegerKey("solver." + std::move(name), fallback, lo, hi, std::move(doc));
  };
  auto flag = [](std::string name, bool fallback, std::string doc) {
    return BoolKey("solver." + std::move(name), fallback, std::move(doc));
  };
  // What LeanSolve (solver.back_end: lean, solver.pcg_above; core/lean_solve.h)
  // does with a key.
  const std::string kLeanIgnores = " (LeanSolve rounds: ignored)";
  const std::string kLeanCeres =
      " (back_end lean: any other value sends the rounds up to pcg_above to Ceres; above "
      "pcg_above: ignored)";
  const std::string kLeanLinear =
      " (back_end lean: LeanSolve's steps are one sparse Cholesky factorisation (CHOLMOD) "
      "each, any other value sends the rounds up to pcg_above to Ceres; above pcg_above: "
      "ignored, the steps are block-Jacobi conjugate gradients; pcg_above: 0 for this solver "
      "on every round)";
  const std::string kLeanWithRefused =
      " (LeanSolve rounds: ignored, applies only to a choice LeanSolve refuses)";
  const std::string kLeanRefusesTrue =
      " (above pcg_above: true is refused, exit 2; back_end lean: true sends the rounds up "
      "to pcg_above to Ceres)";
  const auto kLeanRefusesOther = [](const std::string& only) {
    return " (above pcg_above: any but " + only + " is refused, exit 2; back_end lean: any "
           "but " + only + " sends the rounds up to pcg_above to Ceres)";
  };
  Key subset;
  subset.name = "solver.subset_preconditioner_parts";
  subset.type = Type::kString;
  subset.fallback = std::string("");
  subset.doc =
      "with preconditioner_type: subset (Ceres): the objective parts (term names, comma-separated) "
      "whose residual blocks form the SUBSET preconditioner (planar_quads: the planarity terms "
      "and the barriers)";
  return {
      choice("linear_solver_type", "sparse_normal_cholesky",
             Names<ceres::LinearSolverType>(&ceres::LinearSolverTypeToString, ceres::CGNR),
             "linear solver of each step (Ceres LinearSolverType)" + kLeanLinear),
      choice("sparse_linear_algebra_library_type", "suite_sparse", SparseLibraries(),
             "sparse factorisation library (suite_sparse: CHOLMOD)" + kLeanCeres),
      choice("dense_linear_algebra_library_type", "eigen", DenseLibraries(),
             "dense linear algebra for the dense solvers" + kLeanIgnores),
      choice("preconditioner_type", "jacobi",
             Names<ceres::PreconditionerType>(&ceres::PreconditionerTypeToString, ceres::SUBSET),
             "preconditioner of the iterative solvers (cgnr: identity, jacobi or subset; "
             "iterative_schur: any but subset; subset: with subset_preconditioner_parts)" +
                 kLeanRefusesOther("jacobi")),
      choice("trust_region_strategy_type", "levenberg_marquardt",
             Names<ceres::TrustRegionStrategyType>(&ceres::TrustRegionStrategyTypeToString,
                                                   ceres::DOGLEG),
             "trust-region strategy" + kLeanRefusesOther("levenberg_marquardt")),
      choice("dogleg_type", "traditional_dogleg",
             Names<ceres::DoglegType>(&ceres::DoglegTypeToString, ceres::SUBSPACE_DOGLEG),
             "dogleg variant (with trust_region_strategy_type: dogleg)" + kLeanWithRefused),
      choice("minimizer_type", "trust_region",
             Names<ceres::MinimizerType>(&ceres::MinimizerTypeToString, ceres::TRUST_REGION),
             "trust_region, or line_search (then the line_search_* keys apply)" +
                 kLeanRefusesOther("trust_region")),
      choice("line_search_direction_type", "lbfgs",
             Names<ceres::LineSearchDirectionType>(&ceres::LineSearchDirectionTypeToString,
                                                   ceres::BFGS),
             "direction of the line-search minimizer" + kLeanWithRefused),
      choice("line_search_type", "wolfe",
             Names<ceres::LineSearchType>(&ceres::LineSearchTypeToString, ceres::WOLFE),
             "line search of the line-search minimizer" + kLeanWithRefused),
      integer("max_num_iterations", 50, 0, 1000000, "solver iterations per round at most (Ceres or PCG)"),
      number("max_solver_time_in_seconds", 1e9, 0, 1e9, "wall time per round at most"),
      integer("num_threads", 2, 1, 256, "threads for Jacobian evaluation and linear algebra (LeanSolve: T fixed parts of the "
              "work, the same bits run to run for the same number)"),
      number("function_tolerance", 1e-10, 0, 1, "stop when |Δcost|/cost falls below this"),
      number("gradient_tolerance", 1e-14, 0, 1, "stop when the max-norm gradient falls below this"),
      number("parameter_tolerance", 1e-10, 0, 1, "stop when |Δx| falls below this × (|x| + this)"),
      number("initial_trust_region_radius", 1e4, 0, 1e32, "initial trust-region radius"),
      number("max_trust_region_radius", 1e16, 0, 1e32, "largest trust-region radius"),
      number("min_trust_region_radius", 1e-32, 0, 1, "stop when the radius falls below this"),
      number("min_relative_decrease", 1e-3, 0, 1, "smallest accepted ratio of actual to model decrease"),
      number("min_lm_diagonal", 1e-6, 0, 1e32, "Levenberg-Marquardt diagonal lower bound"),
      number("max_lm_diagonal", 1e32, 0, 1e32, "Levenberg-Marquardt diagonal upper bound"),
      integer("max_num_consecutive_invalid_steps", 5, 0, 1000000, "invalid steps tolerated in a row" +
                  std::string(" (LeanSolve rounds: ignored; a step whose cost fails "
                              "to evaluate is rejected and the trust region shrinks)")),
      flag("use_nonmonotonic_steps", false, "allow steps that raise the cost (non-monotonic)" + kLeanRefusesTrue),
      integer("max_consecutive_nonmonotonic_steps", 5, 0, 1000000, "with use_nonmonotonic_steps" + kLeanWithRefused),
      flag("jacobi_scaling", true, "scale the columns of the Jacobian" +
                std::string(" (LeanSolve rounds: ignored; its damped step and "
                            "block-Jacobi preconditioner do not change with the columns' scale)")),
      flag("use_inner_iterations", false, "inner iterations (non-linear block coordinate descent)" + kLeanRefusesTrue),
      number("inner_iteration_tolerance", 1e-3, 0, 1, "relative decrease that stops inner iterations" + kLeanWithRefused),
      integer("min_linear_solver_iterations", 0, 0, 1000000, "iterative solvers: at least"),
      integer("max_linear_solver_iterations", 500, 1, 1000000, "iterative solvers: at most"),
      number("eta", 0.1, 0, 1, "iterative solvers: forcing sequence (relative accuracy)"),
      flag("use_postordering", false, "sparse Cholesky: postorder the elimination tree" + kLeanIgnores),
      flag("dynamic_sparsity", false, "re-analyse the Jacobian's sparsity every iteration" + kLeanCeres),
      flag("use_mixed_precision_solves", false,
           "single-precision factorisation + refinement (sparse Cholesky only with eigen_sparse: "
           "this Ceres has no single-precision SuiteSparse or CXSparse one)" + kLeanCeres),
      integer("max_num_refinement_iterations", 0, 0, 1000, "iterative refinement steps" + kLeanCeres),
      flag("use_explicit_schur_complement", false, "iterative_schur: form the Schur complement" + kLeanIgnores),
      choice("back_end", "ceres", {"ceres", "lean"},
             "who solves a round of at most pcg_above variables: ceres (ceres::Solve with the "
             "keys here) or lean (LeanSolve, archgeo's own Levenberg-Marquardt on normal "
             "equations assembled once per iteration, each step one sparse Cholesky "
             "factorisation by CHOLMOD whose ordering and symbolic analysis are made once and "
             "kept for every iteration and round of the same structure; core/lean_solve.h; it "
             "ignores the solver keys that do not change such a step, and a round whose keys "
             "ask for what it does not implement goes to Ceres, as each key says) "
             "(planar_quads, conjugate_layout, wave_quads, principal_symmetric, hnet, "
             "total_absolute_curvature: lean)"),
      choice("ordering", "amd", {"amd", "metis"},
             "fill-reducing ordering of LeanSolve's sparse Cholesky steps (back_end lean): amd "
             "(CHOLMOD's approximate minimum degree) or metis (METIS' nested dissection: fewer "
             "flops per factorisation on large surface meshes, a costlier analysis, made once per "
             "structure); back_end ceres: ignored (Debian's Ceres 2.1 orders by AMD) "
             "(wave_quads: metis)"),
      integer("pcg_above", 0, 0, 1000000000,
              "a round with more than this many variables is solved by LeanSolve (whatever "
              "back_end says) with each step by "
              "block-Jacobi conjugate gradients, ended by eta as Ceres ends its own (the "
              "quadratic model's relative decrease), at most max_linear_solver_iterations; "
              "it refuses the solver keys it does not implement (exit 2), as each key says; "
              "0 = never (planar_quads: 100000)"),
      subset,
      number("pcg_function_tolerance", 1e-3, 0, 1,
             "with pcg_above: such a solve stops when the relative cost change, or the next one "
             "extrapolated from the last two, falls below this (or function_tolerance, if "
             "larger); the next round goes on from there"),
  };
}

// Combinations Ceres' own IsValid accepts but aborts on when it solves
// (Debian's Ceres 2.1): refused here, naming the key.
static void CheckSupportedHere(const Settings& s, const ceres::Solver::Options& o) {
  const bool sparse_cholesky = o.linear_solver_type == ceres::SPARSE_NORMAL_CHOLESKY ||
                               o.linear_solver_type == ceres::SPARSE_SCHUR;
  if (o.use_mixed_precision_solves && sparse_cholesky &&
      o.sparse_linear_algebra_library_type != ceres::EIGEN_SPARSE) {
    throw s.Error("solver.use_mixed_precision_solves",
                  "this Ceres has no single-precision " +
                      s.String("solver.sparse_linear_algebra_library_type") +
                      " Cholesky: mixed precision needs sparse_linear_algebra_library_type: "
                      "eigen_sparse or a dense linear solver");
  }
  const ceres::PreconditionerType p = o.preconditioner_type;
  if (o.linear_solver_type == ceres::CGNR && p != ceres::IDENTITY && p != ceres::JACOBI &&
      p != ceres::SUBSET) {
    throw s.Error("solver.preconditioner_type",
                  "linear_solver_type: cgnr works with the identity, jacobi or subset "
                  "preconditioner, not " + s.String("solver.preconditioner_type"));
  }
  if (o.linear_solver_type == ceres::ITERATIVE_SCHUR && p == ceres::SUBSET) {
    throw s.Error("solver.preconditioner_type",
                  "linear_solver_type: iterative_schur does not take the subset preconditioner "
                  "(identity, jacobi, schur_jacobi, cluster_jacobi or cluster_tridiagonal)");
  }
}

ceres::Solver::Options SolverOptions(const Settings& s) {
  ceres::Solver::Options o;
  o.linear_solver_type = Convert(s, "solver.linear_solver_type", &ceres::StringToLinearSolverType);
  o.sparse_linear_algebra_library_type =
      Convert(s, "solver.sparse_linear_algebra_library_type",
              &ceres::StringToSparseLinearAlgebraLibraryType);
  o.dense_linear_algebra_library_type = Convert(
      s, "solver.dense_linear_algebra_library_type", &ceres::StringToDenseLinearAlgebraLibraryType);
  o.preconditioner_type = Convert(s, "solver.preconditioner_type", &ceres::StringToPreconditionerType);
  o.trust_region_strategy_type =
      Convert(s, "solver.trust_region_strategy_type", &ceres::StringToTrustRegionStrategyType);
  o.dogleg_type = Convert(s, "solver.dogleg_type", &ceres::StringToDoglegType);
  o.minimizer_type = Convert(s, "solver.minimizer_type", &ceres::StringToMinimizerType);
  o.line_search_direction_type =
      Convert(s, "solver.line_search_direction_type", &ceres::StringToLineSearchDirectionType);
  o.line_search_type = Convert(s, "solver.line_search_type", &ceres::StringToLineSearchType);
  o.max_num_iterations = int(s.Integer("solver.max_num_iterations"));
  o.max_solver_time_in_seconds = s.Number("solver.max_solver_time_in_seconds");
  o.num_threads = int(s.Integer("solver.num_threads"));
  o.function_tolerance = s.Number("solver.function_tolerance");
  o.gradient_tolerance = s.Number("solver.gradient_tolerance");
  o.parameter_tolerance = s.Number("solver.parameter_tolerance");
  o.initial_trust_region_radius = s.Number("solver.initial_trust_region_radius");
  o.max_trust_region_radius = s.Number("solver.max_trust_region_radius");
  o.min_trust_region_radius = s.Number("solver.min_trust_region_radius");
  o.min_relative_decrease = s.Number("solver.min_relative_decrease");
  o.min_lm_diagonal = s.Number("solver.min_lm_diagonal");
  o.max_lm_diagonal = s.Number("solver.max_lm_diagonal");
  o.max_num_consecutive_invalid_steps = int(s.Integer("solver.max_num_consecutive_invalid_steps"));
  o.use_nonmonotonic_steps = s.Bool("solver.use_nonmonotonic_steps");
  o.max_consecutive_nonmonotonic_steps = int(s.Integer("solver.max_consecutive_nonmonotonic_steps"));
  o.jacobi_scaling = s.Bool("solver.jacobi_scaling");
  o.use_inner_iterations = s.Bool("solver.use_inner_iterations");
  o.inner_iteration_tolerance = s.Number("solver.inner_iteration_tolerance");
  o.min_linear_solver_iterations = int(s.Integer("solver.min_linear_solver_iterations"));
  o.max_linear_solver_iterations = int(s.Integer("solver.max_linear_solver_iterations"));
  o.eta = s.Number("solver.eta");
  o.use_postordering = s.Bool("solver.use_postordering");
  o.dynamic_sparsity = s.Bool("solver.dynamic_sparsity");
  o.use_mixed_precision_solves = s.Bool("solver.use_mixed_precision_solves");
  o.max_num_refinement_iterations = int(s.Integer("solver.max_num_refinement_iterations"));
  o.use_explicit_schur_complement = s.Bool("solver.use_explicit_schur_complement");
  o.logging_type = ceres::SILENT;
  o.minimizer_progress_to_stdout = false;

  // Ceres' SUBSET preconditioner needs its residual blocks, which exist only
  // once a round is built (SolveRound adds them): a stand-in for the check.
  const bool subset = o.preconditioner_type == ceres::SUBSET;
  if (subset && SubsetParts(s).empty()) {
    throw s.Error("solver.subset_preconditioner_parts",
                  "preconditioner_type: subset needs the objective parts that form it");
  }
  if (subset) {
    o.residual_blocks_for_subset_preconditioner.insert(
        reinterpret_cast<ceres::ResidualBlockId>(&o));  // never dereferenced
  }
  CheckSupportedHere(s, o);
  std::string error;
  const bool valid = o.IsValid(&error);
  o.residual_blocks_for_subset_preconditioner.clear();
  if (!valid) {
    // Name the keys Ceres' message is about: those whose option name or
    // (upper-case) value it mentions, given in the spec first.
    std::vector<std::string> keys;
    for (const Key& k : SolverKeys()) {
      const std::string option = k.name.substr(std::string("solver.").size());
      const bool named = error.find(option) != std::string::npos ||
                         (k.type == Type::kChoice &&
                          error.find(Upper(s.String(k.name))) != std::string::npos);
      if (named) keys.push_back(k.name);
    }
    std::stable_partition(keys.begin(), keys.end(),
                          [&](const std::string& k) { return s.Given(k); });
    std::string list;
    for (const std::string& k : keys) list += (list.empty() ? "" : ", ") + k;
    throw s.Error(keys.empty() ? std::string("solver") : keys.front(),
                  "Ceres rejects this combination" + (list.empty() ? "" : " of " + list) + ": " +
                      error);
  }
  return o;
}

std::vector<std::string> SubsetParts(const Settings& s) {
  std::vector<std::string> parts;
  std::string part;
  for (const char c : s.String("solver.subset_preconditioner_parts") + ",") {
    if (c == ',') {
      if (!part.empty()) parts.push_back(part);
      part.clear();
    } else if (!std::isspace(static_cast<unsigned char>(c))) {
      part += c;
    }
  }
  return parts;
}

void ConfigureThreading() {
  // Let libgomp shrink CHOLMOD's hard-coded 4-thread teams to the cores we
  // have, unless the user decided with OMP_DYNAMIC.
  if (!std::getenv("OMP_DYNAMIC")) omp_set_dynamic(1);
  // OpenBLAS on one thread (looked up at run time: another BLAS may serve
  // dgemm_), unless the user decided with OPENBLAS_NUM_THREADS.
  if (!std::getenv("OPENBLAS_NUM_THREADS")) {
    using SetThreads = void (*)(int);
    if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) {
      set(1);
    }
  }
}

void StartWithPassiveOpenMpWaits(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY")) return;
  if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  execv("/proc/self/exe", argv);
}

FullTeams::FullTeams() : previous_(omp_get_dynamic()) {
  if (!std::getenv("OMP_DYNAMIC")) omp_set_dynamic(0);
}
FullTeams::~FullTeams() { omp_set_dynamic(previous_); }

std::string BlasKernels() {
  using CoreName = char* (*)();
  const auto name = reinterpret_cast<CoreName>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  const char* core = name ? name() : nullptr;
  return core ? core : "";
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
