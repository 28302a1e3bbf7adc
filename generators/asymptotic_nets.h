// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — analytic asymptotic quad nets: test surfaces for A-net / H-net
// optimisation [Shi, Wang, Pottmann 2014, §3.2–3.3, Table 1].
//
// An asymptotic net samples a surface of negative Gaussian curvature along its
// two families of asymptotic lines; each neighbour of a vertex is O(h³) off
// the tangent plane (h = edge length), and on a valence-4 star the odd terms
// of opposite neighbours cancel against a tilted plane, so the star is planar
// up to O(h⁴) (O(h³) relative to h; measured in tests/test_asymptotic_nets).
// It is an A-net up to discretisation error, and exactly an A-net on a ruled
// quadric sampled along its rulings and on Enneper's surface (a cubic
// polynomial in the asymptotic parameters; stars planar to rounding).
//
// Minimal surfaces come from Weierstrass data (f, g), w in C:
//
//   x(w) = x0 + Re ∫_{w0}^{w} ( f (1 − g²), i f (1 + g²), 2 f g ) dw
//
// (this normalisation gives Enneper's surface x = u − u³/3 + u v²,
// y = −v + v³/3 − u² v, z = u² − v² for f = 1, g = w = u + i v). Its Hopf
// differential is proportional to f g' dw², so in the variable ζ with
// dζ = sqrt(f g') dw the lines Re ζ = const and Im ζ = const are curvature
// lines (ζ is an isothermal curvature-line parameter) and the lines
// Re ζ ± Im ζ = const are the asymptotic lines. With ζ = ξ + i η we write
//
//   s = ξ + η,  t = ξ − η,   i.e.   ζ = ((s + t) + i (s − t)) / 2,
//
// so (s, t) are asymptotic (and conformal) parameters, and a regular grid in
// (s, t) is an asymptotic net. Positions are computed by integrating
//   dw/dζ = 1 / sqrt(f(w) g'(w)),   dΦ/dζ = (f(1−g²), i f(1+g²), 2fg)(w) dw/dζ
// with classical RK4 along straight segments of the ζ-plane (step ≤
// kWeierstrassStep), tracking the branch of the square root continuously;
// x = x0 + Re Φ. No closed form of w(ζ) is needed.
//
// Every mesh is a quad mesh (triangle meshes for the references) with faces
// oriented counter-clockwise in the parameters (s, t) (resp. (u, v)), so the
// face normals point along x_s × x_t; vertex indices are documented per
// function. Generators throw archgeo::InputError (file "", key = the parameter
// name) on invalid parameters.
#pragma once

#include <complex>
#include <functional>
#include <string>
#include <vector>

#include "mesh/surface_mesh.h"

