// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "spectral/critical_points.h"

namespace archgeo {
namespace {

// f(u) > f(v), ties broken by index.
bool Above(const Eigen::VectorXd& f, int u, int v) { return f[u] > f[v] || (f[u] == f[v] && u > v); }

}  // namespace

CriticalPoints FindCriticalPoints(const std::vector<std::vector<int>>& rings,
                                  const std::vector<bool>& closed, const Eigen::VectorXd& f) {
  CriticalPoints out;
  for (int v = 0; v < int(rings.size()); ++v) {
    const std::vector<int>& ring = rings[v];
    if (!closed[v] || ring.size() < 3) continue;
    int changes = 0, above = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
      const bool a = Above(f, ring[i], v);
      above += a;
      changes += a != Above(f, ring[(i + 1) % ring.size()], v);
    }
    if (changes == 0) {
      (above == 0 ? out.maxima : out.minima) += 1;
    } else if (changes >= 4) {
      out.saddles += changes / 2 - 1;
      out.multi_saddles += changes >= 6;
    }
  }
  return out;
}

}  // namespace archgeo
