// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "surfaces/cubic_spline.h"

#include <cmath>

#include <glog/logging.h>

namespace archgeo {
namespace {

// Chords shorter than this times the mean chord count as zero.
constexpr double kDegenerateChord = 1e-12;

using Rows = std::vector<Eigen::Vector3d>;

// Thomas algorithm: a_k x_{k−1} + b_k x_k + c_k x_{k+1} = r_k, k = 0..n−1
// (a_0 and c_{n−1} unused). Diagonally dominant here (b = 2(h + h') > a + c).
Rows SolveTridiagonal(const std::vector<double>& a, const std::vector<double>& b,
                      const std::vector<double>& c, const Rows& r) {
  const size_t n = b.size();
  std::vector<double> cp(n);
  Rows dp(n), x(n);
  cp[0] = c[0] / b[0];
  dp[0] = r[0] / b[0];
  for (size_t k = 1; k < n; ++k) {
    const double denominator = b[k] - a[k] * cp[k - 1];
    cp[k] = c[k] / denominator;
    dp[k] = (r[k] - a[k] * dp[k - 1]) / denominator;
  }
  x[n - 1] = dp[n - 1];
  for (size_t k = n - 1; k-- > 0;) x[k] = dp[k] - cp[k] * x[k + 1];
  return x;
}

// The cyclic system (a_0 couples x_{n−1}, c_{n−1} couples x_0), n ≥ 3, by
// Sherman–Morrison on the Thomas algorithm [Numerical Recipes, §2.7].
Rows SolveCyclicTridiagonal(const std::vector<double>& a, std::vector<double> b,
                            const std::vector<double>& c, const Rows& r) {
  const size_t n = b.size();
  const double alpha = c[n - 1], beta = a[0];  // corners: row n−1 → x_0, row 0 → x_{n−1}
  const double gamma = -b[0];
  b[0] -= gamma;
  b[n - 1] -= alpha * beta / gamma;
  const Rows x = SolveTridiagonal(a, b, c, r);
  Rows u(n, Eigen::Vector3d::Zero());
  u[0] = Eigen::Vector3d::Constant(gamma);
  u[n - 1] = Eigen::Vector3d::Constant(alpha);
  const Rows z = SolveTridiagonal(a, b, c, u);
  Rows out(n);
  for (int d = 0; d < 3; ++d) {
    const double factor = (x[0][d] + beta * x[n - 1][d] / gamma) /
                          (1.0 + z[0][d] + beta * z[n - 1][d] / gamma);
    for (size_t k = 0; k < n; ++k) out[k][d] = x[k][d] - factor * z[k][d];
  }
  return out;
}

}  // namespace

CubicSpline3::CubicSpline3(std::vector<Eigen::Vector3d> points, bool closed)
    : points_(std::move(points)), closed_(closed) {
  const int n = NumPoints();
  CHECK_GE(n, closed ? 3 : 2) << "CubicSpline3: too few points";
  for (const auto& p : points_) CHECK(p.allFinite()) << "CubicSpline3: non-finite point";
  const int segments = NumSegments();
  const auto next = [&](int k) { return (k + 1) % n; };
  h_.resize(segments);
  double total = 0.0;
  for (int k = 0; k < segments; ++k) total += h_[k] = (points_[next(k)] - points_[k]).norm();
  const double mean = total / segments;
  bool degenerate = !(mean > 0.0);
  for (double h : h_) degenerate = degenerate || h <= kDegenerateChord * mean;
  if (degenerate) h_.assign(segments, mean > 0.0 ? mean : 1.0);

  // Row k: h_{k−1} M_{k−1} + 2 (h_{k−1} + h_k) M_k + h_k M_{k+1} = 6 (d_k − d_{k−1}).
  const auto slope = [&](int k) { return Eigen::Vector3d((points_[next(k)] - points_[k]) / h_[k]); };
  m_.assign(n, Eigen::Vector3d::Zero());
  if (closed_) {
    std::vector<double> a(n), b(n), c(n);
    Rows r(n);
    for (int k = 0; k < n; ++k) {
      const int previous = (k + n - 1) % n;
      a[k] = h_[previous];
      c[k] = h_[k];
      b[k] = 2.0 * (h_[previous] + h_[k]);
      r[k] = 6.0 * (slope(k) - slope(previous));
    }
    m_ = SolveCyclicTridiagonal(a, b, c, r);
  } else if (n > 2) {
    const int inner = n - 2;  // M_0 = M_{n−1} = 0
    std::vector<double> a(inner), b(inner), c(inner);
    Rows r(inner);
    for (int q = 0; q < inner; ++q) {
      const int k = q + 1;
      a[q] = h_[k - 1];
      c[q] = h_[k];
      b[q] = 2.0 * (h_[k - 1] + h_[k]);
      r[q] = 6.0 * (slope(k) - slope(k - 1));
    }
    const Rows x = SolveTridiagonal(a, b, c, r);
    for (int q = 0; q < inner; ++q) m_[q + 1] = x[q];
  }
}

Eigen::Vector3d CubicSpline3::SegmentDerivative(int segment, double s) const {
  const int k = segment, k1 = (segment + 1) % NumPoints();
  const double h = h_[k];
  const Eigen::Vector3d d = (points_[k1] - points_[k]) / h;
  return d - h * (2.0 * m_[k] + m_[k1]) / 6.0 + s * m_[k] + s * s * (m_[k1] - m_[k]) / (2.0 * h);
}

Eigen::Vector3d CubicSpline3::Derivative(int k) const {
  CHECK(k >= 0 && k < NumPoints());
  if (k < NumSegments()) return SegmentDerivative(k, 0.0);
  return SegmentDerivative(k - 1, h_[k - 1]);  // the end of an open curve
}

Eigen::Vector3d CubicSpline3::Evaluate(int segment, double s) const {
  CHECK(segment >= 0 && segment < NumSegments());
  const int k = segment, k1 = (segment + 1) % NumPoints();
  const double h = h_[k];
  const Eigen::Vector3d d = (points_[k1] - points_[k]) / h;
  const Eigen::Vector3d b = d - h * (2.0 * m_[k] + m_[k1]) / 6.0;
  return points_[k] + s * b + s * s * m_[k] / 2.0 + s * s * s * (m_[k1] - m_[k]) / (6.0 * h);
}

double CubicSpline3::ArcLength(int segment) const {
  CHECK(segment >= 0 && segment < NumSegments());
  // 5-point Gauss–Legendre nodes and weights on [−1, 1].
  static const double kNodes[5] = {0.0, -0.5384693101056831, 0.5384693101056831,
                                   -0.9061798459386640, 0.9061798459386640};
  static const double kWeights[5] = {0.5688888888888889, 0.4786286704993665,
                                     0.4786286704993665, 0.2369268850561891,
                                     0.2369268850561891};
  const double h = h_[segment];
  double length = 0.0;
  for (int q = 0; q < 5; ++q) {
    const double s = 0.5 * h * (kNodes[q] + 1.0);
    length += kWeights[q] * SegmentDerivative(segment, s).norm();
  }
  return 0.5 * h * length;
}

}  // namespace archgeo
