// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fields/face_frames.h"
#include "mesh/eigen_point.h"

#include <cmath>
#include <queue>

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <glog/logging.h>

namespace archgeo {
namespace {

std::array<VertexIndex, 3> Corners(const Mesh& mesh, FaceIndex f) {
  const HalfedgeIndex h0 = mesh.halfedge(f);
  const HalfedgeIndex h1 = mesh.next(h0);
  const HalfedgeIndex h2 = mesh.next(h1);
  CHECK(mesh.next(h2) == h0) << "face " << f.idx() << " is not a triangle";
  return {mesh.target(h0), mesh.target(h1), mesh.target(h2)};
}

// Rotation about the axis through the shared edge that maps n_g onto n_f.
Eigen::AngleAxisd Unfolding(const Eigen::Vector3d& axis, const Eigen::Vector3d& n_g,
                            const Eigen::Vector3d& n_f) {
  const double angle = std::atan2(n_g.cross(n_f).dot(axis), n_g.dot(n_f));
  return Eigen::AngleAxisd(angle, axis);
}

}  // namespace

FaceFrames ComputeEdgeFrames(const Mesh& mesh) {
  CHECK(!mesh.has_garbage()) << "face frames need a mesh without garbage";
  FaceFrames fr;
  const size_t n = mesh.number_of_faces();
  fr.e1.resize(n);
  fr.e2.resize(n);
  fr.normal.resize(n);
  fr.centroid.resize(n);
  fr.area.resize(n);
  for (FaceIndex f : mesh.faces()) {
    const auto c = Corners(mesh, f);
    const Eigen::Vector3d p0 = EigenPoint(mesh, c[0]), p1 = EigenPoint(mesh, c[1]), p2 = EigenPoint(mesh, c[2]);
    const Eigen::Vector3d cross = (p1 - p0).cross(p2 - p0);
    const double twice_area = cross.norm();
    CHECK(twice_area > 0.0) << "face " << f.idx() << " has zero area";
    const size_t i = f.idx();
    fr.normal[i] = cross / twice_area;
    fr.e1[i] = (p1 - p0).normalized();
    fr.e2[i] = fr.normal[i].cross(fr.e1[i]);
    fr.centroid[i] = (p0 + p1 + p2) / 3.0;
    fr.area[i] = 0.5 * twice_area;
  }
  return fr;
}

std::vector<EdgeTransport> ComputeTransports(const Mesh& mesh, const FaceFrames& frames,
                                             std::vector<int>* edge_to_transport) {
  std::vector<EdgeTransport> out;
  if (edge_to_transport != nullptr) edge_to_transport->assign(mesh.number_of_edges(), -1);
  for (EdgeIndex e : mesh.edges()) {
    if (mesh.is_border(e)) continue;
    const HalfedgeIndex h = mesh.halfedge(e, 0);
    const FaceIndex f = mesh.face(h);
    const FaceIndex g = mesh.face(mesh.opposite(h));
    const Eigen::Vector3d a = EigenPoint(mesh, mesh.source(h)), b = EigenPoint(mesh, mesh.target(h));
    const Eigen::Vector3d axis = (b - a).normalized();
    const size_t fi = f.idx(), gi = g.idx();
    const Eigen::AngleAxisd unfold = Unfolding(axis, frames.normal[gi], frames.normal[fi]);
    const Eigen::Vector3d e1g = unfold * frames.e1[gi];
    EdgeTransport t;
    t.edge = e;
    t.f = f;
    t.g = g;
    t.angle = std::atan2(frames.e1[fi].cross(e1g).dot(frames.normal[fi]),
                         frames.e1[fi].dot(e1g));
    const Eigen::Vector3d cg = a + unfold * (frames.centroid[gi] - a);
    t.weight = (b - a).norm() / (frames.centroid[fi] - cg).norm();
    if (edge_to_transport != nullptr) (*edge_to_transport)[e.idx()] = static_cast<int>(out.size());
    out.push_back(t);
  }
  return out;
}

double TransportAngle(const EdgeTransport& t, FaceIndex from_g, FaceIndex to_f) {
  if (t.f == to_f && t.g == from_g) return t.angle;
  CHECK(t.f == from_g && t.g == to_f) << "transport of edge " << t.edge.idx()
                                      << " does not join faces " << from_g.idx() << ", "
                                      << to_f.idx();
  return -t.angle;
}

FaceFrames ComputeSmoothFrames(const Mesh& mesh) {
  FaceFrames fr = ComputeEdgeFrames(mesh);
  const std::vector<EdgeTransport> transports = ComputeTransports(mesh, fr);
  const int n = static_cast<int>(mesh.number_of_faces());

  // One root face per connected component (through interior edges).
  std::vector<std::vector<std::pair<int, int>>> adjacency(n);  // (neighbour, transport)
  for (size_t k = 0; k < transports.size(); ++k) {
    adjacency[transports[k].f.idx()].push_back({static_cast<int>(transports[k].g.idx()),
                                                static_cast<int>(k)});
    adjacency[transports[k].g.idx()].push_back({static_cast<int>(transports[k].f.idx()),
                                                static_cast<int>(k)});
  }
  std::vector<bool> is_root(n, false), seen(n, false);
  for (int s = 0; s < n; ++s) {
    if (seen[s]) continue;
    is_root[s] = true;
    std::queue<int> queue;
    queue.push(s);
    seen[s] = true;
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop();
      for (const auto& [g, k] : adjacency[f]) {
        if (!seen[g]) {
          seen[g] = true;
          queue.push(g);
        }
      }
    }
  }

