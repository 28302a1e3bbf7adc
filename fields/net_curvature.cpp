// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — a net's edges against the surface's curvature directions (see
// net_curvature.h).
#include "fields/net_curvature.h"

#include <algorithm>
#include <array>
#include <cmath>


#include "fields/conjugate.h"
#include "fields/face_curvature.h"
#include "mesh/eigen_point.h"

namespace archgeo {
namespace {

// Below this κ × bounding-box diagonal a face or edge counts as flat.
constexpr double kFlat = 1e-6;
// Principal directions are measured only where |k1 − k2| ≥ this × κ.
constexpr double kUmbilic = 0.1;

double Degrees(double radians) { return radians * 180.0 / M_PI; }

// The shape tensor S restricted to the plane normal to n: principal
// curvatures k1 ≥ k2 and their unit directions (3-D, in the plane).
struct Tangent {
  double k1 = 0, k2 = 0;
  Eigen::Vector3d d1, d2;
  double kappa() const { return std::max(std::abs(k1), std::abs(k2)); }
  Eigen::Vector2d In(const Eigen::Vector3d& t) const { return {t.dot(d1), t.dot(d2)}; }
};

Tangent Restrict(const Eigen::Matrix3d& S, const Eigen::Vector3d& n) {
  const Eigen::Vector3d a = n.unitOrthogonal(), b = n.cross(a);
  Eigen::Matrix2d M;
  M << a.dot(S * a), a.dot(S * b), b.dot(S * a), b.dot(S * b);
  M = 0.5 * (M + M.transpose()).eval();
  const SymmetricEigen2 eigen = EigenOfSymmetric2(M);  // ascending
  Tangent t;
  t.k2 = eigen.values[0];
  t.k1 = eigen.values[1];
  const Eigen::Vector2d e1 = eigen.vectors.col(1), e2 = eigen.vectors.col(0);
  t.d1 = e1[0] * a + e1[1] * b;
  t.d2 = e2[0] * a + e2[1] * b;
  return t;
}

// Angle (degrees, 0..90) between the lines of two non-zero plane vectors.
double LineAngleBetween(const Eigen::Vector2d& x, const Eigen::Vector2d& y) {
  const double c = std::abs(x.normalized().dot(y.normalized()));
  return Degrees(std::acos(std::min(1.0, c)));
}

double BboxDiagonal(const Mesh& mesh) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = -lo;
  for (VertexIndex v : mesh.vertices()) {
    lo = lo.cwiseMin(EigenPoint(mesh, v));
    hi = hi.cwiseMax(EigenPoint(mesh, v));
  }
  return mesh.number_of_vertices() > 0 ? (hi - lo).norm() : 0.0;
}


}  // namespace

