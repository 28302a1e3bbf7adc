// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — reference surfaces: closest point and smooth tangent plane on a
// triangulated copy (CGAL AABB tree of triangles), closest point and tangent on
// its boundary polylines (AABB tree of segments).
#include "geometry/reference.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include "geometry/triangle_tree.h"
#include "core/newell.h"
#include "mesh/eigen_point.h"

namespace archgeo {
namespace {

using Segment = Kernel::Segment_3;
using SegmentIterator = std::vector<Segment>::const_iterator;
using SegmentPrimitive = CGAL::AABB_segment_primitive<Kernel, SegmentIterator>;
using SegmentTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, SegmentPrimitive>>;

// v / |v|, or the zero vector if v is (numerically) zero.
Vector Unit(const Vector& v) {
  const double length = std::sqrt(v.squared_length());
  return length > 1e-300 ? v / length : CGAL::NULL_VECTOR;
}

Vector Direction(const Mesh& mesh, HalfedgeIndex h) {
  return mesh.point(mesh.target(h)) - mesh.point(mesh.source(h));
}

// Vector area of a polygon (Newell): area times unit normal.
Vector VectorArea(const Mesh& mesh, FaceIndex f) {
  std::vector<Point> p;  // from the source of the face's halfedge
  for (HalfedgeIndex h : mesh.halfedges_around_face(mesh.halfedge(f))) {
    p.push_back(mesh.point(mesh.source(h)));
  }
  const Eigen::Vector3d n = NewellVector(int(p.size()), [&](int k) { return p[size_t(k)]; });
  return 0.5 * Vector(n[0], n[1], n[2]);
}

// Unit tangent of the border polyline at target(h): the normalised sum of the
// unit directions of the border halfedges h and next(h) (h's own direction at
// a 180-degree cusp).
Vector BorderTangent(const Mesh& mesh, HalfedgeIndex h) {
  const Vector in = Unit(Direction(mesh, h));
  const Vector sum = Unit(in + Unit(Direction(mesh, mesh.next(h))));
  return sum == CGAL::NULL_VECTOR ? in : sum;
}

// Barycentric coordinates of p (in the plane of a, b, c) with respect to a, b, c.
std::array<double, 3> Barycentric(const Point& p, const Point& a, const Point& b, const Point& c) {
  const Vector e0 = b - a, e1 = c - a, d = p - a;
  const double d00 = e0 * e0, d01 = e0 * e1, d11 = e1 * e1, d20 = d * e0, d21 = d * e1;
  const double denominator = d00 * d11 - d01 * d01;
  if (!(denominator > 0)) return {1.0 / 3, 1.0 / 3, 1.0 / 3};  // degenerate triangle
  const double v = (d11 * d20 - d01 * d21) / denominator;
  const double w = (d00 * d21 - d01 * d20) / denominator;
  return {1.0 - v - w, v, w};
}

// Relative difference below which the two splits of a quad count as equal.
constexpr double kSplitTie = 1e-9;

// Splits the quad at `h` (h = halfedge(f)) into two triangles (see TriangulatedCopy).
void SplitQuad(Mesh& mesh, HalfedgeIndex h0) {
  const HalfedgeIndex h1 = mesh.next(h0), h2 = mesh.next(h1), h3 = mesh.next(h2);
  const Point &p0 = mesh.point(mesh.target(h0)), &p1 = mesh.point(mesh.target(h1)),
              &p2 = mesh.point(mesh.target(h2)), &p3 = mesh.point(mesh.target(h3));
  using CGAL::cross_product;
  const double split02 = cross_product(p1 - p0, p1 - p2) * cross_product(p3 - p2, p3 - p0);
  const double split13 = cross_product(p2 - p1, p3 - p2) * cross_product(p0 - p3, p1 - p0);
  bool use02 = split02 > split13;
  if (std::abs(split02 - split13) <= kSplitTie * std::max(std::abs(split02), std::abs(split13))) {
    const auto min02 = std::min(mesh.target(h0), mesh.target(h2));
    const auto min13 = std::min(mesh.target(h1), mesh.target(h3));
    use02 = min02 < min13;
  }
  if (use02) {
    CGAL::Euler::split_face(h0, h2, mesh);
  } else {
    CGAL::Euler::split_face(h1, h3, mesh);
  }
}

// Whether q lies in the closed triangle (a, b, c), counter-clockwise, up to
// `eps` (a point on an edge counts as inside).
bool InTriangle(const Eigen::Vector2d& q, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                const Eigen::Vector2d& c, double eps) {
  const auto side = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v, const Eigen::Vector2d& w) {
    return (v - u).x() * (w - u).y() - (v - u).y() * (w - u).x();
  };
  return side(a, b, q) >= -eps && side(b, c, q) >= -eps && side(c, a, q) >= -eps;
}

// Whether the closed polygon q is simple: no two of its edges that do not
// share a corner meet (up to `eps`).
bool Simple(const std::vector<Eigen::Vector2d>& q, double eps) {
  const int n = int(q.size());
  const auto side = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v, const Eigen::Vector2d& w) {
    return (v - u).x() * (w - u).y() - (v - u).y() * (w - u).x();
  };
  for (int i = 0; i < n; ++i) {
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through corner 0
      const Eigen::Vector2d &a = q[size_t(i)], &b = q[size_t(i + 1)], &c = q[size_t(j)],
                            &d = q[size_t((j + 1) % n)];
      const double s1 = side(a, b, c), s2 = side(a, b, d), s3 = side(c, d, a), s4 = side(c, d, b);
      if (s1 * s2 <= eps * eps && s3 * s4 <= eps * eps &&
          std::max(a.x(), b.x()) >= std::min(c.x(), d.x()) - 1e-12 &&
          std::max(c.x(), d.x()) >= std::min(a.x(), b.x()) - 1e-12 &&
          std::max(a.y(), b.y()) >= std::min(c.y(), d.y()) - 1e-12 &&
          std::max(c.y(), d.y()) >= std::min(a.y(), b.y()) - 1e-12) {
        return false;
      }
    }
  }
  return true;
}

