// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for mesh/asymptotic_nets: the analytic asymptotic test nets of
// [Shi, Wang, Pottmann 2014, §3.3, Table 1].
//  - the Weierstrass ODE route reproduces Enneper's closed form (also through
//    a non-trivial ODE: Enneper in logarithmic coordinates), Scherk's implicit
//    equation and the catenoid's radius cosh z;
//  - vertex stars: exactly planar on the hyperbolic paraboloid and (a finding:
//    Enneper is a cubic polynomial in asymptotic coordinates) on Enneper's
//    surface; O(h³) planar relative to the edge length on Scherk and the
//    catenoid;
//  - the samples are minimal: the net is conformal and harmonic (discrete
//    Laplacian → 0) and asymptotic directions are orthogonal (H = 0);
//  - the catenoid band is a closed annulus with valence-4 interior vertices;
//  - reference triangle meshes cover the nets.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <ceres/cost_function.h>
#include <gtest/gtest.h>

#include "energies/anet_planarity.h"
#include "energies/autodiff.h"
#include "generators/asymptotic_nets.h"
#include "core/input_error.h"
#include "mesh/surface_mesh.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

// The ODE route against closed forms, relative to the size of the piece.
constexpr double kOdeRelativeTolerance = 1e-8;
// Exact A-net (hyperbolic paraboloid): star planarity relative to edge length.
constexpr double kExactPlanarity = 1e-12;
// Convergence rates when h is halved (printed by the tests).
// Laplacian and orthogonality are O(h²) (central differences): measured
// ratios 3.4–4.0 (Scherk 3.37–3.69, catenoid 3.9–4.2, Enneper orthogonality
// 4.0); accept [kQuadraticLow, kQuadraticHigh].
constexpr double kQuadraticLow = 3.0;
constexpr double kQuadraticHigh = 4.7;
// Star planarity relative to the edge length: the naive bound is
// O(h³)/h = O(h²), but on a valence-4 star the h³ terms of opposite
// neighbours have opposite signs and the least-squares plane tilts to absorb
// them, so the distance is O(h⁴) and the relative planarity O(h³): measured
// ratios 7.3–8.0 (Scherk 7.30–7.70, catenoid 7.99–8.00).
constexpr double kCubicLow = 6.0;
constexpr double kCubicHigh = 9.0;
// Enneper's surface is a cubic polynomial in (s, t): its asymptotic samples
// are an exact A-net and harmonic to rounding (measured <= 2.6e-13 and
// 1.6e-11 relative at h/4).
constexpr double kEnneperExact = 1e-10;

using Vec = Eigen::Vector3d;

Vec P(const Mesh& mesh, VertexIndex v) {
  const Point& p = mesh.point(v);
  return Vec(p.x(), p.y(), p.z());
}

// Neighbours of v in cyclic order.
std::vector<VertexIndex> Neighbours(const Mesh& mesh, VertexIndex v) {
  std::vector<VertexIndex> n;
  for (HalfedgeIndex h : mesh.halfedges_around_target(mesh.halfedge(v))) {
    n.push_back(mesh.source(h));
  }
  return n;
}

struct NetQuality {
  double star_planarity = 0;  // max over interior stars: LS-plane distance / mean spoke
  double star_quads = 0;      // max |AnetStarQuad| residual, L = mean spoke
  double laplacian = 0;       // max |Σw − 4v| / max (|w0 − 2v + w2| + |w1 − 2v + w3|)
  double orthogonality = 0;   // max |cos| between w0 − w2 and w1 − w3
  int interior = 0;
};

