// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fields/face_curvature.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <CGAL/Default_diagonalize_traits.h>
#include <glog/logging.h>

#include "core/dense_solve.h"
#include "core/solver_options.h"
#include "fields/conjugate.h"
#include "mesh/eigen_point.h"

namespace archgeo {
namespace {

constexpr int kMaxRings = 8;
constexpr int kMaxDegree = 4;

int NumCoefficients(int degree) { return (degree + 1) * (degree + 2) / 2; }

Eigen::Vector3d VertexNormal(const Mesh& mesh, VertexIndex v) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (HalfedgeIndex h : mesh.halfedges_around_target(mesh.halfedge(v))) {
    if (mesh.is_border(h)) continue;
    const Eigen::Vector3d a = EigenPoint(mesh, mesh.source(h));
    const Eigen::Vector3d b = EigenPoint(mesh, mesh.target(h));
    const Eigen::Vector3d c = EigenPoint(mesh, mesh.target(mesh.next(h)));
    n += (b - a).cross(c - b);  // twice the area times the face normal
  }
  return n.normalized();
}

// The vertex first, then the vertices of growing rings until `min_points`.
std::vector<VertexIndex> Neighbourhood(const Mesh& mesh, VertexIndex v, int rings,
                                       int min_points, std::vector<int>* mark, int stamp) {
  std::vector<VertexIndex> out{v};
  (*mark)[v.idx()] = stamp;
  size_t ring_begin = 0;
  for (int ring = 1; ring <= kMaxRings; ++ring) {
    const size_t ring_end = out.size();
    for (size_t i = ring_begin; i < ring_end; ++i) {
      for (VertexIndex u : mesh.vertices_around_target(mesh.halfedge(out[i]))) {
        if ((*mark)[u.idx()] == stamp) continue;
        (*mark)[u.idx()] = stamp;
        out.push_back(u);
      }
    }
    ring_begin = ring_end;
    if (ring >= rings && static_cast<int>(out.size()) >= min_points) break;
    if (out.size() == ring_end) break;  // the component is exhausted
  }
  return out;
}

// One vertex's shape tensor Σ k d dᵀ from a degree-`degree` jet fitted to
// `points` (the vertex first), oriented so that its normal agrees with
// `normal`: the osculating jet of Cazals & Pouget 2003 step by step, as CGAL
// 5.5's Monge_via_jet_fitting computes it, with its least squares by pivoted
// Householder QR instead of CGAL's Jacobi SVD (the same fit for a full-rank
// system; a rank-deficient one gets QR's basic solution):
//   1. the fitting frame: the principal axes of the points' covariance (the
//      same diagonalisation as CGAL's), the least spread one as z, made
//      direct by flipping the first;
//   2. the jet z = Σ_{k ≤ d} Σ_{i ≤ k} A_{k,i} x^{k−i} y^i / ((k−i)! i!) in
//      that frame about the first point, by least squares on monomials
//      preconditioned by the mean |x|, |y| (monomials by products: CGAL's
//      std::pow took most of a fit's time);
//   3. the Weingarten map I⁻¹ II of the graph at the origin, in the
//      orthonormal tangent basis (Y, Z) of Gram–Schmidt on X_u, X_v; the
//      tensor is that symmetric map in 3-D (what Σ k d dᵀ of its eigen-
//      decomposition gives back), rotated to the world, negated when the
//      fit's normal (−A₁, −A₂, 1) disagrees with `normal`.
Eigen::Matrix3d JetTensor(const std::vector<Point>& points, int degree,
                            const Eigen::Vector3d& normal) {
  const int n = int(points.size());
  double sx = 0, sy = 0, sz = 0, sxx = 0, syy = 0, szz = 0, sxy = 0, sxz = 0, syz = 0;
  for (const Point& p : points) {
    const double x = p.x(), y = p.y(), z = p.z();
    sx += x / n;
    sy += y / n;
    sz += z / n;
    sxx += x * x / n;
    syy += y * y / n;
    szz += z * z / n;
    sxy += x * y / n;
    sxz += x * z / n;
    syz += y * z / n;
  }
  const std::array<double, 6> covariance = {{sxx - sx * sx, sxy - sx * sy, sxz - sx * sz,
                                             syy - sy * sy, syz - sy * sz, szz - sz * sz}};
  std::array<double, 3> values = {{0, 0, 0}};
  std::array<double, 9> vectors = {{0, 0, 0, 0, 0, 0, 0, 0, 0}};
  CGAL::Default_diagonalize_traits<double, 3>::diagonalize_selfadjoint_covariance_matrix(
      covariance, values, vectors);  // ascending
  Eigen::Matrix3d R;  // rows: the fitting axes, world → fitting
  R.row(0) << vectors[6], vectors[7], vectors[8];
  R.row(1) << vectors[3], vectors[4], vectors[5];
  R.row(2) << vectors[0], vectors[1], vectors[2];
  if (R.row(0).dot(R.row(1).cross(R.row(2))) < 0) R.row(0) *= -1.0;

  const Eigen::Vector3d origin(points[0].x(), points[0].y(), points[0].z());
  std::vector<Eigen::Vector3d> local(n);
  double precondition = 0;
  for (int r = 0; r < n; ++r) {
    local[r] = R * (Eigen::Vector3d(points[r].x(), points[r].y(), points[r].z()) - origin);
    precondition += std::abs(local[r].x()) + std::abs(local[r].y());
  }
  precondition /= 2 * n;
  const int coefficients = NumCoefficients(degree);
  double factorial[kMaxDegree + 1] = {1}, scale[kMaxDegree + 1] = {1};
  for (int k = 1; k <= degree; ++k) {
    factorial[k] = factorial[k - 1] * k;
    scale[k] = scale[k - 1] * precondition;
  }
  Eigen::MatrixXd M(n, coefficients);
  Eigen::VectorXd Z(n);
  for (int r = 0; r < n; ++r) {
    double xp[kMaxDegree + 1] = {1}, yp[kMaxDegree + 1] = {1};
    for (int k = 1; k <= degree; ++k) {
      xp[k] = xp[k - 1] * local[r].x();
      yp[k] = yp[k - 1] * local[r].y();
    }
    Z[r] = local[r].z();
    for (int k = 0; k <= degree; ++k) {
      for (int i = 0; i <= k; ++i) {
        M(r, k * (k + 1) / 2 + i) = xp[k - i] * yp[i] / (factorial[i] * factorial[k - i] * scale[k]);
      }
    }
  }
  Eigen::VectorXd A = SolveByQr(M, Z);
  for (int k = 0; k <= degree; ++k) {
    for (int i = 0; i <= k; ++i) A[k * (k + 1) / 2 + i] /= scale[k];
  }

  const double norm2 = 1 + A[1] * A[1] + A[2] * A[2];
  const double e = 1 + A[1] * A[1], f = A[1] * A[2], g = 1 + A[2] * A[2];
  const double l = A[3], m = A[4], nn = A[5];
  const double w = std::sqrt(norm2) * norm2;
  Eigen::Matrix2d W;
  W << (g * l - f * m) / w, (g * m - f * nn) / w, (e * m - f * l) / w, (e * nn - f * m) / w;
  const Eigen::Vector3d Xu(1, 0, A[1]), Xv(0, 1, A[2]);
  const double norm_u = Xu.norm(), uv = Xu.dot(Xv);
  const Eigen::Vector3d Y = Xu / norm_u;
  Eigen::Vector3d T = Xv - uv * Xu / (norm_u * norm_u);
  const double norm_t = T.norm();
  T /= norm_t;
  Eigen::Matrix2d C;  // (X_u, X_v) → (Y, T)
  C << 1 / norm_u, -uv / (norm_u * norm_u * norm_t), 0, 1 / norm_t;
  const Eigen::Matrix2d V = C.inverse() * W * C;
  Eigen::Matrix<double, 3, 2> B;
  B << Y, T;
  Eigen::Matrix2d S;  // the lower triangle, as CGAL's diagonalisation reads it
  S << V(0, 0), V(1, 0), V(1, 0), V(1, 1);
  Eigen::Matrix3d tensor = R.transpose() * (B * S * B.transpose()) * R;
  const Eigen::Vector3d fit_normal = R.transpose() * Eigen::Vector3d(-A[1], -A[2], 1.0) / std::sqrt(norm2);
  if (fit_normal.dot(normal) < 0) tensor = -tensor;
  return tensor;
}

}  // namespace