// The smallest angle of the triangle (a, b, c), in radians.
double SmallestAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const auto angle = [](const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
    return std::atan2(u.cross(v).norm(), u.dot(v));
  };
  return std::min({angle(b - a, c - a), angle(c - b, a - b), angle(a - c, b - c)});
}

// Cuts the polygon of `h` (more than four corners) into triangles by ear
// clipping in the plane of its Newell normal: each step cuts off the ear (a
// convex corner whose triangle holds no other corner) with the largest
// smallest angle, the well-shaped triangles a constrained Delaunay
// triangulation would favour. When the polygon's projection is not simple
// (it overlaps itself, e.g. a strongly warped face) or no corner is an ear,
// the rest is split as a fan from the corner at target(h): topologically
// always possible; the triangles may overlap, as the polygon itself does.
void EarClip(Mesh& mesh, HalfedgeIndex h) {
  std::vector<HalfedgeIndex> ring;  // corner k = target(ring[k])
  while (mesh.degree(mesh.face(h)) > 3) {
    ring.clear();
    for (HalfedgeIndex g : mesh.halfedges_around_face(h)) ring.push_back(g);
    const int n = int(ring.size());
    const auto corner = [&](int k) { return EigenPoint(mesh, mesh.target(ring[size_t((k + n) % n)])); };
    const Eigen::Vector3d normal = NewellNormal(n, corner);
    const Eigen::Vector3d u = normal.unitOrthogonal(), v = normal.cross(u);
    std::vector<Eigen::Vector2d> q(static_cast<size_t>(n));
    double extent = 0;
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector3d p = corner(k) - corner(0);
      q[size_t(k)] = Eigen::Vector2d(p.dot(u), p.dot(v));
      extent = std::max(extent, q[size_t(k)].norm());
    }
    const double eps = 1e-12 * extent * extent;
    const bool simple = Simple(q, eps);
    int best = -1;
    double best_angle = -1;
    for (int k = 0; k < n && simple && normal != Eigen::Vector3d::Zero(); ++k) {
      const Eigen::Vector2d &a = q[size_t((k + n - 1) % n)], &c = q[size_t(k)], &b = q[size_t((k + 1) % n)];
      const double turn = (c - a).x() * (b - c).y() - (c - a).y() * (b - c).x();
      if (!(turn > eps)) continue;  // reflex or straight: not an ear
      bool empty = true;
      for (int j = 0; j < n && empty; ++j) {
        if (j != k && j != (k + 1) % n && j != (k + n - 1) % n) empty = !InTriangle(q[size_t(j)], a, c, b, eps);
      }
      const double angle = SmallestAngle(corner(k - 1), corner(k), corner(k + 1));
      if (empty && angle > best_angle) {
        best = k;
        best_angle = angle;
      }
    }
    if (best < 0) {
      while (mesh.degree(mesh.face(h)) > 3) CGAL::Euler::split_face(h, mesh.next(mesh.next(h)), mesh);
      return;
    }
    // The new halfedge runs from the ear's next corner to its previous one,
    // closing the triangle; its opposite stays on the rest of the polygon.
    const HalfedgeIndex closing = CGAL::Euler::split_face(ring[size_t((best + 1) % n)],
                                                         ring[size_t((best + n - 1) % n)], mesh);
    h = mesh.opposite(closing);
  }
}

}  // namespace

