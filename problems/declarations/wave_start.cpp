// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/declarations/wave_start.h"

#include <cmath>
#include <queue>

#include "energies/wave_elements.h"
#include "energies/wave_transfer.h"

namespace archgeo {
namespace {

namespace wd = wave_data;

WaveTransfer WaveStartTransfer(const ElementSet& edges, size_t k) {
  const double* d = edges.Data(k);
  return WaveTransfer(d[wd::kAlpha], d[wd::kBeta], int(d[wd::kSourceTheta]), d[wd::kSignTheta],
                      int(d[wd::kSourcePhi]), d[wd::kSignPhi]);
}

// The end of edge k that makes P f_j − C f_i zero, from the other end:
// forward (i known) f_j[p_index[r]] = p_sign[r] (C f_i)[r]; backward
// (j known) f_i = Cᵀ P f_j (C orthogonal).
void WaveStartCarry(const WaveTransfer& t, bool forward, const double* from, double* to) {
  if (forward) {
    for (int r = 0; r < 4; ++r) {
      double sum = 0;
      for (int c = 0; c < 4; ++c) sum += t.C[size_t(4 * r + c)] * from[c];
      to[t.p_index[size_t(r)]] = t.p_sign[size_t(r)] * sum;
    }
    return;
  }
  double pf[4];
  for (int r = 0; r < 4; ++r) pf[r] = t.p_sign[size_t(r)] * from[t.p_index[size_t(r)]];
  for (int c = 0; c < 4; ++c) {
    double sum = 0;
    for (int r = 0; r < 4; ++r) sum += t.C[size_t(4 * r + c)] * pf[r];
    to[c] = sum;
  }
}

}  // namespace

std::vector<double> IntegratedWave(const ElementSet& edges, int vertices, int root, double theta,
                                   double phi) {
  const double f0[4] = {std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi),
                        std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi)};
  std::vector<std::vector<size_t>> incident(static_cast<size_t>(vertices));
  for (size_t k = 0; k < edges.size(); ++k) {
    incident[size_t(edges.Vertices(k)[0])].push_back(k);
    incident[size_t(edges.Vertices(k)[1])].push_back(k);
  }
  std::vector<double> f(4 * size_t(vertices), 0.0);
  std::vector<char> reached(size_t(vertices), 0);
  for (int start = 0; start < vertices; ++start) {
    const int seed = start == 0 ? root : start;  // the root first, then other components
    if (reached[size_t(seed)]) continue;
    reached[size_t(seed)] = 1;
    for (int c = 0; c < 4; ++c) f[4 * size_t(seed) + size_t(c)] = f0[c];
    std::queue<int> queue;
    queue.push(seed);
    while (!queue.empty()) {
      const int v = queue.front();
      queue.pop();
      for (size_t k : incident[size_t(v)]) {
        const int* ends = edges.Vertices(k);
        const bool forward = ends[0] == v;
        const int w = forward ? ends[1] : ends[0];
        if (reached[size_t(w)]) continue;
        reached[size_t(w)] = 1;
        WaveStartCarry(WaveStartTransfer(edges, k), forward, &f[4 * size_t(v)],
                       &f[4 * size_t(w)]);
        queue.push(w);
      }
    }
  }
  return f;
}

int KeptWaveStart(const std::vector<bool>& valid, const std::vector<double>& energy) {
  int kept = 0;
  for (size_t k = 0; k < valid.size() && k < energy.size(); ++k) {
    if (valid[k] && (kept == 0 || energy[k] < energy[size_t(kept - 1)])) kept = int(k) + 1;
  }
  return kept;
}

}  // namespace archgeo
