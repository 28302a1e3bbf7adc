// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/surface_band.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/term.h"

namespace archgeo {

namespace {

constexpr double kInside = 1 - 1e-12;  // Minus clamps |o| to this × B

}  // namespace

BandManifold::BandManifold(const Eigen::Vector3d& point,
                           const Eigen::Matrix<double, 3, Eigen::Dynamic>& directions, double bound)
    : point_(point), d_(directions), bound_(bound) {
  CHECK(d_.cols() >= 1 && d_.cols() <= 3) << "BandManifold: one to three directions";
  CHECK(bound_ > 0 && std::isfinite(bound_)) << "BandManifold: bound must be positive";
}

Eigen::VectorXd BandManifold::Offset(const double* x) const {
  return d_.transpose() * (Eigen::Map<const Eigen::Vector3d>(x) - point_);
}

// The radial map |η| → |o|: the identity up to a = B/2, then a smooth
// saturation to B (C¹ at a): s(ρ) = a + (B − a) tanh((ρ − a)/(B − a)).
double BandManifold::Radius(double rho) const {
  const double a = 0.5 * bound_, w = bound_ - a;
  if (rho <= a) return rho;
  // tanh rounds to 1 for large arguments: keep |o| strictly inside.
  return std::min(a + w * std::tanh((rho - a) / w), kInside * bound_);
}

double BandManifold::Rho(double radius) const {
  const double a = 0.5 * bound_, w = bound_ - a;
  const double r = std::min(radius, kInside * bound_);
  return r <= a ? r : a + w * std::atanh((r - a) / w);
}

Eigen::VectorXd BandManifold::ToEta(const Eigen::VectorXd& o) const {
  const double r = o.norm();
  if (r <= 0.5 * bound_) return o;
  return (Rho(r) / r) * o;
}

Eigen::VectorXd BandManifold::ToOffset(const Eigen::VectorXd& eta) const {
  const double rho = eta.norm();
  if (rho <= 0.5 * bound_) return eta;
  return (Radius(rho) / rho) * eta;
}

Eigen::MatrixXd BandManifold::Derivative(const Eigen::VectorXd& o, bool inverse) const {
  const int k = int(o.size());
  const double a = 0.5 * bound_, w = bound_ - a;
  const double r = std::min(o.norm(), kInside * bound_);
  if (r <= a) return Eigen::MatrixXd::Identity(k, k);
  const Eigen::VectorXd u = o / o.norm();
  const double t = (r - a) / w;
  const double radial = 1 - t * t;    // d|o|/d|η|
  const double across = r / Rho(r);   // |o| / |η|
  const Eigen::MatrixXd uu = u * u.transpose();
  const Eigen::MatrixXd rest = Eigen::MatrixXd::Identity(k, k) - uu;
  return inverse ? Eigen::MatrixXd(uu / radial + rest / across)
                 : Eigen::MatrixXd(radial * uu + across * rest);
}

bool BandManifold::Plus(const double* x, const double* delta, double* x_plus_delta) const {
  const Eigen::Map<const Eigen::Vector3d> xv(x), dv(delta);
  const Eigen::VectorXd o = Offset(x);
  const Eigen::VectorXd moved = ToOffset(ToEta(o) + d_.transpose() * dv);
  Eigen::Map<Eigen::Vector3d> out(x_plus_delta);
  out = xv + (dv - d_ * (d_.transpose() * dv)) + d_ * (moved - o);
  return true;
}

bool BandManifold::PlusJacobian(const double* x, double* jacobian) const {
  const Eigen::Matrix3d j = Eigen::Matrix3d::Identity() - d_ * d_.transpose() +
                            d_ * Derivative(Offset(x), false) * d_.transpose();
  Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> out(jacobian);
  out = j;
  return true;
}

bool BandManifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  const Eigen::Map<const Eigen::Vector3d> yv(y), xv(x);
  const Eigen::Vector3d diff = yv - xv;
  Eigen::Map<Eigen::Vector3d> out(y_minus_x);
  out = diff - d_ * (d_.transpose() * diff) + d_ * (ToEta(Offset(y)) - ToEta(Offset(x)));
  return true;
}

bool BandManifold::MinusJacobian(const double* x, double* jacobian) const {
  const Eigen::Matrix3d j = Eigen::Matrix3d::Identity() - d_ * d_.transpose() +
                            d_ * Derivative(Offset(x), true) * d_.transpose();
  Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> out(jacobian);
  out = j;
  return true;
}

double BandBound(double distance, double band, double start) {
  if (distance < start * band) return start * band;
  if (distance < band) return 0.5 * (distance + band);
  return 1.001 * distance;
}

}  // namespace archgeo

// --- term `surface_band` ---------------------------------------------------------

namespace archgeo::terms {
namespace {

// The band b of vertex v is the problem's constant block "surface_band"
// (canonical lengths; ≤ 0: no band there).
void AddSurfaceBand(TermContext& c, size_t i) {
  const int v = c.elements->Vertices(i)[0];
  const double band = c.Block("surface_band", v)[0];
  if (!(band > 0) || c.Fixed(v)) return;
  const Eigen::Vector3d p(c.ProjectedPoint(v)), dir(c.ProjectedDirection(v));
  // On the reference's boundary curve: a ball around the curve point (its
  // tangent line leaves the surface at a corner of the boundary).
  Eigen::Matrix<double, 3, Eigen::Dynamic> d = Eigen::Matrix3d::Identity();
  if (!c.OnBoundaryCurve(v)) {
    if (!(dir.norm() > 0)) return;  // a degenerate reference point: no direction to bound
    d = dir.normalized();
  }
  double* x = c.Position(v);
  const double distance = (d.transpose() * (Eigen::Map<const Eigen::Vector3d>(x) - p)).norm();
  c.SetManifold(x, new BandManifold(p, d, BandBound(distance, band, c.Number("start"))));
}

}  // namespace

const TermSpec& surface_band() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "surface_band";
    t.summary =
        "constraint: every vertex within the deviation band of the reference surface "
        "(tolerance.surface_distance_max; a bounded manifold, no residual), re-projected "
        "every round (on while its weight is > 0)";
    t.paper = "[archgeo: the design deviation as a hard bound]";
    t.elements = "vertices";
    t.needs_projection = true;
    t.reads = {"surface_band"};
    t.options = {NumberKey("start", 0.95, 0.01, 1,
                           "within a round a vertex may go this fraction of the band from the "
                           "reference's tangent plane (the rest absorbs its curvature)")};
    t.add = &AddSurfaceBand;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms
