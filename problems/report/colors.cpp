// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/report/colors.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>

#include "geometry/hnet.h"
#include "analysis/metrics.h"
#include "analysis/smoothness_metrics.h"
#include "problems/declarations/hnet_net.h"

namespace archgeo {
namespace {

constexpr double kKinkRedDegrees = 1.0;
// The default tolerance.pq_normalized_max of planar_quads.
constexpr double kPlanarityRedDefault = 1e-3;

double MeanEdgeLength(const Mesh& mesh) {
  double sum = 0;
  for (EdgeIndex e : mesh.edges()) {
    sum += std::sqrt(
        CGAL::squared_distance(mesh.point(mesh.vertex(e, 0)), mesh.point(mesh.vertex(e, 1))));
  }
  return sum / double(std::max<size_t>(1, mesh.number_of_edges()));
}

// max over a face's edges of ℓ|α| / mean edge length.
std::vector<double> Bending(const Mesh& mesh) {
  const EdgeSmoothness edges = MeasureEdgeSmoothness(mesh, FaceNormals(mesh));
  const double mean = MeanEdgeLength(mesh);
  std::vector<double> values(mesh.num_faces(), 0.0);
  for (FaceIndex f : mesh.faces()) {
    double value = 0;
    for (HalfedgeIndex h : mesh.halfedges_around_face(mesh.halfedge(f))) {
      value = std::max(value, edges.energy[mesh.edge(h).idx()]);
    }
    values[f.idx()] = mean > 0 ? value / mean : 0.0;
  }
  return values;
}

std::vector<double> Kinks(const Mesh& mesh, const Settings* s) {
  const HNet h = BuildHNet(mesh, s ? HNetOptionsOf(*s) : HNetOptions{});
  std::vector<double> values(mesh.num_faces(), 0.0);
  for (EdgeIndex e : mesh.edges()) {
    const double k = h.kink_degrees[e.idx()];
    if (!(k > 0)) continue;
    for (int i = 0; i < 2; ++i) {
      const FaceIndex f = mesh.face(mesh.halfedge(e, i));
      if (f != Mesh::null_face()) values[f.idx()] = std::max(values[f.idx()], k);
    }
  }
  return values;
}

double Max(const std::vector<double>& values) {
  double m = 0;
  for (double x : values) m = std::max(m, x);
  return m;
}

}  // namespace

const std::vector<std::string>& FaceValueNames() {
  static const std::vector<std::string> names = {"planarity", "bending", "curvature", "kinks"};
  return names;
}

FaceValues ComputeFaceValues(const std::string& name, const Mesh& mesh, const Mesh* input,
                             const Settings* s, double color_max) {
  FaceValues v;
  if (name == "planarity") {
    v.name = "pq_normalized";
    v.label = "planarity δ_PQ,n: diagonal distance";
    v.units = "/ mean diagonal";
    v.values = MeasureFacePlanarity(mesh).normalized;
    v.values.resize(mesh.num_faces(), 0.0);
    v.red_at = kPlanarityRedDefault;
    v.red_from = "default 1e-3, planar_quads' default tolerance";
    const char* tolerance = "tolerance.pq_normalized_max";
    if (s && s->schema().Find(tolerance) && s->Number(tolerance) > 0) {
      v.red_at = s->Number(tolerance);
      v.red_from = tolerance;
    }
  } else if (name == "bending" || name == "curvature") {
    v.name = "bending";
    v.label = "bending: max ℓ|α| of the face's edges / mean edge length";
    v.units = "rad";
    v.values = Bending(mesh);
    v.red_at = Max(input ? Bending(*input) : v.values);
    v.red_from = input ? "the input's largest value" : "the largest value";
    if (!(v.red_at > 0)) {
      v.red_at = 1e-3;
      v.red_from = "1e-3 (the mesh is flat)";
    }
  } else if (name == "kinks") {
    v.name = "kink_degrees";
    v.label = "H-net kink: largest kink angle along the face's edges";
    v.units = "degrees";
    v.values = Kinks(mesh, s);
    v.red_at = kKinkRedDegrees;
    v.red_from = "default 1 degree";
  } else {
    LOG(FATAL) << "unknown face values '" << name << "'";
  }
  if (s && s->Given("output.color_max")) {
    v.red_at = s->Number("output.color_max");
    v.red_from = "output.color_max";
  } else if (color_max > 0) {
    v.red_at = color_max;
    v.red_from = "--color-max";
  }
  return v;
}

FaceColors ColorsOf(const FaceValues& values) {
  FaceColors colors;
  colors.reserve(values.values.size());
  for (double x : values.values) colors.push_back(ScaleColor(x, values.red_at));
  return colors;
}

FaceColors OutputColors(const std::string& name, const Mesh& output, const Settings& s,
                        const Mesh* input) {
  return ColorsOf(ComputeFaceValues(name, output, input, &s));
}

}  // namespace archgeo
