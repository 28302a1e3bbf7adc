// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fabrication/nodes.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "core/newell.h"

namespace archgeo {
namespace {

constexpr double kBeamDegreesPerRadian = 180.0 / M_PI;

Eigen::Vector3d FaceNewell(const PlainMesh& mesh, int f) {
  const std::vector<int>& ids = mesh.faces[size_t(f)];
  return NewellVector(int(ids.size()), [&](int k) -> const Eigen::Vector3d& {
    return mesh.points[size_t(ids[size_t(k)])];
  });
}

// The corner angle of face f at vertex v (radians, 3D).
double AngleAt(const PlainMesh& mesh, int f, int v) {
  const std::vector<int>& ids = mesh.faces[size_t(f)];
  const size_t n = ids.size();
  const size_t k = size_t(std::find(ids.begin(), ids.end(), v) - ids.begin());
  CHECK_LT(k, n) << "vertex " << v << " is not a corner of face " << f;
  const Eigen::Vector3d& p = mesh.points[size_t(v)];
  const Eigen::Vector3d a = mesh.points[size_t(ids[(k + 1) % n])] - p;
  const Eigen::Vector3d b = mesh.points[size_t(ids[(k + n - 1) % n])] - p;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// The unit a with a·n_k equal for every unit n_k: the normal of the
// least-squares plane through their tips.
Eigen::Vector3d EqualAngleAxis(const std::vector<Eigen::Vector3d>& normals) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& n : normals) mean += n;
  mean /= double(normals.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& n : normals) scatter += (n - mean) * (n - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  return eigen.eigenvectors().col(0).normalized();
}

}  // namespace

std::vector<NodeAxis> NodeAxes(const PlainMesh& mesh, double cone_bound) {
  CHECK_EQ(mesh.vertex_faces.size(), mesh.points.size()) << "NodeAxes: vertex_faces missing";
  CHECK_EQ(mesh.boundary.size(), mesh.points.size()) << "NodeAxes: boundary missing";
  std::vector<Eigen::Vector3d> face_normals;
  for (size_t f = 0; f < mesh.faces.size(); ++f) face_normals.push_back(FaceNewell(mesh, int(f)));
  std::vector<NodeAxis> nodes(mesh.points.size());
  for (size_t v = 0; v < mesh.points.size(); ++v) {
    NodeAxis& node = nodes[v];
    const std::vector<int>& faces = mesh.vertex_faces[v];
    for (int f : faces) node.normal += face_normals[size_t(f)];
    if (node.normal.norm() > 0) node.normal.normalize();
    node.axis = node.normal;
    if (mesh.boundary[v] || faces.size() != 4) continue;
    double omega[4];
    for (int k = 0; k < 4; ++k) omega[k] = AngleAt(mesh, faces[size_t(k)], int(v));
    node.conical = std::abs((omega[0] + omega[2]) - (omega[1] + omega[3]));
    if (!(cone_bound > 0) || node.conical > cone_bound) continue;
    std::vector<Eigen::Vector3d> units;
    for (int f : faces) units.push_back(face_normals[size_t(f)].normalized());
    Eigen::Vector3d axis = EqualAngleAxis(units);
    if (axis.dot(node.normal) < 0) axis = -axis;
    double cosine = 0;
    for (const Eigen::Vector3d& n : units) cosine += n.dot(axis) / 4;
    if (!(cosine > 0)) continue;  // not a cone the faces can be offset along
    node.axis = axis;
    node.cone = true;
    node.offset_factor = 1 / cosine;
  }
  return nodes;
}

std::vector<Eigen::Vector3d> OffsetNodes(const PlainMesh& mesh, const std::vector<NodeAxis>& nodes,
                                         double depth) {
  std::vector<Eigen::Vector3d> offsets = mesh.points;
  for (size_t v = 0; v < nodes.size(); ++v) {
    double sum = 0, squares = 0;
    for (int f : mesh.vertex_faces[v]) {
      const double c = FaceNewell(mesh, f).normalized().dot(nodes[v].axis);
      sum += c;
      squares += c * c;
    }
    if (squares > 0) offsets[v] += depth * sum / squares * nodes[v].axis;
  }
  return offsets;
}

double FaceOffsetError(const PlainMesh& mesh, const std::vector<Eigen::Vector3d>& offsets,
                       double depth) {
  double error = 0;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Eigen::Vector3d normal = FaceNewell(mesh, int(f)).normalized();
    for (int v : mesh.faces[f]) {
      const double distance = normal.dot(offsets[size_t(v)] - mesh.points[size_t(v)]);
      error = std::max(error, std::abs(distance - depth));
    }
  }
  return error;
}

std::vector<Beam> Beams(const PlainMesh& mesh, const std::vector<NodeAxis>& nodes, double depth) {
  const std::vector<Eigen::Vector3d> offsets = OffsetNodes(mesh, nodes, depth);
  std::vector<Beam> beams;
  for (const auto& [v0, v1] : mesh.edges) {
    Beam b;
    b.v0 = v0, b.v1 = v1;
    const Eigen::Vector3d edge = mesh.points[size_t(v1)] - mesh.points[size_t(v0)];
    b.length = edge.norm();
    b.offset0 = offsets[size_t(v0)], b.offset1 = offsets[size_t(v1)];
    const Eigen::Vector3d side0 = edge.cross(nodes[size_t(v0)].axis);
    const Eigen::Vector3d side1 = edge.cross(nodes[size_t(v1)].axis);
    const Eigen::Vector3d mean = edge.cross(nodes[size_t(v0)].axis + nodes[size_t(v1)].axis);
    if (mean.norm() > 0) b.plane_normal = mean.normalized();
    if (side0.norm() > 0 && side1.norm() > 0) {
      b.twist_degrees =
          std::atan2(side0.cross(side1).norm(), side0.dot(side1)) * kBeamDegreesPerRadian;
    }
    beams.push_back(b);
  }
  return beams;
}

}  // namespace archgeo
