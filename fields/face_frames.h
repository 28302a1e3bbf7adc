// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — per-face orthonormal frames of a triangle mesh and the frame
// transport between adjacent faces (the discrete Levi-Civita connection).
//
// [Zadravec 2010, §2 "Data structure for the conjugacy relation"]: every face
// f carries a frame (e1,f, e2,f = n_f × e1,f) with e1,f the normalised value of
// a smooth "basis" vector field b found by prescribing b in one face and
// minimising a Dirichlet energy [FSDH07]. We do the same with the face-based
// discrete Dirichlet energy of a tangent vector field,
//   E(b) = Σ_{interior edges e = (f, g)} w_e |b_f − T_e b_g|²,
// T_e the transport below, w_e = ℓ_e / d_e (ℓ_e the edge length, d_e the
// distance between the two face centroids after unfolding g onto f's plane);
// b = (1, 0) in the first face of every connected component (its first edge
// direction), a sparse linear solve (Eigen SimplicialLDLT) for the rest.
// Faces where b vanishes (|b_f| < 1e-9 max|b|; closed surfaces must have such
// zeros) fall back to their first edge direction.
//
// Every quantity built on the frames in archgeo is frame-independent once the
// transport is used (see fields/conjugate.h on spin-2 quantities), so the
// frame's smoothness is a convenience (readable per-face coordinates, small
// transport angles), not a requirement.
//
// Include only where CGAL is acceptable (pulls in mesh/surface_mesh.h).
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "mesh/surface_mesh.h"

namespace archgeo {

// Per-face data, indexed by face index (the mesh must have no garbage).
struct FaceFrames {
  std::vector<Eigen::Vector3d> e1, e2;     // orthonormal, in the face plane
  std::vector<Eigen::Vector3d> normal;     // unit, right-handed: e2 = n × e1,
                                           // counter-clockwise face orientation
  std::vector<Eigen::Vector3d> centroid;
  std::vector<double> area;
  int fallback_faces = 0;                  // faces where b vanished (see above)
};

// Frame transport across one interior edge.
struct EdgeTransport {
  EdgeIndex edge;
  FaceIndex f;  // face(halfedge(edge, 0))
  FaceIndex g;  // face(halfedge(edge, 1))
  // τ_fg: after unfolding g onto f's plane by the rotation about the shared
  // edge that maps n_g to n_f, a tangent vector at angle α in g's frame has
  // angle α + τ_fg in f's frame (τ_gf = −τ_fg). In (−π, π].
  double angle = 0.0;
  // w_e = ℓ_e / d_e (dimensionless; the weight of the face-based Dirichlet
  // energy, which then approximates ∫|∇b|² dA).
  double weight = 0.0;
};

// Smooth frames (see the file comment). Precondition (CHECKed): a pure
// triangle mesh without garbage, no face of zero area.
FaceFrames ComputeSmoothFrames(const Mesh& mesh);

// Frames from the first edge of each face (e1 = unit(p1 − p0)): not smooth;
// used for tests of frame independence and as the initial frames of the solve.
FaceFrames ComputeEdgeFrames(const Mesh& mesh);

// Transport for every interior edge, indexed densely (one entry per interior
// edge, in edge-index order); `edge_to_transport` (optional) receives, per
// edge index, the entry index or −1 for a boundary edge.
std::vector<EdgeTransport> ComputeTransports(const Mesh& mesh, const FaceFrames& frames,
                                             std::vector<int>* edge_to_transport = nullptr);

// The angle that maps g's frame to f's frame for an ordered pair of faces
// (τ_fg of the entry, or −τ for the reversed pair). CHECKs that the entry
// joins f and g.
double TransportAngle(const EdgeTransport& t, FaceIndex from_g, FaceIndex to_f);

// Corners of face f in its own frame, relative to its centroid, in the order
// of the corner halfedges h0 = halfedge(f), h1 = next(h0), h2 = next(h1)
// (corner k is the vertex target(h_k)); counter-clockwise, so the signed area
// is positive.
std::array<Eigen::Vector2d, 3> FaceCorners2D(const Mesh& mesh, const FaceFrames& frames,
                                             FaceIndex f);

// A 3-D tangent vector of face f in f's frame coordinates, and back.
Eigen::Vector2d ToFrame(const FaceFrames& frames, FaceIndex f, const Eigen::Vector3d& x);
Eigen::Vector3d FromFrame(const FaceFrames& frames, FaceIndex f, const Eigen::Vector2d& x);

}  // namespace archgeo
