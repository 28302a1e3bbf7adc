// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the curl correction of the level sets' sizes [Gebreiter 2012,
// §8.1.4, after Zhang et al. 2010: log sizes per element chosen so that the
// field scaled by them is curl-free, held to the designated size; Zadravec
// 2010, §5 eq. 5 for the level sets].
//
// Eq. 5 asks ∇g = R v per face with unit v: level lines Δw apart. Where the
// field has curl no g has that gradient, and the least-squares g spreads
// the misfit as uneven spacing (fans, needle panels) and turned level lines.
// A face-wise field G is the gradient of a function linear per triangle
// exactly when its circulation around every interior vertex p vanishes:
// Σ_{f∋p} σ_f G_f·e_f = 0, e_f the edge of f opposite p (counter-clockwise:
// the sum telescopes for a gradient), σ_f = ±1 the matching of the cuts
// crossed from the first face of the ring (fields/cuts.h; the discrete
// rotation of Polthier and Preuß, which the thesis' curl is). With G_f =
// R v_f e^{−s̃_f}, s̃ the log size (the spacing there is Δw e^{s̃}), s̃_f the
// mean of its corners' s̃_v, CorrectLevelSetSizes minimises, per family (g
// with v, h with w),
//
//   Σ_p (1/A_p) (Σ_{f∋p} σ_f (R v_f)·e_f e^{−s̃_f})² + λ Σ_v (A_v/Δw²) s̃_v²,
//   λ = 1 / reach²,
//
// (A_p a third of the ring's area: the first sum is ∫ curl² dA of the scaled
// field) by Gauss–Newton steps on the sparse normal equations
// (SimplicialLDLT), with every s̃_v held within ±log(max_ratio) (an active
// set: spacings between Δw/max_ratio and Δw·max_ratio, so that a cell's
// area stays within max_ratio^{±2} of Δw²). The first sum removes the curl,
// the second holds the size to the spacing asked for, so a change of size
// relaxes back over about `reach` spacings. Vertices on the boundary, singular vertices (the ring's
// matchings do not compose to +1) and vertices beside a face without a field
// carry no condition. The result scales v and w of the alignment term
// (level_set_alignment): its target R v e^{−s̃} is then nearly integrable, so
// eq. 5 fits it with level lines along the field and spacings that vary
// smoothly instead of locally.
//
// Include only where CGAL is acceptable (pulls in mesh/surface_mesh.h).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "fields/cuts.h"
#include "fields/face_frames.h"

namespace archgeo {

struct LevelSetSizeFamily {
  std::vector<double> log_size;  // s̃ per face (0 where the face has no field)
  int vertices = 0;              // vertices that carry a curl condition
  // The area-weighted RMS curl of the scaled field times Δw (dimensionless:
  // how far a cell's level lines miss closing, relative to the spacing),
  // with unit sizes and with the corrected ones.
  double curl_before = 0, curl_after = 0;
  double size_p5 = 1, size_p95 = 1, size_min = 1, size_max = 1;  // e^{s̃}, area-weighted
};

struct LevelSetSizes {
  LevelSetSizeFamily g, h;
};

// v, w: per face, the oriented field directions in the face frame (zero
// where undefined); `chain_sign_v`, `chain_sign_w`: s_C per cut chain of each
// family (fields/cut_jumps.h); spacing Δw and reach > 0 in the frames' units
// and spacings; max_ratio > 1. Preconditions (CHECKed): triangle mesh, sizes
// match.
LevelSetSizes CorrectLevelSetSizes(const Mesh& mesh, const FaceFrames& frames, const CutGraph& cut,
                                   const std::vector<Eigen::Vector2d>& v,
                                   const std::vector<Eigen::Vector2d>& w,
                                   const std::vector<int>& chain_sign_v,
                                   const std::vector<int>& chain_sign_w, double spacing,
                                   double reach, double max_ratio);

}  // namespace archgeo
