// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — reference surfaces for proximity: closest point and tangent
// plane on a triangle mesh (CGAL AABB tree), closest point and tangent on the
// reference's boundary curves.
#pragma once

#include <memory>
#include <optional>

#include "mesh/surface_mesh.h"

namespace archgeo {

class ReferenceSurface {
 public:
  // Copies and triangulates `reference` (polygonal faces allowed; see
  // TriangulatedCopy) and builds the AABB trees. Normals at closest points are
  // interpolated from area-weighted vertex normals (a smooth tangent plane,
  // not the facet's). Throws std::invalid_argument if `reference` has no
  // faces, a face cannot be triangulated, or all faces at a vertex are degenerate.
  explicit ReferenceSurface(const Mesh& reference);
  ~ReferenceSurface();
  ReferenceSurface(ReferenceSurface&&) noexcept;

  struct SurfacePoint {
    Vec3 point;   // closest point on the triangulated reference
    Vec3 normal;  // unit normal of the tangent plane there
    int face = -1;  // its triangle: a face index of Triangles()
  };
  SurfacePoint Closest(const Vec3& query) const;
  // The same closest point, the search started from `near`, a point of the
  // reference on its triangle `near.face` (e.g. where a vertex that moves a
  // little was): much faster when it is close to the answer.
  SurfacePoint Closest(const Vec3& query, const SurfacePoint& near) const;

  struct CurvePoint {
    Vec3 point;    // closest point on the boundary polylines
    Vec3 tangent;  // unit tangent there (interpolated between vertex tangents)
  };
  // Empty when the reference has no boundary.
  std::optional<CurvePoint> ClosestOnBoundary(const Vec3& query) const;
  bool HasBoundary() const;

  // The triangulated reference (for Hausdorff distances and such).
  const Mesh& Triangles() const;

 private:
  SurfacePoint At(const Point& point, FaceIndex face) const;  // with its interpolated normal
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A triangulated copy of `mesh` with the same vertex indices. A quad is split
// along the diagonal whose two triangles' area normals have the larger dot
// product (CGAL's rule); ties up to rounding, as in a regular grid, go to the
// diagonal through the quad's smallest vertex index, so the split does not
// depend on the mesh's position. Other polygons: ear clipping in the plane
// of the face's Newell normal, best-shaped ear first (a fan from one corner
// where the face's projection overlaps itself).
Mesh TriangulatedCopy(const Mesh& mesh);

}  // namespace archgeo
