// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/similarity.h"

#include <Eigen/Dense>
#include <glog/logging.h>

#include <algorithm>
#include <cmath>

namespace archgeo {

Vec3 Similarity::ToCanonical(const Vec3& x) const {
  Vec3 y;
  for (int i = 0; i < 3; ++i) {
    y[i] = ((x[0] - center[0]) * axes[i][0] + (x[1] - center[1]) * axes[i][1] +
            (x[2] - center[2]) * axes[i][2]) / scale;
  }
  return y;
}

Vec3 Similarity::FromCanonical(const Vec3& y) const {
  Vec3 x = center;
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) x[k] += scale * axes[i][k] * y[i];
  }
  return x;
}

namespace {

Eigen::Vector3d Centroid(const Mesh& mesh) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (VertexIndex v : mesh.vertices()) c += Eigen::Vector3d(&mesh.point(v).x());
  return c / double(mesh.number_of_vertices());
}

// The power of two nearest `length` (1 for a length that is not positive
// and finite): dividing by it is exact.
double PowerOfTwoNear(double length) {
  if (!(length > 0) || !std::isfinite(length)) return 1.0;
  return std::ldexp(1.0, int(std::lround(std::log2(length))));
}

}  // namespace

Similarity CanonicalFrame(const Mesh& mesh) {
  CHECK(mesh.number_of_vertices() > 0);
  Similarity s;
  s.scale = MeanEdgeLength(mesh);
  if (!(s.scale > 0)) s.scale = 1.0;
  // Moments of the offsets in units of a power of two near the mean edge:
  // exact, and finite for a mesh scaled by 1e100 (the third moment of file
  // units would overflow).
  const double unit = PowerOfTwoNear(s.scale);
  const Eigen::Vector3d c = Centroid(mesh);
  const auto offset = [&](VertexIndex v) {
    return Eigen::Vector3d((Eigen::Vector3d(&mesh.point(v).x()) - c) / unit);
  };
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (VertexIndex v : mesh.vertices()) cov += offset(v) * offset(v).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Eigen::Matrix3d axes;
  for (int i = 0; i < 3; ++i) axes.col(i) = eig.eigenvectors().col(2 - i);  // largest first
  for (int i = 0; i < 2; ++i) {
    double third = 0;
    for (VertexIndex v : mesh.vertices()) third += std::pow(offset(v).dot(axes.col(i)), 3);
    if (third < 0) axes.col(i) = -axes.col(i);
  }
  axes.col(2) = axes.col(0).cross(axes.col(1));  // right-handed: a rotation, no reflection
  for (int k = 0; k < 3; ++k) s.center[k] = c[k];
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) s.axes[i][k] = axes(k, i);
  }
  return s;
}

Similarity LocalFrame(const Mesh& mesh) {
  Similarity s;
  if (mesh.number_of_vertices() == 0) return s;
  s.scale = PowerOfTwoNear(MeanEdgeLength(mesh));
  const Eigen::Vector3d c = Centroid(mesh);
  for (int k = 0; k < 3; ++k) s.center[k] = c[k];
  return s;
}

Mesh InFrame(const Similarity& s, Mesh mesh) {
  ToCanonical(s, mesh);
  return mesh;
}

double PrincipalBoxDiagonal(const Mesh& mesh) {
  const Similarity s = CanonicalFrame(mesh);
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (VertexIndex v : mesh.vertices()) {
    const Vec3 y = s.ToCanonical(ToVec3(mesh.point(v)));
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], y[k]);
      hi[k] = std::max(hi[k], y[k]);
    }
  }
  return s.scale * std::sqrt(CGAL::square(hi[0] - lo[0]) + CGAL::square(hi[1] - lo[1]) +
                             CGAL::square(hi[2] - lo[2]));
}

void ToCanonical(const Similarity& s, Mesh& mesh) {
  for (VertexIndex v : mesh.vertices()) mesh.point(v) = ToPoint(s.ToCanonical(ToVec3(mesh.point(v))));
}

void FromCanonical(const Similarity& s, Mesh& mesh) {
  for (VertexIndex v : mesh.vertices()) {
    mesh.point(v) = ToPoint(s.FromCanonical(ToVec3(mesh.point(v))));
  }
}

}  // namespace archgeo
