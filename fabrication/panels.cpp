// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fabrication/panels.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "core/newell.h"

namespace archgeo {
namespace {

constexpr double kDegreesPerRadian = 180.0 / M_PI;

// |a − b| / b, with 0 / 0 = 0.
double RelativeChange(double changed, double original) {
  if (original > 0) return std::abs(changed - original) / original;
  return changed > 0 ? 1.0 : 0.0;
}

Eigen::Vector3d PanelNewell(const std::vector<Eigen::Vector3d>& corners) {
  return NewellVector(int(corners.size()),
                      [&](int k) -> const Eigen::Vector3d& { return corners[size_t(k)]; });
}

// The side the panel's projected triangle (q0, qa, qb) turns to: +1 or −1.
double TurnSide(const Eigen::Vector2d& q0, const Eigen::Vector2d& qa, const Eigen::Vector2d& qb) {
  const Eigen::Vector2d a = qa - q0, b = qb - q0;
  return a.x() * b.y() - a.y() * b.x() >= 0 ? 1.0 : -1.0;
}

// The point at distance r0 from d0 and r1 from d1 on the `side` of d0 → d1
// (the triangle inequality clamped: rounding can break it for a sliver).
Eigen::Vector2d ThirdCorner(const Eigen::Vector2d& d0, const Eigen::Vector2d& d1, double r0,
                            double r1, double side) {
  const Eigen::Vector2d base = d1 - d0;
  const double length = base.norm();
  if (!(length > 0)) return d0 + Eigen::Vector2d(r0, 0);
  const Eigen::Vector2d along = base / length;
  const Eigen::Vector2d across(-along.y(), along.x());
  const double x = (r0 * r0 - r1 * r1 + length * length) / (2 * length);
  const double h = std::sqrt(std::max(0.0, r0 * r0 - x * x));
  return d0 + x * along + side * h * across;
}

}  // namespace

BestFitPlane FitPlane(const std::vector<Eigen::Vector3d>& corners) {
  CHECK_GE(corners.size(), 3u) << "FitPlane: a panel has at least 3 corners";
  BestFitPlane plane;
  for (const Eigen::Vector3d& p : corners) plane.centroid += p;
  plane.centroid /= double(corners.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : corners) {
    const Eigen::Vector3d d = p - plane.centroid;
    scatter += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  plane.normal = eigen.eigenvectors().col(0).normalized();  // smallest eigenvalue first
  if (plane.normal.dot(PanelNewell(corners)) < 0) plane.normal = -plane.normal;
  return plane;
}

double PanelFlatness(const std::vector<Eigen::Vector3d>& corners) {
  if (corners.size() <= 3) return 0.0;
  const BestFitPlane plane = FitPlane(corners);
  double flatness = 0;
  for (const Eigen::Vector3d& p : corners) {
    flatness = std::max(flatness, std::abs(plane.normal.dot(p - plane.centroid)));
  }
  return flatness;
}

PanelGeometry MeasurePanel(const std::vector<Eigen::Vector3d>& corners) {
  const size_t n = corners.size();
  PanelGeometry g;
  g.plane = FitPlane(corners);
  g.flatness = PanelFlatness(corners);
  g.area = 0.5 * PanelNewell(corners).norm();
  const Eigen::Vector3d& normal = g.plane.normal;
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d edge = corners[(k + 1) % n] - corners[k];
    g.edges.push_back(edge.norm());
    const Eigen::Vector3d projected = edge - normal.dot(edge) * normal;
    g.projection_change =
        std::max(g.projection_change, RelativeChange(projected.norm(), edge.norm()));
    const Eigen::Vector3d previous = corners[(k + n - 1) % n] - corners[k];
    const Eigen::Vector3d cross = edge.cross(previous);
    const double angle = std::atan2(cross.norm(), edge.dot(previous)) * kDegreesPerRadian;
    g.angles.push_back(cross.dot(normal) < 0 ? 360.0 - angle : angle);
  }
  double sum = 0;
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours across the closing edge
      g.diagonals.push_back((corners[j] - corners[i]).norm());
      sum += g.diagonals.back();
    }
  }
  if (!g.diagonals.empty() && sum > 0)
    g.flatness_relative = g.flatness / (sum / double(g.diagonals.size()));
  return g;
}

FlatOutline FlattenPanel(const std::vector<Eigen::Vector3d>& corners) {
  const size_t n = corners.size();
  const BestFitPlane plane = FitPlane(corners);
  const Eigen::Vector3d& normal = plane.normal;
  // The plane's frame: x along the projected first edge.
  Eigen::Vector3d x_axis = corners[1] - corners[0];
  x_axis -= normal.dot(x_axis) * normal;
  if (!(x_axis.norm() > 0)) x_axis = normal.unitOrthogonal();
  x_axis.normalize();
  const Eigen::Vector3d y_axis = normal.cross(x_axis);
  std::vector<Eigen::Vector2d> projected(n);
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d d = corners[k] - plane.centroid;
    projected[k] = {d.dot(x_axis), d.dot(y_axis)};
  }
  // The fan from p_0, triangle by triangle.
  std::vector<Eigen::Vector2d> developed(n);
  developed[0] = Eigen::Vector2d::Zero();
  developed[1] = {(corners[1] - corners[0]).norm(), 0.0};
  for (size_t k = 2; k < n; ++k) {
    const double side = TurnSide(projected[0], projected[k - 1], projected[k]);
    developed[k] = ThirdCorner(developed[0], developed[k - 1], (corners[k] - corners[0]).norm(),
                               (corners[k] - corners[k - 1]).norm(), side);
  }
  // The rigid motion (no reflection) that best lays it onto the projection.
  Eigen::Vector2d developed_mean = Eigen::Vector2d::Zero(),
                  projected_mean = Eigen::Vector2d::Zero();
  for (size_t k = 0; k < n; ++k) developed_mean += developed[k], projected_mean += projected[k];
  developed_mean /= double(n);
  projected_mean /= double(n);
  double sin_sum = 0, cos_sum = 0;
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d a = developed[k] - developed_mean, b = projected[k] - projected_mean;
    cos_sum += a.dot(b);
    sin_sum += a.x() * b.y() - a.y() * b.x();
  }
  const double turn = std::atan2(sin_sum, cos_sum);
  const Eigen::Matrix2d rotation = Eigen::Rotation2Dd(turn).toRotationMatrix();
  FlatOutline out;
  for (size_t k = 0; k < n; ++k) {
    out.corners.push_back(rotation * (developed[k] - developed_mean) + projected_mean);
  }
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      out.change = std::max(out.change, RelativeChange((out.corners[j] - out.corners[i]).norm(),
                                                       (corners[j] - corners[i]).norm()));
    }
  }
  return out;
}

}  // namespace archgeo
