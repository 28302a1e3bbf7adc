// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `archgeo darboux`: smooth Darboux-cyclide patchworks from an
// H-net [Shi 2014, §4]. The quad net is extended to its H-net (geometry/hnet.h:
// shape parameters by eq. 7 and the optimal λ of eq. 11), every patch is
// sampled, and the samples are mapped by the Darboux transformation δ of
// eq. 12, optionally after a projective map. Rational bilinear patches map to
// Darboux cyclide patches and smooth joins stay smooth, so the result is a
// smooth patchwork no longer restricted to negative curvature.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "problems/commands/run.h"

namespace archgeo {

struct DarbouxOptions {
  double c = 0.5;              // the centre (0,0,0,c) of eq. 12; c ≠ 1
  bool minus_branch = false;   // the ∓ root of eq. 12 (the image inverse in Λ)
  std::vector<double> projective;  // empty, or 16 numbers row-major: the 4×4 map
                                   // applied first to (x, 1)ᵀ (column vectors)
  int samples = 8;             // n × n quads per patch
  double isophote_band = 0;    // > 0: per-vertex isophote bands of this width (degrees)
  std::array<double, 3> isophote_direction{0, 0, 1};
  bool ascii = false;          // ASCII PLY
  std::string rulings;         // optional OBJ path: the mapped rulings (circular arcs)
};

// Reads the quad net `net_path`, writes the mapped patchwork to `out_path`
// (PLY; atomically, after every check). Samples whose image is at infinity or
// not real are left out (counted in the report as failed_vertices, with
// their triangles). Throws InputError for bad input (not a quad mesh, c not
// finite or c = 1, a projective map that is not 16 finite numbers or is
// singular, a bad output extension, every sample left out) and, naming --c,
// when eq. 12 overflows double precision (|c| or the points so large that an
// image that should be finite comes out infinite or NaN, e.g. c = 1e308):
// nothing is written then, so a written patchwork has only finite vertices
// and normals.
RunResult RunDarboux(const std::string& net_path, const std::string& out_path,
                     const DarbouxOptions& options);

}  // namespace archgeo
