// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Welding coincident vertices on reading (io/weld.h, limits.weld_distance):
//  - the weld itself: shared corners merged, file order kept, unused vertices
//    left alone, distance 0 = off;
//  - a per-face-vertices export of a shared mesh reads as the welded file
//    (same faces, same corners) and planar_quads gives the same result on
//    both (corners to 1e-12), the weld counted in the report with a warning;
//  - a weld that collapses a face is bad input naming limits.weld_distance.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "io/io.h"
#include "io/weld.h"
#include "problems/commands/run.h"
#include "problems/spec/spec.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

constexpr const char* kConjugate = ARCHGEO_DATA_DIR "/libigl_inspired_mesh_quads_Conjugate.off";

// `mesh` written as OBJ with every face its own corner vertices.
void WriteUnwelded(const Mesh& mesh, const std::string& path) {
  std::ofstream out(path);
  out.precision(17);
  for (FaceIndex f : mesh.faces()) {
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) {
      const Point& p = mesh.point(v);
      out << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
    }
  }
  std::size_t next = 1;
  for (FaceIndex f : mesh.faces()) {
    out << "f";
    for (std::size_t k = 0; k < mesh.degree(f); ++k) out << " " << next++;
    out << "\n";
  }
}

// The largest distance between corresponding corners of the faces of a and b
// (same face order and corner order).
double CornerDistance(const Mesh& a, const Mesh& b) {
  EXPECT_EQ(a.number_of_faces(), b.number_of_faces());
  double worst = 0;
  auto fb = b.faces().begin();
  for (FaceIndex f : a.faces()) {
    auto vb = b.vertices_around_face(b.halfedge(*fb)).begin();
    for (VertexIndex v : a.vertices_around_face(a.halfedge(f))) {
      worst = std::max(worst, std::sqrt(CGAL::squared_distance(a.point(v), b.point(*vb))));
      ++vb;
    }
    ++fb;
  }
  return worst;
}

TEST(Weld, SharedCornersMergeInFileOrderAndUnusedVerticesStay) {
  // Two triangles with their own corners sharing the edge (1,0,0)-(0,1,0);
  // vertex 6 coincides with vertex 0 but no face uses it.
  std::vector<std::array<double, 3>> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0},
                                               {1, 1, 0}, {0, 1, 0}, {0, 0, 0}};
  std::vector<std::vector<std::size_t>> polygons = {{0, 1, 2}, {3, 4, 5}};
  EXPECT_EQ(WeldCoincidentVertices(&points, &polygons, 1e-6), 2u);
  ASSERT_EQ(points.size(), 5u);
  EXPECT_EQ(polygons[0], (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(polygons[1], (std::vector<std::size_t>{1, 3, 2}));
  EXPECT_EQ(points[3], (std::array<double, 3>{1, 1, 0}));
  EXPECT_EQ(points[4], (std::array<double, 3>{0, 0, 0}));  // unused: kept, not welded
  // Within the distance (relative to the mean edge), not beyond it.
  std::vector<std::array<double, 3>> near = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                             {1 + 1e-9, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  std::vector<std::vector<std::size_t>> two = {{0, 1, 2}, {3, 4, 5}};
  std::vector<std::array<double, 3>> far = near;
  std::vector<std::vector<std::size_t>> two_far = two;
  EXPECT_EQ(WeldCoincidentVertices(&near, &two, 1e-6), 2u);
  EXPECT_EQ(WeldCoincidentVertices(&far, &two_far, 1e-10), 1u);  // only (0,1,0)
  EXPECT_EQ(WeldCoincidentVertices(&far, &two_far, 0), 0u);
}

class WeldTest : public ScratchDirTest {};

TEST_F(WeldTest, APerFaceVerticesExportReadsAsTheWeldedFile) {
  const Mesh welded = ReadMesh(kConjugate);
  WriteUnwelded(welded, Path("unwelded.obj"));
  ReadInfo info;
  const Mesh read = ReadMesh(Path("unwelded.obj"), &info);
  std::size_t corners = 0;
  for (FaceIndex f : welded.faces()) corners += welded.degree(f);
  EXPECT_EQ(read.number_of_vertices(), welded.number_of_vertices());
  EXPECT_EQ(std::size_t(info.welded_vertices), corners - welded.number_of_vertices());
  EXPECT_EQ(CornerDistance(welded, read), 0.0);
  ReadLimits off;
  off.weld_distance = 0;
  EXPECT_EQ(ReadMesh(Path("unwelded.obj"), &info, off).number_of_vertices(), corners);
  EXPECT_EQ(info.welded_vertices, 0);
}

TEST_F(WeldTest, PlanarQuadsGivesTheSameResultOnTheUnweldedExport) {
  WriteUnwelded(ReadMesh(kConjugate), Path("unwelded.obj"));
  const auto run = [&](const std::string& mesh, const std::string& out) {
    return RunSpec(ReadSpec(ARCHGEO_SOURCE_DIR "/examples/planar_quads.yaml",
                            {"mesh=" + mesh, "output.mesh=" + Path(out), "output.image=",
                             "output.report="}),
                   {});
  };
  const RunResult a = run(kConjugate, "a.obj");
  const RunResult b = run(Path("unwelded.obj"), "b.obj");
  ASSERT_EQ(a.exit_code, 0) << a.summary;
  ASSERT_EQ(b.exit_code, 0) << b.summary;
  EXPECT_EQ(a.report["input"]["welded_vertices"].get<int>(), 0);
  EXPECT_GT(b.report["input"]["welded_vertices"].get<int>(), 0);
  EXPECT_NE(b.summary.find("welded on reading"), std::string::npos);
  EXPECT_LE(CornerDistance(ReadMesh(Path("a.obj")), ReadMesh(Path("b.obj"))), 1e-12);
  EXPECT_NEAR(a.report["objective"]["total"].get<double>(),
              b.report["objective"]["total"].get<double>(),
              1e-12 * a.report["objective"]["total"].get<double>());
}

TEST_F(WeldTest, AWeldThatCollapsesAFaceIsBadInputNamingTheKey) {
  // A pentagon whose last two corners are 1e-6 apart (its other edges about
  // 1 long): a readable face, which a weld within 1e-5 mean edge lengths
  // leaves with a corner twice.
  WriteFile("sliver.obj",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 1e-6 1 0\nv 0 1 0\nf 1 2 3 4 5\n");
  ReadLimits wide;
  wide.weld_distance = 1e-5;
  try {
    ReadMesh(Path("sliver.obj"), nullptr, wide);
    FAIL() << "the collapsed face was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "limits.weld_distance");
    EXPECT_NE(e.message().find("after welding 1 coincident vertices"), std::string::npos)
        << e.message();
  }
  // At the default distance the corners stay apart.
  EXPECT_EQ(ReadMesh(Path("sliver.obj")).number_of_vertices(), 5u);
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
