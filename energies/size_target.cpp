// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/size_target.h"

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/size_elements.h"

namespace archgeo::terms {
namespace {

namespace sd = size_data;

void AddSizeTarget(TermContext& c, size_t e) {
  const double* d = c.elements->Data(e);
  AddAutoDiff(c, SizeTarget(d[sd::kTargetMu], d[sd::kTargetEta], d[sd::kWeightMu], d[sd::kWeightEta]),
              {c.Block("wave_size", c.elements->Vertices(e)[0])});
}

}  // namespace

const TermSpec& size_target() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "size_target";
    t.summary = "log sizes held to the designated size field per vertex: √A_v/t (log s − log t)";
    t.paper = "[Gebreiter 2012, §8.1.4; Zhang et al. 2010]";
    t.elements = "size_vertices";
    t.reads = {"wave_size"};
    t.add = &AddSizeTarget;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::SizeTarget)