FaceCurvature CurvatureOfMatrix(const Eigen::Matrix2d& M_in, double flat_curvature,
                                double sign_tolerance) {
  FaceCurvature c;
  c.M = 0.5 * (M_in + M_in.transpose());
  const Principal p = PrincipalOf(c.M);
  c.k1 = p.k1;
  c.k2 = p.k2;
  c.d1 = p.d1;
  c.d2 = p.d2;
  const double kmax = std::max(std::abs(p.k1), std::abs(p.k2));
  c.flat = !(kmax >= flat_curvature) || kmax == 0.0;
  c.z_m_finite = !c.flat && ZOfMatrix(c.M, &c.z_m);
  const double K = p.k1 * p.k2;
  c.gaussian_sign = (c.flat || std::abs(K) <= sign_tolerance * kmax * kmax) ? 0 : (K > 0 ? 1 : -1);
  c.num_asymptotic = c.flat ? 0 : AsymptoticDirections(c.M, c.asymptotic, sign_tolerance);
  return c;
}

namespace {

std::vector<Eigen::Matrix3d> ShapeTensors(const Mesh& mesh, const JetOptions& options,
                                          const std::vector<char>* only) {
  CHECK(!mesh.has_garbage());
  CHECK(options.degree >= 2 && options.degree <= kMaxDegree) << "jet degree must be 2..4";
  CHECK(options.rings >= 1 && options.rings <= kMaxRings) << "jet rings must be 1.." << kMaxRings;
  const int needed = NumCoefficients(options.degree);
  const int min_points = options.min_points > 0 ? options.min_points : 2 * needed;
  CHECK(min_points >= needed) << "jet min_points " << min_points << " < " << needed
                              << " coefficients of a degree-" << options.degree << " jet";

  std::vector<Eigen::Matrix3d> tensors(mesh.number_of_vertices(), Eigen::Matrix3d::Zero());
  const int count = static_cast<int>(mesh.number_of_vertices());
  // Every vertex's fit is independent (each thread has its own marks).
  const FullTeams teams;
#pragma omp parallel
  {
    std::vector<int> mark(mesh.number_of_vertices(), -1);
    std::vector<Point> points;
#pragma omp for schedule(dynamic, 512)
    for (int i = 0; i < count; ++i) {
      const VertexIndex v(static_cast<VertexIndex::size_type>(i));
      if (mesh.is_isolated(v) || (only && !(*only)[size_t(i)])) continue;
      const std::vector<VertexIndex> hood = Neighbourhood(mesh, v, options.rings, min_points, &mark, i);
      // Lower the degree for tiny components rather than fail.
      int degree = options.degree;
      while (degree > 2 && static_cast<int>(hood.size()) < NumCoefficients(degree)) --degree;
      if (static_cast<int>(hood.size()) < NumCoefficients(degree)) continue;  // stays 0
      points.clear();
      for (VertexIndex u : hood) points.push_back(mesh.point(u));
      const Eigen::Vector3d n = VertexNormal(mesh, v);
      tensors[i] = JetTensor(points, degree, n);
    }
  }
  return tensors;
}

}  // namespace