// Quality measures over the interior vertices (all of valence 4 here).
NetQuality Measure(const Mesh& mesh) {
  NetQuality q;
  std::unique_ptr<ceres::CostFunction> unit_quad(MakeAutoDiff(AnetStarQuad(1.0)));
  double lap_max = 0.0, second_max = 0.0;
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_border(v)) continue;
    const std::vector<VertexIndex> nb = Neighbours(mesh, v);
    EXPECT_EQ(nb.size(), 4u);
    if (nb.size() != 4) continue;
    ++q.interior;
    const Vec c = P(mesh, v);
    std::vector<Vec> w;
    for (VertexIndex u : nb) w.push_back(P(mesh, u));
    double spoke = 0.0;
    Vec centroid = c;
    for (const Vec& x : w) {
      spoke += (x - c).norm() / 4.0;
      centroid += x;
    }
    centroid /= 5.0;
    Eigen::Matrix3d cov = (c - centroid) * (c - centroid).transpose();
    for (const Vec& x : w) cov += (x - centroid) * (x - centroid).transpose();
    const Vec normal =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(0);
    double dist = std::abs(normal.dot(c - centroid));
    for (const Vec& x : w) dist = std::max(dist, std::abs(normal.dot(x - centroid)));
    q.star_planarity = std::max(q.star_planarity, dist / spoke);
    for (const auto& t : AnetStarQuadNeighbours(4)) {
      // The functor with L = spoke (the unit factory scaled).
      const double* blocks[4] = {c.data(), w[t[0]].data(), w[t[1]].data(), w[t[2]].data()};
      double r = 0.0;
      EXPECT_TRUE(unit_quad->Evaluate(blocks, &r, nullptr));
      q.star_quads = std::max(q.star_quads, std::abs(r) / spoke);
    }
    lap_max = std::max(lap_max, (w[0] + w[1] + w[2] + w[3] - 4.0 * c).norm());
    second_max = std::max(second_max,
                          (w[0] - 2.0 * c + w[2]).norm() + (w[1] - 2.0 * c + w[3]).norm());
    const Vec a = w[0] - w[2], b = w[1] - w[3];
    q.orthogonality = std::max(q.orthogonality, std::abs(a.dot(b)) / (a.norm() * b.norm()));
  }
  q.laplacian = lap_max / second_max;
  return q;
}

int BoundaryCycles(const Mesh& mesh) {
  std::vector<bool> seen(mesh.number_of_halfedges(), false);
  int cycles = 0;
  for (HalfedgeIndex h : mesh.halfedges()) {
    if (!mesh.is_border(h) || seen[h.idx()]) continue;
    ++cycles;
    HalfedgeIndex g = h;
    do {
      seen[g.idx()] = true;
      g = mesh.next(g);
    } while (g != h);
  }
  return cycles;
}

TEST(AsymptoticNets, EnneperOdeRouteMatchesClosedForm) {
  // (a) f = 1, g = w: ζ = w.
  const ZetaGrid grid = AsymptoticGrid(-1.2, 1.2, 24, -1.2, 1.2, 24);
  const std::vector<Vec3> x = SampleMinimalSurface(EnneperData(), grid);
  // (b) Enneper in logarithmic coordinates w = e^q: f = g = g' = e^q, so
  // dζ = e^q dq, ζ = e^q = w with base ζ0 = 1, q0 = 0: a genuinely non-linear
  // ODE for q(ζ) whose solution must still give Enneper's surface at w = ζ.
  WeierstrassData log_data;
  log_data.f = [](Complex q) { return std::exp(q); };
  log_data.g = [](Complex q) { return std::exp(q); };
  log_data.dg = [](Complex q) { return std::exp(q); };
  log_data.zeta0 = 1.0;
  log_data.w0 = 0.0;
  log_data.x0 = EnneperPoint(1.0, 0.0);
  const ZetaGrid log_grid = AsymptoticGrid(0.6, 2.0, 14, 0.2, 1.6, 14);  // Re ζ >= 0.4
  const std::vector<Vec3> y = SampleMinimalSurface(log_data, log_grid);

  const auto max_error = [](const ZetaGrid& g, const std::vector<Vec3>& pts) {
    double err = 0.0, size = 0.0;
    for (int b = 0; b <= g.n_b; ++b) {
      for (int a = 0; a <= g.n_a; ++a) {
        const Complex zeta = g.origin + double(a) * g.step_a + double(b) * g.step_b;
        const Vec3 e = EnneperPoint(zeta.real(), zeta.imag());
        const Vec3& p = pts[static_cast<size_t>(b) * (g.n_a + 1) + a];
        err = std::max(err, std::hypot(p[0] - e[0], p[1] - e[1], p[2] - e[2]));
        size = std::max(size, std::hypot(e[0], e[1], e[2]));
      }
    }
    return err / size;
  };
  const double err_plain = max_error(grid, x), err_log = max_error(log_grid, y);
  std::printf("Enneper ODE vs closed form, relative: plain %.2e, log %.2e\n", err_plain,
              err_log);
  EXPECT_LT(err_plain, kOdeRelativeTolerance);
  EXPECT_LT(err_log, kOdeRelativeTolerance);
  // A single point along a straight path agrees as well.
  const Vec3 p = MinimalSurfacePoint(log_data, Complex(0.9, -0.6));
  const Vec3 e = EnneperPoint(0.9, -0.6);
  EXPECT_LT(std::hypot(p[0] - e[0], p[1] - e[1], p[2] - e[2]), kOdeRelativeTolerance);
  // The asymptotic grid: s = u + v, t = u − v.
  EXPECT_NEAR(grid.origin.real(), -1.2, 1e-15);
  EXPECT_NEAR(grid.origin.imag(), 0.0, 1e-15);
}

