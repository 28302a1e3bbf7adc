// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the curl correction of the level sets' sizes [Gebreiter 2012,
// §8.1.4; Zadravec 2010, §5].
#include "fields/level_set_sizes.h"

#include <algorithm>
#include <cmath>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <glog/logging.h>

namespace archgeo {
namespace level_set_sizes_impl {  // named: the fields unity build

using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

constexpr int kGaussNewtonSteps = 6;

V3 At(const Mesh& mesh, VertexIndex v) {
  const Point& p = mesh.point(v);
  return V3(p.x(), p.y(), p.z());
}

// One circulation condition: Σ_k a_k e^{−s̃_{f_k}} / sqrt(A_p), s̃_f the mean of
// the face's corners.
struct Ring {
  std::vector<std::array<int, 3>> corners;  // per face of the ring
  std::vector<double> a;                    // σ_f (R v_f)·e_f
  double inv_sqrt_area = 0;
};

// The ring of interior vertex p, or an empty ring where p carries no
// condition (see the header).
Ring RingOf(const Mesh& mesh, const FaceFrames& frames, const CutGraph& cut,
            const std::vector<V2>& dir, const std::vector<int>& chain_sign, VertexIndex p) {
  Ring ring;
  if (mesh.is_border(p, false)) return ring;
  const HalfedgeIndex h0 = mesh.halfedge(p);
  double sigma = 1, area = 0;
  HalfedgeIndex h = h0;
  do {
    const int f = int(mesh.face(h).idx());
    if (dir[f].isZero()) return {};
    const HalfedgeIndex out = mesh.next(h);  // p → x
    const V3 e = At(mesh, mesh.source(h)) - At(mesh, mesh.target(out));  // x → source(h)
    const V2& d = dir[f];
    const V3 rotated = -d.y() * frames.e1[f] + d.x() * frames.e2[f];
    ring.a.push_back(sigma * rotated.dot(e) / d.norm());
    ring.corners.push_back({int(p.idx()), int(mesh.target(out).idx()), int(mesh.source(h).idx())});
    area += frames.area[f];
    const int chain = cut.edge_chain[mesh.edge(out).idx()];
    if (chain >= 0) sigma *= chain_sign[chain];
    h = mesh.opposite(out);
  } while (h != h0);
  if (sigma < 0) return {};  // a singular vertex
  ring.inv_sqrt_area = 1.0 / std::sqrt(area / 3.0);
  return ring;
}

double FaceLog(const Eigen::VectorXd& s, const std::array<int, 3>& c) {
  return (s[c[0]] + s[c[1]] + s[c[2]]) / 3.0;
}

double Residual(const Ring& ring, const Eigen::VectorXd& s) {
  double r = 0;
  for (size_t k = 0; k < ring.a.size(); ++k) r += ring.a[k] * std::exp(-FaceLog(s, ring.corners[k]));
  return r * ring.inv_sqrt_area;
}

// sqrt(Σ r² / Σ A_p) · Δw.
double Curl(const std::vector<Ring>& rings, const Eigen::VectorXd& s, double spacing) {
  double sum = 0, area = 0;
  for (const Ring& ring : rings) {
    const double r = Residual(ring, s);
    sum += r * r;
    area += 1.0 / (ring.inv_sqrt_area * ring.inv_sqrt_area);
  }
  return area > 0 ? std::sqrt(sum / area) * spacing : 0.0;
}

// Area-weighted percentile of e^{s̃} over the faces with a field.
double Percentile(std::vector<std::pair<double, double>> size_area, double q) {
  std::sort(size_area.begin(), size_area.end());
  double total = 0;
  for (const auto& [size, area] : size_area) total += area;
  double run = 0;
  for (const auto& [size, area] : size_area) {
    run += area;
    if (run >= q * total) return size;
  }
  return size_area.empty() ? 1.0 : size_area.back().first;
}

LevelSetSizeFamily Correct(const Mesh& mesh, const FaceFrames& frames, const CutGraph& cut,
                           const std::vector<V2>& dir, const std::vector<int>& chain_sign,
                           double spacing, double reach, double bound) {
  const int n = int(mesh.number_of_vertices());
  std::vector<Ring> rings;
  for (VertexIndex p : mesh.vertices()) {
    Ring ring = RingOf(mesh, frames, cut, dir, chain_sign, p);
    if (!ring.a.empty()) rings.push_back(std::move(ring));
  }
  // The target's weight λ A_v / Δw² per vertex (A_v a third of its faces' area).
  const double lambda = 1.0 / (reach * reach * spacing * spacing);
  Eigen::VectorXd hold = Eigen::VectorXd::Zero(n);
  for (FaceIndex f : mesh.faces()) {
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) {
      hold[v.idx()] += lambda * frames.area[f.idx()] / 3.0;
    }
  }
  Eigen::VectorXd s = Eigen::VectorXd::Zero(n);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  for (int step = 0; step < kGaussNewtonSteps && !rings.empty(); ++step) {
    std::vector<Eigen::Triplet<double>> jt;  // J's rows, one per ring
    Eigen::VectorXd r(rings.size());
    for (size_t i = 0; i < rings.size(); ++i) {
      const Ring& ring = rings[i];
      r[i] = Residual(ring, s);
      for (size_t k = 0; k < ring.a.size(); ++k) {
        const double d = -ring.a[k] * std::exp(-FaceLog(s, ring.corners[k])) *
                         ring.inv_sqrt_area / 3.0;
        for (int v : ring.corners[k]) jt.emplace_back(int(i), v, d);
      }
    }
    Eigen::SparseMatrix<double> J(Eigen::Index(rings.size()), n);
    J.setFromTriplets(jt.begin(), jt.end());
    Eigen::SparseMatrix<double> A = J.transpose() * J;
    for (int v = 0; v < n; ++v) A.coeffRef(v, v) += hold[v];
    Eigen::VectorXd g = J.transpose() * r + hold.cwiseProduct(s);
    // The bound |s̃| ≤ bound by an active set: a vertex at the bound whose
    // gradient pushes it outward keeps its value this step (its row and
    // column replaced by the identity's, so the step there is 0).
    std::vector<char> active(n, 0);
    for (int v = 0; v < n; ++v) {
      active[v] = std::abs(s[v]) >= bound * (1 - 1e-12) && g[v] * s[v] < 0;
    }
    for (int k = 0; k < A.outerSize(); ++k) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it) {
        if (active[it.row()] || active[it.col()]) it.valueRef() = it.row() == it.col() ? 1 : 0;
      }
    }
    for (int v = 0; v < n; ++v) {
      if (active[v]) g[v] = 0;
    }
    if (step == 0) solver.analyzePattern(A);
    solver.factorize(A);
    CHECK(solver.info() == Eigen::Success) << "the size correction's matrix is not positive definite";
    s -= solver.solve(g);
    s = s.cwiseMax(-bound).cwiseMin(bound);
  }

  LevelSetSizeFamily out;
  out.vertices = int(rings.size());
  out.curl_before = Curl(rings, Eigen::VectorXd::Zero(n), spacing);
  out.curl_after = Curl(rings, s, spacing);
  out.log_size.assign(mesh.number_of_faces(), 0.0);
  std::vector<std::pair<double, double>> size_area;
  for (FaceIndex f : mesh.faces()) {
    if (dir[f.idx()].isZero()) continue;
    double sum = 0;
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) sum += s[v.idx()];
    out.log_size[f.idx()] = sum / 3.0;
    size_area.emplace_back(std::exp(sum / 3.0), frames.area[f.idx()]);
  }
  out.size_p5 = Percentile(size_area, 0.05);
  out.size_p95 = Percentile(size_area, 0.95);
  out.size_min = Percentile(size_area, 0.0);
  out.size_max = Percentile(size_area, 1.0);
  return out;
}

}  // namespace level_set_sizes_impl

LevelSetSizes CorrectLevelSetSizes(const Mesh& mesh, const FaceFrames& frames, const CutGraph& cut,
                                   const std::vector<Eigen::Vector2d>& v,
                                   const std::vector<Eigen::Vector2d>& w,
                                   const std::vector<int>& chain_sign_v,
                                   const std::vector<int>& chain_sign_w, double spacing,
                                   double reach, double max_ratio) {
  namespace impl = level_set_sizes_impl;
  CHECK_EQ(v.size(), mesh.number_of_faces());
  CHECK_EQ(w.size(), mesh.number_of_faces());
  CHECK_EQ(frames.area.size(), mesh.number_of_faces());
  CHECK(spacing > 0 && reach > 0 && max_ratio > 1);
  const double bound = std::log(max_ratio);
  return {impl::Correct(mesh, frames, cut, v, chain_sign_v, spacing, reach, bound),
          impl::Correct(mesh, frames, cut, w, chain_sign_w, spacing, reach, bound)};
}

}  // namespace archgeo
