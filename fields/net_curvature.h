// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — how a net's edges lie against the curvature of the surface it
// samples: conjugacy of a quad net (planar quads discretise conjugate nets
// [Zadravec 2010, §1, §3]), closeness of a quad net to the asymptotic
// directions (A-nets discretise asymptotic nets [Shi 2014, §2.2, §3.2 step
// 1]), and closeness of labelled edges to the principal directions (Pellis
// 2019, §5: principal-symmetric meshes). Used to warn before solving when an
// input is far from what the problem can make buildable (problems/
// suitability.h).
//
// Curvature: the jet-fitted shape tensors of fields/face_curvature.h
// (VertexShapeTensors, on the net's own vertices; any polygon mesh), averaged
// over the vertices of the face (or the edge's two ends) and restricted to
// the tangent plane of the face normal (the cross product of a quad's
// diagonals; for an edge the mean of its faces' normals). II(a, b) = aᵀ S b
// on tangent vectors; κ = max(|k1|, |k2|) of the restricted tensor.
// Faces (edges) whose κ · (bounding-box diagonal) < 1e-6 are flat and not
// measured. All figures are unit-free (ratios, degrees).
//
// A net of more than kSampledQuads quads is measured on an even sample of
// them (the quads at ⌊frac(k φ⁻¹) · quads⌋ in face order, k = 1 ..
// kSampledQuads, φ the golden ratio; a few coincide), with jets fitted only
// at the sampled quads' vertices: the figures are the
// sample's: the mean within about 1/√20,000 ≈ 0.7% of the figure's spread
// (the 317² roof of `archgeo generate --noise 0.05`: conjugacy mean 0.3528
// sampled against 0.3538 on every quad; 1,000²: 0.4139 and 0.4111), the max
// the sample's max. Sampled, its work does not grow with the net.
//
// Per quad with corners p0..p3 the two edge directions are the means of
// opposite edges, u = (p1 − p0 + p2 − p3)/2 and v = (p3 − p0 + p2 − p1)/2:
//   conjugacy  |II(u, v)| / (κ |u| |v|)   (0 for a conjugate net);
//   asymptotic angle: the larger, over u and v, of the angle between the
//     direction and the nearest asymptotic direction (the lines where
//     II(t, t) = 0: at tan²θ = −k1/k2 from the principal direction d1), in
//     degrees; only where K < 0 (elsewhere there is no asymptotic direction,
//     counted in positive_curvature_fraction).
// Per labelled edge t: principal angle, the angle between t and the nearest
// principal direction (0..45°), where the two principal curvatures differ by
// at least 10% of κ (elsewhere the directions are not defined: umbilic).
#pragma once

#include <utility>
#include <vector>

#include "mesh/surface_mesh.h"

namespace archgeo {

constexpr int kSampledQuads = 20000;

struct NetCurvatureFigures {
  int quads = 0;                 // quad faces of the net
  int sampled = 0;               // of those, looked at (all, up to kSampledQuads)
  int measured = 0;              // of those, not flat
  double conjugacy_mean = 0, conjugacy_max = 0;
  int negative_curvature = 0;    // measured quads with K < 0
  double positive_curvature_fraction = 0;  // measured quads with K ≥ 0, of measured
  double asymptotic_angle_mean = 0, asymptotic_angle_max = 0;  // over K < 0 quads
};

NetCurvatureFigures MeasureNetCurvature(const Mesh& net);

struct PrincipalLabelFigures {
  int edges = 0;     // labelled edges
  int measured = 0;  // of those, neither flat nor umbilic
  double angle_mean = 0, angle_max = 0;  // degrees, 0..45
};

// `labels`: vertex index pairs that are edges of `mesh` (others are skipped).
PrincipalLabelFigures MeasurePrincipalLabels(const Mesh& mesh,
                                             const std::vector<std::pair<int, int>>& labels);

}  // namespace archgeo
