// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — interpolating cubic spline curve in R³ through given points (no CGAL).
//
// C² cubic spline S(t) with S(t_k) = P_k, chord-length parametrisation
// (t_{k+1} − t_k = ‖P_{k+1} − P_k‖, so |S'| ≈ 1), natural end conditions
// (S'' = 0 at both ends) for an open curve, periodic (C² across the closing
// segment P_{n−1} → P_0) for a closed one. The second derivatives M_k solve the
// usual tridiagonal system (cyclic for a closed curve, by Sherman–Morrison).
// Used for the "grid interpolating spline curves" of the force-directed grids
// paper (§4): one spline through the vertices of every grid line.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace archgeo {

class CubicSpline3 {
 public:
  // Preconditions (CHECKed): ≥ 2 points (≥ 3 if closed), all finite. Chords of
  // zero length (coincident consecutive points) switch the curve to the uniform
  // parametrisation with the mean chord as step.
  CubicSpline3(std::vector<Eigen::Vector3d> points, bool closed);

  int NumPoints() const { return static_cast<int>(points_.size()); }
  // n − 1 for an open curve, n for a closed one (the last joins P_{n−1} to P_0).
  int NumSegments() const { return closed_ ? NumPoints() : NumPoints() - 1; }

  // S'(t_k), the tangent at point k (chord-length parameter).
  Eigen::Vector3d Derivative(int k) const;

  // S on segment `segment` at local parameter s ∈ [0, h_segment].
  Eigen::Vector3d Evaluate(int segment, double s) const;

  // ∫ |S'| over segment `segment` (5-point Gauss–Legendre).
  double ArcLength(int segment) const;

 private:
  Eigen::Vector3d SegmentDerivative(int segment, double s) const;

  std::vector<Eigen::Vector3d> points_;
  bool closed_;
  std::vector<double> h_;              // parameter step of every segment
  std::vector<Eigen::Vector3d> m_;     // S'' at every point
};

}  // namespace archgeo
