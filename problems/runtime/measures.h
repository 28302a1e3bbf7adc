// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the measures a stage logs and its tolerances test, on the
// current state of the store (canonical frame: lengths in input mean edge
// lengths). Measures computed together form a group (one pass):
//
//   pq_normalized_max          max over faces of δ_PQ,n (analysis/metrics.h)
//   flatness_mm                max over faces of the largest distance of a
//                              corner from the face's best-fit plane, in
//                              millimetres through `units` (fabrication/
//                              panels.h; problems/declarations/flatness.h)
//   E, E_prime,                Pellis §3: Σ ℓ ℓ*, Σ ℓ|α|; normal pyramids
//   self_intersecting_pyramids,  and bad saddles (analysis/smoothness_metrics.h)
//   bad_saddles
//   C                          Σ_v |λ1| + |λ2| of W′_v (Pellis §5.3; triangle
//                              meshes; DiscreteTotalAbsoluteCurvature)
//   displacement_max           largest distance of a vertex from its position
//                              at the start of the solve
//   star_planarity_max, _mean  vertex-star planarity (A-nets; geometry/hnet.h
//                              InteriorStarPlanarity)
//   conical_max, _mean         |(ω1 + ω3) − (ω2 + ω4)| (radians) over interior
//                              valence-4 vertices [Liu 2006, §3]
//                              (analysis/goal_metrics.h MeasureConical)
//   face_offset_miss           how far the face planes at an interior vertex,
//                              offset by the mean edge length, miss a common
//                              point, max over vertices / mean edge length
//                              (MeasureFaceOffsets; includes non-planarity)
//   edge_length_spread         max |ℓ/mean − 1| over every edge
//   boundary_spacing_spread    the same over the boundary edges
//   surface_distance_relative, the largest distance of a vertex (and, with a
//   surface_distance           `reference` of its own, a face centroid) from
//                              the reference surface, over the input's
//                              bounding-box diagonal (PrincipalBoxDiagonal)
//                              and in file units (problems/declarations/
//                              design_band.h)
//   force_balance_max          largest resultant force at a free vertex of the
//                              load term's net (vertex loads + the springs of
//                              every edge), over the mean free-vertex load; 0
//                              without a load term (MeasureForceBalance)
//
// A problem adds its own (ProblemDecl::measures).
#pragma once

#include <functional>
#include <map>
#include <string>

#include "mesh/surface_mesh.h"
#include "problems/runtime/model.h"

namespace archgeo {

using MeasureGroup = std::function<std::map<std::string, double>(HookContext&)>;

// The group that computes `name`, or null.
const MeasureGroup* FindMeasureGroup(const std::string& name);

// Σ_v |λ1,v| + |λ2,v| with the exact tangential eigenvalues of
// EvaluateVertexShapeOperator (energies/total_absolute_curvature.h) over the
// `fans` (mesh/elements.h); units: length. Precondition: a triangle mesh.
// [Pellis 2019, §5.3]
double DiscreteTotalAbsoluteCurvature(const Mesh& mesh);

}  // namespace archgeo
