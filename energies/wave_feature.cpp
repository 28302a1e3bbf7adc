// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/wave_feature.h"

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/wave_elements.h"

namespace archgeo {

WaveFeature::WaveFeature(int kind) {
  namespace wd = wave_data;
  CHECK(kind == wd::kSinTheta || kind == wd::kSinPhi || kind == wd::kCorner)
      << "WaveFeature: unknown kind " << kind;
  if (kind == wd::kSinPhi) {
    pick[0] = 1;
    pick[1] = 3;
  } else if (kind == wd::kSinTheta) {
    pick[0] = 2;
    pick[1] = 3;
  } else {
    pick[0] = 1;
    pick[1] = 2;
    pick[2] = 3;
  }
}

namespace terms {
namespace {

void AddWaveFeature(TermContext& c, size_t e) {
  const double* d = c.elements->Data(e);
  AddAutoDiff(c, WaveFeature(int(d[wave_data::kKind])),
              {c.Block("wave_f", c.elements->Vertices(e)[0])});
}

}  // namespace

const TermSpec& wave_feature() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "wave_feature";
    t.summary = "feature constraint of the standing wave on boundary vertices: sin φ = 0 or "
                "sin θ = 0, corners both";
    t.paper = "[Gebreiter 2012, §8.3.2; Zhang et al. 2010]";
    t.elements = "wave_features";
    t.reads = {"wave_f"};
    t.add = &AddWaveFeature;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::WaveFeature)
