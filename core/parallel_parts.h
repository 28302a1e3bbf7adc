// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — ForParts: a loop cut into a fixed number of parts, T, each run on
// a thread of its own, for LeanSolve's assembly, products and sums
// (core/lean_solve.cpp, core/lean_kernels.cpp, core/normal_equations.cpp).
// T is solver.num_threads. Where the cut is fixed by T alone and every sum
// over the parts is added part by part in order (SumParts), a result depends
// on T and not on the threads that happen to run the parts: the same T gives
// the same bits run to run, on any number of cores.
#pragma once

#include <cstddef>
#include <vector>

namespace archgeo {

// Runs body(t) for t = 0 .. parts − 1, on `parts` threads (OpenMP creates
// that many whatever the cores, unless OMP_DYNAMIC lets it create fewer:
// then a thread runs several parts, to the same results).
template <class Body>
void ForParts(int parts, const Body& body) {
#pragma omp parallel for num_threads(parts) schedule(static, 1) if (parts > 1)
  for (int t = 0; t < parts; ++t) body(t);
}

// The first index of part t of [0, n) cut into `parts` near-equal parts
// (t = parts: n).
inline size_t PartStart(size_t n, int parts, int t) { return n * size_t(t) / size_t(parts); }

// Σ_t body(t) over the parts, each part's value computed on its thread, then
// added in part order: ((v_0 + v_1) + v_2) + …
template <class Body>
double SumParts(int parts, const Body& body) {
  std::vector<double> value(size_t(parts), 0.0);
  ForParts(parts, [&](int t) { value[size_t(t)] = body(t); });
  double sum = value[0];
  for (int t = 1; t < parts; ++t) sum += value[size_t(t)];
  return sum;
}

}  // namespace archgeo
