// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the integrated start of the standing wave of `wave_quads`: the
// guidance and size fields integrated along a breadth-first spanning tree
// of the edges [Gebreiter 2012, §8.3.5; Zhang et al. 2010 start from the
// field's integration]. From f_root = (cos θ cos φ, cos θ sin φ, sin θ cos φ,
// sin θ sin φ) each tree edge sets its far end so that its transfer residual
// (energies/wave_transfer.h) is zero; the residuals that remain are those of
// the edges off the tree, where the integration's paths meet (the field's
// curl and singularities, the size fields' discretisation).
#pragma once

#include <vector>

#include "core/elements.h"

namespace archgeo {

// `edges` the element set wave_edges (energies/wave_elements.h) over
// `vertices` vertices; returns 4 doubles per vertex. Vertices the tree does
// not reach (another component) start from the same f_root.
std::vector<double> IntegratedWave(const ElementSet& edges, int vertices, int root, double theta,
                                   double phi);

// The start the restarts keep (1-based): of those whose complex is valid the
// one of lowest energy; 0 when none is valid (the caller then keeps the
// start of lowest energy, whose complex is reported as not valid).
int KeptWaveStart(const std::vector<bool>& valid, const std::vector<double>& energy);

}  // namespace archgeo
