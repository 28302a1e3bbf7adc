// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — Surface: one parametric surface of any kind in surfaces/, placed
// in space by a rigid motion (no CGAL).
//
//   x(u, v) = Q · s(u, v) + t,   s one of the analytic surfaces below,
//                                Q a rotation, t a translation (default: none).
//
// A Surface is a small value (a few dozen doubles): energies hold it by value,
// copies are cheap. Point and Tangents are templated on the scalar, so a Ceres
// Jet passes through (autodiff of residuals through x(u, v)). A new kind (a
// NURBS patch, a mesh-based surface) is one more alternative of Kind with the
// same members (surfaces/parametric.h); nothing else here changes.
#pragma once

#include <variant>

#include <Eigen/Core>

#include "surfaces/catenoid.h"
#include "surfaces/cylinder.h"
#include "surfaces/dupin_cyclide.h"
#include "surfaces/function_graph.h"
#include "surfaces/helicoid.h"
#include "surfaces/klein_bottle.h"
#include "surfaces/parametric.h"
#include "surfaces/plane.h"
#include "surfaces/torus.h"
#include "surfaces/tower.h"

namespace archgeo {

class Surface {
 public:
  using Kind = std::variant<Plane, Cylinder, Torus, Catenoid, Helicoid, KleinBottle, Tower,
                            DupinCyclide, FunctionGraph>;

  // `kind` as it is, not moved (Q = I, t = 0).
  explicit Surface(Kind kind) : kind_(std::move(kind)) {}

  const Kind& kind() const { return kind_; }

  // The kind's factory name ("torus", "tower", ...). A Tower whose sector is
  // open is still "tower": the factory name it came from is not kept.
  const char* KindName() const {
    return std::visit([](const auto& s) { return s.kName; }, kind_);
  }

  ParameterDomain Domain() const {
    return std::visit([](const auto& s) { return s.Domain(); }, kind_);
  }

  // x(u, v).
  template <typename T>
  Vec3T<T> Point(const T& u, const T& v) const {
    const Vec3T<T> p = std::visit([&](const auto& s) { return s.Point(u, v); }, kind_);
    if (!placed_) return p;
    return rotation_.cast<T>() * p + translation_.cast<T>();
  }

  // x_u(u, v), x_v(u, v).
  template <typename T>
  void Tangents(const T& u, const T& v, Vec3T<T>* xu, Vec3T<T>* xv) const {
    std::visit([&](const auto& s) { s.Tangents(u, v, xu, xv); }, kind_);
    if (!placed_) return;
    *xu = rotation_.cast<T>() * *xu;
    *xv = rotation_.cast<T>() * *xv;
  }

  Eigen::Vector3d Point(const Eigen::Vector2d& uv) const { return Point(uv[0], uv[1]); }

  // Unit normal x_u × x_v / |x_u × x_v| (zero where the map is singular).
  Eigen::Vector3d Normal(const Eigen::Vector2d& uv) const;

  // This surface moved by x → rotation · x + translation after its own
  // placement. Precondition (CHECKed): rotation orthonormal with det +1,
  // everything finite.
  Surface Placed(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation) const;

  // The same point written canonically: a periodic direction wrapped into
  // [u0, u1) (resp. [v0, v1)) — across a flipping u-seam v is reflected,
  // v → v0 + v1 − v, once per turn — and an open direction clamped to its
  // bounds (the surface ends there). x(Canonical(uv)) = x(uv) unless clamped.
  Eigen::Vector2d Canonical(Eigen::Vector2d uv) const;

  // Canonical without the clamping: periodic directions wrapped (and v
  // reflected across a flipping u-seam), open ones left as they are (the
  // formulas extend beyond the domain). x(Wrapped(uv)) = x(uv).
  Eigen::Vector2d Wrapped(Eigen::Vector2d uv) const;

  // The parameter of the same point as `uv` in the chart nearest to `near`:
  // whole periods added in the periodic directions, and across a flipping
  // u-seam v reflected once per turn. x(NearestChart(uv, near)) = x(uv).
  Eigen::Vector2d NearestChart(Eigen::Vector2d uv, const Eigen::Vector2d& near) const;

  // The parameter of the point of the surface closest to `x`, by Newton's
  // method on f(u, v) = ½‖x(u, v) − x‖² from `start` (exact Hessian from
  // Tangents<Jet>; a Gauss–Newton step where the Hessian is not positive
  // definite; backtracking on f). Converges quadratically near a point of the
  // surface; `start` must lie in the basin of the wanted closest point (the
  // neighbouring grid vertex's parameter is a good start). Periodic
  // directions are wrapped; open ones are clamped to the domain if
  // `keep_in_domain` (the designed surface), else free (the formula extends
  // beyond the domain, and so may a grid: surfaces/force_directed.h).
  Eigen::Vector2d ClosestParameter(const Eigen::Vector3d& x, const Eigen::Vector2d& start,
                                   bool keep_in_domain = true) const;

  // The same with the start chosen as the closest of a 33 × 33 sample of the
  // domain (for a point with no good guess; O(1000) evaluations).
  Eigen::Vector2d ClosestParameter(const Eigen::Vector3d& x, bool keep_in_domain = true) const;

 private:
  Kind kind_;
  bool placed_ = false;
  Eigen::Matrix3d rotation_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation_ = Eigen::Vector3d::Zero();
};

}  // namespace archgeo
