// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fields/tcd_field.h"

#include <algorithm>
#include <cmath>

#include <glog/logging.h>

namespace archgeo {

FieldGeometry ComputeFieldGeometry(const Mesh& mesh, const JetOptions& jets) {
  FieldGeometry g;
  g.frames = ComputeSmoothFrames(mesh);
  g.transports = ComputeTransports(mesh, g.frames, &g.edge_to_transport);
  g.curvature = ComputeFaceCurvature(mesh, g.frames, jets);
  for (double a : g.frames.area) g.total_area += a;
  for (const FaceCurvature& c : g.curvature) g.flat_faces += c.flat ? 1 : 0;
  return g;
}

bool AllFlat(const FieldGeometry& geometry) {
  return !geometry.curvature.empty() &&
         geometry.flat_faces == static_cast<int>(geometry.curvature.size());
}

TcdField EvaluateField(const Mesh& mesh, const FieldGeometry& geometry,
                       std::vector<Eigen::Vector2d> z_n) {
  CHECK_EQ(z_n.size(), mesh.number_of_faces());
  TcdField field;
  field.z_n = std::move(z_n);
  field.smooth_fallback = AllFlat(geometry);
  if (field.smooth_fallback) {
    field.pairs.resize(field.z_n.size());
    for (ConjugatePair& p : field.pairs) {
      p.v = Eigen::Vector2d(1.0, 0.0);
      p.w = Eigen::Vector2d(0.0, 1.0);
      p.valid = true;
    }
  } else {
    field.pairs = TcdPairs(geometry.curvature, field.z_n);
  }
  field.stats = FieldStats(geometry.curvature, field.pairs);
  double sum = 0;
  int n = 0;
  for (const ConjugatePair& p : field.pairs) {
    if (!p.valid) continue;
    sum += std::acos(std::min(1.0, std::abs(p.v.dot(p.w)))) * 180.0 / M_PI;
    ++n;
  }
  field.mean_angle_deg = n > 0 ? sum / n : 0.0;
  field.vertex_index = VertexIndices(mesh, geometry.transports, geometry.edge_to_transport,
                                     BisectorAngles(field.pairs));
  field.singularities = Singularities(mesh, field.vertex_index);
  for (double x : field.vertex_index) field.index_sum += x;
  return field;
}

}  // namespace archgeo
