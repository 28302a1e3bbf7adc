// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — analytic test meshes.
#pragma once

#include <cstdint>
#include <functional>

#include "mesh/surface_mesh.h"

namespace archgeo {

// A regular (nu x nv)-quad grid on the parametric surface `surface(u, v)`,
// (u, v) in [0,1]^2; vertex (i, j) has index j * (nu + 1) + i. Each vertex
// is then moved along a uniformly random direction by up to `noise` times
// the mean edge length (fixed `seed`), which makes the quads non-planar.
Mesh QuadGrid(int nu, int nv, const std::function<Vec3(double, double)>& surface,
              double noise = 0.0, std::uint64_t seed = 1);

// Moves every vertex along a uniformly random direction (a normalised
// isotropic Gaussian) by a uniformly random distance of up to `noise` times
// the mean edge length (QuadGrid's noise; `archgeo generate --noise`).
void AddNoise(Mesh& mesh, double noise, std::uint64_t seed);

// A doubly curved roof-like patch (x, y) -> (x, y, 0.3 sin(2x) + 0.25 cos(2y))
// over [0, 2] x [0, 1.5], used by demos, tests and scaling runs. It is a
// translational surface, so its parameter lines are conjugate and the
// noise-free QuadGrid has exactly planar quads: the noise alone makes them
// non-planar, and planarity is reachable with movement of the noise's order.
Vec3 RoofSurface(double u, double v);

}  // namespace archgeo