TEST(AsymptoticNets, ScherkAndCatenoidMatchTheirEquations) {
  // Scherk: cos(x/2) e^{z/2} = cos(y/2).
  const Mesh scherk = MakeAsymptoticTestNet(AsymptoticTestNet::kScherk);
  EXPECT_EQ(scherk.number_of_faces(), 576u);
  EXPECT_EQ(scherk.number_of_vertices(), 625u);
  double scherk_err = 0.0;
  for (VertexIndex v : scherk.vertices()) {
    const Vec p = P(scherk, v);
    scherk_err = std::max(scherk_err,
                          std::abs(std::cos(p[0] / 2) * std::exp(p[2] / 2) - std::cos(p[1] / 2)));
  }
  EXPECT_LT(scherk_err, kOdeRelativeTolerance);
  // Catenoid: radius cosh z, heights (k − (rows − 1)/2) π / m.
  const int m = 44, rows = 32;
  const Mesh band = CatenoidBandNet(m, rows);
  double cat_err = 0.0;
  for (VertexIndex v : band.vertices()) {
    const Vec p = P(band, v);
    const int k = static_cast<int>(v.idx()) / m;
    cat_err = std::max(cat_err, std::abs(std::hypot(p[0], p[1]) - std::cosh(p[2])));
    cat_err = std::max(cat_err, std::abs(p[2] - (k - 0.5 * (rows - 1)) * M_PI / m));
  }
  EXPECT_LT(cat_err, kOdeRelativeTolerance);
  std::printf("Scherk equation error %.2e, catenoid radius/height error %.2e\n", scherk_err,
              cat_err);
}

TEST(AsymptoticNets, HyperbolicParaboloidIsAnExactANet) {
  for (int refinement : {1, 3}) {
    const Mesh net = MakeAsymptoticTestNet(AsymptoticTestNet::kHyperbolicParaboloid, refinement);
    const int n = 12 * refinement;
    EXPECT_EQ(net.number_of_faces(), static_cast<size_t>(n * n));
    const NetQuality q = Measure(net);
    EXPECT_EQ(q.interior, (n - 1) * (n - 1));
    EXPECT_LT(q.star_planarity, kExactPlanarity);
    EXPECT_LT(q.star_quads, kExactPlanarity);
    // z = x y is not minimal: its rulings are not orthogonal (the minimality
    // check below can fail).
    EXPECT_GT(q.orthogonality, 0.1);
  }
  // Vertex (i, j) at ((i − n_u/2) h, (j − n_v/2) h, x y).
  const Mesh net = HyperbolicParaboloidNet(4, 2, 0.5);
  const Vec p = P(net, VertexIndex(2 * 5 + 3));
  EXPECT_NEAR((p - Vec(0.5, 0.5, 0.25)).norm(), 0.0, 1e-15);
}

// Star planarity, Laplacian and orthogonality at refinements 1, 2, 4.
void ExpectConvergence(AsymptoticTestNet which, int finest) {
  std::vector<NetQuality> q;
  for (int r = 1; r <= finest; r *= 2) q.push_back(Measure(MakeAsymptoticTestNet(which, r)));
  for (size_t i = 0; i < q.size(); ++i) {
    std::printf("%-14s h/%d: star planarity %.3e, star quads %.3e, laplacian %.3e, "
                "orthogonality %.3e\n",
                AsymptoticTestNetName(which).c_str(), 1 << i, q[i].star_planarity,
                q[i].star_quads, q[i].laplacian, q[i].orthogonality);
  }
  for (size_t i = 0; i + 1 < q.size(); ++i) {
    SCOPED_TRACE(AsymptoticTestNetName(which) + " refinement " + std::to_string(1 << i));
    for (const auto& [coarse, fine] :
         {std::pair{q[i].star_planarity, q[i + 1].star_planarity},
          std::pair{q[i].star_quads, q[i + 1].star_quads}}) {
      EXPECT_GT(coarse / fine, kCubicLow);
      EXPECT_LT(coarse / fine, kCubicHigh);
    }
    for (const auto& [coarse, fine] : {std::pair{q[i].laplacian, q[i + 1].laplacian},
                                       std::pair{q[i].orthogonality, q[i + 1].orthogonality}}) {
      EXPECT_GT(coarse / fine, kQuadraticLow);
      EXPECT_LT(coarse / fine, kQuadraticHigh);
    }
  }
}

