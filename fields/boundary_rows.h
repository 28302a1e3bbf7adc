// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — boundary-aligned rows: one family of layout lines runs along the
// boundary of an open surface: the boundary held on a level of one of the two
// level-set functions [Gebreiter 2012, §8.3.2, after Zhang et al. 2010:
// boundary vertices take an iso-value], with the jumps across the cuts of
// [Zadravec 2010, §5] (g_left = α_C + s_C g_right, α_C a multiple of Δw).
//
// Method (BoundaryRowLevels):
//  1. Each boundary edge takes the family whose direction runs along it in
//     the face across: g (level sets along v) when |sin∠(t, v)| ≤ |sin∠(t, w)|,
//     else h. The field is solved with the boundary tangent as a strongly
//     weighted prescribed direction, so one of v, w is along every boundary
//     edge; the family changes at the boundary's corners (a turn of about
//     the angle between v and w) and where the boundary runs along an
//     asymptotic direction of a saddle (there the conjugate pair closes:
//     v and w are both along the boundary, and the one that follows it
//     changes). Runs of fewer than three edges join their neighbours (the
//     choice flickers where both directions are near the tangent); the loop
//     is cut into runs where the family changes. Corners (a turn above
//     corner_angle_deg, the rule of fields/extract.h) are counted; the
//     extraction keeps them as layout vertices.
//  2. Along a run the function is one constant: the two corners of a boundary
//     face on the boundary edge share the value, and at a boundary vertex
//     where cut chains end (fields/cuts.h), its wedges take the values the
//     jump relations g[left] = α_C + s_C g[right] give, with the rounded α_C.
//     So every wedge of the run is a + b·x (a a sum of α's, b = ±1) in the
//     value x of its first wedge.
//  3. x is the least-squares fit to the current values (x = mean of b(g − a)),
//     rounded to the nearest multiple of the spacing: the boundary is a level
//     of the layout, every wedge value a multiple of the spacing. A closed run
//     (a loop without a family change) whose relations around the loop give
//     x = a + x with a ≠ 0 cannot be one level and is skipped (counted); one
//     giving x = a − x fixes x = a/2, taken when that is a level.
// The caller holds these values constant (a hard constraint of the
// level-set solve); the layout's boundary faces are then the cells between
// the boundary level and the next, quads with a full edge on the boundary.
//
// Include only where CGAL is acceptable (pulls in mesh/surface_mesh.h).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "fields/cuts.h"
#include "fields/face_frames.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

// One wedge value held on the boundary: function 0 = g, 1 = h.
struct BoundaryLevel {
  int function = 0;
  int wedge = -1;
  double value = 0.0;  // function units, a multiple of that function's spacing
};

struct BoundaryRows {
  std::vector<BoundaryLevel> fixed;
  int loops = 0;
  int corners = 0;        // boundary vertices turning by more than the corner angle
  int runs_g = 0, runs_h = 0;  // runs held constant, per family
  int skipped_runs = 0;   // runs not held: no one level, or beyond max_shift
  double max_shift = 0.0; // largest |held − solved| value, in spacings
  // The angle between each boundary edge of a held run and its family's
  // direction in the face across (degrees): how well the field follows the
  // boundary there.
  int edges = 0;
  double angle_mean_deg = 0.0, angle_max_deg = 0.0;
};

// The level-set functions at the moment of rounding, per wedge / chain.
struct WedgeFunctions {
  const std::vector<double>* values[2] = {nullptr, nullptr};  // g, h per wedge
  const std::vector<double>* alpha[2] = {nullptr, nullptr};   // rounded α per chain
  const std::vector<int>* sign[2] = {nullptr, nullptr};       // s_C per chain
  double spacing[2] = {1.0, 1.0};                             // Δw_g, Δw_h > 0
};

// `v`, `w`: the oriented pair per face in the face's frame (zero where
// undefined; an edge whose face has none ends its run and is not held).
// `max_shift`: a run whose held values would differ from the current ones by
// more than this many spacings is not held (the level sets do not follow the
// boundary there; holding it would bend every row beside it). Preconditions (CHECKed): sizes match the mesh and the cut.
BoundaryRows BoundaryRowLevels(const Mesh& mesh, const CutGraph& cut, const FaceFrames& frames,
                               const std::vector<Eigen::Vector2d>& v,
                               const std::vector<Eigen::Vector2d>& w,
                               const WedgeFunctions& functions, double corner_angle_deg,
                               double max_shift);

// The boundary edges of the runs of step 1 (without holding anything): per
// edge its border halfedge and the family (0 = g, 1 = h) whose level sets
// run along it; edges without a field are left out.
struct BoundaryRowEdge {
  HalfedgeIndex border;
  int function = 0;
};
std::vector<BoundaryRowEdge> BoundaryRowEdges(const Mesh& mesh, const FaceFrames& frames,
                                              const std::vector<Eigen::Vector2d>& v,
                                              const std::vector<Eigen::Vector2d>& w);

// How a layout meets its boundary: faces with a vertex on the boundary, and
// among them the quads with at least one whole edge on the boundary.
struct BoundaryFaceCounts {
  int boundary_faces = 0;
  int quads_on_boundary = 0;
  double fraction() const {
    return boundary_faces > 0 ? double(quads_on_boundary) / boundary_faces : 1.0;
  }
};
BoundaryFaceCounts CountBoundaryFaces(const Mesh& layout);

}  // namespace archgeo
