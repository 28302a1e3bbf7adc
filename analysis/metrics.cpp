// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — quality metrics.
#include "analysis/metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/property_map.h>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <glog/logging.h>

#include "core/solver_options.h"
#include "geometry/hausdorff_sampling.h"
#include "geometry/reference.h"
#include "mesh/similarity.h"
#include "mesh/topology.h"
#include "geometry/triangle_tree.h"

namespace archgeo {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;


double Length(const Vector& v) { return std::sqrt(v.squared_length()); }

// a / b, with 0 / 0 = 0 (a face with a zero-length edge or diagonal is planar).
// A non-planar n-gon with a zero-length edge has infinite warp.
double Ratio(double a, double b) {
  if (b > 0) return a / b;
  return a > 0 ? std::numeric_limits<double>::infinity() : 0.0;
}

double ShortestEdge(const std::vector<Point>& p) {
  double shortest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < p.size(); ++i) {
    shortest = std::min(shortest, Length(p[(i + 1) % p.size()] - p[i]));
  }
  return shortest;
}

// Distance between the diagonal lines b0b2 and b1b3: |n·(b1 − b0)|,
// n = unit((b2 − b0) × (b3 − b1)), 0 for parallel diagonals   [Zadravec 2010, §6 diag_f]
double QuadDiagonalDistance(const std::vector<Point>& b) {
  const Vector d0 = b[2] - b[0], d1 = b[3] - b[1];
  const Vector n = CGAL::cross_product(d0, d1);
  const double n_length = Length(n);
  if (!(n_length > 1e-14 * Length(d0) * Length(d1))) return 0.0;
  return std::abs(n * (b[1] - b[0])) / n_length;
}

// Max distance of the vertices from their least-squares plane.
double PlaneFitDistance(const std::vector<Point>& p) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Point& q : p) centroid += Eigen::Vector3d(q.x(), q.y(), q.z());
  centroid /= double(p.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Point& q : p) {
    const Eigen::Vector3d d = Eigen::Vector3d(q.x(), q.y(), q.z()) - centroid;
    covariance += d * d.transpose();
  }
  const Eigen::Vector3d normal =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvectors().col(0);
  double distance = 0;
  for (const Point& q : p) {
    const Eigen::Vector3d d = Eigen::Vector3d(q.x(), q.y(), q.z()) - centroid;
    distance = std::max(distance, std::abs(normal.dot(d)));
  }
  return distance;
}

double MeanDiagonal(const std::vector<Point>& p) {
  double sum = 0;
  for (size_t i = 0; i < p.size(); ++i) sum += Length(p[(i + 2) % p.size()] - p[i]);
  return sum / p.size();
}

struct MaxMean {
  double max = 0, sum = 0;
  int count = 0;
  void Add(double x) { max = std::max(max, x); sum += x; ++count; }
  double Mean() const { return count > 0 ? sum / count : 0.0; }
};

