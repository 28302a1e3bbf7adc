// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/declarations/wave_field.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include <Eigen/Geometry>

#include "energies/wave_elements.h"
#include "fields/conjugate.h"
#include "fields/face_curvature.h"
#include "geometry/reference.h"
#include "mesh/eigen_point.h"

namespace archgeo {
namespace {

namespace wd = wave_data;
using WaveV3 = Eigen::Vector3d;

// Area-weighted vertex normals (the sum of the faces' cross products).
std::vector<WaveV3> WaveNormals(const Mesh& mesh) {
  std::vector<WaveV3> n(mesh.number_of_vertices(), WaveV3::Zero());
  for (FaceIndex f : mesh.faces()) {
    std::vector<int> vs;
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) vs.push_back(int(v.idx()));
    WaveV3 sum = WaveV3::Zero();
    for (size_t k = 0; k < vs.size(); ++k) {
      sum += EigenPoint(mesh, VertexIndex(vs[k]))
                 .cross(EigenPoint(mesh, VertexIndex(vs[(k + 1) % vs.size()])));
    }
    for (int v : vs) n[size_t(v)] += sum;
  }
  for (WaveV3& x : n) x = x.norm() > 0 ? WaveV3(x.normalized()) : WaveV3(0, 0, 1);
  return n;
}

// A unit tangent vector at n (any).
WaveV3 WaveTangent(const WaveV3& n) {
  const WaveV3 a = std::abs(n.x()) < 0.9 ? WaveV3(1, 0, 0) : WaveV3(0, 1, 0);
  return (a - a.dot(n) * n).normalized();
}

// `sweeps` sweeps of the 4-RoSy average of frames.x: each vertex takes the
// mean of its own principal direction, weighted by 4 × its anisotropy, and
// its neighbours' current directions transported into its tangent plane,
// angles times four summed as unit complex numbers (z⁴); at the end each
// vertex keeps the one of the four directions of its z⁴ nearest its own.
// A neighbour u's angle in v's tangent basis is its angle in u's basis plus
// the rotation that carries u's basis into v's (the rotation part of the
// projection of one basis on the other).
void SmoothCross(const Mesh& mesh, WaveFrames& frames, int sweeps) {
  if (sweeps <= 0) return;
  using Complex = std::complex<double>;
  const size_t n = frames.x.size();
  std::vector<WaveV3> t1(n), t2(n);
  std::vector<Complex> own(n), z4(n), next(n);  // z⁴ per vertex, in its basis
  std::vector<int> start(n + 1, 0), ring;
  std::vector<Complex> turn;  // per ring entry: e^{4iρ}, u's basis into v's
  for (size_t v = 0; v < n; ++v) {
    t1[v] = WaveTangent(frames.normal[v]);
    t2[v] = frames.normal[v].cross(t1[v]);
    own[v] = std::pow(Complex(frames.x[v].dot(t1[v]), frames.x[v].dot(t2[v])), 4);
    own[v] /= std::max(std::abs(own[v]), 1e-300);
  }
  for (VertexIndex vi : mesh.vertices()) {
    const size_t v = vi.idx();
    for (VertexIndex ui : mesh.vertices_around_target(mesh.halfedge(vi))) {
      const size_t u = ui.idx();
      const double rho = std::atan2(t2[v].dot(t1[u]) - t1[v].dot(t2[u]),
                                    t1[v].dot(t1[u]) + t2[v].dot(t2[u]));
      ring.push_back(int(u));
      turn.push_back(std::polar(1.0, 4 * rho));
    }
    start[v + 1] = int(ring.size());
  }
  z4 = own;
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    for (size_t v = 0; v < n; ++v) {
      Complex sum = 4 * frames.anisotropy[v] * own[v];
      for (int k = start[v]; k < start[v + 1]; ++k) {
        sum += turn[size_t(k)] * z4[size_t(ring[size_t(k)])];
      }
      const double norm = std::abs(sum);
      next[v] = norm < 1e-12 ? z4[v] : sum / norm;
    }
    std::swap(z4, next);
  }
  for (size_t v = 0; v < n; ++v) {
    const double a = std::arg(z4[v]) / 4;
    const Eigen::Vector2d best(std::cos(a), std::sin(a));
    const Eigen::Vector2d mine(frames.x[v].dot(t1[v]), frames.x[v].dot(t2[v]));
    Eigen::Vector2d pick = best;
    for (const Eigen::Vector2d& c : {Eigen::Vector2d(-best.y(), best.x()), Eigen::Vector2d(-best),
                                     Eigen::Vector2d(best.y(), -best.x())}) {
      if (c.dot(mine) > pick.dot(mine)) pick = c;
    }
    frames.x[v] = (pick.x() * t1[v] + pick.y() * t2[v]).normalized();
  }
}

}  // namespace

