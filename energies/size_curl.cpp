// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/size_curl.h"

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/size_elements.h"

namespace archgeo {

SizeCurl::SizeCurl(double a, const std::array<double, 3>& g, const std::array<int, 3>& source)
    : a(a), g(g), source(source) {
  for (int s : source) CHECK(s == 0 || s == 1) << "SizeCurl: a corner's source is 0 or 1";
}

namespace terms {
namespace {

namespace sd = size_data;

void AddSizeCurl(TermContext& c, size_t e) {
  const double* d = c.elements->Data(e);
  const int* v = c.elements->Vertices(e);
  AddAutoDiff(c,
              SizeCurl(d[sd::kConstant], {d[sd::kGradient], d[sd::kGradient + 1], d[sd::kGradient + 2]},
                       {int(d[sd::kSource]), int(d[sd::kSource + 1]), int(d[sd::kSource + 2])}),
              {c.Block("wave_size", v[0]), c.Block("wave_size", v[1]), c.Block("wave_size", v[2])});
}

}  // namespace

const TermSpec& size_curl() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "size_curl";
    t.summary = "curl of the wave's phase gradient F/s per triangle, linear in the log sizes: "
                "√A (curl F + (n × F)·∇ log s)";
    t.paper = "[Gebreiter 2012, §8.1.4; Zhang et al. 2010; Polthier and Preuß 2003]";
    t.elements = "size_triangles";
    t.reads = {"wave_size"};
    t.add = &AddSizeCurl;
    return t;
  }();
  return spec;
}

}  // namespace terms
}  // namespace archgeo

ARCHGEO_AUTODIFF(archgeo::SizeCurl)
