// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/report/colors.h"

#include <glog/logging.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "core/input_error.h"
#include "geometry/hnet.h"
#include "analysis/metrics.h"
#include "analysis/smoothness_metrics.h"
#include "problems/declarations/hnet_net.h"

namespace archgeo {
namespace {

constexpr double kKinkRedDegrees = 1.0;
// The default tolerance.pq_normalized_max of planar_quads.
constexpr double kPlanarityRedDefault = 1e-3;

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

// Each face's share of E = Σ_e ℓ_e ℓ*_e (half of each of its edges'), in
// units of `mean` (a length).
std::vector<double> EnergyShares(const Mesh& mesh, double mean) {
  const EdgeSmoothness edges = MeasureEdgeSmoothness(mesh, FaceNormals(mesh));
  std::vector<double> values(mesh.num_faces(), 0.0);
  for (FaceIndex f : mesh.faces()) {
    double value = 0;
    for (HalfedgeIndex h : mesh.halfedges_around_face(mesh.halfedge(f))) {
      const size_t e = mesh.edge(h).idx();
      value += 0.5 * edges.length[e] * edges.dual_length[e];
    }
    values[f.idx()] = mean > 0 ? value / mean : 0.0;
  }
  return values;
}

// Each face's share of C = Σ_v |λ1| + |λ2| (W′ of smoothness_metrics.h):
// each corner's value over its number of faces, in units of `mean`.
std::vector<double> CurvatureShares(const Mesh& mesh, double mean) {
  const std::vector<Vec3> normals = FaceNormals(mesh);
  std::vector<double> corner(mesh.num_vertices(), 0.0);
  for (VertexIndex v : mesh.vertices()) {
    const std::array<double, 2> lambda = ShapeOperatorEigenvalues(mesh, normals, v);
    int faces = 0;
    for (FaceIndex f : mesh.faces_around_target(mesh.halfedge(v))) faces += f != Mesh::null_face();
    corner[v.idx()] = faces > 0 ? (std::abs(lambda[0]) + std::abs(lambda[1])) / faces : 0.0;
  }
  std::vector<double> values(mesh.num_faces(), 0.0);
  for (FaceIndex f : mesh.faces()) {
    double value = 0;
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) value += corner[v.idx()];
    values[f.idx()] = mean > 0 ? value / mean : 0.0;
  }
  return values;
}

// The largest |90° − corner angle| of each face, degrees.
std::vector<double> Orthogonality(const Mesh& mesh) {
  std::vector<double> values(mesh.num_faces(), 0.0);
  for (FaceIndex f : mesh.faces()) {
    std::vector<Vector> p;
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) {
      p.push_back(mesh.point(v) - CGAL::ORIGIN);
    }
    double worst = 0;
    for (size_t i = 0; i < p.size(); ++i) {
      const Vector a = p[(i + 1) % p.size()] - p[i], b = p[(i + p.size() - 1) % p.size()] - p[i];
      const double angle = std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b);
      worst = std::max(worst, std::abs(90.0 - angle * 180.0 / 3.14159265358979323846));
    }
    values[f.idx()] = worst;
  }
  return values;
}

// The 95th percentile of `values` (0 for none): a scale that a few extreme
// faces do not set.
double Percentile95(std::vector<double> values) {
  if (values.empty()) return 0;
  const size_t k = size_t(0.95 * double(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + long(k), values.end());
  return values[k];
}

std::vector<double> Kinks(const Mesh& mesh, const Settings* s) {
  for (FaceIndex f : mesh.faces()) {
    if (mesh.degree(f) != 4) {
      throw InputError("", 0, "--value",
                       "kinks are the angles between an H-net's patches, which need an all-quad mesh; "
                       "face " + std::to_string(f.idx()) + " has " + std::to_string(mesh.degree(f)) +
                           " sides (another --value, e.g. bending, shows this mesh)");
    }
  }
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
  static const std::vector<std::string> names = {"planarity", "energy",        "curvature",
                                                 "bending",   "orthogonality", "kinks"};
  return names;
}

namespace {

// red_at from the input's values (the same scale for input and output).
void ScaleByInput(FaceValues& v, const std::vector<double>& input_values, bool from_input) {
  v.red_at = Percentile95(input_values);
  v.red_from = from_input ? "the input's 95th percentile" : "the 95th percentile";
  if (!(v.red_at > 0)) {
    v.red_at = Max(input_values);
    v.red_from = from_input ? "the input's largest value" : "the largest value";
  }
  if (!(v.red_at > 0)) {
    v.red_at = 1e-3;
    v.red_from = "1e-3 (no value above 0)";
  }
}

}  // namespace

FaceValues ComputeFaceValues(const std::string& name, const Mesh& mesh, const Mesh* input,
                             const Settings* s, double color_max) {
  FaceValues v;
  const Mesh& base = input ? *input : mesh;
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
  } else if (name == "energy") {
    const double mean = MeanEdgeLength(base);
    v.name = "energy_share";
    v.label = "E = Σ ℓ ℓ*: the face's share (half of its edges' ℓ ℓ*)";
    v.units = "mean edge (input)";
    v.values = EnergyShares(mesh, mean);
    ScaleByInput(v, input ? EnergyShares(*input, mean) : v.values, input != nullptr);
  } else if (name == "curvature") {
    const double mean = MeanEdgeLength(base);
    v.name = "curvature_share";
    v.label = "C = Σ |κ1|+|κ2| (W′ eigenvalues): the face's share of its corners'";
    v.units = "mean edge (input)";
    v.values = CurvatureShares(mesh, mean);
    ScaleByInput(v, input ? CurvatureShares(*input, mean) : v.values, input != nullptr);
  } else if (name == "bending") {
    v.name = "bending";
    v.label = "bending: max ℓ|α| of the face's edges / mean edge length";
    v.units = "rad";
    v.values = Bending(mesh);
    ScaleByInput(v, input ? Bending(*input) : v.values, input != nullptr);
  } else if (name == "orthogonality") {
    v.name = "orthogonality_degrees";
    v.label = "orthogonality: the face's largest |90° − corner angle|";
    v.units = "degrees";
    v.values = Orthogonality(mesh);
    ScaleByInput(v, input ? Orthogonality(*input) : v.values, input != nullptr);
    if (s && s->schema().Find("tolerance.mdo") && s->Number("tolerance.mdo") > 0) {
      v.red_at = s->Number("tolerance.mdo");
      v.red_from = "tolerance.mdo";
    }
  } else if (name == "none") {
    v.name = "none";
    v.label = "the problem has no per-face quantity to show";
    v.values.assign(mesh.num_faces(), 0.0);
    v.red_at = 1;
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

FaceValues StateFaceValues(std::string name, std::string label, std::string units,
                           std::vector<double> values, const std::vector<double>& input_values,
                           const Settings* s) {
  FaceValues v;
  v.name = std::move(name);
  v.label = std::move(label);
  v.units = std::move(units);
  v.values = std::move(values);
  ScaleByInput(v, input_values, true);
  if (s && s->Given("output.color_max")) {
    v.red_at = s->Number("output.color_max");
    v.red_from = "output.color_max";
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
