// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — curves for the goal library (see curves.h).
#include "geometry/curves.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>
#include <string_view>
#include <utility>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <Eigen/Core>
#include <glog/logging.h>

#include "core/input_error.h"
#include "io/input_file.h"
#include "io/text_scan.h"

namespace archgeo {
namespace {

using Segment = Kernel::Segment_3;
using SegmentIterator = std::vector<Segment>::const_iterator;
using SegmentPrimitive = CGAL::AABB_segment_primitive<Kernel, SegmentIterator>;
using SegmentTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, SegmentPrimitive>>;
using V = Eigen::Vector3d;

V E(const Vec3& p) { return {p[0], p[1], p[2]}; }
V E(const Point& p) { return {p.x(), p.y(), p.z()}; }
Vec3 ToArray(const V& x) { return {x[0], x[1], x[2]}; }

bool Finite(const Vec3& p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

std::string PointName(size_t i) { return "point " + std::to_string(i); }

// The whole token as a number (from_chars also reads "nan" and "inf").
bool ParseCoordinate(std::string_view token, double* value) {
  const char* end = token.data() + token.size();
  const auto [ptr, error] = std::from_chars(token.data(), end, *value);
  return error == std::errc() && ptr == end;
}

bool ParseIndex(std::string_view token, long long* value) {
  token = token.substr(0, token.find('/'));  // "i/vt" → i
  const char* end = token.data() + token.size();
  const auto [ptr, error] = std::from_chars(token.data(), end, *value);
  return !token.empty() && error == std::errc() && ptr == end;
}

// Whitespace-separated tokens of `line` before any '#'.
std::vector<std::string_view> Tokens(std::string_view line) {
  line = line.substr(0, line.find('#'));
  std::vector<std::string_view> tokens;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

}  // namespace

Polyline MakePolyline(const std::vector<Vec3>& points, bool closed, const std::string& file,
                      int line, const std::string& key) {
  Polyline polyline;
  polyline.closed = closed;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!Finite(points[i])) {
      throw InputError(file, line, key, PointName(i) + " has a non-finite coordinate");
    }
    if (polyline.points.empty() || points[i] != polyline.points.back()) {
      polyline.points.push_back(points[i]);
    }
  }
  if (closed && polyline.points.size() > 1 && polyline.points.back() == polyline.points.front()) {
    polyline.points.pop_back();
  }
  const size_t needed = closed ? 3 : 2;
  if (polyline.points.size() < needed) {
    throw InputError(file, line, key,
                     std::string(closed ? "a closed" : "an open") + " polyline needs at least " +
                         std::to_string(needed) + " distinct points, got " +
                         std::to_string(polyline.points.size()));
  }
  return polyline;
}

std::vector<Polyline> ReadPolylines(const std::string& path) {
  const std::string text = ReadInputFile(path, "", std::uint64_t{1} << 30, "");
  std::vector<Vec3> vertices;
  std::vector<Polyline> polylines;
  std::istringstream stream(text);
  std::string raw;
  int line = 0;
  while (std::getline(stream, raw)) {
    ++line;
    const std::vector<std::string_view> tokens = Tokens(raw);
    if (tokens.empty()) continue;
    if (tokens[0] == "v") {
      Vec3 p;
      if (tokens.size() < 4 || !ParseCoordinate(tokens[1], &p[0]) || !ParseCoordinate(tokens[2], &p[1]) ||
          !ParseCoordinate(tokens[3], &p[2])) {
        FailInput(path, line, "malformed vertex: expected 'v x y z'");
      }
      if (!Finite(p)) FailInput(path, line, "vertex has a non-finite coordinate");
      vertices.push_back(p);
    } else if (tokens[0] == "l") {
      std::vector<long long> indices;
      for (size_t k = 1; k < tokens.size(); ++k) {
        long long index = 0;
        if (!ParseIndex(tokens[k], &index)) {
          FailInput(path, line, "bad polyline index " + QuoteToken(tokens[k]));
        }
        const long long count = static_cast<long long>(vertices.size());
        const long long zero_based = index > 0 ? index - 1 : count + index;
        if (index == 0 || zero_based < 0 || zero_based >= count) {
          FailInput(path, line,
                    "polyline index " + QuoteToken(tokens[k]) + " out of range (" +
                        std::to_string(count) + " vertices before this line)");
        }
        indices.push_back(zero_based);
      }
      const bool closed = indices.size() > 2 && indices.front() == indices.back();
      if (closed) indices.pop_back();
      std::vector<Vec3> points;
      for (long long i : indices) points.push_back(vertices[i]);
      polylines.push_back(MakePolyline(points, closed, path, line, ""));
    }
  }
  if (polylines.empty()) {
    FailInput(path, 0, "no polyline: the file has no 'l' record (export the curves as polylines)");
  }
  return polylines;
}

double PolylineLength(const Polyline& polyline) {
  const size_t m = polyline.points.size();
  double length = 0.0;
  for (size_t i = 0; i + 1 < m; ++i) {
    length += (E(polyline.points[i + 1]) - E(polyline.points[i])).norm();
  }
  if (polyline.closed && m > 1) {
    length += (E(polyline.points[0]) - E(polyline.points[m - 1])).norm();
  }
  return length;
}

std::vector<double> Coordinates(const Polyline& polyline) {
  std::vector<double> xyz;
  for (const Vec3& p : polyline.points) xyz.insert(xyz.end(), p.begin(), p.end());
  return xyz;
}

struct PolylineLocator::Impl {
  Polyline polyline;
  std::vector<Segment> segments;
  std::vector<double> arc;  // arc length at the source of each segment
  double length = 0.0;
  SegmentTree tree;
};

PolylineLocator::PolylineLocator(const Polyline& polyline) : impl_(std::make_unique<Impl>()) {
  const size_t m = polyline.points.size();
  CHECK_GE(m, polyline.closed ? 3u : 2u) << "PolylineLocator: too few points";
  impl_->polyline = polyline;
  const size_t count = polyline.closed ? m : m - 1;
  for (size_t i = 0; i < count; ++i) {
    const Vec3& a = polyline.points[i];
    const Vec3& b = polyline.points[(i + 1) % m];
    CHECK(Finite(a) && a != b) << "PolylineLocator: invalid segment " << i;
    impl_->segments.emplace_back(ToPoint(a), ToPoint(b));
    impl_->arc.push_back(impl_->length);
    impl_->length += (E(b) - E(a)).norm();
  }
  impl_->tree.insert(impl_->segments.cbegin(), impl_->segments.cend());
  impl_->tree.build();
  impl_->tree.accelerate_distance_queries();
}

PolylineLocator::~PolylineLocator() = default;
PolylineLocator::PolylineLocator(PolylineLocator&&) noexcept = default;

PolylineLocator::Location PolylineLocator::Closest(const Vec3& query) const {
  const auto [point, id] = impl_->tree.closest_point_and_primitive(ToPoint(query));
  const int i = static_cast<int>(id - impl_->segments.cbegin());
  const Segment& segment = *id;
  Location location;
  location.point = ToVec3(point);
  location.segment = i;
  const V source = E(segment.source());
  const V direction = E(segment.target()) - source;
  const double length = direction.norm();
  // Zero if |direction|² underflows (end points closer than ~1e-154).
  const V tangent = length > 0 ? V(direction / length) : V::Zero();
  location.tangent = ToArray(tangent);
  const double along = (E(point) - source).dot(tangent);
  location.arc_length = impl_->arc[i] + std::clamp(along, 0.0, length);
  location.distance = (E(query) - E(point)).norm();
  return location;
}

double PolylineLocator::length() const { return impl_->length; }
const Polyline& PolylineLocator::polyline() const { return impl_->polyline; }

std::vector<std::vector<VertexIndex>> BoundaryLoops(const Mesh& mesh) {
  std::vector<HalfedgeIndex> starts;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(starts));
  std::vector<std::vector<VertexIndex>> loops;
  for (HalfedgeIndex start : starts) {
    std::vector<VertexIndex> loop;
    for (HalfedgeIndex h : CGAL::halfedges_around_face(start, mesh)) loop.push_back(mesh.source(h));
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    loops.push_back(std::move(loop));
  }
  std::sort(loops.begin(), loops.end(), [](const auto& a, const auto& b) {
    return a.size() != b.size() ? a.size() > b.size() : a.front() < b.front();
  });
  return loops;
}

