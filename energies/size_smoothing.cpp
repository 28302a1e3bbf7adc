// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/size_smoothing.h"

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/size_elements.h"

namespace archgeo {

SizeSmoothing::SizeSmoothing(int source_mu) : source_mu(source_mu) {
  CHECK(source_mu == 0 || source_mu == 1) << "SizeSmoothing: source_mu is 0 or 1";
}

namespace terms {
namespace {

namespace sd = size_data;

void AddSizeSmoothing(TermContext& c, size_t e) {
  const int* v = c.elements->Vertices(e);
  AddAutoDiff(c, SizeSmoothing(int(c.elements->Data(e)[sd::kSourceMu])),
              {c.Block("wave_size", v[0]), c.Block("wave_size", v[1])});
}

}  // namespace

const TermSpec& size_smoothing() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "size_smoothing";
    t.summary = "smooth log sizes: (log s_i − log s_j) per edge, matched across the cross field";
    t.paper = "[Gebreiter 2012, §8.1.4; Zhang et al. 2010]";
    t.elements = "size_edges";
    t.reads = {"wave_size"};
    t.add = &AddSizeSmoothing;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::SizeSmoothing)
