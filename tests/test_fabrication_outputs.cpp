// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The fabrication outputs end to end through the `archgeo` binary
// (issue 46, item 3): examples/planar_quads.yaml with `units: mm` on a
// generated roof at building size (about 11.8 m across, in millimetres).
// Every file is read back here by code of its own (a CSV splitter, a DXF
// group-code reader, an SVD plane fit) and checked against the output mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SVD>
#include <nlohmann/json.hpp>

#include "io/io.h"
#include "tests/scratch_dir.h"
#include "tests/segments_meet.h"
#include "tests/shell.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

// A CSV file as a header → column map per row (fields hold no commas).
struct Csv {
  std::vector<std::map<std::string, std::string>> rows;
};
Csv ReadCsv(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> header;
  Csv csv;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream parts(line);
    for (std::string f; std::getline(parts, f, ',');) fields.push_back(f);
    if (!line.empty() && line.back() == ',') fields.push_back("");
    if (header.empty()) {
      header = fields;
      continue;
    }
    EXPECT_EQ(fields.size(), header.size()) << line;
    std::map<std::string, std::string> row;
    for (size_t i = 0; i < header.size() && i < fields.size(); ++i) row[header[i]] = fields[i];
    csv.rows.push_back(row);
  }
  return csv;
}

std::vector<double> Numbers(const std::string& list) {
  std::vector<double> values;
  std::stringstream parts(list);
  for (std::string f; std::getline(parts, f, ';');) values.push_back(std::stod(f));
  return values;
}

std::vector<Eigen::Vector3d> Corners(const Mesh& mesh, FaceIndex f) {
  std::vector<Eigen::Vector3d> corners;
  for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
    corners.emplace_back(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z());
  }
  return corners;
}

// The largest distance of a corner from the least-squares plane, by SVD of
// the centred corners (the plane's normal: the last right singular vector).
double CornerToPlane(const std::vector<Eigen::Vector3d>& corners) {
  Eigen::MatrixXd centred(corners.size(), 3);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& c : corners) mean += c / double(corners.size());
  for (size_t k = 0; k < corners.size(); ++k)
    centred.row(Eigen::Index(k)) = (corners[k] - mean).transpose();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(centred, Eigen::ComputeFullV);
  const Eigen::Vector3d normal = svd.matrixV().col(2);
  double worst = 0;
  for (const auto& c : corners) worst = std::max(worst, std::abs(normal.dot(c - mean)));
  return worst;
}

// The DXF's entities as (code, value) groups, read two lines at a time.
struct DxfEntity {
  std::string type, layer, text;
  std::vector<Eigen::Vector2d> points;  // POLYLINE: its VERTEXes; TEXT: its insertion point
  bool closed = false;
};
std::vector<DxfEntity> ReadDxfEntities(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::pair<int, std::string>> groups;
  for (std::string code, value; std::getline(in, code) && std::getline(in, value);) {
    groups.push_back({std::stoi(code), value});
  }
  std::vector<DxfEntity> entities;
  bool in_entities = false;
  DxfEntity* polyline = nullptr;
  for (size_t i = 0; i < groups.size(); ++i) {
    const auto& [code, value] = groups[i];
    if (code == 2 && value == "ENTITIES") in_entities = true;
    if (!in_entities || code != 0) continue;
    if (value == "ENDSEC") break;
    std::map<int, std::string> g;
    for (size_t j = i + 1; j < groups.size() && groups[j].first != 0; ++j)
      g[groups[j].first] = groups[j].second;
    if (value == "POLYLINE") {
      entities.push_back({"POLYLINE", g[8], "", {}, (std::stoi(g[70]) & 1) != 0});
      polyline = &entities.back();
    } else if (value == "VERTEX") {
      EXPECT_NE(polyline, nullptr);
      if (polyline) polyline->points.push_back({std::stod(g[10]), std::stod(g[20])});
    } else if (value == "SEQEND") {
      polyline = nullptr;
    } else if (value == "TEXT") {
      entities.push_back({"TEXT", g[8], g[1], {{std::stod(g[11]), std::stod(g[21])}}, false});
    } else {
      ADD_FAILURE() << "unexpected entity " << value;
    }
  }
  return entities;
}

