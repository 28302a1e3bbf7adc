// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/report/fabrication.h"

#include <glog/logging.h>

#include <algorithm>
#include <vector>

#include "analysis/metrics.h"
#include "fabrication/nodes.h"
#include "fabrication/panels.h"
#include "fabrication/plain_mesh.h"
#include "fabrication/sheet_layout.h"
#include "fabrication/units.h"
#include "io/fabrication_files.h"

namespace archgeo {
namespace {

const char* const kFabricationOutputs[] = {"output.panels", "output.cutting", "output.nodes",
                                           "output.beams"};

PlainMesh PlainCopy(const Mesh& mesh) {
  CHECK(!mesh.has_garbage()) << "fabrication: collect the mesh's garbage first";
  PlainMesh plain;
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    plain.points.emplace_back(p.x(), p.y(), p.z());
    std::vector<int> faces;
    for (FaceIndex f : CGAL::faces_around_target(mesh.halfedge(v), mesh)) {
      if (f != Mesh::null_face()) faces.push_back(int(f.idx()));
    }
    plain.vertex_faces.push_back(faces);
    plain.boundary.push_back(mesh.is_border(v));
  }
  for (FaceIndex f : mesh.faces()) {
    std::vector<int> ids;
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      ids.push_back(int(v.idx()));
    plain.faces.push_back(ids);
  }
  for (EdgeIndex e : mesh.edges()) {
    plain.edges.push_back({int(mesh.vertex(e, 0).idx()), int(mesh.vertex(e, 1).idx())});
  }
  return plain;
}

std::vector<Eigen::Vector3d> CornersOf(const PlainMesh& mesh, size_t f) {
  std::vector<Eigen::Vector3d> corners;
  for (int v : mesh.faces[f]) corners.push_back(mesh.points[size_t(v)]);
  return corners;
}

// A tolerance of the problem, if it has the key and it is on.
double BoundOf(const Settings& s, const std::string& key) {
  return s.schema().Find(key) != nullptr ? s.Number(key) : 0.0;
}

std::vector<PanelRecord> PanelTable(const Mesh& mesh, const PlainMesh& plain, const Settings& s,
                                    std::vector<FlatOutline>* outlines) {
  const double mm = MillimetresPerUnit(s.String("units"));
  const double pq_bound = BoundOf(s, "tolerance.pq_normalized_max");
  const double flat_bound = BoundOf(s, "tolerance.flatness_mm");
  const PlanarityMeasure planarity = MeasureFacePlanarity(mesh);
  std::vector<PanelRecord> rows;
  for (size_t f = 0; f < plain.faces.size(); ++f) {
    const std::vector<Eigen::Vector3d> corners = CornersOf(plain, f);
    PanelRecord row;
    row.face = int(f);
    row.vertices = plain.faces[f];
    row.geometry = MeasurePanel(corners);
    outlines->push_back(FlattenPanel(corners));
    row.outline_change = outlines->back().change;
    row.pq_normalized = plain.faces[f].size() > 3 ? planarity.normalized[f] : 0.0;
    if (pq_bound > 0) row.meets.push_back({"pq_normalized_max", row.pq_normalized <= pq_bound});
    if (flat_bound > 0)
      row.meets.push_back({"flatness_mm", row.geometry.flatness * mm <= flat_bound});
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

bool IsFabricationOutput(const std::string& key) {
  return std::find(std::begin(kFabricationOutputs), std::end(kFabricationOutputs), key) !=
         std::end(kFabricationOutputs);
}

void CheckFabricationSettings(const Settings& s) {
  if (MillimetresPerUnit(s.String("units")) > 0) return;
  if (BoundOf(s, "tolerance.flatness_mm") > 0) {
    throw s.Error(
        "tolerance.flatness_mm",
        "a tolerance in millimetres needs the mesh's unit: set `units` (mm, cm, m, in, ft)");
  }
  if (!s.String("output.cutting").empty()) {
    throw s.Error("output.cutting",
                  "the sheets (cutting.sheet, cutting.gap) are in millimetres: set `units`, the "
                  "mesh's unit (mm, cm, m, in, ft)");
  }
  if (s.Number("beams.depth") != 0) {
    throw s.Error("beams.depth",
                  "a beam depth in millimetres needs the mesh's unit: set `units` (mm, cm, m, "
                  "in, ft)");
  }
}

nlohmann::json WriteFabrication(const Mesh& output, const Settings& s,
                                const std::map<std::string, std::string>& temporaries,
                                std::string* headline) {
  bool asked = false;
  for (const char* key : kFabricationOutputs) asked = asked || temporaries.count(key) > 0;
  if (!asked) return nullptr;
  const PlainMesh plain = PlainCopy(output);
  const std::string& unit = s.String("units");
  const double mm = MillimetresPerUnit(unit);
  nlohmann::json report = {{"units", unit}, {"panels", plain.faces.size()}};
  std::vector<FlatOutline> outlines;
  const std::vector<PanelRecord> panels = PanelTable(output, plain, s, &outlines);
  double flatness = 0, change = 0, projection = 0;
  for (const PanelRecord& p : panels) {
    flatness = std::max(flatness, p.geometry.flatness);
    change = std::max(change, p.outline_change);
    projection = std::max(projection, p.geometry.projection_change);
  }
  report["flatness_max"] = flatness;
  if (mm > 0) report["flatness_max_mm"] = flatness * mm;
  report["outline_length_change_max"] = change;
  report["projection_length_change_max"] = projection;
  const auto file = [&](const char* key) {
    const auto it = temporaries.find(key);
    return it == temporaries.end() ? std::string() : it->second;
  };
  if (!file("output.panels").empty())
    WritePanelsCsv(file("output.panels"), panels, mm, "output.panels");
  if (!file("output.cutting").empty()) {
    CHECK_GT(mm, 0) << "CheckFabricationSettings lets output.cutting through without units";
    const std::vector<double> sheet = s.Numbers("cutting.sheet");
    std::vector<std::vector<Eigen::Vector2d>> flat;
    std::vector<int> ids;
    for (size_t f = 0; f < outlines.size(); ++f) {
      flat.push_back(outlines[f].corners);
      ids.push_back(int(f));
    }
    const SheetLayout layout = LayOutOnSheets(flat, Eigen::Vector2d(sheet[0], sheet[1]) / mm,
                                              s.Number("cutting.gap") / mm);
    WriteCuttingDxf(file("output.cutting"), layout, ids, unit, "output.cutting");
    report["sheets"] = layout.sheets.size();
    report["oversize_panels"] = layout.oversize;
    if (!layout.oversize.empty()) {
      *headline += "WARNING: " + std::to_string(layout.oversize.size()) +
                   " panels are larger than a sheet (cutting.sheet); each has a sheet of its own "
                   "in output.cutting (the report's fabrication.oversize_panels)\n";
    }
  }
  if (!file("output.nodes").empty() || !file("output.beams").empty()) {
    const double cone_bound = BoundOf(s, "tolerance.conical_max");
    const std::vector<NodeAxis> nodes = NodeAxes(plain, cone_bound);
    int cones = 0;
    for (const NodeAxis& n : nodes) cones += n.cone;
    report["cone_axes"] = cones;
    if (!file("output.nodes").empty()) {
      WriteNodesCsv(file("output.nodes"), plain.points, nodes, "output.nodes");
    }
    if (!file("output.beams").empty()) {
      const double depth = mm > 0 ? s.Number("beams.depth") / mm : 0.0;
      const std::vector<Beam> beams = Beams(plain, nodes, depth);
      double twist = 0;
      for (const Beam& b : beams) twist = std::max(twist, b.twist_degrees);
      report["beam_twist_max_degrees"] = twist;
      if (depth != 0) {
        const double error = FaceOffsetError(plain, OffsetNodes(plain, nodes, depth), depth);
        report["beam_far_edge_face_offset_error_max_mm"] = error * mm;
      }
      WriteBeamsCsv(file("output.beams"), beams, nodes, depth != 0, "output.beams");
    }
  }
  return report;
}

}  // namespace archgeo
