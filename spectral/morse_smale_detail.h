// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the steps of spectral/morse_smale.h shared by its files.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "spectral/morse_smale.h"

namespace archgeo {
namespace morse_smale {

// One separatrix while the complex is built: from a saddle's wedge to an
// extremum, `guide` the path proposed (steepest, or rerouted through
// cancelled pairs).
struct Draft {
  int saddle = 0;  // node index
  bool ascending = true;
  std::vector<int> wedge;  // the ring vertices of its wedge
  std::vector<int> guide;  // vertices, the saddle's first
  int target = 0;          // node index
  bool alive = true;
};

// Replaces the drafts' guides by paths that share no vertex with another
// arc or a node (shortest paths where the guide does not); appends the arcs
// to `complex` and counts rerouted and unresolved ones.
void EmbedArcs(const std::vector<Eigen::Vector3d>& points,
               const std::vector<std::vector<int>>& rings, const std::vector<bool>& node_vertex,
               const std::vector<Draft>& drafts, const std::vector<int>& node_renumber,
               MorseSmaleComplex& complex);

// The cells between the arcs and their check; sets shared_vertices,
// invalid_cells and valid.
void BuildCells(int vertex_count, const std::vector<std::array<int, 3>>& triangles,
                MorseSmaleComplex& complex);

}  // namespace morse_smale
}  // namespace archgeo