bool Inside(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p) {
  bool inside = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

// Whether two closed outlines share any point: an edge crossing or touching
// one of the other's, or one inside the other.
bool Overlap(const std::vector<Eigen::Vector2d>& p, const std::vector<Eigen::Vector2d>& q) {
  for (size_t a = 0; a < p.size(); ++a) {
    for (size_t b = 0; b < q.size(); ++b) {
      if (SegmentsMeet(p[a], p[(a + 1) % p.size()], q[b], q[(b + 1) % q.size()])) return true;
    }
  }
  return Inside(p, q[0]) || Inside(q, p[0]);
}

class FabricationOutputs : public ScratchDirTest {
 protected:
  void SetUp() override {
    ScratchDirTest::SetUp();
    // The roof of `archgeo generate` (diagonal 2.94) × 4000: 11.8 m in mm,
    // 80 quads of about 0.84 m, δ_PQ,n up to 6.3e-2.
    const Outcome g = Shell(std::string(ARCHGEO_BINARY) + " generate " + Path("roof.obj") +
                            " --nu 10 --nv 8 --noise 0.1 --scale 4000");
    ASSERT_EQ(g.code, 0) << g.output;
  }
  Outcome Solve(const std::string& extra) const {
    return Shell(std::string(ARCHGEO_BINARY) +
                 " solve " ARCHGEO_SOURCE_DIR "/examples/planar_quads.yaml --set mesh=" +
                 Path("roof.obj") + " --set output.mesh=" + Path("out.obj") +
                 " --set output.image= --set output.report=" + Path("report.json") + " " + extra);
  }
  nlohmann::json Report() const { return nlohmann::json::parse(ReadFile(Path("report.json"))); }
};

// Acceptance of issue 46, item 3: the panel table's flatness in mm equals
// the corner-to-plane distances of the output mesh, the DXF's outlines have
// the panels' edge lengths to 1e-9 and no two overlap, the node axes are the
// area-weighted vertex normals.
TEST_F(FabricationOutputs, PlanarQuadsExampleInMillimetres) {
  const Outcome o = Solve(
      "--set units=mm --set tolerance.flatness_mm=2 --set output.panels=" + Path("panels.csv") +
      " --set output.cutting=" + Path("panels.dxf") + " --set output.nodes=" + Path("nodes.csv"));
  ASSERT_EQ(o.code, 0) << o.output;
  const Mesh mesh = ReadMesh(Path("out.obj"));
  ASSERT_EQ(mesh.number_of_faces(), 80u);
  const nlohmann::json report = Report();
  EXPECT_TRUE(report["tolerances"]["tolerance.flatness_mm"]["met"].get<bool>());
  const Outcome schema = Shell("/usr/bin/python3 " ARCHGEO_SOURCE_DIR
                               "/tests/test_report_schema_validate.py " ARCHGEO_SOURCE_DIR
                               "/docs/report.schema.json " +
                               Path("report.json"));
  EXPECT_EQ(schema.code, 0) << schema.output;

  // panels.csv
  const Csv panels = ReadCsv(ReadFile(Path("panels.csv")));
  ASSERT_EQ(panels.rows.size(), mesh.number_of_faces());
  double worst = 0;
  for (FaceIndex f : mesh.faces()) {
    const std::map<std::string, std::string>& row = panels.rows[f.idx()];
    EXPECT_EQ(std::stoi(row.at("panel")), int(f.idx()));
    std::string ids;
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      ids += (ids.empty() ? "" : ";") + std::to_string(v.idx());
    }
    EXPECT_EQ(row.at("vertices"), ids);
    const std::vector<Eigen::Vector3d> corners = Corners(mesh, f);
    const double flatness = CornerToPlane(corners);
    EXPECT_NEAR(std::stod(row.at("flatness_mm")), flatness, 1e-9 * 840) << "panel " << f.idx();
    EXPECT_EQ(row.at("flatness_mm"), row.at("flatness"));  // the mesh is in mm
    worst = std::max(worst, flatness);
    const std::vector<double> edges = Numbers(row.at("edges"));
    ASSERT_EQ(edges.size(), 4u);
    for (size_t k = 0; k < 4; ++k)
      EXPECT_NEAR(edges[k] / (corners[(k + 1) % 4] - corners[k]).norm(), 1, 1e-12);
    const std::vector<double> diagonals = Numbers(row.at("diagonals"));
    EXPECT_NEAR(diagonals[1], (corners[3] - corners[1]).norm(), 1e-9);
    double angles = 0;
    for (double a : Numbers(row.at("angles_degrees"))) angles += a;
    EXPECT_NEAR(angles, 360.0, 0.1);  // a near-planar convex quad
    EXPECT_EQ(row.at("meets_flatness_mm"), std::stod(row.at("flatness_mm")) <= 2 ? "yes" : "no");
    EXPECT_EQ(row.at("meets_pq_normalized_max"),
              std::stod(row.at("pq_normalized")) <= 1e-3 ? "yes" : "no");
  }
  EXPECT_GT(worst, 0.01);  // near-planar, not planar: the outlines below are developed
  EXPECT_NEAR(report["fabrication"]["flatness_max_mm"].get<double>(), worst, 1e-9 * 840);

  // panels.dxf
  std::vector<std::vector<Eigen::Vector2d>> outlines, sheets;
  std::vector<std::pair<int, Eigen::Vector2d>> labels;
  for (const DxfEntity& e : ReadDxfEntities(ReadFile(Path("panels.dxf")))) {
    if (e.type == "POLYLINE" && e.layer == "PANELS") {
      EXPECT_TRUE(e.closed);
      outlines.push_back(e.points);
    }
    if (e.type == "POLYLINE" && e.layer == "SHEETS") sheets.push_back(e.points);
    if (e.type == "TEXT" && e.layer == "IDS") labels.push_back({std::stoi(e.text), e.points[0]});
  }
  ASSERT_EQ(outlines.size(), mesh.number_of_faces());
  ASSERT_EQ(labels.size(), mesh.number_of_faces());
  EXPECT_EQ(sheets.size(), report["fabrication"]["sheets"].get<size_t>());
  EXPECT_GE(sheets.size(), 2u);
  std::vector<bool> seen(mesh.number_of_faces(), false);
  for (const auto& [id, at] : labels) {
    std::vector<size_t> holders;  // the outline(s) the label is in
    for (size_t i = 0; i < outlines.size(); ++i) {
      if (Inside(outlines[i], at)) holders.push_back(i);
    }
    ASSERT_EQ(holders.size(), 1u) << "label " << id;
    ASSERT_FALSE(seen[size_t(id)]);
    seen[size_t(id)] = true;
    const std::vector<Eigen::Vector2d>& outline = outlines[holders[0]];
    const std::vector<Eigen::Vector3d> corners = Corners(mesh, FaceIndex(id));
    ASSERT_EQ(outline.size(), corners.size());
    for (size_t k = 0; k < corners.size(); ++k) {
      const double edge = (corners[(k + 1) % corners.size()] - corners[k]).norm();
      EXPECT_NEAR((outline[(k + 1) % outline.size()] - outline[k]).norm() / edge, 1.0, 1e-9)
          << "panel " << id << " edge " << k;
    }
    size_t on_sheets = 0;  // within one sheet
    for (const auto& sheet : sheets) {
      bool all = true;
      for (const Eigen::Vector2d& c : outline) all = all && Inside(sheet, c);
      on_sheets += all;
    }
    EXPECT_EQ(on_sheets, 1u) << "panel " << id;
  }
  for (size_t i = 0; i < outlines.size(); ++i) {
    for (size_t j = i + 1; j < outlines.size(); ++j) {
      EXPECT_FALSE(Overlap(outlines[i], outlines[j])) << "outlines " << i << " and " << j;
    }
  }

  // nodes.csv
  const Csv nodes = ReadCsv(ReadFile(Path("nodes.csv")));
  ASSERT_EQ(nodes.rows.size(), mesh.number_of_vertices());
  for (VertexIndex v : mesh.vertices()) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();  // Σ over faces of 2 × vector area
    for (FaceIndex f : CGAL::faces_around_target(mesh.halfedge(v), mesh)) {
      if (f == Mesh::null_face()) continue;
      const std::vector<Eigen::Vector3d> c = Corners(mesh, f);
      for (size_t k = 0; k < c.size(); ++k) sum += c[k].cross(c[(k + 1) % c.size()]);
    }
    const std::map<std::string, std::string>& row = nodes.rows[v.idx()];
    EXPECT_EQ(row.at("axis"), "normal");
    const Eigen::Vector3d axis(std::stod(row.at("axis_x")), std::stod(row.at("axis_y")),
                               std::stod(row.at("axis_z")));
    EXPECT_NEAR((axis - sum.normalized()).norm(), 0.0, 1e-9) << "vertex " << v.idx();
    EXPECT_NEAR(std::stod(row.at("x")), mesh.point(v).x(), 1e-9);
  }
}

