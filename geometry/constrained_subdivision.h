// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — constrained Loop and Catmull–Clark subdivision [Gebreiter 2012, §9]
// on plain arrays (no CGAL):
//  - the standard masks (§9.1.1, Fig. 15): Loop with Warren's β (3/16 for
//    valence 3, 3/(8n) otherwise), Catmull–Clark v' = (n−2)/n·v + Σe/n² + Σf/n²;
//  - boundary and crease curves (§9.2.1): an edge whose two ends are
//    consecutive mesh vertices along a curve is tagged; its new edge point is
//    the curve's arc-length halfway point between its ends' parameters (not
//    a spline parameter), a curve vertex gets the crease mask ⅛·¾·⅛ applied to
//    the arc-length parameters of itself and its two curve neighbours and is
//    placed on the curve there; corners (curve ends, vertices on two curves,
//    kinks sharper than the kink angle) stay fixed. Every curve vertex
//    carries its arc-length parameter through the levels;
//  - or the boundary ring locked (§9.2.2, "boundary vertices and their
//    neighbours are simply locked in place"): the boundary vertices and their
//    neighbours keep their positions, and a new vertex whose parents are all
//    locked is their midpoint (edge) or centroid (face), locked in turn;
//  - tangency to boundary surfaces (§9.2.2, Fig. 17), in the manner of
//    Levin's combined subdivision (standard rules, then a correction towards
//    the boundary condition at every level): a curve vertex b on a boundary
//    surface with unit normal n there moves each interior edge neighbour v
//    by −((v − b)·n) n, so the cross-boundary edges lie in the surface's
//    tangent plane (a neighbour of several such vertices takes the shortest
//    move into all their planes); limit positions get the same correction;
//  - limit positions (§9.1.2): Catmull–Clark (n²v + 4Σe_j + Σf_j)/(n(n+5))
//    [Sharp 2000], Loop v∞ = (1 − nχ)v + χΣv_j, χ = 1/(3/(8β) + n) (the left
//    eigenvector of the 1-ring subdivision matrix, for any β); on curves the
//    cubic B-spline limit (s₋ + 4s + s₊)/6 of the parameters, on a standard
//    boundary (a + 4v + b)/6;
//  - reverse subdivision (§9.2.3, after Lanquetin and Neveu 2009): the
//    coarse connectivity is recovered from the fine mesh (vertex classes
//    old/edge/face), then the coarse positions by linear least squares
//    against the standard masks (standard boundary rules) and, given the
//    curves, the curve rules in arc-length parameters; exact for a mesh
//    subdivided with those rules, the residual reported otherwise.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace archgeo {

// A polygon mesh as arrays: faces are counter-clockwise vertex indices.
struct PolyMesh {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<int>> faces;
};

enum class SubdivisionScheme { kLoop, kCatmullClark };

// How boundary vertices without a curve are treated.
enum class SubdivisionBoundary {
  kStandard,  // crease masks ½·½ and ⅛·¾·⅛; a vertex of one face is a corner
  kLocked,    // the boundary ring locked (see above)
};

// A curve for the subdivision: a polyline measured by arc length.
struct SubdivisionCurve {
  std::vector<Eigen::Vector3d> points;  // ≥ 2 distinct (closed: ≥ 3), no repeat of p_0
  bool closed = false;
  bool boundary = false;  // must run along boundary edges of the mesh
  std::string name;       // for messages, e.g. "curves.obj: curve 2 (line 14)"
};

// Bad input (a curve off the mesh or its boundary, crossing curves, …): the
// message names the curve (its `name`) and the mesh vertices concerned.
class SubdivisionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A boundary surface the subdivided surface meets tangentially: true and the
// unit normal of its tangent plane at `point` when the point lies on it.
using TangentNormal = std::function<bool(const Eigen::Vector3d& point, Eigen::Vector3d* normal)>;

struct SubdivisionOptions {
  SubdivisionScheme scheme = SubdivisionScheme::kLoop;
  SubdivisionBoundary boundary = SubdivisionBoundary::kStandard;
  double tolerance = 1e-6;    // a mesh vertex this close to a curve (× diagonal) is on it
  double kink_degrees = 30;   // a curve vertex turning more than this is a kink
  TangentNormal tangent;      // empty: no boundary surface
};

