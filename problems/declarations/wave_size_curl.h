// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the curl correction of the wave's size fields [Gebreiter 2012,
// §8.1.4; Zhang et al. 2010]: the element sets of the terms size_curl,
// size_target and size_smoothing (energies/size_elements.h) on the log sizes
// (μ̃, η̃) per vertex, and the curl of the phase gradient the wave integrates
// (X/μ and Y/η) as a scale-free measure.
#pragma once

#include <vector>

#include "core/elements.h"
#include "mesh/surface_mesh.h"
#include "problems/declarations/wave_field.h"

namespace archgeo {

struct WaveSizeSets {
  ElementSet triangles, vertices, edges;
};

// The element sets from the guidance field and the designated sizes mu
// (along X), eta (along Y) per vertex (canonical lengths, > 0). Polygons
// are split into fans of triangles at their first vertex.
WaveSizeSets WaveSizeCurlSets(const Mesh& mesh, const WaveFrames& frames,
                              const std::vector<double>& mu, const std::vector<double>& eta);

// The curl of the phase gradient per family: the area-weighted RMS over the
// triangles of s_T² curl(F/s) (F = X with s = μ, F = Y with η; the discrete
// curl of Polthier and Preuß with F/s at the edge midpoints the mean of its
// corners' matched values, s_T the mean of the corners' sizes): the phase,
// in turns, by which the wave misses closing around a square of side s.
// 0 for a curl-free (integrable) scaled field, scale-free.
struct WaveSizeCurl {
  double x = 0, y = 0;
};
WaveSizeCurl MeasureWaveSizeCurl(const Mesh& mesh, const WaveFrames& frames,
                                 const std::vector<double>& mu, const std::vector<double>& eta);

}  // namespace archgeo
