// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the data of the standing wave of `wave_quads` [Gebreiter 2012,
// §8.1.3, §8.3; Zhang et al. 2010]: a guidance cross field per vertex (the
// principal curvature directions, propagated into umbilic regions by
// smoothing), the per-edge phase advances and matchings of the transfer term,
// and the feature vertices of the boundary.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/elements.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

// Per vertex: unit normal n, the guidance field's X and Y = n × X (unit,
// tangent), and the anisotropy |k1 − k2| / max that weighed the smoothing.
struct WaveFrames {
  std::vector<Eigen::Vector3d> normal, x, y;
  std::vector<double> anisotropy;
};

// The principal field of `mesh` (any polygon mesh; jets on its
// triangulation): X along the principal direction of the larger |k| (independent
// of the orientation), then `smoothing` sweeps of the 4-RoSy average
// (each vertex: its own direction weighted by its anisotropy, plus its
// neighbours' directions transported into its tangent plane), keeping at
// each vertex the one of the four directions nearest its own X.
WaveFrames PrincipalWaveFrames(const Mesh& mesh, int smoothing);

// The element set `wave_edges` (energies/wave_elements.h) from the frames and
// the size fields mu (along X) and eta (along Y) per vertex (canonical
// lengths, > 0): α = 2π/μ_e X_e·(p_j − p_i), β = 2π/η_e Y_e·(p_j − p_i) with
// X_e, Y_e, μ_e, η_e the means of i's and j's (matched) values.
ElementSet WaveEdges(const Mesh& mesh, const WaveFrames& frames, const std::vector<double>& mu,
                     const std::vector<double>& eta);

// `wave_vertices`: every vertex.
ElementSet WaveVertices(const Mesh& mesh);

// `wave_features`: the boundary vertices, each sin φ = 0 where the boundary
// runs closer to X than to Y (an iso-line of φ), sin θ = 0 otherwise, and
// both (a corner) where the boundary turns by more than corner_degrees.
ElementSet WaveFeatures(const Mesh& mesh, const WaveFrames& frames, double corner_degrees);

}  // namespace archgeo
