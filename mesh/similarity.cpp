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

Similarity CanonicalFrame(const Mesh& mesh) {
  CHECK(mesh.number_of_vertices() > 0);
  Similarity s;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (VertexIndex v : mesh.vertices()) c += Eigen::Vector3d(&mesh.point(v).x());
  c /= double(mesh.number_of_vertices());

  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (VertexIndex v : mesh.vertices()) {
    const Eigen::Vector3d d = Eigen::Vector3d(&mesh.point(v).x()) - c;
    cov += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Eigen::Matrix3d axes;
  for (int i = 0; i < 3; ++i) axes.col(i) = eig.eigenvectors().col(2 - i);  // largest first
  for (int i = 0; i < 2; ++i) {
    double third = 0;
    for (VertexIndex v : mesh.vertices()) {
      third += std::pow((Eigen::Vector3d(&mesh.point(v).x()) - c).dot(axes.col(i)), 3);
    }
    if (third < 0) axes.col(i) = -axes.col(i);
  }
  axes.col(2) = axes.col(0).cross(axes.col(1));  // right-handed: a rotation, no reflection

  double length = 0;
  for (EdgeIndex e : mesh.edges()) {
    length += std::sqrt(CGAL::squared_distance(mesh.point(mesh.vertex(e, 0)),
                                                mesh.point(mesh.vertex(e, 1))));
  }
  s.scale = mesh.number_of_edges() > 0 ? length / double(mesh.number_of_edges()) : 1.0;
  if (!(s.scale > 0)) s.scale = 1.0;
  for (int k = 0; k < 3; ++k) s.center[k] = c[k];
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) s.axes[i][k] = axes(k, i);
  }
  return s;
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