namespace archgeo {

using Complex = std::complex<double>;

// RK4 step bound |Δζ| for the Weierstrass integration (the local error is
// O(|Δζ|⁵) times derivatives of f, g; 1e-3 gives ~1e-12 relative accuracy on
// the presets below).
inline constexpr double kWeierstrassStep = 1e-3;

// Weierstrass data of a minimal surface and the base point of the integration.
struct WeierstrassData {
  std::function<Complex(Complex)> f;   // holomorphic on the sampled region
  std::function<Complex(Complex)> g;   // (stereographic) Gauss map
  std::function<Complex(Complex)> dg;  // g'
  Complex zeta0 = 0.0;  // base point in the ζ-plane ...
  Complex w0 = 0.0;     // ... and the w it maps to; sqrt(f g') at w0 is the
                        // principal root (this fixes the branch of ζ)
  Vec3 x0 = {0.0, 0.0, 0.0};  // x(w0)
};

// A regular grid in the ζ-plane: ζ_ab = origin + a·step_a + b·step_b,
// a = 0 … n_a, b = 0 … n_b. Precondition: f g' has no zero or pole on the
// straight segment from zeta0 to origin nor on the parallelogram spanned by the
// grid (the integration marches along its lines).
struct ZetaGrid {
  Complex origin = 0.0;
  Complex step_a = 0.0, step_b = 0.0;
  int n_a = 0, n_b = 0;  // numbers of steps (>= 1 each)
};

// The grid of asymptotic parameters s = s_min + i (s_max − s_min)/n_s,
// t = t_min + j (t_max − t_min)/n_t, i = 0 … n_s, j = 0 … n_t, as a ZetaGrid
// (a = i, b = j). Throws InputError unless n_s, n_t >= 1 and s_max > s_min,
// t_max > t_min (all finite).
ZetaGrid AsymptoticGrid(double s_min, double s_max, int n_s, double t_min, double t_max, int n_t);

// Points x(ζ_ab) of the minimal surface of `data` on `grid`; entry
// b * (n_a + 1) + a. Throws InputError if the grid is empty or the integration
// produces non-finite values (a zero or pole of f g' on the path).
std::vector<Vec3> SampleMinimalSurface(const WeierstrassData& data, const ZetaGrid& grid);

// x at one ζ, integrated along the straight segment zeta0 → zeta (same
// precondition and error as above).
Vec3 MinimalSurfacePoint(const WeierstrassData& data, Complex zeta);

// Quad mesh of the samples of SampleMinimalSurface: vertex (a, b) has index
// b * (n_a + 1) + a; face (a, b), a < n_a, b < n_b, is
// (a,b), (a+1,b), (a+1,b+1), (a,b+1). For an AsymptoticGrid it is an
// asymptotic net (edges along s and t).
Mesh MinimalSurfaceNet(const WeierstrassData& data, const ZetaGrid& grid);

// Enneper's surface in closed form at w = u + i v (the same as the Weierstrass
// route with EnneperData(): x = u − u³/3 + u v², y = −v + v³/3 − u² v,
// z = u² − v²).
Vec3 EnneperPoint(double u, double v);

// Weierstrass data, base point ζ0 = w0 = 0:
//  Enneper:  f = 1, g = w; ζ = w (f g' = 1). Injective for |w| < √3.
//  Catenoid: f = e^{−w}/2, g = e^{w}; f g' = 1/2, ζ = w/√2;
//            x = (−cosh u cos v, −cosh u sin v, u) for w = u + i v (x0 =
//            (−1, 0, 0)): axis z, waist radius 1, radius cosh z; period
//            w → w + 2πi, i.e. (s, t) → (s + √2 π, t − √2 π).
//  Scherk (doubly periodic):  f = 4/(1 − w⁴), g = w, |w| < 1;
//            x = (4 Re arctan w, −4 Im artanh w, 4 Re artanh w²), the graph
//            cos(x/2) e^{z/2} = cos(y/2). ζ = ∫ 2/sqrt(1 − w⁴) dw maps the unit
//            disk onto the (s, t)-square |s|, |t| < 2K, 2K = 2 ∫_0^1 (1 − r⁴)^{−½}
//            dr ≈ 2.622 (its corners are the poles w = ±1, ±i).
WeierstrassData EnneperData();
WeierstrassData CatenoidData();
WeierstrassData ScherkData();

// z = x y sampled on its rulings: vertex (i, j), i = 0 … n_u, j = 0 … n_v, has
// index j (n_u + 1) + i and position x = (i − n_u/2) h, y = (j − n_v/2) h,
// z = x y; face (i, j) = (i,j), (i+1,j), (i+1,j+1), (i,j+1). Every vertex star
// lies exactly in the tangent plane z = x0 y + y0 x − x0 y0 (an exact A-net).
// Throws InputError unless n_u, n_v >= 1 and h > 0 finite.
Mesh HyperbolicParaboloidNet(int n_u, int n_v, double h);

// A band of the catenoid (CatenoidData) around its axis, sampled on the
// asymptotic lattice s = p h, t = q h − (rows − 1) h / 2 with h = √2 π / m, so
// that the period is m lattice steps. Vertex (k, i), row k = p + q = 0 …
// rows − 1, i = p mod m = 0 … m − 1, has index k m + i and height
// z = (k − (rows − 1)/2) π / m. Face (k, i), k = 0 … rows − 3, is
// (k,i), (k+1,i+1 mod m), (k+2,i+1 mod m), (k+1,i) — the lattice quad with
// corner (p, q) = (i, k − i). The band is closed around the axis (an annulus,
// not simply connected): its only boundaries are the two zig-zag loops through
// rows 0, 1 and rows − 2, rows − 1; rows 2 … rows − 3 are interior vertices of
// valence 4. m quads around the axis per row; m must be even (a bipartite
// vertex graph with an even number of quads around, as for the paper's
// catenoid). Default m = 44, rows = 32: 1320 faces, 1408 vertices, the size of
// the paper's "catenoid" row. Throws InputError unless m >= 4 is even and
// rows >= 5.
Mesh CatenoidBandNet(int m = 44, int rows = 32);

// The named test nets and the rows of Shi 2014 Table 1 they stand for.
enum class AsymptoticTestNet {
  // z = x y on [−½, ½]², 12 × 12 quads, h = 1/12 (exact A-net; a simply
  // connected saddle standing in for "mass spring surface", |F| 247).
  kHyperbolicParaboloid,
  // Enneper, (s, t) ∈ [−1.2, 1.2]², 12 × 12 quads (144 F, 169 V), a symmetric
  // piece around the flat-free centre w = 0: "minimal surface 1" (139 F, 168 V).
  kEnneperLarge,
  // Enneper, s ∈ [0, 1.4], t ∈ [−1.2, 1.2], 7 × 12 quads (84 F, 104 V), an
  // off-centre piece: "minimal surface 2" (84 F, 105 V).
  kEnneperSmall,
  // CatenoidBandNet(44, 32): 1320 F, 1408 V, not simply connected:
  // "catenoid" (1320 F, 1408 V).
  kCatenoidBand,
  // Scherk's doubly periodic surface, (s, t) ∈ [−1.8, 1.8]², 24 × 24 quads
  // (576 F, 625 V), a simply connected saddle piece of one period cell; stands
  // for "Schwarz surface" (702 F, 802 V, which is not simply connected there).
  kScherk,
};

// Short name ("hyperbolic_paraboloid", "enneper_large", "enneper_small",
// "catenoid_band", "scherk") and the paper row it stands for.
std::string AsymptoticTestNetName(AsymptoticTestNet which);
std::string AsymptoticTestNetPaperRow(AsymptoticTestNet which);

// The test net `which` with `refinement` (>= 1) times as many quads in each
// parameter direction over the same region (spacing h / refinement); the
// catenoid band keeps its height range (m → refinement·m, rows →
// refinement·(rows − 1) + 1). Throws InputError for refinement < 1.
Mesh MakeAsymptoticTestNet(AsymptoticTestNet which, int refinement = 1);

// The analytic reference surface of `which` as a triangle mesh (each grid cell
// split along its (a,b)-(a+1,b+1) diagonal), for proximity terms: the region
// of the net grown by 10% of its extent on every side, sampled with
// `resolution` (>= 1) × 4 cells per net quad along each parameter direction:
//  - hyperbolic paraboloid: z = x y on the enlarged square, (x, y) grid;
//  - Enneper, Scherk: the same Weierstrass route on the enlarged (s, t) grid;
//  - catenoid: a curvature-line grid (u = height, v = angle; 4·resolution·m
//    cells around, closed, an annulus) over the band's height range grown by
//    10% on both ends.
// Throws InputError for resolution < 1.
Mesh MakeAsymptoticTestReference(AsymptoticTestNet which, int resolution = 1);

}  // namespace archgeo
