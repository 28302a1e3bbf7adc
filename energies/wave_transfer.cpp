// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/wave_transfer.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/wave_elements.h"

namespace archgeo {

WaveTransfer::WaveTransfer(double alpha, double beta, int source_theta, double sign_theta,
                           int source_phi, double sign_phi) {
  CHECK(source_theta != source_phi && (source_theta == 0 || source_theta == 1) &&
        (source_phi == 0 || source_phi == 1))
      << "WaveTransfer: the matching must take θ and φ from different angles of j";
  CHECK(std::abs(sign_theta) == 1.0 && std::abs(sign_phi) == 1.0) << "WaveTransfer: signs ±1";
  const double ca = std::cos(alpha), sa = std::sin(alpha), cb = std::cos(beta),
               sb = std::sin(beta);
  const double Ra[2][2] = {{ca, -sa}, {sa, ca}}, Rb[2][2] = {{cb, -sb}, {sb, cb}};
  // Component 2a + b of f is trig_a(θ) trig_b(φ) (trig_0 = cos, trig_1 = sin).
  for (int a1 = 0; a1 < 2; ++a1) {
    for (int b1 = 0; b1 < 2; ++b1) {
      for (int a = 0; a < 2; ++a) {
        for (int b = 0; b < 2; ++b) C[size_t(4 * (2 * a1 + b1) + 2 * a + b)] = Ra[a1][a] * Rb[b1][b];
      }
      // i's θ^i = s_θ · ang_j[source_θ]: trig_a1(θ^i) = s_θ^a1 trig_a1(ang_j[source_θ]).
      const int r = 2 * a1 + b1;
      p_sign[size_t(r)] = (a1 ? sign_theta : 1.0) * (b1 ? sign_phi : 1.0);
      p_index[size_t(r)] = source_theta == 0 ? 2 * a1 + b1 : 2 * b1 + a1;
    }
  }
}

namespace terms {
namespace {

namespace wd = wave_data;

void AddWaveTransfer(TermContext& c, size_t e) {
  const double* d = c.elements->Data(e);
  const int* v = c.elements->Vertices(e);
  AddAutoDiff(c,
              WaveTransfer(d[wd::kAlpha], d[wd::kBeta], int(d[wd::kSourceTheta]),
                           d[wd::kSignTheta], int(d[wd::kSourcePhi]), d[wd::kSignPhi]),
              {c.Block("wave_f", v[0]), c.Block("wave_f", v[1])});
}

}  // namespace

const TermSpec& wave_transfer() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "wave_transfer";
    t.summary = "standing wave carried along each edge by the guidance and size fields: "
                "P_ij f_j = (R(α_ij) ⊗ R(β_ij)) f_i";
    t.paper = "[Gebreiter 2012, §8.3.1; Zhang et al. 2010]";
    t.elements = "wave_edges";
    t.reads = {"wave_f"};
    t.add = &AddWaveTransfer;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::WaveTransfer)