double AxisAlignedBoxDiagonal(const Mesh& mesh) {
  if (mesh.number_of_vertices() == 0) return 0.0;
  CGAL::Bbox_3 box;
  for (VertexIndex v : mesh.vertices()) box += mesh.point(v).bbox();
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

// Symmetric Hausdorff distance between the triangulated `mesh` and `triangles`,
// approximated by sampling each surface (every vertex, and a regular grid on
// each edge and triangle) and taking the largest distance of a sample to the
// other surface (CGAL's approximate_symmetric_Hausdorff_distance). The grid
// spacing is HausdorffGridSpacing (geometry/hausdorff_sampling.h): 0.25 mean edge
// lengths of the sampled surface, increased where needed so that each
// surface gets at most kHausdorffMaxGridSamples grid samples besides its
// vertices: the work is bounded by the vertex count plus a constant, whatever
// the geometry. The result is a lower bound of the true
// distance, with a sampling density of one grid spacing: the distance to the
// other surface is 1-Lipschitz and every point of a triangle lies within
// about one spacing of a sample, so the true distance exceeds the result by
// at most about one spacing (0.25 mean edge lengths unless the cap applied).
// Deterministic and invariant under similarity transforms. CGAL's
// bounded_error_symmetric_Hausdorff_distance is exact to its error bound but
// slowest when the two surfaces are close, as after an optimisation; the grid
// costs the same at every distance.
//
// Pruned: the vertices of both surfaces are samples and are queried first,
// each with the triangle of the other surface it is closest to; L is their
// largest distance. The distance to one triangle T′ of the other surface is
// convex, so on a triangle T it is largest at a corner of T: no point of T is
// farther from the other surface than U = max over T's corners v of
// d(v, T′). T′ is tried as the triangle of the same index (the input's own,
// when one surface is the other moved), as the triangle closest to each
// corner (no query), then as the one closest to T's centroid (one query). A
// triangle with U ≤ L cannot raise the maximum and is not sampled; only the
// others get their grid (CGAL's sample_triangle_mesh with the spacing of the
// whole surface, on a copy of just those triangles), queried on every core.
// So the result is at least the full grid's and keeps its density
// guarantee, and on a mesh that barely moved most triangles are pruned.
//
// Queries: the reference's own tree answers for the reference side, and the
// vertices' distances to it are those the proximity metrics measured; the
// other surface gets a tree with CGAL's search tree for the first bound
// (geometry/triangle_tree.h), which starts each query near its answer.

Kernel::Triangle_3 Triangle(const Mesh& mesh, FaceIndex f) {
  const HalfedgeIndex h = mesh.halfedge(f);
  return {mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
          mesh.point(mesh.target(mesh.next(h)))};
}

// One direction: the triangle mesh `from` sampled against the surface `to`.
struct Side {
  const Mesh* from = nullptr;
  const Mesh* to = nullptr;
  const ReferenceSurface* reference = nullptr;  // `to` is its Triangles(), or
  std::unique_ptr<TriangleTree> tree;           // `to`'s own tree
  std::vector<double> distance;    // per vertex of `from`: squared, to `to`
  std::vector<FaceIndex> nearest;  // per vertex: the closest triangle of `to`
  double lower = 0;                // the largest `distance`

  // The closest point of `to` and its triangle.
  std::pair<Point, FaceIndex> Closest(const Point& p) const {
    if (!reference) return tree->closest_point_and_primitive(p);
    const ReferenceSurface::SurfacePoint c = reference->Closest(ToVec3(p));
    return {ToPoint(c.point), FaceIndex(FaceIndex::size_type(c.face))};
  }
};

// Queries every point on every core and calls visit(i, squared distance,
// closest triangle). Returns the largest squared distance.
template <class Visit>
double QueryAll(const Side& side, const std::vector<Point>& points, const Visit& visit) {
  double worst = 0;
  const FullTeams teams;
#pragma omp parallel for schedule(dynamic, 1024) reduction(max : worst)
  for (long i = 0; i < long(points.size()); ++i) {
    const auto [closest, face] = side.Closest(points[size_t(i)]);
    const double d = CGAL::squared_distance(closest, points[size_t(i)]);
    visit(size_t(i), d, face);
    worst = std::max(worst, d);
  }
  return worst;
}

// Every vertex of `from`: its distance and closest triangle.
void QueryVertices(Side& side) {
  const Mesh& from = *side.from;
  std::vector<Point> points;
  std::vector<size_t> index;
  for (VertexIndex v : from.vertices()) points.push_back(from.point(v)), index.push_back(v.idx());
  side.distance.assign(from.num_vertices(), 0.0);
  side.nearest.assign(from.num_vertices(), FaceIndex());
  side.lower = QueryAll(side, points, [&](size_t k, double d, FaceIndex f) {
    side.distance[index[k]] = d;
    side.nearest[index[k]] = f;
  });
}

// The triangles of `from` that may hold a point farther than `lower`
// (squared) from `to`, as a triangle mesh of their own.
Mesh MayBeFarther(const Side& side, double lower) {
  const Mesh &from = *side.from, &to = *side.to;
  const long count = long(from.num_faces());
  std::vector<char> keep(static_cast<size_t>(count), 0);
  const FullTeams teams;
#pragma omp parallel for schedule(dynamic, 4096)
  for (long i = 0; i < count; ++i) {
    const FaceIndex f(static_cast<FaceIndex::size_type>(i));
    if (from.is_removed(f)) continue;
    std::array<VertexIndex, 3> corner;
    int k = 0;
    for (VertexIndex v : from.vertices_around_face(from.halfedge(f))) {
      if (k < 3) corner[size_t(k)] = v;
      ++k;
    }
    if (k != 3) {
      keep[size_t(i)] = 1;
      continue;
    }
    // The largest squared distance of the corners from one triangle of `to`.
    const auto farthest = [&](FaceIndex t) {
      const Kernel::Triangle_3 triangle = Triangle(to, t);
      double d = 0;
      for (VertexIndex v : corner) d = std::max(d, CGAL::squared_distance(from.point(v), triangle));
      return d;
    };
    bool within = i < long(to.num_faces()) && !to.is_removed(f) && to.degree(f) == 3 &&
                  farthest(f) <= lower;
    for (VertexIndex c : corner) within = within || farthest(side.nearest[c.idx()]) <= lower;
    if (!within) {
      const Point g = CGAL::centroid(from.point(corner[0]), from.point(corner[1]),
                                     from.point(corner[2]));
      within = farthest(side.Closest(g).second) <= lower;
    }
    keep[size_t(i)] = !within;
  }
  Mesh kept;
  std::vector<VertexIndex> copy(from.num_vertices());
  std::vector<char> copied(from.num_vertices(), 0);
  for (long i = 0; i < count; ++i) {
    if (!keep[size_t(i)]) continue;
    std::vector<VertexIndex> corners;
    for (VertexIndex v : from.vertices_around_face(from.halfedge(FaceIndex(FaceIndex::size_type(i))))) {
      if (!copied[v.idx()]) {
        copy[v.idx()] = kept.add_vertex(from.point(v));
        copied[v.idx()] = 1;
      }
      corners.push_back(copy[v.idx()]);
    }
    if (kept.add_face(corners) == Mesh::null_face()) {  // not a manifold copy: on its own
      std::vector<VertexIndex> own;
      for (VertexIndex v : corners) own.push_back(kept.add_vertex(kept.point(v)));
      kept.add_face(own);
    }
  }
  return kept;
}

// Symmetric Hausdorff distance between the triangulated `mesh` and the
// reference; `distance` and `nearest` hold, per vertex of `mesh`, its squared
// distance to the reference and its closest triangle there.
double Hausdorff(const Mesh& mesh, const ReferenceSurface& reference,
                 std::vector<double> distance, std::vector<FaceIndex> nearest) {
  const Mesh mesh_triangles = TriangulatedCopy(mesh);
  std::array<Side, 2> sides;
  sides[0].from = &mesh_triangles, sides[0].to = &reference.Triangles();
  sides[0].reference = &reference;
  sides[0].distance = std::move(distance), sides[0].nearest = std::move(nearest);
  for (double d : sides[0].distance) sides[0].lower = std::max(sides[0].lower, d);
  sides[1].from = &reference.Triangles(), sides[1].to = &mesh_triangles;
  sides[1].tree = std::make_unique<TriangleTree>();
  BuildTriangleTree(mesh_triangles, sides[1].tree.get());
  QueryVertices(sides[1]);
  double worst = std::max(sides[0].lower, sides[1].lower);
  for (Side& side : sides) {
    const Mesh kept = MayBeFarther(side, worst);
    if (kept.number_of_faces() == 0) continue;
    std::vector<Point> samples;
    PMP::sample_triangle_mesh(
        kept, std::back_inserter(samples),
        PMP::parameters::use_grid_sampling(true).grid_spacing(HausdorffGridSpacing(*side.from)));
    worst = std::max(worst, QueryAll(side, samples, [](size_t, double, FaceIndex) {}));
  }
  return std::sqrt(worst);
}

}  // namespace

