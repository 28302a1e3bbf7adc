// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// conjugate_layout with layout.method: streamlines end to end
// (problems/declarations/streamline_layout.h, [Gebreiter 2012, §8.2]): a
// waisted surface of revolution (its conjugate field the meridians and
// parallels, no singularity) laid out from the crossings of its streamlines,
// cleaned up, made planar and judged like the level-set layout. The layout
// written by output.layout is the streamline mesh, its faces the report's.
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "generators/smoothness_surfaces.h"
#include "io/io.h"
#include "problems/commands/run.h"
#include "problems/spec/spec.h"
#include "scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

class StreamlineLayoutTest : public ScratchDirTest {};

TEST_F(StreamlineLayoutTest, SurfaceOfRevolutionIsLaidOutFromStreamlineCrossings) {
  // Waisted (negative curvature everywhere: no umbilic, so no singularity).
  RevolutionProfile profile;
  profile.r1 = 0.9;
  profile.bulge = -0.15;
  WriteMesh(Path("design.obj"), RevolutionTriangles(profile, 48, 16));
  const std::string spec =
      WriteFile("spec.yaml", "mesh: design.obj\nproblem: conjugate_layout\n"
                             "layout: {method: streamlines}\nlevel_sets: {target_faces: 150}\n"
                             "output: {mesh: m.obj, layout: l.obj, report: r.json}\n");
  const RunResult run = RunSpec(ReadSpec(spec), {});
  const nlohmann::json& r = run.report;
  const nlohmann::json& net = r.at("details").at("net");
  const nlohmann::json& layout = net.at("layout");
  const nlohmann::json& mesh = net.at("streamline_mesh");
  std::printf("streamline layout: %d faces, quads %.3f, edge-to-field angle mean %.3f°, "
              "crossings %d, T-ends %d, dangling %d; exit %d, δ_PQ,n max after %.2e\n",
              layout.at("faces").get<int>(), layout.at("quad_fraction").get<double>(),
              layout.at("edge_field_angle_mean_deg").get<double>(),
              mesh.at("crossings").get<int>(), mesh.at("extended_ends").get<int>(),
              mesh.at("dangling_ends").get<int>(), run.exit_code,
              r.at("after").at("pq_normalized_max").get<double>());
  EXPECT_EQ(net.at("method"), "streamlines");
  EXPECT_GE(layout.at("faces").get<int>(), 100);
  EXPECT_GE(layout.at("quad_fraction").get<double>(), 0.95);
  EXPECT_LE(layout.at("edge_field_angle_mean_deg").get<double>(), 2.0);
  EXPECT_GE(mesh.at("crossings").get<int>(), 80);
  // The layout written is the streamline mesh the PQ step started from.
  ASSERT_TRUE(std::filesystem::exists(Path("l.obj")));
  const Mesh written = ReadMesh(Path("l.obj"));
  EXPECT_EQ(int(written.number_of_faces()), r.at("before").at("faces").get<int>());
  EXPECT_EQ(run.exit_code, 0) << run.summary;
  EXPECT_LE(r.at("after").at("pq_normalized_max").get<double>(), 1e-3);
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
