// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The per-element data of the size-field curl correction (size_curl.h,
// size_target.h, size_smoothing.h), shared by the terms' adders and the
// problem that builds their element sets
// (problems/declarations/wave_size_curl.cpp). Not a cost functor.
//
// Block (per vertex, declared by the problem): "wave_size", the log sizes
// (μ̃, η̃) = (log μ, log η) of the wavelengths along the guidance field's X
// and Y at the vertex (canonical lengths) [Gebreiter 2012, §8.1.4; Zhang et
// al. 2010].
//
// Element sets:
//   size_triangles  two per triangle (one per family, X with μ̃ and Y with
//                   η̃); vertices = {a, b, c}; data: the constant, the three
//                   gradient coefficients and which of each vertex's two log
//                   sizes belongs to the family there (the cross field's
//                   matching to the triangle's first vertex)
//   size_vertices   one per vertex; data: the target log sizes and their weights
//   size_edges      one per edge ij; vertices = {i, j}; data: which of j's log
//                   sizes is i's μ̃ (the matching across the edge)
#ifndef ARCHGEO_ENERGIES_SIZE_ELEMENTS_H_
#define ARCHGEO_ENERGIES_SIZE_ELEMENTS_H_

namespace archgeo::size_data {

inline constexpr int kWidth = 2;  // doubles of wave_size per vertex: μ̃, η̃

// size_triangles: r = kConstant + Σ_k kGradient[k] · s_k[kSource[k]].
inline constexpr int kConstant = 0, kGradient = 1, kSource = 4;
inline constexpr int kTriangleWidth = 7;

// size_vertices: r = (kWeightMu (μ̃ − kTargetMu), kWeightEta (η̃ − kTargetEta)).
inline constexpr int kTargetMu = 0, kTargetEta = 1, kWeightMu = 2, kWeightEta = 3;
inline constexpr int kVertexWidth = 4;

// size_edges: i's μ̃ at j is s_j[kSourceMu], i's η̃ the other.
inline constexpr int kSourceMu = 0;
inline constexpr int kEdgeWidth = 1;

}  // namespace archgeo::size_data

#endif  // ARCHGEO_ENERGIES_SIZE_ELEMENTS_H_
