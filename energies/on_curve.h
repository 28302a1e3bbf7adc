// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Vertices that slide on a polyline — the YAML term `on_curve`, in two forms:
//
// (a) Exact (CurveManifold, recommended): the vertex's position block gets a
//     ceres::Manifold of tangent size 1,
//
//       x = C(t),   Plus(x, δ) = C(τ(x) + δ),
//
//     where C is the arc-length parametrisation of the polyline and
//     τ(x) the arc length of x on it (CurvePolyline::Parameter). Every other
//     term keeps reading the 3 coordinates, the solver moves only t, and the
//     vertex is on the curve to rounding by construction, whatever the other
//     terms pull. No residual, no extra block, no weight.
//
// (b) Soft (OnCurve functor): a per-vertex curve parameter t (a variable
//     block of width 1, initialised with CurvePolyline::Parameter(v)) and one
//     3-vector residual
//
//       r = (v − C(t)) / L,
//
//     a penalty that lets v slide (t is free) but leaves v off the curve by
//     about (competing force)/(weight): for vertices attracted to a guide
//     curve rather than bound to it.
//
//   [Gebreiter 2012, §10.1 "vertex locations can be restricted to guide
//    surfaces, meshes or planes"; §11.2.2 boundary vertices "pulled to the
//    perimeter curves, where springs would distribute them evenly";
//    §11.7.1 "boundary vertices were constrained to the perimeter curve"]
//
// Curve: a polyline p_0 … p_{m−1} (open: m − 1 segments; closed: m, the last
// joining p_{m−1} to p_0), arc length a_i at p_i, total length Λ. C(t) =
// p_i + (t − a_i)/(a_{i+1} − a_i) · (p_{i+1} − p_i) on segment i, the segment
// chosen from the value of t (the scalar part of a Jet). Closed curves are
// periodic: t is taken modulo Λ. Open curves are extended linearly beyond
// their ends along the end segments (so the soft residual stays smooth there;
// the engine bounds t to [0, Λ] with Problem::SetParameterLower/UpperBound),
// and the manifold clamps t to [0, Λ] (a vertex stops at the curve's end).
//
// Non-smoothness: C is continuous but its tangent jumps at every polyline
// vertex by the polyline's turning angle. The soft residual's ∂C/∂t is the
// unit direction of the segment at t (the forward segment at a vertex). The
// manifold's Jacobian (PlusJacobian) is the same inside a segment and, at a
// polyline vertex (within 1e-12 Λ), the unit bisector of the two segments
// (the central difference of C, normalised): with the forward direction only,
// a vertex at a right-angled corner would see no gradient towards the
// segment behind it and could not move back (a vertex sitting on a corner is
// the start of every run on a mesh's own boundary loop). A step that crosses
// a vertex is still evaluated exactly on the polyline, only the linear model
// is off, which the trust region absorbs. A vertex whose optimum is a corner
// of the polyline (a corner of the perimeter) stays there. A smooth design
// curve given by few points should be resampled first (geometry/curves.h
// SampleCatmullRom): the turning angle per sample then shrinks with the
// sample spacing.
//
// Units / normalisation (soft form): L = 1/inv_length is a fixed length
// chosen by the builder, r is unit-free. t is in the curve's length units.
//
// Singular configurations: none in the evaluation (segments have positive
// length, a precondition); the kinks above. τ(x) of a point on the curve is
// exact unless the curve comes within rounding of itself elsewhere (then
// either branch may be returned). Never returns false.
//
// Invariances: rigid motions and uniform scaling applied to the curve and the
// vertex together (t scales with the curve; r → R r, ‖r‖ unchanged with
// inv_length → inv_length / s); reversing the polyline maps t → Λ − t.
#ifndef ARCHGEO_ENERGIES_ON_CURVE_H_
#define ARCHGEO_ENERGIES_ON_CURVE_H_

#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <ceres/jet.h>
#include <ceres/manifold.h>

#include "energies/autodiff.h"

