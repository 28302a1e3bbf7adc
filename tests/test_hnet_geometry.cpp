// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for mesh/bilinear_patch and mesh/hnet [Shi, Wang, Pottmann 2014]:
//  (a) rational bilinear patches: corners, frame points, straight rulings,
//      W = 1 is bilinear, derivatives vs finite differences (eq. 1–4);
//  (b) smooth join of two patches by eq. 5/7 and a kink when perturbed;
//  (c) H-nets on nets with exactly planar stars (hyperbolic paraboloid,
//      hyperboloid of one sheet sampled on rulings): planarity, W, kinks;
//  (d) λ of eq. 11 from the quartic vs brute-force minimisation;
//  (e) Darboux transformation (eq. 12): inversion at c = −1, the two branches
//      inverse in Λ, lines to circles, failure statuses;
//  (f) a closed ring band: mismatch of eq. 7 on the closing edge;
//  (g) sampling, isophotes, rulings, OBJ polylines, Darboux map of a patchwork.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "geometry/bilinear_patch.h"
#include "geometry/hnet.h"
#include "core/input_error.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

constexpr unsigned kSeed = 20140301;
// Agreement of quantities equal in exact arithmetic (coordinates of order 1).
constexpr double kTolerance = 1e-12;
// Richardson-extrapolated central differences, step h: error ~ h⁴ + ε/h.
constexpr double kFiniteDifferenceStep = 1e-3;
constexpr double kFiniteDifferenceTolerance = 1e-8;
// Kink of a join that is smooth in exact arithmetic (degrees), per the brief.
constexpr double kSmoothKinkDegrees = 1e-9;
// H-net kinks on nets with exactly planar stars (degrees).
constexpr double kNetKinkDegrees = 1e-6;
// Star planarity of exactly planar stars (relative to the mean edge length).
constexpr double kPlanarStar = 1e-12;
// λ from the quartic vs brute force (relative).
constexpr double kLambdaRelative = 1e-9;
// Relative co-circularity of Darboux images of a line.
constexpr double kCircleTolerance = 1e-9;

using V3 = Eigen::Vector3d;

V3 E(const Vec3& x) { return {x[0], x[1], x[2]}; }

V3 RandomVec(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return V3(u(rng), u(rng), u(rng));
}

BilinearPatch RandomPatch(std::mt19937& rng) {
  std::uniform_real_distribution<double> weight(0.3, 3.0);
  BilinearPatch patch;
  // A skew quad near the unit square, lifted and perturbed.
  const V3 corners[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int i = 0; i < 4; ++i) {
    patch.b[i] = corners[i] + RandomVec(rng, 0.25) + V3(0, 0, i % 2 == 0 ? 0.3 : -0.3);
    patch.w[i] = weight(rng);
  }
  return patch;
}

Mesh MakeMesh(const std::vector<V3>& points, const std::vector<std::array<int, 4>>& faces) {
  Mesh mesh;
  for (const V3& p : points) mesh.add_vertex(Point(p[0], p[1], p[2]));
  for (const auto& face : faces) {
    const FaceIndex f = mesh.add_face(VertexIndex(face[0]), VertexIndex(face[1]),
                                      VertexIndex(face[2]), VertexIndex(face[3]));
    EXPECT_NE(f, Mesh::null_face());
  }
  return mesh;
}

// A (nx × ny)-quad grid; vertex (i, j) = j (nx + 1) + i at position(i, j).
template <typename F>
Mesh Grid(int nx, int ny, F position) {
  std::vector<V3> points;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) points.push_back(position(i, j));
  }
  std::vector<std::array<int, 4>> faces;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i;
      faces.push_back({a, a + 1, a + nx + 2, a + nx + 1});
    }
  }
  return MakeMesh(points, faces);
}

// z = xy sampled on its rulings x = const, y = const (non-uniform steps, off-centre).
Mesh HyperbolicParaboloidNet() {
  return Grid(6, 5, [](int i, int j) {
    const double x = -0.7 + 0.23 * i, y = -0.4 + 0.19 * j;
    return V3(x, y, x * y);
  });
}

// x² + y² − z² = 1 sampled on its rulings: vertex (i, j) is the intersection
// of the rulings β = φ_i + atan z and β = ψ_j − atan z, so atan z = (ψ − φ)/2,
// β = (φ + ψ)/2. Every edge is a ruling segment, every star planar.
Mesh HyperboloidNet() {
  return Grid(6, 6, [](int i, int j) {
    const double phi = 0.15 * i, psi = 0.1 + 0.15 * j;
    const double z = std::tan(0.5 * (psi - phi)), beta = 0.5 * (phi + psi);
    const double r = std::sqrt(1 + z * z);
    return V3(r * std::cos(beta), r * std::sin(beta), z);
  });
}

// A closed band of `around` quads, one row, on the hyperboloid x² + y² − z² = 1:
// the rungs are rulings from height −h to h. Bottom vertex i = i, top = around + i.
Mesh RingBand(int around, const V3& perturb_top0) {
  const double h = 0.6, r = std::sqrt(1 + h * h), twist = std::atan(h);
  std::vector<V3> points;
  for (int level = 0; level < 2; ++level) {
    for (int i = 0; i < around; ++i) {
      const double beta = 2 * M_PI * i / around + (level == 0 ? -twist : twist);
      points.push_back(V3(r * std::cos(beta), r * std::sin(beta), level == 0 ? -h : h));
    }
  }
  points[around] += perturb_top0;
  std::vector<std::array<int, 4>> faces;
  for (int i = 0; i < around; ++i) {
    const int k = (i + 1) % around;
    faces.push_back({i, k, around + k, around + i});
  }
  return MakeMesh(points, faces);
}

