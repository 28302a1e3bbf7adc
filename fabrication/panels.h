// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — what a façade contractor needs of one panel: its best-fit
// plane, flatness, area, edge lengths, corner angles and diagonals, and its
// outline flattened into that plane for cutting. Lengths in the mesh's
// unit; no CGAL (corners as Eigen vectors).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace archgeo {

// The least-squares plane of a panel's corners: through their centroid,
// normal = the eigenvector of the smallest eigenvalue of their scatter
// matrix (it minimises Σ distance²), turned to agree with the corners'
// Newell normal (core/newell.h), so it points to the side the face's
// orientation does. Precondition: ≥ 3 corners.
struct BestFitPlane {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};
BestFitPlane FitPlane(const std::vector<Eigen::Vector3d>& corners);

// max_k |n·(p_k − c)|: the largest distance of a corner from the best-fit
// plane (0 for a triangle and for any planar panel).
double PanelFlatness(const std::vector<Eigen::Vector3d>& corners);

// One panel, corners p_0..p_{n−1} in face order; edge k joins p_k and p_{k+1}.
struct PanelGeometry {
  BestFitPlane plane;
  double flatness = 0;           // PanelFlatness
  double flatness_relative = 0;  // flatness / mean diagonal length (0 without diagonals)
  double area = 0;               // |Newell vector| / 2: exact for a planar panel
  std::vector<double> edges;     // |p_{k+1} − p_k|
  // Interior angle at p_k in degrees: the 3D angle between its two edges,
  // 360° minus it where the corner turns against the best-fit normal (reflex).
  std::vector<double> angles;
  // |p_i − p_j| for every pair of corners that are not neighbours, i < j in
  // order (a quad: p0p2, p1p3).
  std::vector<double> diagonals;
  // Largest |ℓ' − ℓ| / ℓ over the edges, ℓ' the edge's length projected
  // onto the best-fit plane (0 for a planar panel).
  double projection_change = 0;
};
PanelGeometry MeasurePanel(const std::vector<Eigen::Vector3d>& corners);

// The panel developed into its best-fit plane: the triangles of the fan
// from p_0 laid flat one after the other with their true side lengths, each
// on the side its projection lies, then moved rigidly onto the projected
// corners (least squares). The outline keeps every edge length and the
// diagonals from p_0; the other diagonals and the corner angles differ
// from the 3D panel's by as much as the panel is not planar (`change`).
// Corner k of the outline is p_k; coordinates in the plane's frame
// (x along the projected first edge, y = normal × x), seen from the side
// the normal points to (counter-clockwise for a convex panel).
struct FlatOutline {
  std::vector<Eigen::Vector2d> corners;
  // Largest |d' − d| / d over every pair of corners, d' in the outline
  // (0 up to rounding for a planar panel).
  double change = 0;
};
FlatOutline FlattenPanel(const std::vector<Eigen::Vector3d>& corners);

// One row of the panel table (output.panels).
struct PanelRecord {
  int face = 0;               // the face's index in the mesh file
  std::vector<int> vertices;  // its vertex ids, in order
  PanelGeometry geometry;
  double outline_change = 0;  // FlatOutline::change
  double pq_normalized = 0;   // δ_PQ,n of the face (analysis/metrics.h; 0 for a triangle)
  std::vector<std::pair<std::string, bool>> meets;  // tolerance key → whether the panel meets it
};

}  // namespace archgeo