PlanarityMeasure MeasureFacePlanarity(const Mesh& mesh) {
  PlanarityMeasure result;
  result.distance.assign(mesh.num_faces(), 0.0);
  result.normalized.assign(mesh.num_faces(), 0.0);
  result.warp.assign(mesh.num_faces(), 0.0);
  const long faces = long(mesh.num_faces());
  const FullTeams teams;
#pragma omp parallel
  {
    std::vector<Point> p;
#pragma omp for schedule(dynamic, 4096)
    for (long i = 0; i < faces; ++i) {
      const FaceIndex f(static_cast<FaceIndex::size_type>(i));
      if (mesh.is_removed(f)) continue;
      p.clear();
      for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) p.push_back(mesh.point(v));
      if (p.size() < 4) continue;
      double distance, diagonal;
      if (p.size() == 4) {
        distance = QuadDiagonalDistance(p);
        diagonal = 0.5 * (Length(p[2] - p[0]) + Length(p[3] - p[1]));
      } else {
        distance = PlaneFitDistance(p);
        diagonal = MeanDiagonal(p);
      }
      result.distance[f.idx()] = distance;
      result.normalized[f.idx()] = Ratio(distance, diagonal);
      result.warp[f.idx()] = Ratio(distance, ShortestEdge(p));
    }
  }
  return result;
}