TEST(AsymptoticNets, EnneperNetsAreExactANets) {
  for (AsymptoticTestNet which :
       {AsymptoticTestNet::kEnneperLarge, AsymptoticTestNet::kEnneperSmall}) {
    std::vector<double> orthogonality;
    for (int r : {1, 2, 4}) {
      const NetQuality q = Measure(MakeAsymptoticTestNet(which, r));
      std::printf("%-14s h/%d: star planarity %.3e, star quads %.3e, laplacian %.3e, "
                  "orthogonality %.3e\n",
                  AsymptoticTestNetName(which).c_str(), r, q.star_planarity, q.star_quads,
                  q.laplacian, q.orthogonality);
      EXPECT_LT(q.star_planarity, kEnneperExact);
      EXPECT_LT(q.star_quads, kEnneperExact);
      EXPECT_LT(q.laplacian, kEnneperExact);
      orthogonality.push_back(q.orthogonality);
    }
    // Edge directions are central differences: orthogonal up to O(h²).
    for (size_t i = 0; i + 1 < orthogonality.size(); ++i) {
      EXPECT_GT(orthogonality[i] / orthogonality[i + 1], kQuadraticLow);
      EXPECT_LT(orthogonality[i] / orthogonality[i + 1], kQuadraticHigh);
    }
  }
}

TEST(AsymptoticNets, ScherkAndCatenoidStarsConverge) {
  ExpectConvergence(AsymptoticTestNet::kScherk, 4);
  ExpectConvergence(AsymptoticTestNet::kCatenoidBand, 2);
  // Absolute level at the paper-sized resolution (printed above).
  const NetQuality q = Measure(MakeAsymptoticTestNet(AsymptoticTestNet::kScherk));
  EXPECT_LT(q.star_planarity, 1e-3);
  EXPECT_GT(q.star_planarity, 1e-6);  // sampled, not exact
}

TEST(AsymptoticNets, CatenoidBandIsAClosedAnnulus) {
  for (const auto& [m, rows] : {std::pair{44, 32}, std::pair{8, 6}}) {
    const Mesh band = CatenoidBandNet(m, rows);
    EXPECT_EQ(band.number_of_vertices(), static_cast<size_t>(m * rows));
    EXPECT_EQ(band.number_of_faces(), static_cast<size_t>(m * (rows - 2)));
    EXPECT_TRUE(band.is_valid(false));
    // V − E + F = 0 (annulus) and exactly two boundary loops (top and
    // bottom): nothing is open along the band's sides.
    EXPECT_EQ(static_cast<long>(band.number_of_vertices()) -
                  static_cast<long>(band.number_of_edges()) +
                  static_cast<long>(band.number_of_faces()),
              0);
    EXPECT_EQ(BoundaryCycles(band), 2);
    for (VertexIndex v : band.vertices()) {
      const int k = static_cast<int>(v.idx()) / m;
      const bool border_row = k <= 1 || k >= rows - 2;
      EXPECT_EQ(band.is_border(v), border_row) << k;
      if (!border_row) {
        EXPECT_EQ(band.degree(v), 4u);
      }
    }
    // Bipartite: every edge joins rows of different parity.
    for (EdgeIndex e : band.edges()) {
      const int k0 = static_cast<int>(band.vertex(e, 0).idx()) / m;
      const int k1 = static_cast<int>(band.vertex(e, 1).idx()) / m;
      EXPECT_EQ(std::abs(k0 - k1), 1);
    }
  }
  const Mesh paper = MakeAsymptoticTestNet(AsymptoticTestNet::kCatenoidBand);
  EXPECT_EQ(paper.number_of_faces(), 1320u);  // Shi Table 1 "catenoid"
  EXPECT_EQ(paper.number_of_vertices(), 1408u);
}