// Circumcentre of a triangle in 3-D.
V3 Circumcentre(const V3& a, const V3& b, const V3& c) {
  const V3 ab = b - a, ac = c - a, n = ab.cross(ac);
  return a + (ac.squaredNorm() * n.cross(ab) + ab.squaredNorm() * ac.cross(n)) /
                 (2 * n.squaredNorm());
}

// dF/dλ of eq. 11 written out directly (not via the quartic).
double ShapeEnergyDerivative(double lambda, const std::vector<double>& W) {
  double d = 0;
  for (double w : W) d += 2 * w * (lambda * w - 1) - 2 * (1 / (lambda * w) - 1) / (lambda * lambda * w);
  return d;
}

// Brute force: F on 20001 log-spaced samples, then golden section around the
// best sample, then bisection of the sign of dF/dλ for full precision.
double BruteForceShapeScale(const std::vector<double>& W) {
  const double w_min = *std::min_element(W.begin(), W.end());
  const double w_max = *std::max_element(W.begin(), W.end());
  const double lo = std::log(0.25 / w_max), hi = std::log(4 / w_min);
  constexpr int kSamples = 20001;
  int best = 0;
  double best_energy = INFINITY;
  for (int k = 0; k < kSamples; ++k) {
    const double energy = ShapeEnergy(std::exp(lo + (hi - lo) * k / (kSamples - 1)), W);
    if (energy < best_energy) best_energy = energy, best = k;
  }
  double a = std::exp(lo + (hi - lo) * std::max(best - 1, 0) / (kSamples - 1));
  double b = std::exp(lo + (hi - lo) * std::min(best + 1, kSamples - 1) / (kSamples - 1));
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  for (int it = 0; it < 60; ++it) {
    const double x1 = b - g * (b - a), x2 = a + g * (b - a);
    if (ShapeEnergy(x1, W) < ShapeEnergy(x2, W)) {
      b = x2;
    } else {
      a = x1;
    }
  }
  // Bracket the stationary point near the golden-section result, then bisect.
  double left = 0.5 * (a + b) * (1 - 1e-6), right = 0.5 * (a + b) * (1 + 1e-6);
  while (ShapeEnergyDerivative(left, W) > 0) left *= 1 - 1e-6;
  while (ShapeEnergyDerivative(right, W) < 0) right *= 1 + 1e-6;
  for (int it = 0; it < 200 && right - left > 1e-16 * right; ++it) {
    const double mid = 0.5 * (left + right);
    (ShapeEnergyDerivative(mid, W) < 0 ? left : right) = mid;
  }
  return 0.5 * (left + right);
}

// ---------------------------------------------------------------- (a) patches

TEST(BilinearPatch, CornersAndFramePoints) {
  std::mt19937 rng(kSeed);
  for (int sample = 0; sample < 20; ++sample) {
    const BilinearPatch p = RandomPatch(rng);
    EXPECT_LE((PatchPoint(p, 0, 0) - p.b[0]).norm(), kTolerance);
    EXPECT_LE((PatchPoint(p, 1, 0) - p.b[1]).norm(), kTolerance);
    EXPECT_LE((PatchPoint(p, 1, 1) - p.b[2]).norm(), kTolerance);
    EXPECT_LE((PatchPoint(p, 0, 1) - p.b[3]).norm(), kTolerance);
    const auto f = FramePoints(p);
    EXPECT_LE((PatchPoint(p, 0.5, 0) - f[0]).norm(), kTolerance);
    EXPECT_LE((PatchPoint(p, 1, 0.5) - f[1]).norm(), kTolerance);
    EXPECT_LE((PatchPoint(p, 0.5, 1) - f[2]).norm(), kTolerance);
    EXPECT_LE((PatchPoint(p, 0, 0.5) - f[3]).norm(), kTolerance);
    // f_0 divides b0b1 in the inverse ratio of the weights: |f0−b0| : |f0−b1| = w1 : w0.
    EXPECT_NEAR((f[0] - p.b[0]).norm() * p.w[0], (f[0] - p.b[1]).norm() * p.w[1], kTolerance);
    // Edge parameters: fraction s along edge i runs from b_i to b_{i+1}.
    for (int edge = 0; edge < 4; ++edge) {
      const Eigen::Vector2d start = EdgeParameter(edge, 0), end = EdgeParameter(edge, 1);
      EXPECT_LE((PatchPoint(p, start[0], start[1]) - p.b[edge]).norm(), kTolerance);
      EXPECT_LE((PatchPoint(p, end[0], end[1]) - p.b[(edge + 1) % 4]).norm(), kTolerance);
    }
  }
}

TEST(BilinearPatch, RulingsAreStraight) {
  std::mt19937 rng(kSeed + 1);
  for (int sample = 0; sample < 20; ++sample) {
    const BilinearPatch p = RandomPatch(rng);
    for (double fixed : {0.0, 0.21, 0.5, 0.83}) {
      for (int family = 0; family < 2; ++family) {
        const auto at = [&](double t) -> V3 {
          return family == 0 ? PatchPoint(p, fixed, t) : PatchPoint(p, t, fixed);
        };
        const V3 a = at(0), b = at(1), direction = (b - a).normalized();
        for (double t : {0.1, 0.37, 0.64, 0.9}) {
          EXPECT_LE((at(t) - a).cross(direction).norm(), kTolerance);
        }
      }
    }
  }
}