// tolerance.flatness_mm is a tolerance like δ_PQ,n's: tighter than what
// δ_PQ,n ≤ 1e-3 gives (0.64 mm), the run goes on until it holds.
TEST_F(FabricationOutputs, FlatnessInMillimetresIsEnforced) {
  const std::string panels = " --set output.panels=" + Path("panels.csv");
  ASSERT_EQ(Solve("--set units=mm" + panels).code, 0);
  const double relative_only = Report()["fabrication"]["flatness_max_mm"].get<double>();
  const double bound = 0.05;
  ASSERT_GT(relative_only, 2 * bound);
  const Outcome o = Solve("--set units=mm --set tolerance.flatness_mm=0.05" + panels);
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_LE(Report()["fabrication"]["flatness_max_mm"].get<double>(), bound);
  EXPECT_TRUE(Report()["tolerances"]["tolerance.flatness_mm"]["met"].get<bool>());
  for (const auto& row : ReadCsv(ReadFile(Path("panels.csv"))).rows)
    EXPECT_EQ(row.at("meets_flatness_mm"), "yes");
}

// The same roof in metres: the tolerance in millimetres is converted
// (0.05 mm = 5e-5 m); out of reach, the run exits 4 for it.
TEST_F(FabricationOutputs, FlatnessInMillimetresOnAMeshInMetres) {
  const std::string panels = " --set output.panels=" + Path("panels.csv");
  ASSERT_EQ(Shell(std::string(ARCHGEO_BINARY) + " generate " + Path("roof.obj") +
                  " --nu 10 --nv 8 --noise 0.1 --scale 4")
                .code,
            0);
  ASSERT_EQ(Solve("--set units=m --set tolerance.flatness_mm=0.05" + panels).code, 0);
  EXPECT_LE(Report()["fabrication"]["flatness_max"].get<double>(), 5e-5);
  EXPECT_NEAR(Report()["fabrication"]["flatness_max_mm"].get<double>(),
              1000 * Report()["fabrication"]["flatness_max"].get<double>(), 1e-12);
  // δ_PQ,n ≤ 0.5 holds from the start, flatness 1e-9 mm not after one round:
  // exit 4 for the flatness alone.
  const Outcome missed = Solve(
      "--set units=m --set tolerance.pq_normalized_max=0.5 "
      "--set tolerance.flatness_mm=1e-9 --set schedule.outer_iterations=1");
  EXPECT_EQ(missed.code, 4) << missed.output;
  EXPECT_TRUE(Report()["tolerances"]["tolerance.pq_normalized_max"]["met"].get<bool>());
  EXPECT_FALSE(Report()["tolerances"]["tolerance.flatness_mm"]["met"].get<bool>());
  EXPECT_NE(missed.output.find("tolerance tolerance.flatness_mm <= 1e-09: NOT met"),
            std::string::npos)
      << missed.output;
}