Mesh TriangulatedCopy(const Mesh& mesh) {
  Mesh copy = mesh;
  std::vector<FaceIndex> quads, polygons;
  for (FaceIndex f : copy.faces()) {
    if (copy.degree(f) == 4) quads.push_back(f);
    if (copy.degree(f) > 4) polygons.push_back(f);
  }
  for (FaceIndex f : quads) SplitQuad(copy, copy.halfedge(f));
  for (FaceIndex f : polygons) EarClip(copy, copy.halfedge(f));
  return copy;
}

struct ReferenceSurface::Impl {
  Mesh triangles;
  std::vector<Vector> vertex_normals;  // unit, indexed by vertex index
  TriangleTree triangle_tree;
  std::vector<Segment> segments;                      // border edges, along the border
  std::vector<std::array<Vector, 2>> segment_tangents;  // unit tangents at source, target
  SegmentTree segment_tree;
};

ReferenceSurface::ReferenceSurface(const Mesh& reference) : impl_(std::make_unique<Impl>()) {
  if (reference.number_of_faces() == 0) {
    throw std::invalid_argument("reference surface has no faces");
  }
  // Area-weighted vertex normals of the polygonal faces, indexed by vertex
  // index (TriangulatedCopy keeps the indices).
  std::vector<Vector>& normals = impl_->vertex_normals;
  normals.assign(reference.num_vertices(), CGAL::NULL_VECTOR);
  std::vector<Vector> largest(reference.num_vertices(), CGAL::NULL_VECTOR);
  for (FaceIndex f : reference.faces()) {
    const Vector area = VectorArea(reference, f);
    for (VertexIndex v : reference.vertices_around_face(reference.halfedge(f))) {
      normals[v.idx()] = normals[v.idx()] + area;
      if (area.squared_length() > largest[v.idx()].squared_length()) largest[v.idx()] = area;
    }
  }
  for (VertexIndex v : reference.vertices()) {
    if (reference.is_isolated(v)) continue;
    Vector n = Unit(normals[v.idx()]);
    if (n == CGAL::NULL_VECTOR) n = Unit(largest[v.idx()]);  // opposed faces cancel
    if (n == CGAL::NULL_VECTOR) {
      throw std::invalid_argument("reference surface: every face at vertex " +
                                  std::to_string(v.idx()) + " is degenerate");
    }
    normals[v.idx()] = n;
  }

  Mesh& tri = impl_->triangles;
  try {
    tri = TriangulatedCopy(reference);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(std::string("reference surface: ") + error.what());
  }
  BuildTriangleTree(tri, &impl_->triangle_tree);

  for (HalfedgeIndex h : tri.halfedges()) {
    if (!tri.is_border(h)) continue;
    impl_->segments.emplace_back(tri.point(tri.source(h)), tri.point(tri.target(h)));
    impl_->segment_tangents.push_back({BorderTangent(tri, tri.prev(h)), BorderTangent(tri, h)});
  }
  if (!impl_->segments.empty()) {
    impl_->segment_tree.insert(impl_->segments.cbegin(), impl_->segments.cend());
    impl_->segment_tree.build();
    impl_->segment_tree.accelerate_distance_queries();
  }
}

