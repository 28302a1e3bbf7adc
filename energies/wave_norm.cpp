// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/wave_norm.h"

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo::terms {
namespace {

void AddWaveNorm(TermContext& c, size_t e) {
  AddAutoDiff(c, WaveNorm(), {c.Block("wave_f", c.elements->Vertices(e)[0])});
}

}  // namespace

const TermSpec& wave_norm() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "wave_norm";
    t.summary = "unit 4-vector of the standing wave per vertex: |f_i|² = 1 (w1)";
    t.paper = "[Gebreiter 2012, §8.3.1; Zhang et al. 2010]";
    t.elements = "wave_vertices";
    t.reads = {"wave_f"};
    t.add = &AddWaveNorm;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::WaveNorm)
