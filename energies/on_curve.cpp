// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/on_curve.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {
namespace {

// A parameter within this fraction of the curve's length of a knot is at the
// knot (CentralTangent).
constexpr double kKnotTolerance = 1e-12;

}  // namespace

CurvePolyline::CurvePolyline(const std::vector<double>& xyz, bool closed)
    : closed_(closed) {
  CHECK_EQ(xyz.size() % 3, 0u) << "CurvePolyline: 3 doubles per point";
  const size_t m = xyz.size() / 3;
  CHECK_GE(m, closed ? 3u : 2u) << "CurvePolyline: too few points";
  for (size_t i = 0; i < m; ++i) {
    const Eigen::Vector3d p(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    CHECK(p.allFinite()) << "CurvePolyline: non-finite point " << i;
    points_.push_back(p);
  }
  if (closed) points_.push_back(points_.front());
  arc_.push_back(0.0);
  for (size_t i = 0; i + 1 < points_.size(); ++i) {
    const double length = (points_[i + 1] - points_[i]).norm();
    CHECK(length > 0.0) << "CurvePolyline: zero-length segment " << i;
    arc_.push_back(arc_.back() + length);
  }
}

double CurvePolyline::Wrap(double t) const {
  if (!closed_) return t;
  const double wrapped = t - length() * std::floor(t / length());
  return wrapped < length() ? wrapped : 0.0;  // rounding can give Λ
}

int CurvePolyline::Segment(double t) const { return SegmentOf(Wrap(t)); }

int CurvePolyline::SegmentOf(double s) const {
  const int i = static_cast<int>(std::upper_bound(arc_.begin(), arc_.end(), s) -
                                 arc_.begin()) -
                1;
  return std::clamp(i, 0, num_segments() - 1);
}

Eigen::Vector3d CurvePolyline::Tangent(double t) const {
  const int i = Segment(t);
  return (points_[i + 1] - points_[i]) / (arc_[i + 1] - arc_[i]);
}

Eigen::Vector3d CurvePolyline::CentralTangent(double t) const {
  const double s = Wrap(t);
  const double tolerance = kKnotTolerance * length();
  const int n = num_segments();
  // The knot nearest s: a_i or a_{i+1} of its segment (closed: a_n = Λ ≡ a_0).
  const int i = SegmentOf(s);
  int knot = -1;
  if (std::abs(s - arc_[i]) <= tolerance) knot = i;
  if (std::abs(arc_[i + 1] - s) <= tolerance) knot = i + 1;
  if (closed_ && knot == n) knot = 0;
  if (knot < 0 || (!closed_ && (knot == 0 || knot == n))) return Tangent(t);
  const int before = knot == 0 ? n - 1 : knot - 1;  // the segment ending at the knot
  const Eigen::Vector3d in = (points_[before + 1] - points_[before]).normalized();
  const Eigen::Vector3d out = (points_[knot + 1] - points_[knot]).normalized();
  const Eigen::Vector3d bisector = in + out;
  return bisector.norm() > 1e-12 ? Eigen::Vector3d(bisector.normalized()) : Tangent(t);
}

double CurvePolyline::Parameter(const double* x) const {
  const Eigen::Vector3d q(x[0], x[1], x[2]);
  double best = std::numeric_limits<double>::infinity();
  double parameter = 0.0;
  for (int i = 0; i < num_segments(); ++i) {
    const Eigen::Vector3d d = points_[i + 1] - points_[i];
    const double s =
        std::clamp((q - points_[i]).dot(d) / d.squaredNorm(), 0.0, 1.0);
    const double distance2 = (points_[i] + s * d - q).squaredNorm();
    if (distance2 < best) {
      best = distance2;
      parameter = arc_[i] + s * (arc_[i + 1] - arc_[i]);
    }
  }
  return Wrap(parameter);
}

CurveManifold::CurveManifold(std::shared_ptr<const CurvePolyline> curve)
    : curve_(std::move(curve)) {}

bool CurveManifold::Plus(const double* x, const double* delta,
                         double* x_plus_delta) const {
  double t = curve_->Parameter(x) + delta[0];
  if (!curve_->closed()) t = std::clamp(t, 0.0, curve_->length());
  Eigen::Map<Eigen::Vector3d> result(x_plus_delta);
  result = curve_->Evaluate(t);
  return true;
}

bool CurveManifold::PlusJacobian(const double* x, double* jacobian) const {
  Eigen::Map<Eigen::Vector3d> result(jacobian);
  result = curve_->CentralTangent(curve_->Parameter(x));
  return true;
}

bool CurveManifold::Minus(const double* y, const double* x,
                          double* y_minus_x) const {
  double difference = curve_->Parameter(y) - curve_->Parameter(x);
  if (curve_->closed()) {
    const double length = curve_->length();
    difference -= length * std::floor(difference / length);  // [0, Λ)
    if (difference > 0.5 * length) difference -= length;     // (−Λ/2, Λ/2]
  }
  y_minus_x[0] = difference;
  return true;
}

bool CurveManifold::MinusJacobian(const double* x, double* jacobian) const {
  // Row vector 1 × 3 (row-major): the unit tangent.
  Eigen::Map<Eigen::Vector3d> result(jacobian);
  result = curve_->CentralTangent(curve_->Parameter(x));
  return true;
}

ceres::Manifold* MakeCurveManifold(std::shared_ptr<const CurvePolyline> curve) {
  CHECK(curve != nullptr) << "MakeCurveManifold: null curve";
  return new CurveManifold(std::move(curve));
}

}  // namespace archgeo

