// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// conjugate_layout's streamline path [Gebreiter 2012, §8.2]; see
// problems/declarations/streamline_layout.h.
#include "problems/declarations/streamline_layout.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include "fields/extract.h"
#include "fields/field_io.h"
#include "fields/pair_cancellation.h"
#include "fields/streamline_mesh.h"
#include "mesh/similarity.h"

namespace archgeo {
namespace {

double Area(const StreamlineInput& in) {
  double area = 0;
  for (const auto& t : in.triangles) {
    area += 0.5 * (in.points[size_t(t[1])] - in.points[size_t(t[0])])
                      .cross(in.points[size_t(t[2])] - in.points[size_t(t[0])])
                      .norm();
  }
  return area;
}

// d_sep in the canonical frame (see the header).
double Separation(const Settings& s, const FieldResult& field, const StreamlineInput& in) {
  if (s.Given("streamlines.separation")) {
    return s.Number("streamlines.separation") * PrincipalBoxDiagonal(field.mesh);
  }
  const double edge = s.Number("level_sets.edge_length");
  if (edge > 0) return edge / field.frame.scale;
  return std::sqrt(Area(in) / double(s.Integer("level_sets.target_faces")));
}

}  // namespace

Key LayoutMethodKey() {
  return ChoiceKey("layout.method", "level_sets", {"level_sets", "streamlines"},
                   "how the layout is cut out of the field: level_sets (two functions along it, "
                   "[Zadravec 2010, §5]) or streamlines (the crossings of its evenly spaced "
                   "streamlines of both families, [Gebreiter 2012, §8.2]; spacing "
                   "streamlines.separation if given, else from level_sets.target_faces or "
                   "edge_length)");
}

std::shared_ptr<const LevelSetResult> SolveStreamlineLayout(
    const Settings& s, const Mesh& design, const ProgressSink& progress,
    const std::map<std::string, Value>& overrides, StreamlineResult* lines) {
  auto result = std::make_shared<LevelSetResult>();
  std::shared_ptr<const FieldResult> field = SolveField(s, design, progress, overrides);
  const double d_sep =
      Separation(s, *field, StreamlineInputOf(field->mesh, field->geometry, field->field));
  // field.cancel_pairs, .cancel_region, .boundary_push as on the level-set
  // path, in units of d_sep (its spacing).
  PairCancellationOptions pairs;
  pairs.max_distance = s.Number("field.cancel_pairs") * d_sep;
  pairs.region = s.Number("field.cancel_region");
  pairs.boundary_distance = s.Number("field.boundary_push") * d_sep;
  const PairCancellation pc =
      CancelSingularityPairs(field->mesh, field->geometry, field->field, pairs);
  const size_t singularities_before = field->field.singularities.size();
  if (pc.cancelled > 0 || pc.pushed_out > 0) {
    auto changed = std::make_shared<FieldResult>(*field);
    changed->field = EvaluateField(changed->mesh, changed->geometry, pc.z_n);
    field = changed;
  }
  result->field = field;
  result->frame = field->frame;
  const StreamlineInput input = StreamlineInputOf(field->mesh, field->geometry, field->field);
  StreamlineOptions o;
  o.separation = d_sep;
  o.test_ratio = s.Number("streamlines.test_ratio");
  o.step = s.Number("streamlines.step");
  o.separatrices = s.Bool("streamlines.separatrices");
  StreamlineResult traced = TraceStreamlines(input, o);
  StreamlineMeshOptions mo;
  mo.corner_angle_deg = s.Number("extraction.corner_angle");
  const StreamlineMesh m = MeshFromStreamlines(input, traced.lines, traced.d_sep, mo);
  const EdgeFieldAngle raw_angle = MeasureEdgeFieldAngle(input, m.points, m.faces);
  const int raw_faces = int(m.faces.size());
  int raw_quads = 0;
  for (const auto& f : m.faces) raw_quads += f.size() == 4;
  result->layout = LayoutFromSoup(m.points, m.on_boundary, m.is_corner, m.faces, ExtractOptionsOf(s));
  const Extraction& x = result->layout;
  if (!x.ok) {
    throw s.Error("layout.method", "the streamlines cut out no layout face (" +
                                       std::to_string(traced.lines.size()) + " lines, " +
                                       std::to_string(m.crossings) + " crossings)");
  }
  const EdgeFieldAngle angle = LayoutFieldAngle(*field, x.mesh);
  const int count = int(x.mesh.number_of_faces());
  int lines_v = 0, lines_w = 0, separatrices = 0;
  for (const Streamline& l : traced.lines) ++(l.separatrix ? separatrices : l.family == 0 ? lines_v : lines_w);
  nlohmann::json valence = nlohmann::json::object();
  for (const auto& [k, n] : x.interior_valence) valence[std::to_string(k)] = n;
  nlohmann::json degrees = nlohmann::json::object();
  for (const auto& [k, n] : x.face_degrees) degrees[std::to_string(k)] = n;
  const double unit = field->frame.scale;
  result->details["method"] = "streamlines";
  result->details["layout"] = {
      {"faces", count},
      {"vertices", x.mesh.number_of_vertices()},
      {"quads", x.quads},
      {"triangles", x.triangles},
      {"pentagons", x.pentagons},
      {"other_faces", x.other_faces},
      {"quad_fraction", count > 0 ? double(x.quads) / count : 0.0},
      {"face_degrees", degrees},
      {"interior_valence", valence},
      {"irregular_interior_vertices", x.irregular_interior_vertices.size()},
      {"irregular_interior_faces", x.irregular_interior_faces.size()},
      {"singularities", field->field.singularities.size()},
      {"singularities_before_cancellation", singularities_before},
      {"cancelled_pairs", pc.cancelled},
      {"edge_field_angle_mean_deg", angle.mean_deg},
      {"edge_field_angle_max_deg", angle.max_deg},
      {"merged_vertices", x.merged_vertices},
      {"snapped_vertices", x.snapped_vertices},
      {"merged_valence_two", x.merged_valence_two},
      {"merged_caps", x.merged_caps},
      {"removed_slits", x.removed_slits},
      {"split_reflex_corners", x.split_reflex_corners},
      {"duplicated_vertices", x.duplicated_vertices}};
  result->details["streamline_mesh"] = {
      {"d_sep", traced.d_sep * unit},
      {"lines_v", lines_v},
      {"lines_w", lines_w},
      {"separatrices", separatrices},
      {"crossings", m.crossings},
      {"boundary_ends", m.boundary_ends},
      {"extended_ends", m.extended_ends},
      {"dangling_ends", m.dangling_ends},
      {"pruned_edges", m.pruned_edges},
      {"joined_nodes", m.joined_nodes},
      {"dropped_faces", m.dropped_faces},
      {"dropped_large_faces", m.dropped_large_faces},
      {"faces_before_cleanup", raw_faces},
      {"quads_before_cleanup", raw_quads},
      {"edge_field_angle_mean_deg_before_cleanup", raw_angle.mean_deg}};
  char line[600];
  std::snprintf(line, sizeof line,
                "streamline layout: d_sep %.4g, %d v-lines, %d w-lines, %d separatrices, %d "
                "crossings, %d T-ends extended, %d dangling; %d faces (%d quads, %.1f%%, "
                "edge-to-field angle mean %.2f°) before clean-up\nlayout: %d faces, %d quads (%.1f%%), %d triangles, %d pentagons, %d "
                "other; %zu irregular interior vertices, %zu singularities; edge-to-field angle "
                "mean %.2f° max %.1f°\n",
                traced.d_sep * unit, lines_v, lines_w, separatrices, m.crossings, m.extended_ends,
                m.dangling_ends, raw_faces, raw_quads,
                raw_faces > 0 ? 100.0 * raw_quads / raw_faces : 0.0, raw_angle.mean_deg, count, x.quads,
                count > 0 ? 100.0 * x.quads / count : 0.0, x.triangles, x.pentagons, x.other_faces,
                x.irregular_interior_vertices.size(), field->field.singularities.size(),
                angle.mean_deg, angle.max_deg);
  result->headline = field->headline + line;
  if (lines) *lines = std::move(traced);
  return result;
}

}  // namespace archgeo