Polyline LoopPolyline(const Mesh& mesh, const std::vector<VertexIndex>& loop) {
  std::vector<Vec3> points;
  for (VertexIndex v : loop) points.push_back(ToVec3(mesh.point(v)));
  return MakePolyline(points, /*closed=*/true, "", 0, "boundary loop");
}

namespace {

// Centripetal Catmull-Rom on p0 p1 p2 p3 at u ∈ [0, 1] between p1 and p2
// (Barry–Goldman pyramid with knot intervals |p_{i+1} − p_i|^½).
V CatmullRom(const V& p0, const V& p1, const V& p2, const V& p3, double u) {
  const double t0 = 0.0;
  const double t1 = t0 + std::sqrt((p1 - p0).norm());
  const double t2 = t1 + std::sqrt((p2 - p1).norm());
  const double t3 = t2 + std::sqrt((p3 - p2).norm());
  const double t = t1 + u * (t2 - t1);
  const auto lerp = [](const V& a, const V& b, double ta, double tb, double t) -> V {
    return (tb - t) / (tb - ta) * a + (t - ta) / (tb - ta) * b;
  };
  const V a1 = lerp(p0, p1, t0, t1, t);
  const V a2 = lerp(p1, p2, t1, t2, t);
  const V a3 = lerp(p2, p3, t2, t3, t);
  const V b1 = lerp(a1, a2, t0, t2, t);
  const V b2 = lerp(a2, a3, t1, t3, t);
  return lerp(b1, b2, t1, t2, t);
}

}  // namespace

Polyline SampleCatmullRom(const Polyline& polyline, int samples_per_segment) {
  const int m = static_cast<int>(polyline.points.size());
  CHECK_GE(m, polyline.closed ? 3 : 2) << "SampleCatmullRom: too few points";
  CHECK_GE(samples_per_segment, 1) << "SampleCatmullRom: samples_per_segment must be >= 1";
  const auto& p = polyline.points;
  // Point i of the extended sequence (phantom points at open ends).
  const auto at = [&](int i) -> V {
    if (polyline.closed) return E(p[((i % m) + m) % m]);
    if (i < 0) return 2.0 * E(p[0]) - E(p[1]);
    if (i >= m) return 2.0 * E(p[m - 1]) - E(p[m - 2]);
    return E(p[i]);
  };
  Polyline result;
  result.closed = polyline.closed;
  const int segments = polyline.closed ? m : m - 1;
  for (int i = 0; i < segments; ++i) {
    result.points.push_back(p[i]);
    for (int s = 1; s < samples_per_segment; ++s) {
      result.points.push_back(ToArray(CatmullRom(at(i - 1), at(i), at(i + 1), at(i + 2),
                                                 static_cast<double>(s) / samples_per_segment)));
    }
  }
  if (!polyline.closed) result.points.push_back(p[m - 1]);
  return result;
}

}  // namespace archgeo