TEST_F(FabricationOutputs, MillimetresWithoutUnitsAreRefused) {
  const Outcome tolerance = Solve("--set tolerance.flatness_mm=2");
  EXPECT_EQ(tolerance.code, 2);
  EXPECT_NE(tolerance.output.find("tolerance.flatness_mm"), std::string::npos) << tolerance.output;
  EXPECT_NE(tolerance.output.find("units"), std::string::npos);
  const Outcome cutting = Solve("--set output.cutting=" + Path("panels.dxf"));
  EXPECT_EQ(cutting.code, 2);
  EXPECT_NE(cutting.output.find("output.cutting"), std::string::npos) << cutting.output;
  const Outcome depth = Solve("--set beams.depth=200 --set output.beams=" + Path("beams.csv"));
  EXPECT_EQ(depth.code, 2);
  EXPECT_NE(depth.output.find("beams.depth"), std::string::npos) << depth.output;
  EXPECT_FALSE(std::filesystem::exists(Path("beams.csv")));
  const Outcome named = Solve("--set units=mm --set output.panels=" + Path("panels.txt"));
  EXPECT_EQ(named.code, 2);
  EXPECT_NE(named.output.find(".csv"), std::string::npos) << named.output;
  EXPECT_FALSE(std::filesystem::exists(Path("out.obj")));
}

