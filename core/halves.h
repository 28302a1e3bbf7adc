// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — ForHalves: one loop split into two fixed halves, each on a
// thread of its own where there are two (core/lean_solve.cpp's sums and
// products, core/normal_equations.cpp's pattern). The halves are fixed, so
// a result built half by half is the same on one thread or two.
#pragma once

#include <algorithm>
#include <cstddef>

#include <omp.h>

namespace archgeo {

// Runs body(t, first, end) for the two fixed halves of [0, n), t = 0 on
// [0, split) and t = 1 on [split, n): on two threads where there are, and
// the same sums on one (omp_set_num_threads(1) runs both halves there).
template <class Body>
void ForHalves(size_t split, size_t n, const Body& body) {
  const int threads = std::min(2, omp_get_max_threads());
#pragma omp parallel for num_threads(threads) schedule(static, 1)
  for (int t = 0; t < 2; ++t) body(t, t == 0 ? 0 : split, t == 0 ? split : n);
}

}  // namespace archgeo