TEST(BilinearPatch, ShapeParameterOneIsHyperbolicParaboloid) {
  std::mt19937 rng(kSeed + 2);
  std::uniform_real_distribution<double> weight(0.3, 3.0);
  for (int sample = 0; sample < 20; ++sample) {
    BilinearPatch p = RandomPatch(rng);
    // Any weights with W = w0 w2 / (w1 w3) = 1 give the bilinear patch
    // (eq. 3), reparameterised: w factors as a(i) b(j), so x(u, v) is the
    // bilinear point at u' = u w1 / ((1−u) w0 + u w1), v' = v w3 / ((1−v) w0 + v w3).
    p.w = {weight(rng), weight(rng), 0, weight(rng)};
    p.w[2] = p.w[1] * p.w[3] / p.w[0];
    EXPECT_NEAR(ShapeParameter(p.w), 1.0, kTolerance);
    for (double u : {0.0, 0.3, 0.7, 1.0}) {
      for (double v : {0.0, 0.45, 0.9}) {
        const double s = u * p.w[1] / ((1 - u) * p.w[0] + u * p.w[1]);
        const double t = v * p.w[3] / ((1 - v) * p.w[0] + v * p.w[3]);
        const V3 bilinear = (1 - s) * (1 - t) * p.b[0] + s * (1 - t) * p.b[1] + s * t * p.b[2] +
                            (1 - s) * t * p.b[3];
        EXPECT_LE((PatchPoint(p, u, v) - bilinear).norm(), kTolerance);
      }
    }
    // With all weights equal the parameterisation is the bilinear one itself.
    p.w = {1.7, 1.7, 1.7, 1.7};
    const V3 mid = 0.25 * (p.b[0] + p.b[1] + p.b[2] + p.b[3]);
    EXPECT_LE((PatchPoint(p, 0.5, 0.5) - mid).norm(), kTolerance);
    // W ≠ 1 leaves the hyperbolic paraboloid: the centre moves towards b2
    // (w2 > 1 pulls the point x(½,½) = Σ w_i b_i / Σ w_i).
    p.w = WeightsFromShapeParameter(3.0);
    EXPECT_GT((PatchPoint(p, 0.5, 0.5) - mid).norm(), 0.01);
  }
  // Four points of z = xy: the W = 1 patch is a piece of that surface.
  BilinearPatch hp;
  const double x0 = -0.3, x1 = 0.8, y0 = 0.2, y1 = 1.1;
  hp.b = {V3(x0, y0, x0 * y0), V3(x1, y0, x1 * y0), V3(x1, y1, x1 * y1), V3(x0, y1, x0 * y1)};
  hp.w = WeightsFromShapeParameter(1.0);
  for (double u : {0.1, 0.5, 0.77}) {
    for (double v : {0.2, 0.6, 0.95}) {
      const V3 x = PatchPoint(hp, u, v);
      EXPECT_NEAR(x[2], x[0] * x[1], kTolerance);
    }
  }
  EXPECT_DOUBLE_EQ(ShapeParameter(WeightsFromShapeParameter(2.5)), 2.5);
}

TEST(BilinearPatch, DerivativesAndNormalMatchFiniteDifferences) {
  std::mt19937 rng(kSeed + 3);
  const double h = kFiniteDifferenceStep;
  for (int sample = 0; sample < 20; ++sample) {
    const BilinearPatch p = RandomPatch(rng);
    for (double u : {0.0, 0.25, 0.6, 1.0}) {
      for (double v : {0.0, 0.4, 0.85, 1.0}) {
        const PatchJet jet = PatchDerivatives(p, u, v);
        // Richardson-extrapolated central differences (error O(h⁴)).
        const auto du = [&](double step) -> V3 {
          return (PatchPoint(p, u + step, v) - PatchPoint(p, u - step, v)) / (2 * step);
        };
        const auto dv = [&](double step) -> V3 {
          return (PatchPoint(p, u, v + step) - PatchPoint(p, u, v - step)) / (2 * step);
        };
        const V3 xu = (4 * du(h / 2) - du(h)) / 3, xv = (4 * dv(h / 2) - dv(h)) / 3;
        EXPECT_LE((jet.xu - xu).norm(), kFiniteDifferenceTolerance);
        EXPECT_LE((jet.xv - xv).norm(), kFiniteDifferenceTolerance);
        const V3 n = PatchNormal(p, u, v);
        EXPECT_NEAR(n.norm(), 1.0, kTolerance);
        EXPECT_LE((n - xu.cross(xv).normalized()).norm(), kFiniteDifferenceTolerance);
      }
    }
  }
  // Collinear edges at b0: the normal there is undefined (zero).
  BilinearPatch flat;
  flat.b = {V3(0, 0, 0), V3(1, 0, 0), V3(2, 1, 0.5), V3(-1, 0, 0)};
  EXPECT_EQ(PatchNormal(flat, 0, 0), V3::Zero());
}

// ---------------------------------------------------------- (b) smooth join

