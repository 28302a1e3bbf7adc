// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the jumps of level-set functions across a cut graph
// (fields/cuts.h) [Zadravec 2010, §5]: the matching signs s_C of a direction
// field across the cut chains, the constraints the relations g[left] = α_C +
// s_C g[right] impose on the constants α_C at cut junctions, their consistent
// rounding to multiples of the spacing, and the exact projection of
// per-wedge values onto the relations.
//
// Include only where CGAL is acceptable (pulls in mesh/surface_mesh.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "fields/cuts.h"
#include "fields/face_frames.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

// A linear condition Σ coefficient · k_chain = 0 on the jump constants
// (k = α/Δw) that the relations impose: composing the relations around a
// regular vertex where several chains meet must give the identity, and two
// relations that fix the value of one group of wedges (branch points) must
// fix it to the same value.
struct JumpConstraint {
  std::vector<std::pair<int, int>> terms;  // (chain, integer coefficient), nonzero
  VertexIndex vertex;                      // where the relations meet
};

// The constraints for one function whose matching signs per chain are
// `chain_sign` (OrientField). Precondition (CHECKed): one sign ±1 per chain.
std::vector<JumpConstraint> JumpConstraints(const CutGraph& cut,
                                            const std::vector<int>& chain_sign);

// Rounds the jump constants of one function [Zadravec 2010, §5: "rounding the
// constants α_C … to the nearest even (odd) integer multiple of the step
// size"] so that the constraints hold exactly: each constraint's pivot chain
// (coefficient ±1, preferably a chain not from a singularity) is computed
// from the other chains, which are rounded to the nearest multiple of
// `spacing` — chains from a singularity with s_C = −1 to the nearest even
// (parity 0) or odd (parity 1) multiple, chains from a singularity with s_C =
// +1 (a cut that runs on from a singular vertex, or joins two) to the nearest
// even multiple, the others to the nearest multiple. Why: at a singular
// vertex the relations around it give its value as (Σ ±k_C)/2 over its
// chains, and an odd number of them have s_C = −1 (the matching around a
// ±1/2 singularity is −1), so the value is an integer (on a level of both
// functions: the quads-only configuration) for parity 0 and a half-integer
// for parity 1; an odd k on an s_C = +1 chain would flip that. `alpha`, `rounded`
// per chain, function units. Returns false (values still filled) when a
// pivot had to be a singularity chain and came out with another parity, or
// a constraint could not be pivoted (reported in *message).
bool RoundJumps(const CutGraph& cut, const std::vector<int>& chain_sign,
                const std::vector<double>& alpha, double spacing, int parity,
                std::vector<double>* rounded, std::string* message);

// Consistent signs for a face-based direction field on the cut surface.
struct FieldOrientation {
  std::vector<int> face_sign;   // ±1 per face: the oriented direction is sign · d_f
  std::vector<int> chain_sign;  // s_C per chain (majority over its edges)
  int mismatched_cut_edges = 0; // cut edges whose matching differs from their chain's s_C
  int mismatched_edges = 0;     // uncut interior edges across which the signs disagree
};
// `direction`: per face, a tangent vector in the face frame (zero or NaN:
// undefined, the reference is carried through). The signs are propagated by
// breadth-first search through uncut interior edges, choosing for each face
// the sign that makes it agree (positive dot product after transport) with
// the face it is reached from. Preconditions (CHECKed): sizes match.
FieldOrientation OrientField(const Mesh& mesh, const CutGraph& cut,
                             const std::vector<EdgeTransport>& transports,
                             const std::vector<int>& edge_to_transport,
                             const std::vector<Eigen::Vector2d>& direction);

// Consistent signs for the two directions v, w of a conjugate pair field
// (per face, frame coordinates; a face with a zero or NaN v or w is
// undefined). The matching across every edge is taken from the bisector of
// the lines of v and w (fields/conjugate.h BisectorAngle), whose rotation
// defines the field's singularities (fields/singularities.h VertexIndices):
// the bisector is oriented by OrientField, and v, w are oriented at −δ/2 and
// +δ/2 from it (δ ∈ [0, π) the turn from line v to line w). Orienting v and
// w separately by OrientField can disagree with the bisector's index at
// vertices where a direction turns by about 90° between adjacent faces (near
// singularities): a chain from a ±1/2 singularity then gets s_C = +1 for one
// of the functions (no branch point, the quads around it fold) and cut edges
// mismatch their chain. Here s_C and the mismatch counts are the bisector's,
// the same for v and w; δ is single-valued, so the two rotate alike.
// Preconditions (CHECKed): sizes match.
struct PairOrientation {
  FieldOrientation v, w;
};
PairOrientation OrientPair(const Mesh& mesh, const CutGraph& cut,
                           const std::vector<EdgeTransport>& transports,
                           const std::vector<int>& edge_to_transport,
                           const std::vector<Eigen::Vector2d>& v,
                           const std::vector<Eigen::Vector2d>& w);

// Projects per-wedge values of one function, in spacing units (u = g/Δw),
// onto the relations u[left] = k_C + s_C u[right] exactly, k_C = α_C/Δw
// integers: per group of related wedges all values are a + b·x (a integer,
// b = ±1); x is fixed by a branch point (x = k/2) or is the group's mean.
// Returns false with *error set when the relations are inconsistent (the k's
// violate a JumpConstraint); *max_change is the largest change of a value.
// Preconditions (CHECKed): sizes match (values: num_wedges, k and
// chain_sign: one per chain).
bool ProjectOntoJumps(const CutGraph& cut, const std::vector<double>& k,
                      const std::vector<int>& chain_sign, std::vector<double>* values,
                      double* max_change, std::string* error);

}  // namespace archgeo
