// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — metrics of the goal library (see goal_metrics.h).
#include "analysis/goal_metrics.h"

#include "core/dense_solve.h"
#include "core/newell.h"
#include "mesh/eigen_point.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <glog/logging.h>

namespace archgeo {
namespace {

// Relative singular-value threshold of PlanesMiss: normals that span fewer
// directions than this resolves are treated as rank-deficient.
constexpr double kRankThreshold = 1e-12;

using V = Eigen::Vector3d;

// Vector area (Newell) of a face: area times unit normal.
V VectorArea(const Mesh& mesh, FaceIndex f) {
  std::vector<V> p;  // from the source of the face's halfedge
  for (HalfedgeIndex h : mesh.halfedges_around_face(mesh.halfedge(f))) {
    p.push_back(EigenPoint(mesh, mesh.source(h)));
  }
  return 0.5 * NewellVector(int(p.size()), [&](int k) { return p[size_t(k)]; });
}

V Centroid(const Mesh& mesh, FaceIndex f) {
  V sum = V::Zero();
  int n = 0;
  for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) {
    sum += EigenPoint(mesh, v);
    ++n;
  }
  return (1.0 / n) * sum;
}

double Angle(const V& a, const V& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

}  // namespace

ConicalMeasure MeasureConical(const Mesh& mesh) {
  ConicalMeasure measure;
  double sum = 0.0;
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_border(v, /*check_all_incident_halfedges=*/true) || mesh.degree(v) != 4) continue;
    std::vector<V> edges;
    for (VertexIndex w : mesh.vertices_around_target(mesh.halfedge(v))) {
      edges.push_back(EigenPoint(mesh, w) - EigenPoint(mesh, v));
    }
    double omega[4];
    for (int k = 0; k < 4; ++k) omega[k] = Angle(edges[k], edges[(k + 1) % 4]);
    const double r = std::abs((omega[0] + omega[2]) - (omega[1] + omega[3]));
    ++measure.vertices;
    sum += r;
    if (r > measure.max || measure.worst_vertex < 0) {
      measure.max = r;
      measure.worst_vertex = static_cast<int>(v.idx());
    }
  }
  if (measure.vertices > 0) measure.mean = sum / measure.vertices;
  return measure;
}

double PlanesMiss(const std::vector<Vec3>& normals, const std::vector<double>& heights) {
  CHECK_EQ(normals.size(), heights.size()) << "PlanesMiss: one height per plane";
  CHECK_GE(normals.size(), 1u) << "PlanesMiss: no plane";
  const int k = static_cast<int>(normals.size());
  Eigen::MatrixXd n(k, 3);
  Eigen::VectorXd h(k);
  for (int f = 0; f < k; ++f) {
    n.row(f) << normals[f][0], normals[f][1], normals[f][2];
    h[f] = heights[f];
  }
  const Eigen::Vector3d q = SolveBySvd(n, h, kRankThreshold);
  return (n * q - h).cwiseAbs().maxCoeff();
}

FaceOffsetMeasure MeasureFaceOffsets(const Mesh& mesh, double offset) {
  CHECK(std::isfinite(offset)) << "MeasureFaceOffsets: non-finite offset";
  FaceOffsetMeasure measure;
  measure.offset = offset;
  measure.mean_edge_length = MeanEdgeLength(mesh);
  double sum = 0.0;
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_border(v, true) || mesh.degree(v) < 4) continue;
    const V p = EigenPoint(mesh, v);
    std::vector<Vec3> normals;
    std::vector<double> heights;
    for (FaceIndex f : mesh.faces_around_target(mesh.halfedge(v))) {
      const V area = VectorArea(mesh, f);
      const double length = area.norm();
      const V n = length > 0 ? V(area / length) : V::Zero();  // zero: no area, or NaN
      normals.push_back({n[0], n[1], n[2]});
      heights.push_back(n.dot(Centroid(mesh, f) - p) + offset);
    }
    const double miss = PlanesMiss(normals, heights);
    ++measure.vertices;
    sum += miss;
    if (miss > measure.max_miss || measure.worst_vertex < 0) {
      measure.max_miss = miss;
      measure.worst_vertex = static_cast<int>(v.idx());
    }
  }
  if (measure.vertices > 0) measure.mean_miss = sum / measure.vertices;
  if (measure.mean_edge_length > 0) {
    measure.max_relative = measure.max_miss / measure.mean_edge_length;
    measure.mean_relative = measure.mean_miss / measure.mean_edge_length;
  }
  return measure;
}

