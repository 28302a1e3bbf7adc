// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/runtime/measures.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>

#include "energies/total_absolute_curvature.h"
#include "fabrication/panels.h"
#include "fabrication/units.h"
#include "mesh/elements.h"
#include "analysis/goal_metrics.h"
#include "geometry/hnet.h"
#include "analysis/metrics.h"
#include "analysis/smoothness_metrics.h"
#include "geometry/reference.h"
#include "mesh/similarity.h"

namespace archgeo {
namespace {

std::map<std::string, double> Planarity(HookContext& c) {
  const PlanarityMeasure p = MeasureFacePlanarity(c.store->mesh());
  const double max =
      p.normalized.empty() ? 0.0 : *std::max_element(p.normalized.begin(), p.normalized.end());
  return {{"pq_normalized_max", max}};
}

// The largest distance of a panel corner from its best-fit plane
// (fabrication/panels.h), in millimetres through `units` (0 without them:
// CheckFabricationSettings refuses the tolerance then).
std::map<std::string, double> Flatness(HookContext& c) {
  const Mesh& mesh = c.store->mesh();
  double worst = 0;
  std::vector<Eigen::Vector3d> corners;
  for (FaceIndex f : mesh.faces()) {
    corners.clear();
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      const Point& p = mesh.point(v);
      corners.emplace_back(p.x(), p.y(), p.z());
    }
    worst = std::max(worst, PanelFlatness(corners));
  }
  return {{"flatness_mm", worst * c.frame.scale * MillimetresPerUnit(c.settings->String("units"))}};
}

std::map<std::string, double> EdgeSmoothness(HookContext& c) {
  const SmoothnessMetrics m = ComputeEdgeSmoothnessMetrics(c.store->mesh());
  return {{"E", m.E}, {"E_prime", m.E_prime}};
}

std::map<std::string, double> StarSmoothness(HookContext& c) {
  const SmoothnessMetrics m = ComputeSmoothnessMetrics(c.store->mesh());
  return {{"self_intersecting_pyramids", m.self_intersecting_pyramids},
          {"bad_saddles", m.bad_saddles}};
}

std::map<std::string, double> Curvature(HookContext& c) {
  return {{"C", DiscreteTotalAbsoluteCurvature(c.store->mesh())}};
}

std::map<std::string, double> Displacement(HookContext& c) {
  const Mesh& now = c.store->mesh();
  double m = 0;
  // The input in the canonical frame: the store's original positions are
  // the model's; the input mesh itself is in file units.
  for (VertexIndex v : now.vertices()) {
    if (v.idx() >= c.input->number_of_vertices()) break;
    const Vec3 x0 = c.frame.ToCanonical(ToVec3(c.input->point(v)));
    const Point& p = now.point(v);
    m = std::max(m, std::hypot(p.x() - x0[0], p.y() - x0[1], p.z() - x0[2]));
  }
  return {{"displacement_max", m}};
}

std::map<std::string, double> Stars(HookContext& c) {
  const StarPlanarities p = InteriorStarPlanarity(c.store->mesh());
  return {{"star_planarity_max", p.max}, {"star_planarity_mean", p.mean}};
}

std::map<std::string, double> Conical(HookContext& c) {
  const ConicalMeasure m = MeasureConical(c.store->mesh());
  return {{"conical_max", m.max}, {"conical_mean", m.mean}};
}

std::map<std::string, double> FaceOffsets(HookContext& c) {
  const Mesh& mesh = c.store->mesh();
  return {{"face_offset_miss", MeasureFaceOffsets(mesh, EdgeLengthSpread(mesh).mean).max_relative}};
}

std::map<std::string, double> EdgeSpread(HookContext& c) {
  return {{"edge_length_spread", EdgeLengthSpread(c.store->mesh()).max_relative_deviation}};
}

std::map<std::string, double> BoundarySpread(HookContext& c) {
  return {{"boundary_spacing_spread",
           BoundaryEdgeLengthSpread(c.store->mesh()).max_relative_deviation}};
}

// The deviation from the design: vertices (and face centroids, when the
// reference is a surface of its own) against the reference surface
// (canonical frame), as a fraction of the input's diagonal and in file
// units. Without a `reference` the design is the input's triangulation,
// known at the input's vertices: the centroid of a non-planar input quad
// is off it by about half the quad's warp, a property of the input, not a
// deviation of the result.
std::map<std::string, double> SurfaceDistance(HookContext& c) {
  const Mesh& mesh = c.store->mesh();
  double worst = 0;
  const auto add = [&](const Vec3& x) {
    const Vec3 p = c.reference->Closest(x).point;
    worst = std::max(worst, std::hypot(x[0] - p[0], x[1] - p[1], x[2] - p[2]));
  };
  for (VertexIndex v : mesh.vertices()) add(ToVec3(mesh.point(v)));
  if (!c.settings->String("reference").empty()) {
    for (FaceIndex f : mesh.faces()) {
      Vec3 centroid{0, 0, 0};
      int n = 0;
      for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
        const Point& p = mesh.point(v);
        centroid = {centroid[0] + p.x(), centroid[1] + p.y(), centroid[2] + p.z()};
        ++n;
      }
      add({centroid[0] / n, centroid[1] / n, centroid[2] / n});
    }
  }
  const double diagonal = PrincipalBoxDiagonal(*c.input) / c.frame.scale;
  return {{"surface_distance_relative", diagonal > 0 ? worst / diagonal : 0.0},
          {"surface_distance", worst * c.frame.scale}};
}

