// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — quality metrics, printed in every report and by `archgeo measure`.
#pragma once

#include <array>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesh/surface_mesh.h"

namespace archgeo {

class ReferenceSurface;

// Per-face planarity, indexed by face index (0 for triangles).
//  quads:   distance between the diagonal lines [Zadravec 2010, §6 diag_f];
//           normalised = that / mean diagonal length of the face (δ_PQ,n);
//           warp = that / shortest edge [Gebreiter 2012, §11.7.2].
//  n-gons (n > 4): max distance of a vertex from the least-squares plane,
//           normalised by the mean length of the diagonals (i, i+2),
//           warp by the shortest edge.
struct PlanarityMeasure {
  std::vector<double> distance, normalized, warp;
};
PlanarityMeasure MeasureFacePlanarity(const Mesh& mesh);

// Face colours for δ_PQ,n: green at 0 to red at `red_at` and above (Zadravec Fig. 1).
std::vector<std::array<unsigned char, 3>> PlanarityColors(const PlanarityMeasure& planarity,
                                                         double red_at = 0.01);

// All lengths in file units. Reference-based entries are -1 without a
// reference, displacement entries are -1 without an original of the same
// vertex count.
struct Metrics {
  int vertices = 0, faces = 0, triangles = 0, quads = 0, polygons = 0;  // polygons: > 4 sides
  // The unit of every "_relative" value: the diagonal of the bounding box
  // aligned with the principal axes of the vertices (mesh/similarity.h), so
  // it does not change when the mesh is rotated; aabb_diagonal is the
  // axis-aligned one (within 1% of it on 8 of the 9 meshes in
  // ../shared/data, 3% on the botanic bubble).
  double bbox_diagonal = 0, aabb_diagonal = 0, mean_edge_length = 0;
  double pq_max = 0, pq_mean = 0;                        // δ_PQ over quads (and n-gons)
  double pq_normalized_max = 0, pq_normalized_mean = 0;  // δ_PQ,n
  double warp_max = 0, warp_mean = 0;
  double prox_max = -1;           // δ_prox: interior vertices (all if the reference is
                                  // closed) to the tangent plane at π(v)
  double boundary_prox_max = -1;  // δ∂_prox: boundary vertices to the tangent line at π̃(v)
  double surface_distance_max = -1, surface_distance_mean = -1;  // vertices to the reference
  double hausdorff = -1;          // symmetric Hausdorff distance to the reference (sampled)
  double displacement_max = -1, displacement_mean = -1;  // vertices vs the original
};

struct MetricsOptions {
  bool hausdorff = true;  // the one expensive entry; off for very large meshes
};

Metrics ComputeMetrics(const Mesh& mesh, const ReferenceSurface* reference, const Mesh* original,
                       const MetricsOptions& options = {});

// `m` with every length multiplied by `factor`: the metrics of a mesh
// measured in a frame whose unit is `factor` file units (mesh/similarity.h
// LocalFrame), in file units. Entries that are -1 (not computed) stay -1.
Metrics ScaleLengths(Metrics m, double factor);

// JSON object: every entry in file units, and for lengths also
// "<name>_relative" = value / `scale` (normally the input's bbox diagonal).
// Entries that are -1 (not computed) are written as null.
nlohmann::json MetricsToJson(const Metrics& metrics, double scale);

}  // namespace archgeo
