// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — evenly spaced streamlines and separatrices of the two families of
// a conjugate (TCD) field on a triangle mesh [Gebreiter 2012, §8.2 "Streamline
// trace", §8.1.3 (asymptotic directions of a singularity after Tricoche 2002)];
// the field is the per-face pair (v, w) of [Zadravec 2010, §2–3]; the seeding
// is Jobard & Lefer's (1997): a separation d_sep and a test distance d_test.
//
// Plain Eigen and std (no CGAL): the mesh comes as arrays
// (fields/field_io.h StreamlineInputOf converts a Mesh and its TcdField).
//
// The field each family is traced in: per vertex the line of the family,
// the dominant eigenvector of Σ_f A_f d_f d_fᵀ over the incident faces (a
// sign-free average), and inside a face the barycentric blend of its three
// corner lines, each corner taking the family (v or w) closest to the face's
// own direction of the traced family and the sign closest to the direction
// of travel; RK4 steps of length h = step·d_sep in the face plane. A step that
// leaves its face is cut at the edge it crosses (the exact crossing of the
// step's chord) and the direction carried into the next face by the rotation
// about the shared edge (unfolding, the frame transport of
// fields/face_frames.h); there the family whose line (v or w, either sign) is
// closest to the carried direction continues the line (near a singularity v
// and w can exchange labels).
//
// A line stops: at the boundary; on a face without a pair; within r_s =
// d_test of a singular vertex (a separatrix then ends at the vertex); when
// its next step would come closer than d_test to a line of its family (the
// segment distance, so no part of two lines of a family is closer than
// d_test) or to its own earlier part (more than 3 d_test back along it): near
// its own start a line is closed (a loop), elsewhere it stops (it never crosses
// itself); or at the length cap.
//
// Seeds (Jobard & Lefer): every d_sep/4 along each traced line, a point
// d_sep to either side along the surface (a straight walk across faces,
// perpendicular to the line); a seed is traced both ways when no line of its
// family is within 0.9 d_sep of it (the walk's chord is shorter than d_sep on
// a curved surface); the separatrices are the first lines, and face centroids
// far from every line start the lines of regions the queue does not reach.
//
// Separatrices (Tricoche, Gebreiter §8.1.3: "the angles to those points on
// the triangle edges where the vector field is approaching the singularity
// asymptotically"): around a singular vertex p, for each family, the angle
// ψ = θ − φ between the field's line and the radial direction is followed
// through the ring of faces (θ is constant in a face, so ψ falls there; it
// jumps between faces by the smallest rotation). Around a singularity of
// index k a line field turns by 2πk while the radial direction turns by 2π:
// ψ changes by 2π(k − 1), and the radial lines, ψ ≡ 0 (mod π), number
// 2|1 − k| (k = +1/2: one, k = −1/2: three, a trisector; k = −1: four;
// k = +1: none but the degenerate node). A piecewise-constant field wiggles
// about the radial direction and crosses it more often: adjacent crossings of
// opposite sense are removed in pairs, the closest first, which leaves
// exactly the 2|1 − k| the discrete turning gives. Each separatrix leaves p
// along its radial direction (its first step straight) and is traced
// forward like a streamline; one that reaches another singularity ends at
// its vertex.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace archgeo {

struct StreamlineInput {
  std::vector<Eigen::Vector3d> points;      // vertex positions
  std::vector<std::array<int, 3>> triangles;  // corner vertices, counter-clockwise
  // Per face: unit v, w in the face plane (3-D) and whether the face has a pair.
  std::vector<std::array<Eigen::Vector3d, 2>> directions;
  std::vector<bool> valid;
  struct Singular {
    int vertex = 0;
    double index = 0;  // ±1/2, ±1, …
  };
  std::vector<Singular> singularities;
};

struct StreamlineOptions {
  double separation = 0;   // d_sep (mesh units, > 0)
  double test_ratio = 0.5;  // d_test = test_ratio · d_sep, in (0, 1]
  double step = 0.1;        // RK4 step as a fraction of d_sep
  bool separatrices = true;
  double max_length = 0;    // per line; 0: 10 × the bounding-box diagonal
};

struct Streamline {
  int family = 0;           // 0: v, 1: w (the family it starts in)
  bool separatrix = false;
  int singularity = -1;     // a separatrix: its singularity (index into the input's list)
  bool closed = false;      // a loop: the last point joins the first
  std::vector<Eigen::Vector3d> points;
  double length = 0;
};

struct StreamlineResult {
  std::vector<Streamline> lines;
  // Per input singularity and family: the separatrix directions found.
  std::vector<std::array<int, 2>> separatrix_directions;
  double d_sep = 0, d_test = 0;
};

// Preconditions (CHECKed): sizes match, indices in range, options in range.
StreamlineResult TraceStreamlines(const StreamlineInput& input, const StreamlineOptions& options);

// Measured on the output: the smallest distance between two lines of the same
// family (segment to segment), pairs of separatrices excepted (they meet at
// their singularities); +inf when there is no pair.
double SmallestSeparation(const std::vector<Streamline>& lines, double cell);
// The smallest distance between two segments of one line more than `window`
// apart along it (cyclically for a closed line); +inf when there are none.
double SmallestSelfDistance(const std::vector<Streamline>& lines, double window, double cell);

// The number of separatrix directions of a line field around a singularity of
// index k (the radial directions, see above): 2|1 − k|; −1 for k = 1 (none
// generically, every direction for a radial node).
int ExpectedSeparatrices(double index);

}  // namespace archgeo
