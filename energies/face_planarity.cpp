// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/face_planarity.h"

#include <array>
#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "core/newell.h"
#include "core/tolerance_band.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

namespace {


FacePlanarity CheckedFacePlanarity(const double center[3], double inv_length) {
  CHECK(center != nullptr);
  CHECK(std::isfinite(center[0]) && std::isfinite(center[1]) &&
        std::isfinite(center[2]))
      << "FacePlanarity: non-finite center";
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "FacePlanarity: inv_length must be finite and > 0, got "
      << inv_length;
  return FacePlanarity(center, inv_length);
}

}  // namespace

}  // namespace archgeo

// --- term `face_planarity` -----------------------------------------------------

namespace archgeo::terms {
void InitFacePlaneNormal(TermContext& c, int face, const int* vs, int count) {
  double* n = c.Block("face_plane_normal", face);
  if (n[0] != 0 || n[1] != 0 || n[2] != 0) return;  // set already
  const Eigen::Vector3d unit =
      NewellNormal(count, [&](int k) { return c.Position(vs[k]); });  // core/newell.h
  const bool ok = unit.norm() > 0;
  n[0] = ok ? unit[0] : 0;
  n[1] = ok ? unit[1] : 0;
  n[2] = ok ? unit[2] : 1;
}

namespace {

void InitFacePlanes(TermContext& c) {
  for (size_t i = 0; i < c.elements->size(); ++i) {
    InitFacePlaneNormal(c, c.elements->face[i], c.elements->Vertices(i), c.elements->Count(i));
    c.Block("face_plane_offset", c.elements->face[i])[0] = 0;
  }
}

// Each round the plane is re-centred at the face's current centroid c (the
// offset d becomes the mean of n·(v − c)), L = the mean (i, i+2) diagonal.
void AddFacePlanarity(TermContext& c, size_t i) {
  const int* vs = c.elements->Vertices(i);
  const int k = c.elements->Count(i);
  const int face = c.elements->face[i];
  std::array<double, 3> center{0, 0, 0};
  for (int j = 0; j < k; ++j) {
    for (int a = 0; a < 3; ++a) center[a] += c.Position(vs[j])[a];
  }
  for (int a = 0; a < 3; ++a) center[a] /= double(k);
  double diagonal = 0;
  for (int j = 0; j < k; ++j) {
    const double* p = c.Position(vs[(j + 2) % k]);
    const double* q = c.Position(vs[j]);
    diagonal += std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                          (p[2] - q[2]) * (p[2] - q[2]));
  }
  double* n = c.Block("face_plane_normal", face);
  double* d = c.Block("face_plane_offset", face);
  double offset = 0;
  for (int j = 0; j < k; ++j) {
    const double* p = c.Position(vs[j]);
    offset += (n[0] * (p[0] - center[0]) + n[1] * (p[1] - center[1]) + n[2] * (p[2] - center[2])) /
              double(k);
  }
  d[0] = offset;
  const double inv_length = diagonal > 0 ? double(k) / diagonal : 1.0;
  const FacePlanarity functor = CheckedFacePlanarity(center.data(), inv_length);
  for (int j = 0; j < k; ++j) AddAutoDiff(c, functor, {n, d, c.Position(vs[j])}, c.band);
  c.SetUnit(n);
}

}  // namespace

const TermSpec& face_planarity() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "face_planarity";
    t.summary = "faces with more sides: every vertex on the face's plane (unit normal + offset)";
    t.paper = "[Pellis 2019, Fig. 18; Zadravec 2010, §6 for polygons]";
    t.elements = "polygons";
    t.element_choices = {"non_triangles", "faces", "quads"};
    t.declares = {
        {"face_plane_normal", Site::kFace, 3, FrameMap::kDirection, true, Carry::kReinitialise,
         false, false, "unit normal of a face's plane (face_planarity, dihedral_energy)"},
        {"face_plane_offset", Site::kFace, 1, FrameMap::kLength, false, Carry::kReinitialise,
         false, false, "offset of a face's plane from its centroid"}};
    t.supports_band = true;
    t.init = &InitFacePlanes;
    t.drives = "pq_normalized_max";
    t.add = &AddFacePlanarity;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::FacePlanarity)
