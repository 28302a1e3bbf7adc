// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — folded panels of an extracted quad mesh unfolded on the design
// surface.
//
// A chart's base edges are shortest paths along the design mesh's edges: at a
// node where they leave unevenly (two of a valence-3 node's three edges
// nearly opposite), the quad between them has a corner of 180° or more
// after extraction, and RelaxQuads (quad_relax.h), which never lets a
// convex corner bend, cannot open it. UntangleQuads does, by the local
// optimisation of mesh untangling (Freitag and Plassmann 2000). Each movable
// vertex in turn (interior and of valence 4, one of `centres`, or with
// `move_irregular` any interior vertex) goes to the point of its tangent
// plane, mapped onto the design surface, that maximises the worst corner of
// the quads round it — a corner's quality min(θ, 180° − θ), θ its interior
// angle in the plane of the quad's normal (as validity measures it), −180°
// for a quad facing away from the surface's normals at its corners — by a
// compass search (16 directions) from half its mean edge down to 1/256 of
// it. A
// move is kept only when that worst corner improves, no edge at the vertex
// falls below half its length as given or a quarter of the mean edge
// (an edge shorter than that as given: below its length), and the quads round the vertex and
// its neighbours do not wrap round them twice. Two steps, only when some
// quad is bent: the vertices within two rings of the bent quads until none
// is (or no move helps), then those round the quads with a corner within
// 10° of 0° or 180°, that step undone if it leaves more quads bent. The
// boundary and the connectivity stay; irregular vertices stay unless
// `move_irregular` (a base complex's nodes placed by a function's critical
// points, not by the designer).
#pragma once

#include <array>
#include <functional>
#include <vector>

#include <Eigen/Core>

namespace archgeo {

struct UntangleResult {
  int bent_before = 0;  // quads with a corner bent inward (or turned over)
  int bent_after = 0;
  int moves = 0;        // vertex moves kept
};

// The design surface's closest point to a point, and its unit normal there.
struct SurfaceSample {
  Eigen::Vector3d point, normal;
};

// `onto` samples the design surface; `centres`: irregular vertices that may
// move in any case (−1 entries ignored).
UntangleResult UntangleQuads(const std::vector<std::array<int, 4>>& quads,
                             const std::function<SurfaceSample(const Eigen::Vector3d&)>& onto,
                             std::vector<Eigen::Vector3d>* points, const std::vector<int>& centres,
                             bool move_irregular);

}  // namespace archgeo