WaveFrames PrincipalWaveFrames(const Mesh& mesh, int smoothing) {
  const size_t n = mesh.number_of_vertices();
  WaveFrames out;
  out.normal = WaveNormals(mesh);
  out.x.assign(n, WaveV3::Zero());
  out.anisotropy.assign(n, 0.0);
  const std::vector<Eigen::Matrix3d> tensors = VertexShapeTensors(TriangulatedCopy(mesh), JetOptions());
  double largest = 0;
  for (size_t v = 0; v < n; ++v) {
    const WaveV3& nv = out.normal[v];
    const WaveV3 t1 = WaveTangent(nv), t2 = nv.cross(t1);
    Eigen::Matrix2d S;
    S << t1.dot(tensors[v] * t1), t1.dot(tensors[v] * t2), t2.dot(tensors[v] * t1),
        t2.dot(tensors[v] * t2);
    S = 0.5 * (S + S.transpose()).eval();
    const SymmetricEigen2 eig = EigenOfSymmetric2(S);
    const int larger = std::abs(eig.values(1)) >= std::abs(eig.values(0)) ? 1 : 0;
    const Eigen::Vector2d d1 = eig.vectors.col(larger);  // larger |k|
    out.x[v] = (d1.x() * t1 + d1.y() * t2).normalized();
    out.anisotropy[v] = eig.values(1) - eig.values(0);
    largest = std::max(largest, out.anisotropy[v]);
  }
  for (double& a : out.anisotropy) a = largest > 0 ? a / largest : 0.0;
  SmoothCross(mesh, out, smoothing);
  out.y.resize(n);
  for (size_t v = 0; v < n; ++v) out.y[v] = out.normal[v].cross(out.x[v]);
  return out;
}

ElementSet WaveEdges(const Mesh& mesh, const WaveFrames& frames, const std::vector<double>& mu,
                     const std::vector<double>& eta) {
  ElementSet set;
  set.site = Site::kEdge;
  set.data_width = wd::kEdgeWidth;
  for (EdgeIndex e : mesh.edges()) {
    const HalfedgeIndex h = mesh.halfedge(e);
    const size_t i = mesh.source(h).idx(), j = mesh.target(h).idx();
    // j's angles relabelled into i's: i's X at j is the one of ±X_j, ±Y_j
    // nearest X_i; i's Y the one of the other pair nearest Y_i.
    const WaveV3 cand[2] = {frames.x[j], frames.y[j]};
    int source_theta = 0;
    double sign_theta = 1, best = -2;
    for (int k = 0; k < 2; ++k) {
      for (double s : {1.0, -1.0}) {
        const double d = s * cand[k].dot(frames.x[i]);
        if (d > best) best = d, source_theta = k, sign_theta = s;
      }
    }
    const int source_phi = 1 - source_theta;
    const double sign_phi = cand[source_phi].dot(frames.y[i]) >= 0 ? 1.0 : -1.0;
    const WaveV3 xe = (frames.x[i] + sign_theta * cand[source_theta]).normalized();
    const WaveV3 ye = (frames.y[i] + sign_phi * cand[source_phi]).normalized();
    const double mu_j = source_theta == 0 ? mu[j] : eta[j];
    const double eta_j = source_theta == 0 ? eta[j] : mu[j];
    const double mu_e = 0.5 * (mu[i] + mu_j), eta_e = 0.5 * (eta[i] + eta_j);
    const WaveV3 d = EigenPoint(mesh, VertexIndex(j)) - EigenPoint(mesh, VertexIndex(i));
    const double alpha = 2 * M_PI / mu_e * xe.dot(d), beta = 2 * M_PI / eta_e * ye.dot(d);
    set.Add({int(i), int(j)}, int(e.idx()), -1, int(e.idx()), 0,
            {alpha, beta, double(source_theta), sign_theta, double(source_phi), sign_phi});
  }
  return set;
}

ElementSet WaveVertices(const Mesh& mesh) {
  ElementSet set;
  set.site = Site::kVertex;
  for (VertexIndex v : mesh.vertices()) set.Add({int(v.idx())}, int(v.idx()));
  return set;
}

ElementSet WaveFeatures(const Mesh& mesh, const WaveFrames& frames, double corner_degrees) {
  ElementSet set;
  set.site = Site::kVertex;
  set.data_width = wd::kFeatureWidth;
  for (HalfedgeIndex h : mesh.halfedges()) {
    if (!mesh.is_border(h)) continue;  // h runs along the boundary into target(h)
    const VertexIndex v = mesh.target(h);
    const WaveV3 p = EigenPoint(mesh, v);
    const WaveV3 in = (p - EigenPoint(mesh, mesh.source(h))).normalized();
    const WaveV3 out = (EigenPoint(mesh, mesh.target(mesh.next(h))) - p).normalized();
    const double turn = std::acos(std::clamp(in.dot(out), -1.0, 1.0)) * 180 / M_PI;
    const WaveV3 t = (in + out).norm() > 1e-12 ? WaveV3((in + out).normalized()) : in;
    int kind = std::abs(t.dot(frames.x[v.idx()])) >= std::abs(t.dot(frames.y[v.idx()]))
                   ? wd::kSinPhi
                   : wd::kSinTheta;
    if (turn > corner_degrees) kind = wd::kCorner;
    set.Add({int(v.idx())}, int(v.idx()), -1, -1, 0, {double(kind)});
  }
  return set;
}

}  // namespace archgeo
