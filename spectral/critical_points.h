// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the discrete critical points of a function on a mesh's vertices
// (Gebreiter 2012, §7.1.2; Edelsbrunner et al. 2001): a vertex is a maximum
// (minimum) when every neighbour is lower (higher); around an interior
// vertex's ordered one-ring the sign of f(u) − f(v) changes 2m times, and
// m ≥ 2 makes it a saddle of multiplicity m − 1 (a multi-saddle for m > 2).
// Ties are broken by vertex index (symbolic perturbation), so every vertex is
// classified. A boundary vertex is classified on the surface doubled across
// its boundary (the Neumann boundary of the Laplacians makes eigenfunctions
// symmetric there): its open fan of c sign changes mirrored gives 2c, so
// c = 0 is an extremum and c ≥ 2 a saddle of multiplicity c − 1 of the
// double. On the double interior points count twice and boundary points
// once, so max + min − saddles = χ with boundary points counted half
// (EulerSum); on a closed surface the plain count.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace archgeo {

struct CriticalPoints {
  int maxima = 0, minima = 0;
  int saddles = 0;        // counted by multiplicity
  int multi_saddles = 0;  // vertices of multiplicity ≥ 2
  // On the boundary (of the doubled surface, see above).
  int boundary_maxima = 0, boundary_minima = 0, boundary_saddles = 0;

  // max + min − saddles, boundary points counted half: χ of the surface.
  double EulerSum() const {
    return maxima + minima - saddles +
           0.5 * (boundary_maxima + boundary_minima - boundary_saddles);
  }
};

// `rings[v]`: v's neighbours in cyclic order (a boundary vertex's from one
// boundary neighbour to the other); `closed[v]`: whether that ring closes.
CriticalPoints FindCriticalPoints(const std::vector<std::vector<int>>& rings,
                                  const std::vector<bool>& closed, const Eigen::VectorXd& f);

}  // namespace archgeo