// Fig. 2 layout: left (b0, b1, b2, b3), right (b0, b3, b4, b5), edge b0b3 on
// the y axis; b0, b1, b3, b5 in z = 0 (plane T0), b0, b2, b3, b4 in the plane
// through the y axis tilted by θ (T3) [Shi 2014, Proposition 1].
struct TwoPatches {
  BilinearPatch left, right;
  JoinDeterminants determinants;
};
TwoPatches PlanarStarPair(double w2) {
  const double theta = 0.7, c = std::cos(theta), s = std::sin(theta);
  const V3 b0(0, 0, 0), b1(1, -0.1, 0), b2(1.1 * c, 1.2, 1.1 * s), b3(0, 1, 0),
      b4(-0.9 * c, 0.8, -0.9 * s), b5(-1, -0.15, 0);
  TwoPatches pair;
  pair.determinants = SmoothJoinDeterminants(b0, b1, b2, b3, b4, b5);
  pair.left.b = {b0, b1, b2, b3};
  pair.right.b = {b0, b3, b4, b5};
  pair.left.w = WeightsFromShapeParameter(w2);
  if (pair.determinants.equitwist()) {
    pair.right.w = WeightsFromShapeParameter(w2 * pair.determinants.ratio());  // eq. 5 / 7
  }
  return pair;
}

TEST(SmoothJoin, Equation7GivesCommonTangentPlanes) {
  for (double w2 : {0.4, 1.0, 2.3}) {
    const TwoPatches pair = PlanarStarPair(w2);
    ASSERT_TRUE(pair.determinants.equitwist());
    // By the construction above the ratio is 1.1 / 0.9 (the y components).
    EXPECT_NEAR(pair.determinants.ratio(), 1.1 / 0.9, kTolerance);
    // Left edge 3 runs b3 → b0, right edge 0 runs b0 → b3.
    const double kink = SharedEdgeKinkDegrees(pair.left, 3, pair.right, 0, 11);
    EXPECT_GE(kink, 0.0);
    EXPECT_LE(kink, kSmoothKinkDegrees) << "w2 = " << w2;
    // A perturbed weight breaks smoothness in the interior of the edge (the
    // tangent planes at the end points are T0 and T3 whatever the weights).
    TwoPatches bad = pair;
    bad.right.w[2] *= 1.2;
    const double bad_kink = SharedEdgeKinkDegrees(bad.left, 3, bad.right, 0, 11);
    EXPECT_GT(bad_kink, 0.1) << "w2 = " << w2;
    EXPECT_LE(SharedEdgeKinkDegrees(bad.left, 3, bad.right, 0, 2), kSmoothKinkDegrees);
  }
}

TEST(SmoothJoin, EquitwistViolated) {
  const double c = std::cos(0.7), s = std::sin(0.7);
  // b4 on the same side of T0 as b2: the determinants have opposite signs.
  const JoinDeterminants d = SmoothJoinDeterminants(
      V3(0, 0, 0), V3(1, -0.1, 0), V3(1.1 * c, 1.2, 1.1 * s), V3(0, 1, 0),
      V3(-0.9 * c, 0.8, 0.9 * s), V3(-1, -0.15, 0));
  EXPECT_FALSE(d.equitwist());
  EXPECT_LT(d.numerator * d.denominator, 0.0);
}

// ------------------------------------------------------------- (c) H-nets

TEST(HNet, HyperbolicParaboloidIsSmoothWithUnitShape) {
  const Mesh mesh = HyperbolicParaboloidNet();
  for (int start : {0, 17}) {
    HNetOptions options;
    options.start_face = start;
    const HNet hnet = BuildHNet(mesh, options);
    EXPECT_TRUE(hnet.pure_quad);
    EXPECT_TRUE(hnet.odd_valence_vertices.empty());
    EXPECT_TRUE(hnet.not_equitwist_edges.empty());
    EXPECT_TRUE(hnet.bipartite);
    EXPECT_LE(hnet.star_planarity_max, kPlanarStar);
    EXPECT_GE(hnet.star_planarity_max, 0.0);
    EXPECT_EQ(hnet.lambda_of_component.size(), 1u);
    EXPECT_NEAR(hnet.lambda, 1.0, kTolerance);
    for (double W : hnet.W) EXPECT_NEAR(W, 1.0, kTolerance);
    EXPECT_NEAR(hnet.W_min, 1.0, kTolerance);
    EXPECT_NEAR(hnet.W_max, 1.0, kTolerance);
    EXPECT_LE(hnet.mismatch_max, kTolerance);
    EXPECT_LE(hnet.kink_max, kNetKinkDegrees);
    EXPECT_LE(hnet.kink_mean, kNetKinkDegrees);
    // 6×5 grid: 6·4 + 5·5 = 49 interior edges, 30 faces, a tree has 29.
    int interior = 0;
    for (double k : hnet.kink_degrees) interior += k >= 0;
    EXPECT_EQ(interior, 49);
    EXPECT_EQ(hnet.closing_edges.size(), 49u - 29u);
    // Each face's chosen diagonal joins its two colour-0 vertices.
    for (const auto& c : hnet.patch_vertices) {
      EXPECT_EQ(hnet.colour[c[0]], 0);
      EXPECT_EQ(hnet.colour[c[2]], 0);
      EXPECT_EQ(hnet.colour[c[1]], 1);
    }
    // Frame points are edge midpoints (all weights 1) and lie on z = xy.
    for (const auto& frame : hnet.frame_points) {
      for (const Vec3& f : frame) EXPECT_NEAR(f[2], f[0] * f[1], kTolerance);
    }
  }
}