// A conical mesh (the principal net of a torus, conical by symmetry) solved
// with the conical term: its nodes get the cones' axes and its beams no twist.
TEST_F(FabricationOutputs, ConicalNetGetsConeAxes) {
  ASSERT_EQ(Shell(std::string(ARCHGEO_BINARY) + " generate " + Path("torus.obj") +
                  " --surface torus --nu 24 --nv 12")
                .code,
            0);
  const std::string spec = WriteFile(
      "conical.yaml",
      "problem: custom\nmesh: torus.obj\nterms: {conical: 1, pq_diagonal: 1, anchor: 0.01}\n"
      "tolerance: {conical_max: 1.0e-6, pq_normalized_max: 1.0e-6}\n"
      "units: m\nbeams: {depth: 150}\n"
      "output: {nodes: nodes.csv, beams: beams.csv, report: report.json}\n");
  const Outcome o = Shell(std::string(ARCHGEO_BINARY) + " solve " + spec);
  ASSERT_EQ(o.code, 0) << o.output;
  const Csv nodes = ReadCsv(ReadFile(Path("nodes.csv")));
  ASSERT_EQ(nodes.rows.size(), 24u * 12u);
  for (const auto& row : nodes.rows) {
    EXPECT_EQ(row.at("axis"), "cone");
    EXPECT_LE(std::stod(row.at("conical_radians")), 1e-6);
    EXPECT_GT(std::stod(row.at("face_offset_factor")), 1.0 - 1e-12);
  }
  // The cone's axis is not the area-weighted normal where the faces above
  // and below a parallel differ in size.
  double apart = 0;
  for (const auto& row : nodes.rows) {
    const Eigen::Vector3d axis(std::stod(row.at("axis_x")), std::stod(row.at("axis_y")),
                               std::stod(row.at("axis_z")));
    const Eigen::Vector3d normal(std::stod(row.at("normal_x")), std::stod(row.at("normal_y")),
                                 std::stod(row.at("normal_z")));
    apart = std::max(apart, (axis - normal).norm());
  }
  EXPECT_GT(apart, 1e-3);
  const Csv beams = ReadCsv(ReadFile(Path("beams.csv")));
  ASSERT_EQ(beams.rows.size(), 2u * 24u * 12u);
  for (const auto& row : beams.rows) EXPECT_LE(std::stod(row.at("twist_degrees")), 1e-6);
  // The far edges 150 mm along the cone axes, where the faces offset by
  // 0.15 m meet: at 0.15 · face_offset_factor along the axis.
  const auto Column = [](const std::map<std::string, std::string>& row, const std::string& name) {
    const std::string p = name.empty() ? "" : name + "_";
    return Eigen::Vector3d(std::stod(row.at(p + "x")), std::stod(row.at(p + "y")),
                           std::stod(row.at(p + "z")));
  };
  for (const auto& row : beams.rows) {
    for (const char* end : {"0", "1"}) {
      const auto& node = nodes.rows.at(size_t(std::stoi(row.at(std::string("v") + end))));
      const Eigen::Vector3d expected =
          Column(node, "") + 0.15 * std::stod(node.at("face_offset_factor")) * Column(node, "axis");
      EXPECT_LE((Column(row, std::string("far") + end) - expected).norm(), 1e-9);
    }
  }
  // Within 1 µm of the faces offset by 150 mm (the conical residual is 1e-6).
  EXPECT_LE(Report().at("fabrication").at("beam_far_edge_face_offset_error_max_mm").get<double>(),
            1e-3);
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