ReferenceSurface::~ReferenceSurface() = default;
ReferenceSurface::ReferenceSurface(ReferenceSurface&&) noexcept = default;

ReferenceSurface::SurfacePoint ReferenceSurface::Closest(const Vec3& query) const {
  const auto [point, face] = impl_->triangle_tree.closest_point_and_primitive(ToPoint(query));
  return At(point, face);
}

ReferenceSurface::SurfacePoint ReferenceSurface::Closest(const Vec3& query,
                                                         const SurfacePoint& near) const {
  const auto hint = std::make_pair(ToPoint(near.point), FaceIndex(near.face));
  const auto [point, face] = impl_->triangle_tree.closest_point_and_primitive(ToPoint(query), hint);
  return At(point, face);
}

ReferenceSurface::SurfacePoint ReferenceSurface::At(const Point& point, FaceIndex face) const {
  const Mesh& tri = impl_->triangles;
  const HalfedgeIndex h = tri.halfedge(face);
  const std::array<VertexIndex, 3> v = {tri.source(h), tri.target(h), tri.target(tri.next(h))};
  const std::array<double, 3> w =
      Barycentric(point, tri.point(v[0]), tri.point(v[1]), tri.point(v[2]));
  // Smooth tangent plane: interpolated vertex normals, continuous across edges.
  Vector normal = Unit(w[0] * impl_->vertex_normals[v[0].idx()] +
                       w[1] * impl_->vertex_normals[v[1].idx()] +
                       w[2] * impl_->vertex_normals[v[2].idx()]);
  if (normal == CGAL::NULL_VECTOR) normal = Unit(VectorArea(tri, face));
  if (normal == CGAL::NULL_VECTOR) {
    const int nearest = int(std::max_element(w.begin(), w.end()) - w.begin());
    normal = impl_->vertex_normals[v[nearest].idx()];
  }
  return {ToVec3(point), {normal.x(), normal.y(), normal.z()}, int(face.idx())};
}

std::optional<ReferenceSurface::CurvePoint> ReferenceSurface::ClosestOnBoundary(
    const Vec3& query) const {
  if (!HasBoundary()) return std::nullopt;
  const auto [point, id] = impl_->segment_tree.closest_point_and_primitive(ToPoint(query));
  const Segment& segment = *id;
  const auto& tangents = impl_->segment_tangents[id - impl_->segments.cbegin()];
  const double length2 = segment.squared_length();
  const double along = CGAL::squared_distance(segment.source(), point);
  const double s = length2 > 0 ? std::min(1.0, std::sqrt(along / length2)) : 0.0;
  Vector tangent = Unit((1.0 - s) * tangents[0] + s * tangents[1]);
  if (tangent == CGAL::NULL_VECTOR) tangent = Unit(segment.to_vector());
  return CurvePoint{ToVec3(point), {tangent.x(), tangent.y(), tangent.z()}};
}

bool ReferenceSurface::HasBoundary() const { return !impl_->segments.empty(); }

const Mesh& ReferenceSurface::Triangles() const { return impl_->triangles; }

}  // namespace archgeo
