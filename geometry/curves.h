// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — curves for the goal library: polylines read from OBJ `l` records
// or given as points, closest point with arc length and tangent, the
// boundary loops of a mesh, and Catmull-Rom resampling.
//
// A polyline here is a list of distinct consecutive points; a closed one does
// not repeat its first point. energies/on_curve.h takes the same points as
// flat coordinates (Coordinates below) in a CurvePolyline.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "mesh/surface_mesh.h"

namespace archgeo {

struct Polyline {
  std::vector<Vec3> points;  // p_0 … p_{m−1}; m ≥ 2 (closed: m ≥ 3)
  bool closed = false;       // a segment p_{m−1} p_0 closes the curve
};

// Validates user-given points: every coordinate finite, consecutive equal
// points merged into one (also the last and first of a closed curve, so
// "p_0 … p_0" is accepted as closed), then at least 2 distinct points
// (closed: 3). Throws InputError(file, line, key, message) naming the point
// (0-based) otherwise; file/line/key are where the points came from (e.g. a
// YAML list), "" / 0 when unknown.
Polyline MakePolyline(const std::vector<Vec3>& points, bool closed, const std::string& file = "",
                      int line = 0, const std::string& key = "");

// The polylines of an ASCII OBJ file, one per `l` record, in file order.
// `v x y z [...]` records give the points (extra numbers, e.g. w or colours,
// are ignored); `l i j k …` lists 1-based vertex indices (negative: relative
// to the last `v` before the record, −1 = that vertex; "i/vt" forms use i).
// A record whose last index equals its first is a closed polyline. Other
// records (f, vn, vt, o, g, …) are ignored; '#' starts a comment. A curve
// exported as separate 2-point `l` records stays that many polylines (join
// it in the CAD tool first).
// Throws InputError naming `path` and the 1-based line for: a malformed or
// non-finite `v`, an index that is not an integer, is 0 or out of range, an
// `l` record with fewer than 2 distinct points (closed: 3), no `l` record;
// and (without a line) for a file that cannot be read.
std::vector<Polyline> ReadPolylines(const std::string& path);

// Total length (including the closing segment of a closed polyline).
double PolylineLength(const Polyline& polyline);

// Flat coordinates x0 y0 z0 x1 … for energies/on_curve.h CurvePolyline.
std::vector<double> Coordinates(const Polyline& polyline);

// Closest points on one polyline (CGAL AABB tree of its segments).
class PolylineLocator {
 public:
  // Precondition (CHECKed): a valid polyline (as MakePolyline returns).
  explicit PolylineLocator(const Polyline& polyline);
  ~PolylineLocator();
  PolylineLocator(PolylineLocator&&) noexcept;

  struct Location {
    Vec3 point;         // the closest point of the polyline
    double arc_length;  // its arc length from p_0, in [0, length]
    Vec3 tangent;       // unit direction of its segment (p_i → p_{i+1})
    int segment;        // i (closed: m − 1 is the closing segment)
    double distance;    // |query − point|
  };
  Location Closest(const Vec3& query) const;
  double length() const;
  const Polyline& polyline() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The boundary loops of `mesh` as vertex cycles, each in the direction of its
// border halfedges (for a consistently oriented disc the outer loop runs
// clockwise about the faces' normals), starting at its smallest vertex index;
// loops sorted by length (longest first, so loop 0 is usually the outer
// perimeter), ties by smallest vertex index. Empty for a closed mesh.
std::vector<std::vector<VertexIndex>> BoundaryLoops(const Mesh& mesh);

// The closed polyline through the positions of `loop` (MakePolyline: equal
// consecutive positions are merged; InputError if fewer than 3 remain).
Polyline LoopPolyline(const Mesh& mesh, const std::vector<VertexIndex>& loop);

// Centripetal Catmull-Rom spline through the points [Yuksel, Schaefer,
// Keyser 2011], sampled with `samples_per_segment` points per segment
// (p_i included, p_{i+1} starting the next one): the result passes through
// every p_i, is C¹ between them, and its polyline's turning angle per sample
// shrinks with the sample spacing. Open ends use reflected phantom points
// p_{−1} = 2p_0 − p_1, p_m = 2p_{m−1} − p_{m−2}. Preconditions (CHECKed):
// a valid polyline; samples_per_segment ≥ 1 (1 returns the points).
Polyline SampleCatmullRom(const Polyline& polyline, int samples_per_segment);

}  // namespace archgeo
