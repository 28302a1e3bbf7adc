// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/wave_product.h"

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo::terms {
namespace {

void AddWaveProduct(TermContext& c, size_t e) {
  AddAutoDiff(c, WaveProduct(), {c.Block("wave_f", c.elements->Vertices(e)[0])});
}

}  // namespace

const TermSpec& wave_product() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "wave_product";
    t.summary = "product form of the standing wave per vertex: f1 f4 − f2 f3 = 0 (w2)";
    t.paper = "[Gebreiter 2012, §8.3.1; Zhang et al. 2010]";
    t.elements = "wave_vertices";
    t.reads = {"wave_f"};
    t.add = &AddWaveProduct;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::WaveProduct)
