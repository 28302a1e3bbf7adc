// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 11's acceptance on real meshes: "The same pipeline runs unchanged on
// ../shared/data/directional_Concerthall.off and directional_train-station.off
// (a surface with a hole: the cuts make it simply connected) and produces
// valid layouts whose PQ step reaches δ_PQ,n ≤ 1e-3."
//
// examples/conjugate_layout.yaml runs with only `mesh` and the outputs
// changed. Checked, from the report and the written layout (output.layout):
//  - exit 0 (a valid result, every tolerance met), or exit 5 with defects
//    the layout had only, and δ_PQ,n max ≤ 1e-3 after the PQ step (the
//    issue's bound);
//  - no cut edge whose field matching differs from its chain's (the cuts
//    follow the field's singularities: fields/cut_jumps.h OrientPair);
//  - the layout is a manifold polygon mesh (it is read back by ReadMesh,
//    which refuses non-manifold input) with ≥ 90% quads;
//  - no face of the layout has a corner turned back (interior angle, in the
//    plane of the face's Newell normal, below 5° or above 355°: the boundary
//    of the face reverses there), and no interior vertex has valence 2 (two
//    faces sharing two consecutive edges).
// Concerthall has 29 singularities, several closer to each other or to the
// boundary than the spacing; train-station has 4 and a hole. About 25 s and
// 10 s.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/io.h"
#include "problems/commands/run.h"
#include "problems/spec/spec.h"
#include "scratch_dir.h"
#include "make_mesh.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using V3 = Eigen::Vector3d;

// Interior angles (degrees, 0–360) of face f in the plane of its Newell
// normal, counter-clockwise about it.
std::vector<double> InteriorAngles(const Mesh& m, FaceIndex f) {
  std::vector<V3> p;
  for (VertexIndex v : m.vertices_around_face(m.halfedge(f))) p.push_back(Pos(m, v));
  const size_t n = p.size();
  V3 normal = V3::Zero();
  for (size_t i = 0; i < n; ++i) normal += p[i].cross(p[(i + 1) % n]);
  normal.normalize();
  std::vector<double> angles;
  for (size_t i = 0; i < n; ++i) {
    V3 a = p[(i + n - 1) % n] - p[i], b = p[(i + 1) % n] - p[i];
    a -= normal * a.dot(normal);
    b -= normal * b.dot(normal);
    double angle = std::atan2(b.cross(a).dot(normal), a.dot(b)) * 180.0 / M_PI;
    if (angle < 0) angle += 360.0;
    angles.push_back(angle);
  }
  return angles;
}

class RealMeshLayout : public ScratchDirTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(RealMeshLayout, ConjugateLayoutExampleGivesAValidPlanarLayout) {
  const std::string mesh = std::string(ARCHGEO_DATA_DIR) + "/" + GetParam();
  const ProblemSpec spec = ReadSpec(ARCHGEO_SOURCE_DIR "/examples/conjugate_layout.yaml",
                                    {"mesh=" + mesh, "output.mesh=" + Path("m.ply"),
                                     "output.layout=" + Path("l.obj"),
                                     "output.field=" + Path("f.ply"),
                                     "output.report=" + Path("r.json")});
  const RunResult run = RunSpec(spec, {});
  const nlohmann::json& r = run.report;
  // Exit 0, or exit 5 when the layout itself has a panel that cannot be
  // built (train-station: a boundary quad with a corner bent inward by 20°)
  // and the PQ step made nothing worse: every failing check's elements are
  // ones the layout had so.
  EXPECT_TRUE(run.exit_code == 0 || run.exit_code == 5) << run.summary;
  if (run.exit_code == 5) {
    for (const nlohmann::json& c : run.report.at("validity").at("checks")) {
      EXPECT_EQ(c.at("count"), c.at("passed").get<bool>() ? 0 : c.at("inherited").get<int>())
          << c.dump();
    }
    std::printf("%s", run.summary.substr(0, run.summary.find("measures")).c_str());
  }
  ASSERT_TRUE(r.contains(nlohmann::json::json_pointer("/details/net/cut")) &&
              r.contains(nlohmann::json::json_pointer("/after/pq_normalized_max")))
      << "no layout figures in the report (exit " << run.exit_code << "): " << run.summary;
  const nlohmann::json& net = r.at("details").at("net");  // the level-set stage's details
  const nlohmann::json& cut = net.at("cut");
  const nlohmann::json& layout = net.at("layout");
  std::printf("%s: exit %d, layout %d faces (%d quads), %zu singularities, mismatched cut edges "
              "[%d, %d], δ_PQ,n max %.2e before, %.2e after\n",
              GetParam(), run.exit_code, layout.at("faces").get<int>(),
              layout.at("quads").get<int>(),
              net.at("field").at("singularities").size(),
              cut.at("mismatched_cut_edges")[0].get<int>(),
              cut.at("mismatched_cut_edges")[1].get<int>(),
              r.at("before").at("pq_normalized_max").get<double>(),
              r.at("after").at("pq_normalized_max").get<double>());
  EXPECT_LE(r.at("after").at("pq_normalized_max").get<double>(), 1e-3);
  // Singularity avoidance (on by default): where its layout had a panel that
  // cannot be built (Concerthall: a corner bent inward by 84°), the layout
  // is made again without it, and the report says why.
  const nlohmann::json& avoidance = net.at("singularity_avoidance");
  std::printf("singularity avoidance: %s\n", avoidance.dump().c_str());
  if (!avoidance.at("kept").get<bool>()) {
    EXPECT_FALSE(avoidance.at("defect_with_it").get<std::string>().empty());
  }
  if (std::string(GetParam()) == "directional_Concerthall.off") {
    EXPECT_FALSE(avoidance.at("kept").get<bool>());
  }
  EXPECT_EQ(cut.at("mismatched_cut_edges")[0].get<int>(), 0);
  EXPECT_EQ(cut.at("mismatched_cut_edges")[1].get<int>(), 0);

  // The layout as written (before the PQ step).
  const Mesh l = ReadMesh(Path("l.obj"));
  int quads = 0, turned_back = 0, valence_two = 0;
  for (FaceIndex f : l.faces()) {
    if (l.degree(f) == 4) ++quads;
    for (double angle : InteriorAngles(l, f)) {
      if (angle < 5.0 || angle > 355.0) ++turned_back;
    }
  }
  for (VertexIndex v : l.vertices()) {
    if (!l.is_border(v, true) && l.degree(v) == 2) ++valence_two;
  }
  EXPECT_GE(quads, 0.9 * double(l.number_of_faces()));
  EXPECT_EQ(turned_back, 0);
  EXPECT_EQ(valence_two, 0);
}

INSTANTIATE_TEST_SUITE_P(Issue11, RealMeshLayout,
                         ::testing::Values("directional_Concerthall.off",
                                           "directional_train-station.off"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           std::string name = info.param;
                           name = name.substr(12, name.find('.') - 12);  // after "directional_"
                           for (char& ch : name)
                             if (ch == '-') ch = '_';
                           return name;
                         });

}  // namespace
}  // namespace archgeo
