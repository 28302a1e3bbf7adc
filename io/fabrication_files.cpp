// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/fabrication_files.h"

#include <cstdio>
#include <map>
#include <sstream>
#include <type_traits>
#include <utility>

#include "io/output_files.h"

namespace archgeo {
namespace {

// A number that reads back to the same double.
std::string FabNumber(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

template <typename T>
std::string FabList(const std::vector<T>& values) {
  std::string text;
  for (const T& v : values) {
    if (!text.empty()) text += ';';
    if constexpr (std::is_integral_v<T>) {
      text += std::to_string(v);
    } else {
      text += FabNumber(v);
    }
  }
  return text;
}

// One DXF group: its code and value, each on a line.
void Group(std::ostringstream& out, int code, const std::string& value) {
  out << code << '\n' << value << '\n';
}
void Group(std::ostringstream& out, int code, double value) { Group(out, code, FabNumber(value)); }

// A closed POLYLINE through `corners` (offset by `origin`) on `layer`.
void DxfPolyline(std::ostringstream& out, const std::vector<Eigen::Vector2d>& corners,
                 const Eigen::Vector2d& origin, const std::string& layer) {
  Group(out, 0, "POLYLINE");
  Group(out, 8, layer);
  Group(out, 66, "1");
  Group(out, 10, 0.0);
  Group(out, 20, 0.0);
  Group(out, 30, 0.0);
  Group(out, 70, "1");  // closed
  for (const Eigen::Vector2d& c : corners) {
    Group(out, 0, "VERTEX");
    Group(out, 8, layer);
    Group(out, 10, origin.x() + c.x());
    Group(out, 20, origin.y() + c.y());
    Group(out, 30, 0.0);
  }
  Group(out, 0, "SEQEND");
  Group(out, 8, layer);
}

// TEXT centred (horizontally and vertically: alignment 4, "middle") at `at`.
void DxfText(std::ostringstream& out, const std::string& text, const Eigen::Vector2d& at,
             double height, const std::string& layer) {
  Group(out, 0, "TEXT");
  Group(out, 8, layer);
  Group(out, 10, at.x());
  Group(out, 20, at.y());
  Group(out, 30, 0.0);
  Group(out, 40, height);
  Group(out, 1, text);
  Group(out, 72, "4");
  Group(out, 11, at.x());
  Group(out, 21, at.y());
  Group(out, 31, 0.0);
}

// $INSUNITS codes of the DXF reference.
int InsUnits(const std::string& unit) {
  static const std::map<std::string, int> codes = {
      {"in", 1}, {"ft", 2}, {"mm", 4}, {"cm", 5}, {"m", 6}};
  const auto it = codes.find(unit);
  return it == codes.end() ? 0 : it->second;
}

}  // namespace

void WritePanelsCsv(const std::string& path, const std::vector<PanelRecord>& panels,
                    double mm_per_unit, const std::string& key) {
  std::ostringstream out;
  out << "panel,vertices,flatness" << (mm_per_unit > 0 ? ",flatness_mm" : "")
      << ",flatness_relative,pq_normalized,area,edges,angles_degrees,diagonals,"
         "projection_length_change,outline_length_change";
  if (!panels.empty()) {
    for (const auto& [tolerance, met] : panels.front().meets) out << ",meets_" << tolerance;
  }
  out << '\n';
  for (const PanelRecord& p : panels) {
    const PanelGeometry& g = p.geometry;
    out << p.face << ',' << FabList(p.vertices) << ',' << FabNumber(g.flatness);
    if (mm_per_unit > 0) out << ',' << FabNumber(g.flatness * mm_per_unit);
    out << ',' << FabNumber(g.flatness_relative) << ',' << FabNumber(p.pq_normalized) << ','
        << FabNumber(g.area) << ',' << FabList(g.edges) << ',' << FabList(g.angles) << ','
        << FabList(g.diagonals) << ',' << FabNumber(g.projection_change) << ','
        << FabNumber(p.outline_change);
    for (const auto& [tolerance, met] : p.meets) out << ',' << (met ? "yes" : "no");
    out << '\n';
  }
  WriteTextFile(path, out.str(), key);
}

void WriteCuttingDxf(const std::string& path, const SheetLayout& layout,
                     const std::vector<int>& face_ids, const std::string& unit,
                     const std::string& key) {
  std::ostringstream out;
  Group(out, 0, "SECTION");
  Group(out, 2, "HEADER");
  Group(out, 9, "$ACADVER");
  Group(out, 1, "AC1009");
  Group(out, 9, "$INSUNITS");
  Group(out, 70, std::to_string(InsUnits(unit)));
  Group(out, 0, "ENDSEC");
  Group(out, 0, "SECTION");
  Group(out, 2, "TABLES");
  Group(out, 0, "TABLE");
  Group(out, 2, "LAYER");
  Group(out, 70, "3");
  const std::pair<const char*, int> layers[] = {{"SHEETS", 8}, {"PANELS", 7}, {"IDS", 1}};
  for (const auto& [name, color] : layers) {
    Group(out, 0, "LAYER");
    Group(out, 2, name);
    Group(out, 70, "0");
    Group(out, 62, std::to_string(color));
    Group(out, 6, "CONTINUOUS");
  }
  Group(out, 0, "ENDTAB");
  Group(out, 0, "ENDSEC");
  Group(out, 0, "SECTION");
  Group(out, 2, "ENTITIES");
  std::vector<Eigen::Vector2d> origins;
  double x = 0;
  for (const Eigen::Vector2d& sheet : layout.sheets) {
    origins.push_back({x, 0.0});
    const std::vector<Eigen::Vector2d> border = {
        {0, 0}, {sheet.x(), 0}, {sheet.x(), sheet.y()}, {0, sheet.y()}};
    DxfPolyline(out, border, origins.back(), "SHEETS");
    DxfText(out, "sheet " + std::to_string(origins.size()),
            origins.back() + Eigen::Vector2d(0.5 * sheet.x(), -0.03 * sheet.y()), 0.02 * sheet.y(),
            "SHEETS");
    x += sheet.x() * 1.1;
  }
  for (size_t i = 0; i < layout.outlines.size(); ++i) {
    const PlacedOutline& placed = layout.outlines[i];
    const Eigen::Vector2d& origin = origins[size_t(placed.sheet)];
    DxfPolyline(out, placed.corners, origin, "PANELS");
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& c : placed.corners) centre += c;
    centre /= double(placed.corners.size());
    const Eigen::Vector2d size = placed.high - placed.low;
    DxfText(out, std::to_string(face_ids[i]), origin + centre, 0.15 * size.minCoeff(), "IDS");
  }
  Group(out, 0, "ENDSEC");
  Group(out, 0, "EOF");
  WriteTextFile(path, out.str(), key);
}

void WriteNodesCsv(const std::string& path, const std::vector<Eigen::Vector3d>& points,
                   const std::vector<NodeAxis>& nodes, const std::string& key) {
  std::ostringstream out;
  out << "vertex,x,y,z,axis,axis_x,axis_y,axis_z,normal_x,normal_y,normal_z,conical_radians,"
         "face_offset_factor\n";
  for (size_t v = 0; v < nodes.size(); ++v) {
    const NodeAxis& n = nodes[v];
    out << v << ',' << FabNumber(points[v].x()) << ',' << FabNumber(points[v].y()) << ','
        << FabNumber(points[v].z()) << ',' << (n.cone ? "cone" : "normal") << ','
        << FabNumber(n.axis.x()) << ',' << FabNumber(n.axis.y()) << ',' << FabNumber(n.axis.z())
        << ',' << FabNumber(n.normal.x()) << ',' << FabNumber(n.normal.y()) << ','
        << FabNumber(n.normal.z()) << ',' << (n.conical >= 0 ? FabNumber(n.conical) : "") << ','
        << (n.cone ? FabNumber(n.offset_factor) : "") << '\n';
  }
  WriteTextFile(path, out.str(), key);
}

void WriteBeamsCsv(const std::string& path, const std::vector<Beam>& beams,
                   const std::vector<NodeAxis>& nodes, bool far_edges, const std::string& key) {
  std::ostringstream out;
  out << "edge,v0,v1,length,plane_normal_x,plane_normal_y,plane_normal_z,twist_degrees,axis0,"
         "axis1"
      << (far_edges ? ",far0_x,far0_y,far0_z,far1_x,far1_y,far1_z" : "") << '\n';
  for (size_t e = 0; e < beams.size(); ++e) {
    const Beam& b = beams[e];
    out << e << ',' << b.v0 << ',' << b.v1 << ',' << FabNumber(b.length) << ','
        << FabNumber(b.plane_normal.x()) << ',' << FabNumber(b.plane_normal.y()) << ','
        << FabNumber(b.plane_normal.z()) << ',' << FabNumber(b.twist_degrees) << ','
        << (nodes[size_t(b.v0)].cone ? "cone" : "normal") << ','
        << (nodes[size_t(b.v1)].cone ? "cone" : "normal");
    if (far_edges) {
      for (const Eigen::Vector3d* p : {&b.offset0, &b.offset1}) {
        out << ',' << FabNumber(p->x()) << ',' << FabNumber(p->y()) << ',' << FabNumber(p->z());
      }
    }
    out << '\n';
  }
  WriteTextFile(path, out.str(), key);
}

}  // namespace archgeo