TEST(AsymptoticNets, TestNetSizesMatchTheirPaperRows) {
  const std::map<AsymptoticTestNet, std::pair<size_t, size_t>> sizes = {
      {AsymptoticTestNet::kHyperbolicParaboloid, {144, 169}},
      {AsymptoticTestNet::kEnneperLarge, {144, 169}},
      {AsymptoticTestNet::kEnneperSmall, {84, 104}},
      {AsymptoticTestNet::kCatenoidBand, {1320, 1408}},
      {AsymptoticTestNet::kScherk, {576, 625}},
  };
  for (const auto& [which, fv] : sizes) {
    const Mesh net = MakeAsymptoticTestNet(which);
    EXPECT_EQ(net.number_of_faces(), fv.first) << AsymptoticTestNetName(which);
    EXPECT_EQ(net.number_of_vertices(), fv.second) << AsymptoticTestNetName(which);
    EXPECT_FALSE(AsymptoticTestNetPaperRow(which).empty());
    for (FaceIndex f : net.faces()) EXPECT_EQ(net.degree(f), 4u);
  }
}

TEST(AsymptoticNets, ReferencesCoverTheNets) {
  for (AsymptoticTestNet which :
       {AsymptoticTestNet::kHyperbolicParaboloid, AsymptoticTestNet::kEnneperLarge,
        AsymptoticTestNet::kEnneperSmall, AsymptoticTestNet::kCatenoidBand,
        AsymptoticTestNet::kScherk}) {
    SCOPED_TRACE(AsymptoticTestNetName(which));
    const Mesh net = MakeAsymptoticTestNet(which);
    const Mesh ref = MakeAsymptoticTestReference(which);
    EXPECT_TRUE(ref.is_valid(false));
    for (FaceIndex f : ref.faces()) ASSERT_EQ(ref.degree(f), 3u);
    EXPECT_EQ(BoundaryCycles(ref), which == AsymptoticTestNet::kCatenoidBand ? 2 : 1);
    double ref_edge = 0.0, ref_mean = 0.0, net_mean = 0.0;
    for (EdgeIndex e : ref.edges()) {
      const double l = (P(ref, ref.vertex(e, 0)) - P(ref, ref.vertex(e, 1))).norm();
      ref_edge = std::max(ref_edge, l);
      ref_mean += l / ref.number_of_edges();
    }
    for (EdgeIndex e : net.edges()) {
      net_mean += (P(net, net.vertex(e, 0)) - P(net, net.vertex(e, 1))).norm() /
                  net.number_of_edges();
    }
    EXPECT_LT(ref_mean, 0.5 * net_mean);  // finer than the net
    // Every net vertex is within one (longest) reference edge of a reference
    // vertex, and the reference's boundary is more than a (mean) reference
    // edge away from every net vertex (the region grew).
    std::vector<Vec> ref_points;
    for (VertexIndex v : ref.vertices()) ref_points.push_back(P(ref, v));
    std::vector<Vec> ref_border;
    for (VertexIndex v : ref.vertices()) {
      if (ref.is_border(v)) ref_border.push_back(P(ref, v));
    }
    double worst = 0.0, closest_border = 1e300;
    for (VertexIndex v : net.vertices()) {
      const Vec p = P(net, v);
      double best = 1e300;
      for (const Vec& r : ref_points) best = std::min(best, (r - p).norm());
      worst = std::max(worst, best);
      for (const Vec& r : ref_border) closest_border = std::min(closest_border, (r - p).norm());
    }
    EXPECT_LT(worst, ref_edge);
    EXPECT_GT(closest_border, ref_mean);
  }
}

TEST(AsymptoticNets, InvalidParametersThrow) {
  EXPECT_THROW(CatenoidBandNet(45, 32), InputError);  // odd number around
  EXPECT_THROW(CatenoidBandNet(44, 4), InputError);
  EXPECT_THROW(HyperbolicParaboloidNet(0, 3, 0.1), InputError);
  EXPECT_THROW(HyperbolicParaboloidNet(3, 3, -0.1), InputError);
  EXPECT_THROW(MakeAsymptoticTestNet(AsymptoticTestNet::kScherk, 0), InputError);
  EXPECT_THROW(MakeAsymptoticTestReference(AsymptoticTestNet::kScherk, 0), InputError);
  EXPECT_THROW(AsymptoticGrid(1.0, 0.0, 4, 0.0, 1.0, 4), InputError);
  WeierstrassData flat = EnneperData();
  flat.dg = [](Complex) { return Complex(0.0, 0.0); };  // g constant: a plane
  EXPECT_THROW(SampleMinimalSurface(flat, AsymptoticGrid(0, 1, 2, 0, 1, 2)), InputError);
}

}  // namespace
}  // namespace archgeo