// --- term `on_curve` -----------------------------------------------------------

namespace archgeo::terms {
namespace {

// The exact form has no residual: the other terms' residuals put the vertex
// into the problem and `finish` binds it to its curve.
void AddOnCurve(TermContext&, size_t) {}

// Each selected free vertex goes to the closest point of the closest curve
// (the option `curve` or `curve_points`, or the reference's boundary loops) and is optimised
// on that curve (CurveManifold: one arc-length coordinate).
void FinishOnCurve(TermContext& c) {
  std::vector<std::shared_ptr<const CurvePolyline>> curves;
  for (const TermContext::Curve& k : c.Curves("curve")) {
    curves.push_back(std::make_shared<const CurvePolyline>(k.xyz, k.closed));
  }
  for (size_t i = 0; i < c.elements->size(); ++i) {
    const int v = c.elements->Vertices(i)[0];
    if (c.Fixed(v)) continue;
    double* x = c.Position(v);
    size_t best = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    Eigen::Vector3d projected = Eigen::Vector3d::Zero();
    for (size_t k = 0; k < curves.size(); ++k) {
      const Eigen::Vector3d p = curves[k]->Evaluate(curves[k]->Parameter(x));
      const double d = (p - Eigen::Map<const Eigen::Vector3d>(x)).norm();
      if (d < best_distance) {
        best_distance = d;
        best = k;
        projected = p;
      }
    }
    Eigen::Map<Eigen::Vector3d> position(x);
    position = projected;
    c.SetManifold(x, MakeCurveManifold(curves[best]));
  }
}

}  // namespace

const TermSpec& on_curve() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "on_curve";
    t.summary = "vertices slide on curves (exactly: one arc-length coordinate each), by default "
                "the boundary vertices on the reference's boundary; any weight > 0 turns it on";
    t.paper = "[Gebreiter 2012, §10.1 guide curves, §11.2.2 and §11.7.1 perimeter curves]";
    t.elements = "boundary_vertices";
    t.element_choices = {"vertices"};
    t.options = {[] {
      Key k;
      k.name = "curve";
      k.type = Type::kInputPath;
      k.fallback = std::string();
      k.doc = "OBJ file of polylines (`l` records, file units); each vertex slides on the "
              "closest one; empty (and no curve_points): the boundary loops of the reference "
              "(or the input)";
      return k;
    }(), [] {
      Key k;
      k.name = "curve_points";
      k.type = Type::kCustom;
      k.doc = "instead of `curve`: one polyline as a list of points [x, y, z] (file units), "
              "closed when the last point repeats the first";
      k.example = "[[0, 0, 0], [10, 0, 0], [10, 5, 2]]";
      return k;
    }()};
    t.finish = &FinishOnCurve;
    t.add = &AddOnCurve;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::OnCurve)