TEST(HNet, HyperboloidRulingNetIsSmoothWithNonTrivialShape) {
  const Mesh mesh = HyperboloidNet();
  const HNet hnet = BuildHNet(mesh);
  EXPECT_LE(hnet.star_planarity_max, kPlanarStar);
  EXPECT_TRUE(hnet.not_equitwist_edges.empty());
  EXPECT_LE(hnet.mismatch_max, 1e-10);
  EXPECT_LE(hnet.kink_max, kNetKinkDegrees);
  // Not a paraboloid: the shape parameters vary.
  EXPECT_GT(hnet.W_max / hnet.W_min, 1.01);
  // λ is optimal: F_shape is not lowered by a nearby scale.
  const double F = ShapeEnergy(1.0, hnet.W);
  EXPECT_LE(F, ShapeEnergy(1.001, hnet.W));
  EXPECT_LE(F, ShapeEnergy(0.999, hnet.W));
  // The perturbed net is no longer an A-net: planarity and kinks respond.
  Mesh bent = mesh;
  const VertexIndex v(3 * 7 + 3);
  bent.point(v) = bent.point(v) + Vector(0, 0, 0.05);
  const HNet bent_hnet = BuildHNet(bent);
  EXPECT_GT(bent_hnet.star_planarity[v.idx()], 0.003);
  EXPECT_GT(bent_hnet.kink_max, 0.1);
}

TEST(HNet, RejectsBadInput) {
  Mesh triangle;
  const VertexIndex a = triangle.add_vertex(Point(0, 0, 0)), b = triangle.add_vertex(Point(1, 0, 0)),
                    c = triangle.add_vertex(Point(0, 1, 0));
  triangle.add_face(a, b, c);
  EXPECT_THROW(BuildHNet(triangle), InputError);
  EXPECT_THROW(BuildHNet(Mesh()), InputError);
  HNetOptions options;
  options.start_face = 30;
  EXPECT_THROW(BuildHNet(HyperbolicParaboloidNet(), options), InputError);
  options.start_face = 0;
  options.kink_samples = 4;
  EXPECT_THROW(BuildHNet(HyperbolicParaboloidNet(), options), InputError);
}

TEST(HNet, OddValenceReported) {
  // Five quads around a centre vertex (valence 5).
  std::vector<V3> points{{0, 0, 0}};
  for (int k = 0; k < 10; ++k) {
    const double a = 2 * M_PI * k / 10, r = k % 2 == 0 ? 1.0 : 1.3;
    points.push_back({r * std::cos(a), r * std::sin(a), k % 2 == 0 ? 0.0 : 0.2});
  }
  std::vector<std::array<int, 4>> faces;
  for (int k = 0; k < 5; ++k) faces.push_back({0, 1 + 2 * k, 2 + 2 * k, 1 + (2 * k + 2) % 10});
  const HNet hnet = BuildHNet(MakeMesh(points, faces));
  EXPECT_EQ(hnet.odd_valence_vertices, std::vector<int>{0});
  EXPECT_GE(hnet.star_planarity[0], 0.0);
  EXPECT_EQ(hnet.star_planarity[1], -1.0);
  // Still bipartite: centre colour 0, spoke ends 1, rim corners between them 0.
  EXPECT_TRUE(hnet.bipartite);
}

// ---------------------------------------------------------------- (d) λ

TEST(ShapeScale, QuarticMatchesBruteForce) {
  std::mt19937 rng(kSeed + 4);
  std::uniform_real_distribution<double> log_w(std::log(0.1), std::log(10.0));
  std::uniform_int_distribution<int> size(1, 40);
  for (int sample = 0; sample < 30; ++sample) {
    std::vector<double> W(size(rng));
    for (double& w : W) w = std::exp(log_w(rng));
    const double lambda = OptimalShapeScale(W);
    const double brute = BruteForceShapeScale(W);
    EXPECT_NEAR(lambda, brute, kLambdaRelative * brute) << "sample " << sample;
    EXPECT_LE(ShapeEnergy(lambda, W), ShapeEnergy(brute, W) * (1 + 1e-14));
    // The stationarity condition: A λ⁴ − B λ³ + C λ − D = 0 (relative).
    double A = 0, B = 0, C = 0, D = 0;
    for (double w : W) A += w * w, B += w, C += 1 / w, D += 1 / (w * w);
    const double p = A * std::pow(lambda, 4) - B * std::pow(lambda, 3) + C * lambda - D;
    const double scale = A * std::pow(lambda, 4) + B * std::pow(lambda, 3) + C * lambda + D;
    EXPECT_LE(std::abs(p), 1e-13 * scale);
  }
  // Equal shape parameters: λ = 1/W exactly.
  EXPECT_NEAR(OptimalShapeScale({4.0, 4.0, 4.0}), 0.25, kTolerance);
  // Widely spread values (W and 1/W): λ = 1 by symmetry of F under W → 1/W.
  EXPECT_NEAR(OptimalShapeScale({50.0, 0.02}), 1.0, kTolerance);
}

// ------------------------------------------------------------- (e) Darboux

