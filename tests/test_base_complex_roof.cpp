// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// End to end: the Shanghai roof workflow [Gebreiter 2012, §11.2] as its three
// example steps run it — a hand-drawn triangle base complex with three
// valence-7 nodes, Loop-subdivided onto its perimeter curve
// (examples/base_complex_roof.yaml), form found as a hanging net
// (examples/base_complex_roof_form.yaml), remeshed (examples/remesh.yaml).
#include <cmath>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "geometry/isotropic_remesh.h"
#include "geometry/reference.h"
#include "io/io.h"
#include "tests/scratch_dir.h"
#include "tests/shell.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

class BaseComplexRoof : public ScratchDirTest {
 protected:
  Outcome Solve(const std::string& example, const std::string& out, const std::string& sets = "") {
    return Shell(std::string(ARCHGEO_BINARY) + " solve " + ARCHGEO_SOURCE_DIR + "/examples/" + example +
                 " --quiet --set output.mesh=" + Path(out + ".obj") + " --set output.report=" + Path(out + ".json") +
                 " " + sets);
  }
  nlohmann::json Details(const std::string& out) {
    return nlohmann::json::parse(std::ifstream(Path(out + ".json"))).at("details");
  }
};

TEST_F(BaseComplexRoof, ThreeStepsKeepTheValenceSevenNodesThePerimeterAndBalance) {
  // 1. Subdivision: Loop keeps the base complex's interior valences (3 × 7)
  // and gives every new interior vertex valence 6.
  const Outcome sub = Solve("base_complex_roof.yaml", "sub");
  ASSERT_EQ(sub.code, 0) << sub.output;
  const nlohmann::json s = Details("sub").at("subdivision");
  EXPECT_LE(s.at("curve_distance_max_relative").get<double>(), 1e-9);
  EXPECT_LE(s.at("mean_edge_length").get<double>(), 0.8);
  const Mesh fine = ReadMesh(Path("sub.obj"));
  std::map<int, int> interior_valences;
  for (VertexIndex v : fine.vertices()) {
    if (!fine.is_border(v)) ++interior_valences[int(fine.degree(v))];
  }
  EXPECT_EQ(interior_valences.size(), 2u);
  EXPECT_EQ(interior_valences[7], 3);
  EXPECT_GT(interior_valences[6], 1000);
  // The committed input of step 2 is step 1's output.
  const Mesh committed = ReadMesh(std::string(ARCHGEO_SOURCE_DIR) + "/examples/base_complex_roof_subdivided.obj");
  ASSERT_EQ(committed.number_of_vertices(), fine.number_of_vertices());
  ASSERT_EQ(committed.number_of_faces(), fine.number_of_faces());
  for (VertexIndex v : fine.vertices()) {
    EXPECT_LE(std::sqrt(CGAL::squared_distance(fine.point(v), committed.point(v))), 1e-9);
  }
  // 2. Form finding: in balance, the perimeter where it was, a vault.
  const Outcome form = Solve("base_complex_roof_form.yaml", "vault", "--set mesh=" + Path("sub.obj"));
  ASSERT_EQ(form.code, 0) << form.output;
  const nlohmann::json load = Details("vault").at("load");
  EXPECT_LE(load.at("force_balance_max").get<double>(), 1e-9);
  EXPECT_EQ(load.at("supports").get<int>(), s.at("curve_vertices").get<int>());
  EXPECT_GT(load.at("rise").get<double>(), 0.05 * load.at("span").get<double>());
  const Mesh vault = ReadMesh(Path("vault.obj"));
  for (VertexIndex v : vault.vertices()) {
    if (vault.is_border(v)) {
      EXPECT_EQ(vault.point(v), fine.point(v));
    }
  }
  // 3. Remeshing the vault: even, well-shaped triangles.
  const Outcome remeshed = Solve("remesh.yaml", "remeshed", "--set mesh=" + Path("vault.obj"));
  ASSERT_EQ(remeshed.code, 0) << remeshed.output;
  const nlohmann::json r = Details("remeshed").at("remesh");
  EXPECT_GE(r.at("min_angle_30_fraction").get<double>(), 0.99);
  EXPECT_LE(r.at("edge_length_cv").get<double>(), 0.12);
  // Beside them, the input's own (the vault as read, triangulated).
  const Mesh vault_triangles = TriangulatedCopy(vault);
  const TriangleQuality in = MeasureTriangles(vault_triangles);
  const nlohmann::json& input = r.at("input");
  EXPECT_EQ(input.at("triangles").get<size_t>(), size_t(vault_triangles.number_of_faces()));
  EXPECT_DOUBLE_EQ(input.at("min_angle_degrees").get<double>(), in.min_angle_degrees);
  EXPECT_DOUBLE_EQ(input.at("edge_length_cv").get<double>(), in.edge_cv);
  EXPECT_NE(remeshed.output.find("triangles: input " + std::to_string(vault_triangles.number_of_faces())),
            std::string::npos)
      << remeshed.output;
  // No solve: the metrics table has one column, not a "before" equal to "after".
  const size_t header = remeshed.output.find("\nmetric ");
  ASSERT_NE(header, std::string::npos) << remeshed.output;
  const std::string line = remeshed.output.substr(header + 1, remeshed.output.find('\n', header + 1) - header - 1);
  EXPECT_NE(line.find("value"), std::string::npos) << line;
  EXPECT_EQ(line.find("after"), std::string::npos) << line;
}

// A feature curve along no edge of the input is refused naming the file and
// the key, and nothing is written.
TEST_F(BaseComplexRoof, RemeshRefusesAFeatureCurveOffTheInputEdges) {
  {
    std::ofstream curve(Path("curve.obj"));
    curve << "v -10 0.3 1\nv 10 0.7 1.2\nl 1 2\n";
  }
  const Outcome o = Solve("remesh.yaml", "refused", "--set remesh.features=" + Path("curve.obj"));
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find("remesh.features"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("curve.obj"), std::string::npos) << o.output;
  EXPECT_FALSE(std::ifstream(Path("refused.obj")).good());
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
