#include "problems/colors.h"

#include <glog/logging.h>

#include <algorithm>

#include "mesh/hnet.h"
#include "mesh/metrics.h"
#include "mesh/smoothness_metrics.h"

namespace archgeo {
namespace {

constexpr double kKinkRedDegrees = 1.0;

FaceColors Kinks(const Mesh& output, const Settings& s) {
  HNetOptions options;
  options.start_face = int(s.Integer("hnet.start_face"));
  options.kink_samples = int(s.Integer("hnet.kink_samples"));
  const HNet h = BuildHNet(output, options);
  PlanarityMeasure kink;  // reuses the green → red scale of the planarity colours
  kink.normalized.assign(output.number_of_faces(), 0.0);
  for (EdgeIndex e : output.edges()) {
    const double k = h.kink_degrees[e.idx()];
    if (k <= 0) continue;
    for (int i = 0; i < 2; ++i) {
      const FaceIndex f = output.face(output.halfedge(e, i));
      if (f != Mesh::null_face()) kink.normalized[f.idx()] = std::max(kink.normalized[f.idx()], k);
    }
  }
  return PlanarityColors(kink, kKinkRedDegrees);
}

}  // namespace

FaceColors OutputColors(const std::string& name, const Mesh& output, const Settings& s) {
  const double color_max = s.Number("output.color_max");
  if (name == "planarity") return PlanarityColors(MeasureFacePlanarity(output), color_max);
  if (name == "bending") return BendingColors(output, color_max);
  if (name == "curvature") {
    return SmoothnessColors(output, MeasureEdgeSmoothness(output, FaceNormals(output)));
  }
  if (name == "kinks") return Kinks(output, s);
  LOG(FATAL) << "unknown colouring '" << name << "'";
  return {};
}

}  // namespace archgeo
