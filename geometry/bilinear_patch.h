// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — rational bilinear patches, their smooth joins and the Darboux
// transformation [Shi, Wang, Pottmann 2014, §2 and §4].
//
// Pure math on Eigen vectors (no CGAL): usable from energies/, problems/ and
// tools/. The mesh-level H-net (patches on a quad mesh) is geometry/hnet.h.
//
// Conventions (all lengths in the caller's units, angles in degrees):
//  - A patch has control points b0..b3 in cyclic order and weights w0..w3 > 0;
//    b0 sits at (u, v) = (0, 0), b1 at (1, 0), b2 at (1, 1), b3 at (0, 1)
//    [Shi 2014, eq. 1].
//  - Edge i of a patch runs from b_i to b_{i+1} (indices mod 4):
//    edge 0 is v = 0, edge 1 is u = 1, edge 2 is v = 1, edge 3 is u = 0.
//  - The normal is unit(x_u × x_v): b0 → b1 → b2 → b3 counter-clockwise seen
//    from the side the normal points to.
#pragma once

#include <array>

#include <Eigen/Core>

namespace archgeo {

// A rational bilinear patch [Shi 2014, eq. 1]. Preconditions of every function
// taking a patch (CHECKed): weights finite and > 0.
struct BilinearPatch {
  std::array<Eigen::Vector3d, 4> b;        // control points b0..b3, cyclic
  std::array<double, 4> w{1.0, 1.0, 1.0, 1.0};  // weights w0..w3, > 0
};

// Point and first partial derivatives of a patch at (u, v).
struct PatchJet {
  Eigen::Vector3d x, xu, xv;
};

// x(u, v) of eq. 1 [Shi 2014, eq. 1]. (u, v) is normally in [0, 1]²; values
// outside extrapolate the quadric (the denominator must stay > 0, CHECKed).
Eigen::Vector3d PatchPoint(const BilinearPatch& patch, double u, double v);

// x, ∂x/∂u and ∂x/∂v at (u, v) (quotient rule on eq. 1).
PatchJet PatchDerivatives(const BilinearPatch& patch, double u, double v);

// Unit normal unit(x_u × x_v) of the tangent plane at (u, v); the zero vector
// where x_u × x_v vanishes (|x_u × x_v| ≤ 1e-14 |x_u| |x_v|), e.g. at a corner
// whose two edges are collinear.
Eigen::Vector3d PatchNormal(const BilinearPatch& patch, double u, double v);

// (u, v) of the point at fraction s ∈ [0, 1] along edge `edge` ∈ {0..3}
// (from b_edge to b_edge+1), see the conventions above.
Eigen::Vector2d EdgeParameter(int edge, double s);

// Frame point f_i = (w_i b_i + w_{i+1} b_{i+1}) / (w_i + w_{i+1}), i ∈ {0..3},
// indices mod 4; f_0 = x(½,0), f_1 = x(1,½), f_2 = x(½,1), f_3 = x(0,½)
// [Shi 2014, §2.1].
Eigen::Vector3d FramePoint(const BilinearPatch& patch, int i);
std::array<Eigen::Vector3d, 4> FramePoints(const BilinearPatch& patch);

// Shape parameter W = w0 w2 / (w1 w3) for the diagonal b0b2 [Shi 2014, eq. 4];
// the other diagonal b1b3 has 1/W. Two patches with the same control points
// and the same W are the same quadric patch (eq. 3); W = 1 is a hyperbolic
// paraboloid (a bilinear patch).
double ShapeParameter(const std::array<double, 4>& w);

// The normalised weights (1, 1, W, 1) with shape parameter W for the diagonal
// b0b2 [Shi 2014, eqs. 2–4]. Precondition (CHECKed): W finite and > 0.
std::array<double, 4> WeightsFromShapeParameter(double W);

// Smooth join of two patches along a common edge, in the layout of [Shi 2014,
// Fig. 2]: left patch (b0, b1, b2, b3), right patch (b0, b3, b4, b5), common
// edge b0b3 (consistently oriented: the left patch runs b3 → b0, the right one
// b0 → b3). With the diagonal b0b2 for the left patch (W_l = w0 w2 / w1 w3) and
// b0b4 for the right one (W_r = w0 w4 / w3 w5), the patches join with a common
// tangent plane along b0b3, provided the vertex stars at b0 and b3 are planar,
// iff [Shi 2014, eq. 7]
//   W_r / W_l = det(b30, b50, b20) / det(b30, b10, b40),   b_ij = b_i − b_j.
struct JoinDeterminants {
  double numerator = 0;    // det(b30, b50, b20)
  double denominator = 0;  // det(b30, b10, b40)
  // Equitwist condition [Shi 2014, Remark 2]: both determinants non-zero and
  // of the same sign, i.e. positive weights can satisfy eq. 7.
  bool equitwist() const { return numerator * denominator > 0; }
  // W_r / W_l of eq. 7; meaningful only if equitwist() (CHECKed).
  double ratio() const;
};
JoinDeterminants SmoothJoinDeterminants(const Eigen::Vector3d& b0, const Eigen::Vector3d& b1,
                                        const Eigen::Vector3d& b2, const Eigen::Vector3d& b3,
                                        const Eigen::Vector3d& b4, const Eigen::Vector3d& b5);

// Kink along a common edge: the largest angle (degrees, in [0, 180]) between
// the two patches' oriented unit normals at `samples` ≥ 2 points equally spaced
// along the edge segment, end points included. (Each patch's parameter for a
// point of the edge depends on its end-point weights, so the two patches are
// evaluated at their own parameters of the same point.) Precondition: edge `edge_a` of `a` (from
// a.b[edge_a] to a.b[edge_a + 1]) is edge `edge_b` of `b` traversed the other
// way (consistently oriented neighbours), so the two patches agree in the
// points compared. Samples where either normal is undefined (zero, see
// PatchNormal) are skipped; returns −1 if all are. 0 for a smooth join.
double SharedEdgeKinkDegrees(const BilinearPatch& a, int edge_a, const BilinearPatch& b,
                             int edge_b, int samples);

// Darboux transformation [Shi 2014, §4, eq. 12]:
//   δ(x) = (c² − c ± s) / (|x|² + 1 − c ∓ s) · x,   s = sqrt((c − 1)² + (1 − c²)|x|²),
// optionally after a projective map P of 3-space. c ≠ 1 places the projection
// centre (0, 0, 0, c) in R⁴; the two branches (±) are inverse to each other
// in the sphere Λ: |x|² = c² − 1. For c = −1 the + branch is the inversion
// δ(x) = 4 x / |x|² (|δ(x)| |x| = (1 − c)² = 4) and the − branch collapses
// everything to 0. δ maps lines to (Möbius) circles and planes to spheres.
enum class DarbouxBranch { kPlus, kMinus };

struct DarbouxTransform {
  double c = 0.5;                            // ≠ 1, finite
  DarbouxBranch branch = DarbouxBranch::kPlus;
  // Applied first, to column vectors in homogeneous coordinates:
  //   (y, y4)ᵀ = projective · (x, 1)ᵀ,   P(x) = y / y4.
  Eigen::Matrix4d projective = Eigen::Matrix4d::Identity();
};

enum class DarbouxStatus {
  kOk,
  kPointAtInfinity,   // the projective map sends x to infinity (y4 = 0)
  kNegativeRadicand,  // (c − 1)² + (1 − c²)|P(x)|² < 0: the image is not real
                      // (only possible for |c| > 1, beyond the sphere Λ)
  kZeroDenominator,   // |P(x)|² + 1 − c ∓ s = 0: the image is at infinity
};

struct DarbouxResult {
  Eigen::Vector3d point;  // δ(P(x)) if status == kOk, else NaN in every coordinate
  DarbouxStatus status = DarbouxStatus::kOk;
};

// Applies `transform` to x. A quantity is treated as zero when it is below
// 1e-14 times the size of the terms it is computed from. Throws InputError if
// transform.c is 1 or not finite (c usually comes from a user's file).
DarbouxResult ApplyDarboux(const DarbouxTransform& transform, const Eigen::Vector3d& x);

}  // namespace archgeo