TEST(Darboux, MinusOneIsAnInversion) {
  std::mt19937 rng(kSeed + 5);
  DarbouxTransform inversion;
  inversion.c = -1;
  inversion.branch = DarbouxBranch::kPlus;
  for (int sample = 0; sample < 20; ++sample) {
    const V3 x = RandomVec(rng, 3.0);
    const DarbouxResult r = ApplyDarboux(inversion, x);
    ASSERT_EQ(r.status, DarbouxStatus::kOk);
    // δ(x) = 4x/|x|²: same direction, |δ(x)|·|x| = (1 − c)² = 4.
    EXPECT_NEAR(r.point.norm() * x.norm(), 4.0, kTolerance);
    EXPECT_LE(r.point.normalized().cross(x.normalized()).norm(), kTolerance);
    EXPECT_GT(r.point.dot(x), 0.0);
  }
  EXPECT_EQ(ApplyDarboux(inversion, V3::Zero()).status, DarbouxStatus::kZeroDenominator);
  EXPECT_TRUE(ApplyDarboux(inversion, V3::Zero()).point.hasNaN());
}

TEST(Darboux, BranchesAreInverseInLambda) {
  std::mt19937 rng(kSeed + 6);
  for (double c : {-3.0, -0.4, 0.3, 0.8, 2.5}) {
    DarbouxTransform plus, minus;
    plus.c = minus.c = c;
    minus.branch = DarbouxBranch::kMinus;
    for (int sample = 0; sample < 10; ++sample) {
      // |x| small enough that the radicand is positive for |c| > 1.
      const V3 x = RandomVec(rng, std::abs(c) > 1 ? 0.3 : 2.0);
      const DarbouxResult p = ApplyDarboux(plus, x), m = ApplyDarboux(minus, x);
      ASSERT_EQ(p.status, DarbouxStatus::kOk);
      ASSERT_EQ(m.status, DarbouxStatus::kOk);
      // Inverse in Λ: |x|² = c² − 1 (imaginary for |c| < 1): δ₊·δ₋ = c² − 1, collinear.
      EXPECT_NEAR(p.point.dot(m.point), c * c - 1, kTolerance * std::max(1.0, c * c));
      EXPECT_LE(p.point.cross(m.point).norm(), kTolerance * p.point.norm() * m.point.norm() * 10);
    }
  }
}

TEST(Darboux, LinesMapToCircles) {
  std::mt19937 rng(kSeed + 7);
  for (int sample = 0; sample < 10; ++sample) {
    DarbouxTransform t;
    t.c = sample % 2 == 0 ? 0.3 : -0.6;
    t.branch = sample % 4 < 2 ? DarbouxBranch::kPlus : DarbouxBranch::kMinus;
    if (sample >= 5) {  // a projective map first (column vectors): lines stay lines
      t.projective = Eigen::Matrix4d::Identity();
      for (int col = 0; col < 3; ++col) t.projective.block<3, 1>(0, col) += RandomVec(rng, 0.2);
      t.projective.block<3, 1>(0, 3) = RandomVec(rng, 0.5);
      t.projective.block<1, 3>(3, 0) = 0.05 * RandomVec(rng, 1.0).transpose();
    }
    const V3 p = RandomVec(rng, 1.0), d = RandomVec(rng, 1.0).normalized();
    std::vector<V3> images;
    for (double s : {-1.5, -0.7, 0.0, 0.4, 1.1, 2.0}) {
      const DarbouxResult r = ApplyDarboux(t, p + s * d);
      ASSERT_EQ(r.status, DarbouxStatus::kOk);
      images.push_back(r.point);
    }
    const V3 centre = Circumcentre(images[0], images[1], images[2]);
    const double radius = (images[0] - centre).norm();
    const V3 normal = (images[1] - images[0]).cross(images[2] - images[0]).normalized();
    for (size_t k = 3; k < images.size(); ++k) {
      EXPECT_NEAR((images[k] - centre).norm(), radius, kCircleTolerance * radius);
      EXPECT_LE(std::abs(normal.dot(images[k] - images[0])), kCircleTolerance * radius);
    }
    // ... and not a line: the image points are not collinear.
    EXPECT_GT((images[1] - images[0]).normalized().cross((images[5] - images[0]).normalized()).norm(),
              1e-3);
  }
}

TEST(Darboux, FailuresAreReported) {
  DarbouxTransform t;
  t.c = 2.0;  // radicand 1 − 3|x|² < 0 for |x|² > 1/3
  const DarbouxResult r = ApplyDarboux(t, V3(1, 0, 0));
  EXPECT_EQ(r.status, DarbouxStatus::kNegativeRadicand);
  EXPECT_TRUE(r.point.hasNaN());
  EXPECT_EQ(ApplyDarboux(t, V3(0.2, 0, 0)).status, DarbouxStatus::kOk);
  DarbouxTransform projective;
  projective.projective.row(3) << 1, 0, 0, 0;  // x ↦ x / x₁
  EXPECT_EQ(ApplyDarboux(projective, V3(0, 1, 2)).status, DarbouxStatus::kPointAtInfinity);
  EXPECT_EQ(ApplyDarboux(projective, V3(2, 1, 2)).status, DarbouxStatus::kOk);
  DarbouxTransform one;
  one.c = 1.0;
  EXPECT_THROW(ApplyDarboux(one, V3(1, 0, 0)), InputError);
}

// ------------------------------------------------------------- (f) ring band

