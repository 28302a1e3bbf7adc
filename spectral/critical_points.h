// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the discrete critical points of a function on a mesh's vertices
// (Gebreiter 2012, §7.1.2; Edelsbrunner et al. 2001): a vertex is a maximum
// (minimum) when every neighbour is lower (higher); around an interior
// vertex's ordered one-ring the sign of f(u) − f(v) changes 2m times, and
// m ≥ 2 makes it a saddle of multiplicity m − 1 (a multi-saddle for m > 2).
// Ties are broken by vertex index (symbolic perturbation), so every vertex is
// classified. On a closed surface #max + #min − #saddles = χ.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace archgeo {

struct CriticalPoints {
  int maxima = 0, minima = 0;
  int saddles = 0;        // counted by multiplicity
  int multi_saddles = 0;  // vertices of multiplicity ≥ 2
};

// `rings[v]`: v's neighbours in cyclic order; `closed[v]`: whether that ring
// closes (an interior vertex). Boundary vertices are not classified.
CriticalPoints FindCriticalPoints(const std::vector<std::vector<int>>& rings,
                                  const std::vector<bool>& closed, const Eigen::VectorXd& f);

}  // namespace archgeo