// The net of the load term (energies/load.cpp): its vertex loads and spring
// rest lengths are constant blocks, its stiffness a setting.
std::map<std::string, double> ForceBalance(HookContext& c) {
  Store& store = *c.store;
  if (!store.Has("load_force") || !store.Has("load_rest_length")) {
    return {{"force_balance_max", 0.0}};
  }
  const Mesh& mesh = store.mesh();
  std::vector<Vec3> loads;
  for (VertexIndex v : mesh.vertices()) {
    const double* f = store.At("load_force", int(v.idx()));
    loads.push_back({f[0], f[1], f[2]});
  }
  std::vector<double> rest;
  for (EdgeIndex e : mesh.edges()) rest.push_back(store.At("load_rest_length", int(e.idx()))[0]);
  const std::vector<double> stiffness(mesh.number_of_edges(),
                                      c.settings->Number("terms.load.stiffness"));
  return {{"force_balance_max",
           MeasureForceBalance(mesh, loads, stiffness, rest, c.fixed).max_relative}};
}

const std::map<std::string, MeasureGroup>& Groups() {
  static const std::map<std::string, MeasureGroup> groups = {
      {"pq_normalized_max", &Planarity},
      {"flatness_mm", &Flatness},
      {"E", &EdgeSmoothness},
      {"E_prime", &EdgeSmoothness},
      {"self_intersecting_pyramids", &StarSmoothness},
      {"bad_saddles", &StarSmoothness},
      {"C", &Curvature},
      {"displacement_max", &Displacement},
      {"star_planarity_max", &Stars},
      {"star_planarity_mean", &Stars},
      {"conical_max", &Conical},
      {"conical_mean", &Conical},
      {"face_offset_miss", &FaceOffsets},
      {"edge_length_spread", &EdgeSpread},
      {"boundary_spacing_spread", &BoundarySpread},
      {"force_balance_max", &ForceBalance},
      {"surface_distance_relative", &SurfaceDistance},
      {"surface_distance", &SurfaceDistance},
  };
  return groups;
}

}  // namespace

const MeasureGroup* FindMeasureGroup(const std::string& name) {
  const auto it = Groups().find(name);
  return it == Groups().end() ? nullptr : &it->second;
}

double DiscreteTotalAbsoluteCurvature(const Mesh& mesh) {
  for (FaceIndex f : mesh.faces()) {
    CHECK_EQ(mesh.degree(f), 3u) << "DiscreteTotalAbsoluteCurvature: triangle meshes only";
  }
  const ElementSet fans = BuildElementSet(mesh, "fans");
  double c = 0;
  for (size_t i = 0; i < fans.size(); ++i) {
    const int* vs = fans.Vertices(i);
    std::vector<const double*> ring;
    for (int k = 1; k < fans.Count(i); ++k) ring.push_back(PositionBlock(mesh, VertexIndex(vs[k])));
    const VertexShapeOperator op = EvaluateVertexShapeOperator(
        PositionBlock(mesh, VertexIndex(vs[0])), ring, !fans.Has(i, kOpen));
    c += std::abs(op.lambda1) + std::abs(op.lambda2);
  }
  return c;
}

}  // namespace archgeo
