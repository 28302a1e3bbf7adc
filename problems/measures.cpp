#include "problems/measures.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>

#include "energies/total_absolute_curvature.h"
#include "mesh/elements.h"
#include "mesh/hnet.h"
#include "mesh/metrics.h"
#include "mesh/smoothness_metrics.h"

namespace archgeo {
namespace {

std::map<std::string, double> Planarity(HookContext& c) {
  const PlanarityMeasure p = MeasureFacePlanarity(c.store->mesh());
  const double max =
      p.normalized.empty() ? 0.0 : *std::max_element(p.normalized.begin(), p.normalized.end());
  return {{"pq_normalized_max", max}};
}

std::map<std::string, double> Smoothness(HookContext& c) {
  const SmoothnessMetrics m = ComputeSmoothnessMetrics(c.store->mesh());
  return {{"E", m.E},
          {"E_prime", m.E_prime},
          {"self_intersecting_pyramids", m.self_intersecting_pyramids},
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

const std::map<std::string, MeasureGroup>& Groups() {
  static const std::map<std::string, MeasureGroup> groups = {
      {"pq_normalized_max", &Planarity},
      {"E", &Smoothness},
      {"E_prime", &Smoothness},
      {"self_intersecting_pyramids", &Smoothness},
      {"bad_saddles", &Smoothness},
      {"C", &Curvature},
      {"displacement_max", &Displacement},
      {"star_planarity_max", &Stars},
      {"star_planarity_mean", &Stars},
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