NetCurvatureFigures MeasureNetCurvature(const Mesh& net) {
  NetCurvatureFigures out;
  std::vector<FaceIndex> sample;
  for (FaceIndex f : net.faces()) {
    if (net.degree(f) == 4) sample.push_back(f);
  }
  out.quads = int(sample.size());
  if (sample.size() > size_t(kSampledQuads)) {
    // The golden-ratio (Weyl) sequence over the face order: spread over the
    // rows and the columns of a grid of any width (a fixed stride that
    // divides the width, e.g. 200 on a 1000-wide grid, would read 5 columns).
    std::vector<size_t> pick;
    for (int k = 1; k <= kSampledQuads; ++k) {
      const double t = k * 0.6180339887498949;
      pick.push_back(size_t((t - std::floor(t)) * double(sample.size())));
    }
    std::sort(pick.begin(), pick.end());
    pick.erase(std::unique(pick.begin(), pick.end()), pick.end());
    std::vector<FaceIndex> kept;
    for (size_t i : pick) kept.push_back(sample[i]);
    sample.swap(kept);
  }
  out.sampled = int(sample.size());
  std::vector<char> fit(net.number_of_vertices(), 0);
  for (FaceIndex f : sample) {
    for (VertexIndex v : net.vertices_around_face(net.halfedge(f))) fit[v.idx()] = 1;
  }
  const std::vector<Eigen::Matrix3d> S = VertexShapeTensors(net, JetOptions(), fit);
  const double flat = kFlat / std::max(BboxDiagonal(net), 1e-300);
  double conjugacy_sum = 0, angle_sum = 0;
  for (FaceIndex f : sample) {
    std::array<Eigen::Vector3d, 4> p;
    Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
    int k = 0;
    for (VertexIndex v : net.vertices_around_face(net.halfedge(f))) {
      tensor += 0.25 * S[v.idx()];
      p[k++] = EigenPoint(net, v);
    }
    const Eigen::Vector3d normal = (p[2] - p[0]).cross(p[3] - p[1]);
    if (normal.norm() == 0) continue;
    const Tangent t = Restrict(tensor, normal.normalized());
    if (t.kappa() < flat) continue;
    const Eigen::Vector2d u = t.In(0.5 * (p[1] - p[0] + p[2] - p[3]));
    const Eigen::Vector2d v = t.In(0.5 * (p[3] - p[0] + p[2] - p[1]));
    if (u.norm() == 0 || v.norm() == 0) continue;
    ++out.measured;
    const auto II = [&](const Eigen::Vector2d& x, const Eigen::Vector2d& y) {
      return t.k1 * x[0] * y[0] + t.k2 * x[1] * y[1];
    };
    const double conjugacy = std::abs(II(u, v)) / (t.kappa() * u.norm() * v.norm());
    conjugacy_sum += conjugacy;
    out.conjugacy_max = std::max(out.conjugacy_max, conjugacy);
    if (!(t.k1 > 0 && t.k2 < 0)) continue;
    ++out.negative_curvature;
    const double theta = std::atan(std::sqrt(-t.k1 / t.k2));
    const Eigen::Vector2d a(std::cos(theta), std::sin(theta)), b(std::cos(theta), -std::sin(theta));
    const auto nearest = [&](const Eigen::Vector2d& x) {
      return std::min(LineAngleBetween(x, a), LineAngleBetween(x, b));
    };
    const double angle = std::max(nearest(u), nearest(v));
    angle_sum += angle;
    out.asymptotic_angle_max = std::max(out.asymptotic_angle_max, angle);
  }
  if (out.measured > 0) {
    out.conjugacy_mean = conjugacy_sum / out.measured;
    out.positive_curvature_fraction = 1.0 - double(out.negative_curvature) / out.measured;
  }
  if (out.negative_curvature > 0) out.asymptotic_angle_mean = angle_sum / out.negative_curvature;
  return out;
}

PrincipalLabelFigures MeasurePrincipalLabels(const Mesh& mesh,
                                             const std::vector<std::pair<int, int>>& labels) {
  PrincipalLabelFigures out;
  const std::vector<Eigen::Matrix3d> S = VertexShapeTensors(mesh, JetOptions());
  const double flat = kFlat / std::max(BboxDiagonal(mesh), 1e-300);
  double sum = 0;
  for (const auto& [i, j] : labels) {
    ++out.edges;
    if (i < 0 || j < 0 || i >= int(mesh.number_of_vertices()) ||
        j >= int(mesh.number_of_vertices())) {
      continue;
    }
    const HalfedgeIndex h = mesh.halfedge(VertexIndex(i), VertexIndex(j));
    if (h == Mesh::null_halfedge()) continue;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    for (HalfedgeIndex g : {h, mesh.opposite(h)}) {
      if (mesh.is_border(g)) continue;
      const Eigen::Vector3d a = EigenPoint(mesh, mesh.source(g)), b = EigenPoint(mesh, mesh.target(g)),
                            c = EigenPoint(mesh, mesh.target(mesh.next(g)));
      const Eigen::Vector3d n = (b - a).cross(c - b);
      if (n.norm() > 0) normal += n.normalized();
    }
    if (normal.norm() == 0) continue;
    const Tangent t = Restrict(0.5 * (S[i] + S[j]), normal.normalized());
    if (t.kappa() < flat || t.k1 - t.k2 < kUmbilic * t.kappa()) continue;
    const Eigen::Vector2d e = t.In(EigenPoint(mesh, VertexIndex(j)) - EigenPoint(mesh, VertexIndex(i)));
    if (e.norm() == 0) continue;
    ++out.measured;
    const double angle = std::min(LineAngleBetween(e, Eigen::Vector2d(1, 0)),
                                  LineAngleBetween(e, Eigen::Vector2d(0, 1)));
    sum += angle;
    out.angle_max = std::max(out.angle_max, angle);
  }
  if (out.measured > 0) out.angle_mean = sum / out.measured;
  return out;
}

}  // namespace archgeo