std::vector<std::array<unsigned char, 3>> PlanarityColors(const PlanarityMeasure& planarity,
                                                            double red_at) {
  CHECK_GT(red_at, 0.0);
  std::vector<std::array<unsigned char, 3>> colors;
  colors.reserve(planarity.normalized.size());
  for (double value : planarity.normalized) {
    // green -> yellow -> red, so the middle of the scale stays bright
    const double t = std::clamp(value / red_at, 0.0, 1.0);
    const auto channel = [](double x) {
      return static_cast<unsigned char>(std::lround(255 * std::min(1.0, x)));
    };
    colors.push_back({channel(2 * t), channel(2 * (1 - t)), 0});
  }
  return colors;
}

Metrics ComputeMetrics(const Mesh& mesh, const ReferenceSurface* reference, const Mesh* original,
                       const MetricsOptions& options) {
  Metrics m;
  m.vertices = int(mesh.number_of_vertices());
  m.faces = int(mesh.number_of_faces());
  for (FaceIndex f : mesh.faces()) {
    const auto degree = mesh.degree(f);
    (degree == 3 ? m.triangles : degree == 4 ? m.quads : m.polygons) += 1;
  }
  m.bbox_diagonal = mesh.number_of_vertices() > 0 ? PrincipalBoxDiagonal(mesh) : 0.0;
  m.aabb_diagonal = AxisAlignedBoxDiagonal(mesh);
  m.mean_edge_length = MeanEdgeLength(mesh);

  const PlanarityMeasure planarity = MeasureFacePlanarity(mesh);
  MaxMean pq, pq_normalized, warp;
  for (FaceIndex f : mesh.faces()) {
    if (mesh.degree(f) < 4) continue;
    pq.Add(planarity.distance[f.idx()]);
    pq_normalized.Add(planarity.normalized[f.idx()]);
    warp.Add(planarity.warp[f.idx()]);
  }
  m.pq_max = pq.max, m.pq_mean = pq.Mean();
  m.pq_normalized_max = pq_normalized.max, m.pq_normalized_mean = pq_normalized.Mean();
  m.warp_max = warp.max, m.warp_mean = warp.Mean();

  if (reference != nullptr) {
    const std::vector<bool> boundary = BoundaryVertices(mesh);
    // Each vertex's distances in parallel (CGAL's trees answer concurrent
    // queries), then summed in vertex order.
    const std::vector<VertexIndex> vertices(mesh.vertices().begin(), mesh.vertices().end());
    const long n = long(vertices.size());
    std::vector<double> to_surface(n), to_plane(n, -1), to_curve(n, -1);
    // Per vertex index, for the Hausdorff distance: squared, and the triangle.
    std::vector<double> squared(mesh.num_vertices(), 0.0);
    std::vector<FaceIndex> nearest(mesh.num_vertices());
    {
      const FullTeams teams;
#pragma omp parallel for schedule(dynamic, 1024)
      for (long i = 0; i < n; ++i) {
        const VertexIndex v = vertices[i];
        const Vec3 x = ToVec3(mesh.point(v));
        const ReferenceSurface::SurfacePoint closest = reference->Closest(x);
        const Vector offset = mesh.point(v) - ToPoint(closest.point);
        to_surface[i] = Length(offset);
        squared[v.idx()] = offset.squared_length();
        nearest[v.idx()] = FaceIndex(FaceIndex::size_type(closest.face));
        if (!boundary[v.idx()] || !reference->HasBoundary()) {
          // δ_prox: distance to the tangent plane at π(v)   [Zadravec 2010, §6]
          // (boundary vertices too when the reference has no boundary curve to
          // measure them against, as the planar_quads builder treats them)
          const Vector normal(closest.normal[0], closest.normal[1], closest.normal[2]);
          to_plane[i] = std::abs(offset * normal);
        } else {
          // δ∂_prox: distance to the boundary tangent at π̃(v)   [Zadravec 2010, §6]
          const ReferenceSurface::CurvePoint curve = *reference->ClosestOnBoundary(x);
          const Vector d = mesh.point(v) - ToPoint(curve.point);
          const Vector t(curve.tangent[0], curve.tangent[1], curve.tangent[2]);
          to_curve[i] = Length(d - (d * t) * t);
        }
      }
    }
    MaxMean prox, boundary_prox, surface;
    for (long i = 0; i < n; ++i) {
      surface.Add(to_surface[i]);
      if (to_plane[i] >= 0) prox.Add(to_plane[i]);
      if (to_curve[i] >= 0) boundary_prox.Add(to_curve[i]);
    }
    m.prox_max = prox.max;
    m.boundary_prox_max = reference->HasBoundary() ? boundary_prox.max : -1;
    m.surface_distance_max = surface.max, m.surface_distance_mean = surface.Mean();
    if (options.hausdorff && mesh.number_of_faces() > 0) {
      m.hausdorff = Hausdorff(mesh, *reference, std::move(squared), std::move(nearest));
    }
  }

  if (original != nullptr && original->number_of_vertices() == mesh.number_of_vertices()) {
    MaxMean displacement;
    auto o = original->vertices().begin();
    for (VertexIndex v : mesh.vertices()) {
      displacement.Add(Length(mesh.point(v) - original->point(*o++)));
    }
    m.displacement_max = displacement.max, m.displacement_mean = displacement.Mean();
  }
  return m;
}

