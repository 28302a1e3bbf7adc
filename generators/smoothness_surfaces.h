// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — analytic test meshes for the visual-smoothness analysis
// [Pellis et al. 2019]: the torus principal mesh of Fig. 7, surfaces of
// revolution between two circles (§4, Fig. 13), and the parallelogram
// lattices inscribed in a paraboloid of §3.3 / Fig. 11.
//
// Invalid parameters throw archgeo::InputError naming the parameter (key).
#pragma once

#include <array>

#include "mesh/surface_mesh.h"

namespace archgeo {

// ---------------------------------------------------------------------------
// Torus (Fig. 7)
//
//   x(u, v) = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v),  u, v ∈ [0, 2π)
//
// Vertex (i, j) = x(2π i/n_u, 2π j/n_v) has index j·n_u + i; face (i, j) is
// (i, j), (i+1, j), (i+1, j+1), (i, j+1) (indices mod n_u, n_v), ordered so
// that its normal points outwards (along x_u × x_v). The parameter lines are
// the curvature lines (parallels and meridians), so this is a principal quad
// mesh; each quad is symmetric in the meridian plane u = 2π(i + ½)/n_u, hence
// a planar isosceles trapezoid. Closed (genus 1), 2 n_u n_v edges.
// Preconditions (InputError): 0 < r < R finite, n_u ≥ 3, n_v ≥ 3.
Mesh TorusPrincipalQuads(double R, double r, int n_u, int n_v);

// Total absolute curvature of the torus (R, r) [Pellis 2019, §3.1 and §4]:
//   κ1 = 1/r (meridians), κ2 = cos v/(R + r cos v) (parallels),
//   dA = r (R + r cos v) du dv, so
//   ∫|κ1| dA = ∫∫ (R + r cos v) du dv = 4π² R,
//   ∫|κ2| dA = ∫∫ r |cos v| du dv     = 2π · 4r = 8π r,
//   C(Φ) = 4π² R + 8π r   (a length). Same preconditions as above.
double TorusTotalAbsoluteCurvature(double R, double r);

// ---------------------------------------------------------------------------
// Surface of revolution about the z axis between the circles of radius r0 at
// z = 0 and r1 at z = height [Pellis 2019, §4, Fig. 13]:
//   ρ(z) = r0 + (r1 − r0) z/height + bulge · sin(π z/height),
// i.e. the straight cone (cylinder if r0 = r1) through both circles plus a
// bulge that vanishes on them (bulge = 0: the cone, the minimiser of C among
// surfaces of revolution).
struct RevolutionProfile {
  double r0 = 1.0, r1 = 0.5, height = 1.0, bulge = 0.2;
  double Radius(double z) const;  // ρ(z) above
};

// Triangle mesh of the profile: n_rings + 1 rings at z_j = height·j/n_rings,
// each of n_around vertices at angles 2π(i + j/2)/n_around (every ring turned
// by half a step, so interior vertices have valence 6 and the triangles are
// near-equilateral); vertex (i, j) has index j·n_around + i. The boundary
// rings are polygons inscribed in the two circles. Faces are oriented with
// outward normals (away from the axis).
// Preconditions (InputError): finite r0 > 0, r1 > 0, height > 0, finite
// bulge, ρ(z_j) > 0 on every ring, n_around ≥ 3, n_rings ≥ 1.
Mesh RevolutionTriangles(const RevolutionProfile& profile, int n_around, int n_rings);

// Max over the vertices of |ρ(v) − ρ_cone(z(v))| / height, where
// ρ = sqrt(x² + y²) and ρ_cone(z) = r0 + (r1 − r0) z/height is the straight
// generator through the two circles (extended linearly beyond [0, height]):
// the radial deviation of the mesh from the cone, relative to its height.
// 0 on a cone mesh. On RevolutionTriangles (whose vertices lie exactly on
// the profile) it is |bulge| max_j sin(π j/n_rings) / height, i.e. exactly
// |bulge|/height when n_rings is even (a ring at z = height/2).
// Preconditions (InputError): finite r0, r1, height > 0. 0 for an empty mesh.
double ConeDeviation(const Mesh& mesh, double r0, double r1, double height);

// ---------------------------------------------------------------------------
// Fig. 11: parallelogram lattices inscribed in the paraboloid
//   z = α x² + β y²,
// with vertex p_ij = lift(i a + j b) for a lattice spanned by a, b in the xy
// plane, lift(x, y) = (x, y, α x² + β y²). Lifted quads are planar only when
// a and b are conjugate (B(a, b) = α a_x b_x + β a_y b_y = 0, e.g. the
// principal directions a ∥ x, b ∥ y), so the faces are chosen by:
enum class LatticeFaces {
  // Quads p_ij p_i+1,j p_i+1,j+1 p_i,j+1 with the diagonal-cross normal of
  // FaceNormal; only the lattice edges carry energy.
  kQuads,
  // Each quad split along its diagonal a + b (p_ij – p_i+1,j+1): triangles;
  // lattice edges and diagonals carry energy ([Pellis 2019, §3.3]: E = E0 + E1).
  kTrianglesDiagonalAPlusB,
  // Each quad split along its diagonal a − b (p_i+1,j – p_i,j+1).
  kTrianglesDiagonalAMinusB,
  // The mean of the two triangulations (independent of the arbitrary choice
  // of diagonal, and symmetric under θ → −θ); the measure of benchmarks/
  // pellis_fig11.
  kTrianglesAveraged,
};

// Energy per area at the vertex p_00 = origin (where the paraboloid's tangent
// plane is z = 0 and its principal directions are x, y):
//   (½ Σ_{e ∋ origin} ℓ_e ℓ*_e) / |a × b|,
// the E of [Pellis 2019, §3] of the edges of the origin's star, each shared
// with its other endpoint, over the xy area of one lattice cell (one vertex
// per cell). The lifted lattice is point-symmetric about the origin, so this
// is the energy of exactly one period of the star (½ Σ over ±e = Σ over the
// 2 or 3 edge directions). Evaluated on the 3 × 3-vertex patch i, j ∈ {−1,
// 0, 1} (every star edge is interior). Units: 1/length (curvature); it tends
// to a limit as a, b shrink, with relative error O(‖a‖² max(|α|, |β|)²).
// For the principal lattice a = (h, 0), b = (0, h) the quads are planar
// rectangles and the limit is 2|α| + 2|β| = |κ1| + |κ2| (Fig. 11's minimum).
// Preconditions (InputError): finite α, β, a, b; |a × b| > 0.
double LatticeEnergyPerArea(double alpha, double beta, const std::array<double, 2>& a,
                            const std::array<double, 2>& b, LatticeFaces faces);

// The rotated square lattice of Fig. 11: a = h(cos θ, sin θ), b = h(−sin θ,
// cos θ) with h = kLatticeStep / max(|α|, |β|) (h = kLatticeStep if both are
// 0), small enough that the value is the h → 0 limit to ~1e-6 relative.
// θ: polar angle of the edge a in radians (any finite value).
inline constexpr double kLatticeStep = 1e-3;
double LatticeEnergyPerArea(double alpha, double beta, double theta, LatticeFaces faces);

}  // namespace archgeo