std::vector<Eigen::Matrix3d> VertexShapeTensors(const Mesh& mesh, const JetOptions& options) {
  return ShapeTensors(mesh, options, nullptr);
}

std::vector<Eigen::Matrix3d> VertexShapeTensors(const Mesh& mesh, const JetOptions& options,
                                                const std::vector<char>& only) {
  CHECK_EQ(only.size(), mesh.number_of_vertices());
  return ShapeTensors(mesh, options, &only);
}

Eigen::Matrix2d FaceMatrix(const Mesh& mesh, const FaceFrames& frames, FaceIndex f,
                           const std::vector<Eigen::Matrix3d>& vertex_tensors) {
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
  int n = 0;
  for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) {
    S += vertex_tensors[v.idx()];
    ++n;
  }
  S /= n;
  Eigen::Matrix<double, 3, 2> E;
  E.col(0) = frames.e1[f.idx()];
  E.col(1) = frames.e2[f.idx()];
  const Eigen::Matrix2d M = E.transpose() * S * E;
  return 0.5 * (M + M.transpose());
}

std::vector<FaceCurvature> ComputeFaceCurvature(const Mesh& mesh, const FaceFrames& frames,
                                                const JetOptions& options) {
  const std::vector<Eigen::Matrix3d> tensors = VertexShapeTensors(mesh, options);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (VertexIndex v : mesh.vertices()) {
    lo = lo.cwiseMin(EigenPoint(mesh, v));
    hi = hi.cwiseMax(EigenPoint(mesh, v));
  }
  const double diagonal = (hi - lo).norm();
  const double flat_curvature = diagonal > 0 ? options.flat_tolerance / diagonal : INFINITY;
  std::vector<FaceCurvature> out(mesh.number_of_faces());
  for (FaceIndex f : mesh.faces()) {
    out[f.idx()] = CurvatureOfMatrix(FaceMatrix(mesh, frames, f, tensors), flat_curvature,
                                     options.sign_tolerance);
  }
  return out;
}

}  // namespace archgeo