// How far the subdivided surface's tangent planes turn from the boundary
// surface's along the curves on it (degrees; see Tangency()).
struct TangencyMeasure {
  int vertices = 0;  // curve vertices on the boundary surface
  double max_degrees = 0, mean_degrees = 0;
};

struct ReverseResult {
  PolyMesh coarse;
  double residual_max = 0;  // max over fine vertices of |S·coarse − fine|
  double residual_rms = 0;
  // False when the masks are singular on this connectivity (e.g. Catmull–Clark
  // on a cube: the ±1 pattern of its bipartite vertices subdivides to zero
  // at valence 3), so the coarse positions are one of many exact solutions.
  bool unique = true;
};

class ConstrainedSubdivision {
 public:
  // Tags the mesh against the curves: vertices within tolerance of a curve
  // are moved onto it, consecutive ones along it must be joined by an edge
  // (a boundary edge for a boundary curve). Throws SubdivisionError for a
  // non-finite point, a curve with fewer than two mesh vertices on it (for a
  // boundary curve: boundary vertices), consecutive curve vertices without an
  // edge, a boundary curve along an interior edge, crossing curves, and a
  // Loop mesh with a non-triangle face. Precondition: a valid manifold mesh.
  ConstrainedSubdivision(PolyMesh mesh, std::vector<SubdivisionCurve> curves,
                         SubdivisionOptions options);

  void Step();  // one subdivision level
  int levels() const { return levels_; }
  const PolyMesh& mesh() const { return mesh_; }

  // Limit positions of the current vertices (see above). Catmull–Clark needs
  // an all-quad mesh (any mesh after one level): throws SubdivisionError otherwise.
  std::vector<Eigen::Vector3d> LimitPositions() const;

  // Curve vertices: how many, and the largest distance of one from its curve
  // (closest point on the polyline, computed afresh), in the mesh's units.
  int CurveVertexCount() const;
  double MaxCurveDistance() const { return MaxCurveDistance(mesh_.points); }
  double MaxCurveDistance(const std::vector<Eigen::Vector3d>& points) const;  // e.g. limit positions
  int CornerCount() const;
  // At each curve vertex on the boundary surface (options.tangent): the angle
  // between the surface's tangent plane and the mesh's at `points` (the plane
  // normal to the sum of the incident faces' Newell normals).
  TangencyMeasure Tangency(const std::vector<Eigen::Vector3d>& points) const;
  // Reverse subdivision (§9.2.3) of the current mesh as one subdivided with
  // these curves and options: the coarse curve vertices from the curve
  // rules by least squares in their arc-length parameters, the others from
  // the masks; exact for a mesh this class subdivided (not for limit
  // positions or a tangent surface: their residual is reported). Throws
  // SubdivisionError as ReverseSubdivision.
  ReverseResult Reverse() const;
  // Per vertex: on a curve (1), fixed corner or locked (2), else 0.
  std::vector<int> VertexKinds() const;
  double diagonal() const { return diagonal_; }

 private:
  struct Entry {
    int curve;
    double s;
  };
  struct Curve {
    SubdivisionCurve input;
    std::vector<double> cumulative;  // arc length at each point
    double length = 0;
    Eigen::Vector3d At(double s) const;
    double Interval(double from, double to) const;  // forward arc length from→to
  };
  struct TaggedEdge {
    int from, to, curve;  // from before to along the curve
  };
  void Tag();
  // The correction above on `points` (the current level's positions or their limits).
  void ImposeTangency(std::vector<Eigen::Vector3d>& points) const;

  SubdivisionOptions options_;
  PolyMesh mesh_;
  std::vector<Curve> curves_;
  std::vector<std::vector<Entry>> on_;  // per vertex: curves it lies on
  std::vector<char> fixed_, locked_;
  std::vector<TaggedEdge> tagged_;
  double diagonal_ = 1;
  int levels_ = 0;
};

// One step of the standard (unconstrained, standard boundary) masks.
PolyMesh SubdivideStandard(const PolyMesh& mesh, SubdivisionScheme scheme);


// Reverse subdivision: the coarse mesh whose standard subdivision is closest
// to `fine` in least squares. Throws SubdivisionError if `fine` does not have
// the connectivity of a subdivided mesh of `scheme`.
ReverseResult ReverseSubdivision(const PolyMesh& fine, SubdivisionScheme scheme);

}  // namespace archgeo