namespace archgeo {

// The scalar value of a double or a Jet (to choose a segment).
inline double ScalarPart(double x) { return x; }
template <typename T, int N>
double ScalarPart(const ceres::Jet<T, N>& x) {
  return ScalarPart(x.a);
}

// A polyline parametrised by arc length (no CGAL; geometry/curves.h reads and
// validates polylines and converts them).
class CurvePolyline {
 public:
  // xyz: 3 doubles per point, p_0 … p_{m−1}, a closed curve without repeating
  // p_0 at the end. Preconditions (CHECKed): m ≥ 2 (closed: m ≥ 3), finite
  // coordinates, every segment of positive length.
  CurvePolyline(const std::vector<double>& xyz, bool closed);

  bool closed() const { return closed_; }
  double length() const { return arc_.back(); }  // Λ
  int num_segments() const { return static_cast<int>(arc_.size()) - 1; }

  // Closed: t modulo Λ in [0, Λ); open: t unchanged.
  double Wrap(double t) const;
  // The segment of (wrapped) t: i with a_i ≤ t < a_{i+1}, clamped to the
  // first/last segment for t outside [0, Λ] (open curves).
  int Segment(double t) const;
  // Unit direction of Segment(t).
  Eigen::Vector3d Tangent(double t) const;
  // The manifold's direction at t: Tangent(t) inside a segment; at a knot a_i
  // of two segments (|Wrap(t) − a_i| ≤ 1e-12 Λ; an open curve's ends excluded)
  // the unit bisector of their directions (Tangent(t) if they are opposite).
  Eigen::Vector3d CentralTangent(double t) const;
  // Arc length of the point of the polyline closest to x (3 doubles), in
  // [0, Λ] (open) or [0, Λ) (closed); the first segment wins ties. Linear in
  // the number of segments.
  double Parameter(const double* x) const;

  // C(t), differentiable in t within a segment (see the header comment).
  template <typename T>
  Eigen::Matrix<T, 3, 1> Evaluate(const T& t) const {
    T wrapped = t;
    if (closed_) wrapped -= T(length() * std::floor(ScalarPart(t) / length()));
    const int i = SegmentOf(ScalarPart(wrapped));
    const T s = (wrapped - T(arc_[i])) / T(arc_[i + 1] - arc_[i]);
    return points_[i].cast<T>() +
           s * (points_[i + 1] - points_[i]).template cast<T>();
  }

 private:
  // The segment containing arc length s (no wrapping), clamped to the first
  // and last segment.
  int SegmentOf(double s) const;

  std::vector<Eigen::Vector3d> points_;  // closed: p_0 repeated at the end
  std::vector<double> arc_;              // a_i, one per entry of points_
  bool closed_;
};

// Soft form: r = (v − C(t)) / L.
struct OnCurve {
  using Shape = CostShape<3, 3, 1>;

  // curve: shared by every vertex on it (not null); inv_length: 1/L.
  OnCurve(std::shared_ptr<const CurvePolyline> curve, double inv_length)
      : curve(std::move(curve)), inv_length(inv_length) {}

  // v: 3 doubles, the vertex; t: 1 double, its curve parameter;
  // residual: 3 doubles.
  template <typename T>
  bool operator()(const T* v_ptr, const T* t_ptr, T* residual_ptr) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> v(v_ptr);
    Eigen::Map<Vec3> residual(residual_ptr);
    residual = (v - curve->Evaluate(t_ptr[0])) * T(inv_length);
    return true;
  }

  std::shared_ptr<const CurvePolyline> curve;
  double inv_length;
};

// Exact form: a 3-vector position on the curve, tangent size 1 (arc length).
// Plus/Minus/Jacobians as in the header comment; x must lie on the curve
// (project it first: x = C(Parameter(x))). MinusJacobian · PlusJacobian = 1.
class CurveManifold : public ceres::Manifold {
 public:
  explicit CurveManifold(std::shared_ptr<const CurvePolyline> curve);
  int AmbientSize() const override { return 3; }
  int TangentSize() const override { return 1; }
  bool Plus(const double* x, const double* delta,
            double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;
  // Closed curves: the difference of parameters wrapped to (−Λ/2, Λ/2].
  bool Minus(const double* y, const double* x,
             double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;

 private:
  std::shared_ptr<const CurvePolyline> curve_;
};

// Returns a new CurveManifold (the caller, usually ceres::Problem, takes
// ownership). Precondition (CHECKed): curve not null.
ceres::Manifold* MakeCurveManifold(std::shared_ptr<const CurvePolyline> curve);

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_ON_CURVE_H_