LengthSpread SpreadOf(const std::vector<double>& lengths) {
  LengthSpread spread;
  spread.count = static_cast<int>(lengths.size());
  if (lengths.empty()) return spread;
  const auto [min, max] = std::minmax_element(lengths.begin(), lengths.end());
  spread.min = *min;
  spread.max = *max;
  double sum = 0.0;
  for (double l : lengths) sum += l;
  spread.mean = sum / lengths.size();
  spread.ratio = spread.min > 0 ? spread.max / spread.min : 0.0;
  if (spread.mean > 0) {
    double squares = 0.0;
    for (double l : lengths) {
      squares += (l - spread.mean) * (l - spread.mean);
      spread.max_relative_deviation =
          std::max(spread.max_relative_deviation, std::abs(l / spread.mean - 1.0));
    }
    spread.relative_std = std::sqrt(squares / lengths.size()) / spread.mean;
  }
  return spread;
}

LengthSpread EdgeLengthSpread(const Mesh& mesh) {
  std::vector<double> lengths;
  for (EdgeIndex e : mesh.edges()) lengths.push_back(EdgeLength(mesh, e));
  return SpreadOf(lengths);
}

LengthSpread BoundaryEdgeLengthSpread(const Mesh& mesh) {
  std::vector<double> lengths;
  for (EdgeIndex e : mesh.edges()) {
    if (mesh.is_border(e)) lengths.push_back(EdgeLength(mesh, e));
  }
  return SpreadOf(lengths);
}

int NonConvexQuads(const Mesh& mesh) {
  int count = 0;
  for (FaceIndex f : mesh.faces()) {
    if (mesh.degree(f) != 4) continue;
    const V n = VectorArea(mesh, f);
    std::vector<V> p;
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) p.push_back(EigenPoint(mesh, v));
    bool convex = n.norm() > 0;
    for (int k = 0; k < 4 && convex; ++k) {
      const V turn = (p[k] - p[(k + 3) % 4]).cross(p[(k + 1) % 4] - p[k]);
      convex = turn.dot(n) > 0;
    }
    if (!convex) ++count;
  }
  return count;
}

std::vector<double> TributaryAreas(const Mesh& mesh) {
  std::vector<double> areas(mesh.num_vertices(), 0.0);
  for (FaceIndex f : mesh.faces()) {
    const double share = VectorArea(mesh, f).norm() / mesh.degree(f);
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) areas[v.idx()] += share;
  }
  return areas;
}

ForceBalanceMeasure MeasureForceBalance(const Mesh& mesh, const std::vector<Vec3>& loads,
                                        const std::vector<double>& stiffness,
                                        const std::vector<double>& rest_length,
                                        const std::vector<bool>& fixed) {
  CHECK_EQ(loads.size(), mesh.num_vertices()) << "MeasureForceBalance: one load per vertex";
  CHECK_EQ(fixed.size(), mesh.num_vertices()) << "MeasureForceBalance: one flag per vertex";
  CHECK_EQ(stiffness.size(), mesh.num_edges()) << "MeasureForceBalance: one stiffness per edge";
  CHECK_EQ(rest_length.size(), mesh.num_edges()) << "MeasureForceBalance: one rest length per edge";
  std::vector<V> resultant;
  resultant.reserve(loads.size());
  for (const Vec3& load : loads) resultant.push_back(EigenVector(load));
  for (EdgeIndex e : mesh.edges()) {
    CHECK(stiffness[e.idx()] > 0 && rest_length[e.idx()] >= 0)
        << "MeasureForceBalance: bad spring on edge " << e.idx();
    const HalfedgeIndex h = mesh.halfedge(e);
    const VertexIndex a = mesh.source(h), b = mesh.target(h);
    const V d = EigenPoint(mesh, b) - EigenPoint(mesh, a);  // a → b
    const double length = d.norm();
    const double l0 = rest_length[e.idx()];
    const double tension = l0 == 0      ? stiffness[e.idx()]
                           : length > 0 ? stiffness[e.idx()] * (1.0 - l0 / length)
                                        : 0.0;
    const V force = tension * d;  // on a, towards b
    resultant[a.idx()] += force;
    resultant[b.idx()] -= force;
  }
  ForceBalanceMeasure measure;
  double load_sum = 0.0, resultant_sum = 0.0;
  for (VertexIndex v : mesh.vertices()) {
    if (fixed[v.idx()]) continue;
    ++measure.free_vertices;
    load_sum += EigenVector(loads[v.idx()]).norm();
    const double r = resultant[v.idx()].norm();
    resultant_sum += r;
    measure.max_resultant = std::max(measure.max_resultant, r);
  }
  if (measure.free_vertices > 0) {
    measure.mean_load = load_sum / measure.free_vertices;
    measure.mean_resultant = resultant_sum / measure.free_vertices;
  }
  if (measure.mean_load > 0) measure.max_relative = measure.max_resultant / measure.mean_load;
  return measure;
}

}  // namespace archgeo