  // Normal equations of E(b) with b = (1, 0) at the roots (moved to the
  // right-hand side); b in the edge frames of ComputeEdgeFrames.
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * n);
  auto add = [&](int r, int c, double v) { triplets.emplace_back(r, c, v); };
  for (int f = 0; f < n; ++f) {
    if (is_root[f]) {
      add(2 * f, 2 * f, 1.0);
      add(2 * f + 1, 2 * f + 1, 1.0);
      rhs(2 * f) = 1.0;
    }
  }
  for (const EdgeTransport& t : transports) {
    const int f = t.f.idx(), g = t.g.idx();
    const double w = t.weight;
    Eigen::Matrix2d R;  // maps g-coordinates to f-coordinates
    R << std::cos(t.angle), -std::sin(t.angle), std::sin(t.angle), std::cos(t.angle);
    // Row block f: w (b_f − R b_g); row block g: w (b_g − Rᵀ b_f).
    auto couple = [&](int row, int col, const Eigen::Matrix2d& B) {
      if (is_root[row]) return;
      add(2 * row, 2 * row, w);
      add(2 * row + 1, 2 * row + 1, w);
      if (is_root[col]) {
        rhs.segment<2>(2 * row) += w * B * Eigen::Vector2d(1.0, 0.0);
        return;
      }
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) add(2 * row + i, 2 * col + j, -w * B(i, j));
    };
    couple(f, g, R);
    couple(g, f, R.transpose());
  }
  Eigen::SparseMatrix<double> A(2 * n, 2 * n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  CHECK(solver.info() == Eigen::Success) << "frame field: factorisation failed";
  const Eigen::VectorXd b = solver.solve(rhs);
  CHECK(solver.info() == Eigen::Success) << "frame field: solve failed";

  double max_norm = 0.0;
  for (int f = 0; f < n; ++f) max_norm = std::max(max_norm, b.segment<2>(2 * f).norm());
  for (int f = 0; f < n; ++f) {
    const Eigen::Vector2d bf = b.segment<2>(2 * f);
    if (!(bf.norm() > 1e-9 * max_norm) || !bf.allFinite()) {
      ++fr.fallback_faces;  // keep the edge frame
      continue;
    }
    const Eigen::Vector3d e1 = (bf.x() * fr.e1[f] + bf.y() * fr.e2[f]).normalized();
    fr.e1[f] = e1;
    fr.e2[f] = fr.normal[f].cross(e1);
  }
  return fr;
}

std::array<Eigen::Vector2d, 3> FaceCorners2D(const Mesh& mesh, const FaceFrames& frames,
                                             FaceIndex f) {
  const auto c = Corners(mesh, f);
  std::array<Eigen::Vector2d, 3> out;
  for (int k = 0; k < 3; ++k) out[k] = ToFrame(frames, f, EigenPoint(mesh, c[k]) - frames.centroid[f.idx()]);
  return out;
}

Eigen::Vector2d ToFrame(const FaceFrames& frames, FaceIndex f, const Eigen::Vector3d& x) {
  return Eigen::Vector2d(frames.e1[f.idx()].dot(x), frames.e2[f.idx()].dot(x));
}

Eigen::Vector3d FromFrame(const FaceFrames& frames, FaceIndex f, const Eigen::Vector2d& x) {
  return x.x() * frames.e1[f.idx()] + x.y() * frames.e2[f.idx()];
}

}  // namespace archgeo
