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
    if (ring.size() < 2) continue;
    const size_t steps = closed[v] ? ring.size() : ring.size() - 1;
    int changes = 0, above = 0;
    for (size_t i = 0; i < ring.size(); ++i) above += Above(f, ring[i], v);
    for (size_t i = 0; i < steps; ++i) {
      changes += Above(f, ring[i], v) != Above(f, ring[(i + 1) % ring.size()], v);
    }
    const int extremum = changes == 0 ? (above == 0 ? 1 : -1) : 0;  // 1 max, −1 min
    if (closed[v]) {
      out.maxima += extremum == 1;
      out.minima += extremum == -1;
      if (changes >= 4) out.saddles += changes / 2 - 1;
      out.multi_saddles += changes >= 6;
    } else {
      out.boundary_maxima += extremum == 1;
      out.boundary_minima += extremum == -1;
      if (changes >= 2) out.boundary_saddles += changes - 1;
    }
  }
  return out;
}

}  // namespace archgeo
