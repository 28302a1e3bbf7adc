// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — node axes and beams of a panel mesh's support structure.
//
// A node's axis is its area-weighted vertex normal (the sum of its faces'
// Newell vectors, core/newell.h, normalised), except where the mesh is
// conical: at an interior vertex of four faces whose conical residual
// |(ω1 + ω3) − (ω2 + ω4)| is within `cone_bound` the four face planes touch
// a cone of revolution with its apex at the vertex [Liu et al. 2006, §3],
// and the axis is that cone's: the unit a with a·n_f equal for the four unit
// face normals n_f (the normal of the plane through their tips, by least
// squares), turned to agree with the vertex normal. Then every face plane
// makes the same angle with the axis, and the faces offset by d meet on it
// at v + d / cos(φ) a, cos φ = a·n_f (the face offset [Liu 2006; Pottmann
// et al. 2007, "Geometry of multi-layer freeform structures"]).
//
// A beam on edge (v0, v1) is centred on the plane through the edge spanned
// by the mean of its end axes; its twist is the angle between the planes
// spanned by the edge and each end's axis (0: the two axes are coplanar
// with the edge, as at the cone axes of a conical mesh, which both lie in
// the bisector plane of the edge's two faces).
//
// A beam of depth d (signed: along the axes, the side the face normals point
// to) ends at each node on its axis, at the point of it nearest (least
// squares) to every incident face plane offset by d: v + t a with
// t = d Σ(a·n_f) / Σ(a·n_f)². At a cone node that is v + d / cos(φ) a, where
// the offset planes meet exactly, so a conical mesh's beam ends form its
// face offset; elsewhere FaceOffsetError says how far they are from it.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "fabrication/plain_mesh.h"

namespace archgeo {

struct NodeAxis {
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();    // unit
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // the area-weighted vertex normal
  bool cone = false;                                 // axis is the cone's
  double conical = -1;  // the conical residual (radians; −1 where not a 4-face interior vertex)
  double offset_factor = 0;  // cone: 1 / cos φ (the face offset by d meets the axis at
                             // v + d · factor · axis); 0 elsewhere
};

// `mesh` with vertex_faces and boundary filled; `cone_bound` ≤ 0: no cone axes.
std::vector<NodeAxis> NodeAxes(const PlainMesh& mesh, double cone_bound);

struct Beam {
  int v0 = 0, v1 = 0;
  double length = 0;
  Eigen::Vector3d plane_normal = Eigen::Vector3d::Zero();  // unit, ⟂ the edge
  double twist_degrees = 0;
  // The beam's far edge at depth d (Beams' `depth`; the nodes when 0).
  Eigen::Vector3d offset0 = Eigen::Vector3d::Zero(), offset1 = Eigen::Vector3d::Zero();
};

// Each node moved along its axis to depth `depth` (see above).
std::vector<Eigen::Vector3d> OffsetNodes(const PlainMesh& mesh, const std::vector<NodeAxis>& nodes,
                                         double depth);

// The largest |n_f·(o_v − v) − depth| over the faces f and their corners v
// (unit normals n_f): how far the offset nodes `offsets` are from the face
// planes offset by `depth` (0 for a face offset).
double FaceOffsetError(const PlainMesh& mesh, const std::vector<Eigen::Vector3d>& offsets,
                       double depth);

// One per mesh.edges entry, from NodeAxes' axes; far edges at `depth`.
std::vector<Beam> Beams(const PlainMesh& mesh, const std::vector<NodeAxis>& nodes,
                        double depth = 0);

}  // namespace archgeo
