#include "fields/face_curvature.h"

#include <algorithm>
#include <cmath>

// Jet fitting needs an SVD traits class; naming CGAL::Eigen_svd explicitly
// avoids depending on CGAL_EIGEN3_ENABLED (CGAL::Eigen3_support) for the
// default template argument. JetOptions::qr swaps in pivoted QR.
#include <CGAL/Eigen_matrix.h>
#include <CGAL/Eigen_svd.h>
#include <CGAL/Eigen_vector.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <Eigen/QR>
#include <glog/logging.h>

#include "core/solver_options.h"
#include "fields/conjugate.h"

namespace archgeo {
namespace {

constexpr int kMaxRings = 8;

// A jet fit's least squares (CGAL's SvdTraits concept) by pivoted
// Householder QR (JetOptions::qr). The condition number it returns (which
// archgeo never reads) is QR's estimate: the ratio of R's largest to smallest
// diagonal entry (an exact one, from the eigenvalues of RᵀR, took about a
// tenth of the fitting time).
struct QrLeastSquares {
  using FT = double;
  using Vector = CGAL::Eigen_vector<FT>;
  using Matrix = CGAL::Eigen_matrix<FT>;
  static FT solve(const Matrix& M, Vector& B) {
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(M.eigen_object());
    B.eigen_object() = qr.solve(Eigen::VectorXd(B.eigen_object()));
    const Eigen::VectorXd d = qr.matrixR().diagonal().cwiseAbs();
    return d.maxCoeff() / d.minCoeff();
  }
};

Eigen::Vector3d P(const Mesh& mesh, VertexIndex v) {
  const Point& p = mesh.point(v);
  return Eigen::Vector3d(p.x(), p.y(), p.z());
}

int NumCoefficients(int degree) { return (degree + 1) * (degree + 2) / 2; }

Eigen::Vector3d VertexNormal(const Mesh& mesh, VertexIndex v) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (HalfedgeIndex h : mesh.halfedges_around_target(mesh.halfedge(v))) {
    if (mesh.is_border(h)) continue;
    const Eigen::Vector3d a = P(mesh, mesh.source(h));
    const Eigen::Vector3d b = P(mesh, mesh.target(h));
    const Eigen::Vector3d c = P(mesh, mesh.target(mesh.next(h)));
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

template <class LeastSquares>
std::vector<Eigen::Matrix3d> ShapeTensors(const Mesh& mesh, const JetOptions& options,
                                          const std::vector<char>* only) {
  CHECK(!mesh.has_garbage());
  CHECK(options.degree >= 2 && options.degree <= 4) << "jet degree must be 2..4";
  CHECK(options.rings >= 1 && options.rings <= kMaxRings) << "jet rings must be 1.." << kMaxRings;
  const int needed = NumCoefficients(options.degree);
  const int min_points = options.min_points > 0 ? options.min_points : 2 * needed;
  CHECK(min_points >= needed) << "jet min_points " << min_points << " < " << needed
                              << " coefficients of a degree-" << options.degree << " jet";

  using Fitting = CGAL::Monge_via_jet_fitting<Kernel, Kernel, LeastSquares>;
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
      Fitting fitting;
      typename Fitting::Monge_form monge = fitting(points.begin(), points.end(), degree, 2);
      const Eigen::Vector3d n = VertexNormal(mesh, v);
      monge.comply_wrt_given_normal(Vector(n.x(), n.y(), n.z()));
      const Vector d1 = monge.maximal_principal_direction();
      const Vector d2 = monge.minimal_principal_direction();
      const Eigen::Vector3d a(d1.x(), d1.y(), d1.z()), b(d2.x(), d2.y(), d2.z());
      tensors[i] = monge.principal_curvatures(0) * a * a.transpose() +
                   monge.principal_curvatures(1) * b * b.transpose();
    }
  }
  return tensors;
}

}  // namespace

std::vector<Eigen::Matrix3d> VertexShapeTensors(const Mesh& mesh, const JetOptions& options) {
  return options.qr ? ShapeTensors<QrLeastSquares>(mesh, options, nullptr)
                    : ShapeTensors<CGAL::Eigen_svd>(mesh, options, nullptr);
}

std::vector<Eigen::Matrix3d> VertexShapeTensors(const Mesh& mesh, const JetOptions& options,
                                                const std::vector<char>& only) {
  CHECK_EQ(only.size(), mesh.number_of_vertices());
  return options.qr ? ShapeTensors<QrLeastSquares>(mesh, options, &only)
                    : ShapeTensors<CGAL::Eigen_svd>(mesh, options, &only);
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
    lo = lo.cwiseMin(P(mesh, v));
    hi = hi.cwiseMax(P(mesh, v));
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
