// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The per-element data of the standing-wave terms (wave_*.h), shared by the
// terms' adders and the problem that builds their element sets
// (problems/declarations/wave_quads.cpp). Not a cost functor.
//
// Block (per vertex, declared by the problem): "wave_f", the 4-vector
//   f_i = (cos θ cos φ, cos θ sin φ, sin θ cos φ, sin θ sin φ)
// [Gebreiter 2012, §8.3.1; Zhang et al. 2010]; its first component is the
// wave, cos θ cos φ.
//
// Element sets:
//   wave_edges     one per mesh edge ij; vertices = {i, j}; data: α_ij, β_ij
//                  (the phase advance of θ and φ from i to j in i's labels)
//                  and the matching of j's frame to i's (which of j's angles,
//                  with which sign, is i's θ and i's φ)
//   wave_vertices  one per vertex (the penalties)
//   wave_features  one per constrained vertex; data: the kind (below)
#ifndef ARCHGEO_ENERGIES_WAVE_ELEMENTS_H_
#define ARCHGEO_ENERGIES_WAVE_ELEMENTS_H_

namespace archgeo::wave_data {

inline constexpr int kWidth = 4;  // doubles of wave_f per vertex

// wave_edges: α, β, then i's θ at j = sign_θ · (θ_j if source_θ = 0 else φ_j),
// i's φ at j = sign_φ · (θ_j if source_φ = 0 else φ_j).
inline constexpr int kAlpha = 0, kBeta = 1, kSourceTheta = 2, kSignTheta = 3, kSourcePhi = 4,
                     kSignPhi = 5;
inline constexpr int kEdgeWidth = 6;

// wave_features: the constraint of a feature (boundary) vertex.
inline constexpr int kKind = 0;
inline constexpr int kFeatureWidth = 1;
inline constexpr int kSinTheta = 0;  // sin θ = 0: the feature runs along an iso-line of θ
inline constexpr int kSinPhi = 1;    // sin φ = 0
inline constexpr int kCorner = 2;    // cos θ sin φ = sin θ cos φ = sin θ sin φ = 0

}  // namespace archgeo::wave_data

#endif  // ARCHGEO_ENERGIES_WAVE_ELEMENTS_H_