TEST(HNet, ClosedRingReportsMismatchOnClosingEdge) {
  HNetOptions propagated;
  propagated.shape = HNetShape::kPropagated;
  for (int around : {7, 8}) {
    const Mesh ring = RingBand(around, V3(0.05, -0.03, 0.04));
    const HNet hnet = BuildHNet(ring, propagated);
    EXPECT_EQ(hnet.bipartite, around % 2 == 0) << around;
    EXPECT_EQ(hnet.monochrome_edges.empty(), around % 2 == 0) << around;
    ASSERT_TRUE(hnet.not_equitwist_edges.empty());
    // The dual graph is a cycle: one edge closes it, the others are exact.
    ASSERT_EQ(hnet.closing_edges.size(), 1u);
    const int closing = hnet.closing_edges[0];
    EXPECT_GT(hnet.edge_mismatch[closing], 1e-3) << around;
    EXPECT_EQ(hnet.mismatch_max, hnet.edge_mismatch[closing]);
    int interior = 0;
    for (size_t e = 0; e < hnet.edge_mismatch.size(); ++e) {
      if (hnet.edge_mismatch[e] < 0) continue;
      ++interior;
      if (int(e) != closing) {
        EXPECT_LE(hnet.edge_mismatch[e], kTolerance);
      }
    }
    EXPECT_EQ(interior, around);
    // The inconsistency shows as a kink at the closing edge.
    EXPECT_GT(hnet.kink_degrees[closing], 1e-3);
    std::cout << "ring of " << around << ": closing-edge mismatch " << hnet.edge_mismatch[closing]
              << ", kink " << hnet.kink_degrees[closing] << " deg, alpha_max " << hnet.kink_max
              << ", W in [" << hnet.W_min << ", " << hnet.W_max << "]\n";
  }
}

// Least squares over every edge spreads the ring's holonomy H (the product of
// the eq. 7 ratios around it) evenly: on a cycle of n edges every edge's
// residual log(W_r/W_l/ratio) is ±log(H)/n (the sign is the edge's
// orientation), so every edge misses eq. 7 by the factor H^(±1/n), where the
// propagation leaves all of H on the one closing edge (mismatch |H − 1|).
TEST(HNet, LeastSquaresSpreadsTheRingsHolonomyOverEveryEdge) {
  const int around = 8;  // bipartite: the ring's equations have one gauge freedom
  const Mesh ring = RingBand(around, V3(0.05, -0.03, 0.04));
  HNetOptions propagated;
  propagated.shape = HNetShape::kPropagated;
  const HNet tree = BuildHNet(ring, propagated);
  ASSERT_EQ(tree.closing_edges.size(), 1u);
  const double closing = tree.edge_mismatch[tree.closing_edges[0]];
  const HNet spread = BuildHNet(ring);  // the default: least squares
  // H = 1 ± closing (the mismatch is an absolute value); each edge misses by
  // the factor e^(±r), r = |log H| / n: mismatch e^r − 1 or 1 − e^(−r).
  std::vector<double> mismatches;
  for (double m : spread.edge_mismatch) {
    if (m >= 0) mismatches.push_back(m);
  }
  ASSERT_EQ(int(mismatches.size()), around);
  // The distance of the farthest edge from its share, for the better H.
  double best = 1;
  for (double H : {1 + closing, 1 - closing}) {
    const double r = std::abs(std::log(H)) / around;
    double worst = 0;
    for (double m : mismatches) {
      worst = std::max(worst, std::min(std::abs(m - std::expm1(r)), std::abs(m + std::expm1(-r))));
    }
    best = std::min(best, worst);
  }
  EXPECT_LE(best, 1e-9) << "not every edge misses eq. 7 by the same factor H^(±1/n)";
  EXPECT_LT(spread.mismatch_max, 1.5 * closing / around);
  std::cout << "ring of " << around << ": propagated mismatch " << closing
            << " on one edge; least squares " << spread.mismatch_max << " on every edge\n";
}

// ------------------------------------------- (g) sampling, rulings, output

class HNetOutput : public ScratchDirTest {};

TEST_F(HNetOutput, SampledPatchworkLiesOnParaboloid) {
  const Mesh mesh = HyperbolicParaboloidNet();
  const HNet hnet = BuildHNet(mesh);
  const int n = 4;
  const SampledPatchwork s = SamplePatchwork(mesh, hnet, n);
  ASSERT_EQ(s.positions.size(), mesh.num_faces() * (n + 1) * (n + 1));
  ASSERT_EQ(s.triangles.size(), mesh.num_faces() * 2 * n * n);
  ASSERT_EQ(s.triangle_face.size(), s.triangles.size());
  for (size_t i = 0; i < s.positions.size(); ++i) {
    const V3 x = E(s.positions[i]), normal = E(s.normals[i]);
    EXPECT_NEAR(x[2], x[0] * x[1], kTolerance);
    // The surface normal of z = xy is ±(−y, −x, 1)/‖·‖; the mesh is oriented
    // counter-clockwise seen from +z, so +.
    EXPECT_LE((normal - V3(-x[1], -x[0], 1).normalized()).norm(), kTolerance);
  }
  for (const auto& t : s.triangles) {  // triangles oriented like the normals
    const V3 a = E(s.positions[t[0]]), b = E(s.positions[t[1]]), c = E(s.positions[t[2]]);
    EXPECT_GT((b - a).cross(c - a).dot(E(s.normals[t[0]])), 0.0);
  }
  // Isophotes with respect to +z: angle = acos(n_z); banded every 10°.
  const std::vector<double> angles = IsophoteAngles(s.normals, {0, 0, 2});
  for (size_t i = 0; i < angles.size(); ++i) {
    EXPECT_NEAR(angles[i], std::acos(s.normals[i][2]) * 180 / M_PI, 1e-9);
  }
  const auto colors = IsophoteColors({5.0, 15.0, 25.0, 9.999}, 10.0);
  EXPECT_EQ(colors[0][0], 235);
  EXPECT_EQ(colors[1][0], 40);
  EXPECT_EQ(colors[2][0], 235);
  EXPECT_EQ(colors[3][0], 235);
  EXPECT_THROW(IsophoteAngles(s.normals, {0, 0, 0}), InputError);
  EXPECT_THROW(IsophoteColors(angles, 0.0), InputError);
}