Metrics ScaleLengths(Metrics m, double factor) {
  for (double* length : {&m.bbox_diagonal, &m.aabb_diagonal, &m.mean_edge_length, &m.pq_max,
                         &m.pq_mean, &m.prox_max, &m.boundary_prox_max, &m.surface_distance_max,
                         &m.surface_distance_mean, &m.hausdorff, &m.displacement_max,
                         &m.displacement_mean}) {
    if (*length != -1) *length *= factor;
  }
  return m;
}

nlohmann::json MetricsToJson(const Metrics& m, double scale) {
  CHECK_GT(scale, 0.0) << "MetricsToJson: scale must be positive";
  nlohmann::json json;
  const auto value = [](double x) { return x == -1 ? nlohmann::json(nullptr) : nlohmann::json(x); };
  const auto length = [&](const char* name, double x) {
    json[name] = value(x);
    json[std::string(name) + "_relative"] = value(x == -1 ? x : x / scale);
  };
  json["vertices"] = m.vertices;
  json["faces"] = m.faces;
  json["triangles"] = m.triangles;
  json["quads"] = m.quads;
  json["polygons"] = m.polygons;
  length("bbox_diagonal", m.bbox_diagonal);
  length("aabb_diagonal", m.aabb_diagonal);
  length("mean_edge_length", m.mean_edge_length);
  length("pq_max", m.pq_max);
  length("pq_mean", m.pq_mean);
  json["pq_normalized_max"] = value(m.pq_normalized_max);
  json["pq_normalized_mean"] = value(m.pq_normalized_mean);
  json["warp_max"] = value(m.warp_max);
  json["warp_mean"] = value(m.warp_mean);
  length("prox_max", m.prox_max);
  length("boundary_prox_max", m.boundary_prox_max);
  length("surface_distance_max", m.surface_distance_max);
  length("surface_distance_mean", m.surface_distance_mean);
  length("hausdorff", m.hausdorff);
  length("displacement_max", m.displacement_max);
  length("displacement_mean", m.displacement_mean);
  return json;
}

}  // namespace archgeo