TEST_F(HNetOutput, RulingsAndObjPolylines) {
  const Mesh mesh = HyperboloidNet();
  const HNet hnet = BuildHNet(mesh);
  const Polylines rulings = PatchRulings(mesh, hnet, 3, 5);
  ASSERT_EQ(rulings.lines.size(), mesh.num_faces() * 6);
  for (const auto& line : rulings.lines) {
    ASSERT_EQ(line.size(), 5u);
    const V3 a = E(line.front()), direction = (E(line.back()) - a).normalized();
    for (const Vec3& p : line) EXPECT_LE((E(p) - a).cross(direction).norm(), kTolerance);
  }
  // per_family = 1: the rulings join opposite frame points (u = ½ joins f0, f2).
  const Polylines middle = PatchRulings(mesh, hnet, 1, 2);
  ASSERT_EQ(middle.lines.size(), 2 * mesh.num_faces());
  for (size_t k = 0; k < middle.lines.size(); ++k) {
    const auto& frame = hnet.frame_points[middle.face[k]];
    const int first = middle.family[k] == 0 ? 0 : 3, second = middle.family[k] == 0 ? 2 : 1;
    EXPECT_LE((E(middle.lines[k][0]) - E(frame[first])).norm(), kTolerance);
    EXPECT_LE((E(middle.lines[k][1]) - E(frame[second])).norm(), kTolerance);
  }
  // OBJ: v records then l records (1-based), values round-trip.
  const std::string path = Path("rulings.obj");
  WritePolylinesObj(path, middle.lines);
  std::ifstream in(path);
  std::string line;
  std::vector<V3> vertices;
  std::vector<std::vector<int>> polylines;
  while (std::getline(in, line)) {
    std::istringstream record(line);
    std::string kind;
    record >> kind;
    if (kind == "v") {
      V3 p;
      record >> p[0] >> p[1] >> p[2];
      vertices.push_back(p);
    } else if (kind == "l") {
      polylines.emplace_back();
      for (int i; record >> i;) polylines.back().push_back(i);
    }
  }
  ASSERT_EQ(vertices.size(), 2 * middle.lines.size());
  ASSERT_EQ(polylines.size(), middle.lines.size());
  for (size_t k = 0; k < polylines.size(); ++k) {
    ASSERT_EQ(polylines[k].size(), 2u);
    for (int i = 0; i < 2; ++i) {
      EXPECT_EQ((vertices[polylines[k][i] - 1] - E(middle.lines[k][i])).norm(), 0.0);
    }
  }
  EXPECT_THROW(WritePolylinesObj(Path("missing/dir/x.obj"), middle.lines), InputError);
}

TEST_F(HNetOutput, DarbouxMapOfPatchwork) {
  const Mesh mesh = HyperbolicParaboloidNet();
  const HNet hnet = BuildHNet(mesh);
  const SampledPatchwork s = SamplePatchwork(mesh, hnet, 3);
  // Translated away from the origin, then inverted (c = −1): no failures.
  DarbouxTransform inversion;
  inversion.c = -1;
  inversion.projective.block<3, 1>(0, 3) = V3(0.5, 0.2, 2.0);
  std::vector<int> failed;
  const SampledPatchwork mapped = DarbouxMapPatchwork(s, inversion, &failed);
  EXPECT_TRUE(failed.empty());
  ASSERT_EQ(mapped.positions.size(), s.positions.size());
  EXPECT_EQ(mapped.triangles.size(), s.triangles.size());
  for (size_t i = 0; i < s.positions.size(); ++i) {
    const V3 y = E(s.positions[i]) + V3(0.5, 0.2, 2.0);
    EXPECT_LE((E(mapped.positions[i]) - 4 * y / y.squaredNorm()).norm(), kTolerance);
    EXPECT_NEAR(E(mapped.normals[i]).norm(), 1.0, kTolerance);
  }
  // c = 2: images are real only for |x|² ≤ 1/3; the others are reported and
  // their triangles dropped.
  DarbouxTransform partial;
  partial.c = 2;
  const SampledPatchwork cut = DarbouxMapPatchwork(s, partial, &failed);
  int expected_failures = 0;
  for (const Vec3& p : s.positions) expected_failures += E(p).squaredNorm() > 1.0 / 3.0;
  EXPECT_GT(expected_failures, 0);
  EXPECT_EQ(int(failed.size()), expected_failures);
  EXPECT_LT(cut.triangles.size(), s.triangles.size());
  EXPECT_GT(cut.triangles.size(), 0u);
  for (int i : failed) EXPECT_TRUE(E(cut.positions[i]).hasNaN());
  for (const auto& t : cut.triangles) {
    for (int k : t) EXPECT_FALSE(E(cut.positions[k]).hasNaN());
  }
}

}  // namespace
}  // namespace archgeo
