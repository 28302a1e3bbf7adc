// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for mesh/io (ReadMesh, WriteMesh) and mesh/output_files (StagedOutputs):
// round trips in every format, the real meshes of ../shared/data, one test per
// class of bad input, and the all-or-nothing output files.
#include <CGAL/IO/PLY.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "io/io.h"
#include "io/output_files.h"
#include "mesh/surface_mesh.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

namespace fs = std::filesystem;
using Faces = std::vector<std::vector<std::size_t>>;

// A fresh directory under the system temporary directory, removed at the end.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = fs::temp_directory_path() /
            ("archgeo_test_io_" + std::to_string(getpid()) + "_" + std::to_string(counter++));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  std::string Path(const std::string& name) const { return (path_ / name).string(); }
  std::string Write(const std::string& name, const std::string& content) const {
    std::ofstream(Path(name), std::ios::binary) << content;
    return Path(name);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string FileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Each face's vertex indices, rotated to start at its smallest index.
Faces FacesOf(const Mesh& mesh) {
  Faces faces;
  for (FaceIndex f : mesh.faces()) {
    std::vector<std::size_t> face;
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      face.push_back(v.idx());
    std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
    faces.push_back(face);
  }
  return faces;
}

std::vector<Point> PointsOf(const Mesh& mesh) {
  std::vector<Point> points;
  for (VertexIndex v : mesh.vertices()) points.push_back(mesh.point(v));
  return points;
}

Mesh MakeMesh(const std::vector<Point>& points, const Faces& faces) {
  Mesh mesh;
  for (const Point& p : points) mesh.add_vertex(p);
  for (const auto& face : faces) {
    std::vector<VertexIndex> vertices;
    for (std::size_t i : face) vertices.push_back(VertexIndex(static_cast<Mesh::size_type>(i)));
    EXPECT_TRUE(mesh.add_face(vertices).is_valid());
  }
  return mesh;
}

// A pentagon with two quads on its sides, coordinates that need all 17
// digits, and an isolated vertex (5) in the middle of the vertex list.
Mesh PolygonalMesh() {
  const double t = 1.0 / 3.0;
  return MakeMesh({{0, 0, 0},
                   {2 + t, 0, 0},
                   {2 + t, 1, 0},
                   {1, 2 + t, 0},
                   {0, 1, 0},
                   {5, 5, 5},
                   {0, -1, 0.2},
                   {2 + t, -1, 0.2},
                   {3, 0, t},
                   {3, 1, t}},
                  {{0, 1, 2, 3, 4}, {1, 0, 6, 7}, {2, 1, 8, 9}});
}

void ExpectSameMesh(const Mesh& expected, const Mesh& actual) {
  const auto expected_points = PointsOf(expected), actual_points = PointsOf(actual);
  ASSERT_EQ(expected_points.size(), actual_points.size());
  for (std::size_t i = 0; i < expected_points.size(); ++i) {
    EXPECT_EQ(expected_points[i], actual_points[i]) << "vertex " << i;  // bit-exact
  }
  EXPECT_EQ(FacesOf(expected), FacesOf(actual));
}

// The message of the InputError that reading `content` as file `name` throws.
std::string ReadError(const TempDir& dir, const std::string& name, const std::string& content,
                      int* line = nullptr) {
  const std::string path = dir.Write(name, content);
  try {
    ReadMesh(path);
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path);
    if (line != nullptr) *line = error.line();
    return error.what();
  }
  ADD_FAILURE() << "no InputError for " << name;
  return "";
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// --- Round trips -----------------------------------------------------------

struct FormatCase {
  std::string file;
  bool ascii_ply;
  std::string format;  // ReadInfo::format
};

void PrintTo(const FormatCase& c, std::ostream* os) { *os << c.file; }

class RoundTrip : public ::testing::TestWithParam<FormatCase> {};

TEST_P(RoundTrip, WriteThenReadGivesTheSameMesh) {
  TempDir dir;
  const Mesh mesh = PolygonalMesh();
  const std::string path = dir.Path(GetParam().file);
  WriteMesh(path, mesh, nullptr, GetParam().ascii_ply);
  ReadInfo info;
  const Mesh read = ReadMesh(path, &info);
  ExpectSameMesh(mesh, read);
  EXPECT_EQ(info.reoriented_faces, 0);
  EXPECT_EQ(info.format, GetParam().format);
}

INSTANTIATE_TEST_SUITE_P(
    Formats, RoundTrip,
    ::testing::Values(FormatCase{"mesh.obj", false, "obj"}, FormatCase{"mesh.off", false, "off"},
                      FormatCase{"ascii.ply", true, "ply"}, FormatCase{"binary.ply", false, "ply"},
                      FormatCase{"UPPER.OBJ", false, "obj"}),
    [](const auto& info) {
      return info.param.file.substr(0, info.param.file.find('.')) + "_" + info.param.format;
    });

// PLY face colours come back; only vertices, faces and colours are written,
// even when the mesh carries other property maps.
TEST(WriteMesh, PlyFaceColoursAndNothingElse) {
  for (const bool ascii : {false, true}) {
    TempDir dir;
    Mesh mesh = PolygonalMesh();
    AddBlocks<VertexIndex, 3>(mesh, "v:auxiliary");
    AddBlocks<FaceIndex, 1>(mesh, "f:weight");
    const std::vector<Rgb> colors = {{255, 0, 7}, {1, 128, 254}, {9, 8, 0}};
    const std::string path = dir.Path("colored.ply");
    WriteMesh(path, mesh, &colors, ascii);

    const std::string text = FileText(path);
    const std::string header = text.substr(0, text.find("end_header"));
    EXPECT_TRUE(Contains(header, ascii ? "format ascii" : "format binary_little_endian"));
    EXPECT_TRUE(Contains(header,
                         "element vertex 10\nproperty double x\nproperty double y\n"
                         "property double z\nelement face 3\n"
                         "property list uchar int vertex_indices\nproperty uchar red\n"
                         "property uchar green\nproperty uchar blue\n"))
        << header;
    EXPECT_EQ(std::count(header.begin(), header.end(), '\n'), 12) << header;  // nothing else

    std::ifstream in(path, std::ios::binary);
    std::vector<Point> points;
    Faces polygons;
    std::vector<CGAL::IO::Color> read_colors, vertex_colors;
    ASSERT_TRUE(CGAL::IO::read_PLY(in, points, polygons, read_colors, vertex_colors, false));
    ASSERT_EQ(read_colors.size(), colors.size());
    for (std::size_t f = 0; f < colors.size(); ++f) {
      EXPECT_EQ(read_colors[f].red(), colors[f][0]);
      EXPECT_EQ(read_colors[f].green(), colors[f][1]);
      EXPECT_EQ(read_colors[f].blue(), colors[f][2]);
    }
    ExpectSameMesh(mesh, ReadMesh(path));
  }
}

TEST(WriteMesh, UnknownExtensionAndUnwritablePathThrow) {
  TempDir dir;
  EXPECT_THROW(WriteMesh(dir.Path("mesh.stl"), PolygonalMesh()), InputError);
  EXPECT_THROW(WriteMesh(dir.Path("missing/dir/mesh.obj"), PolygonalMesh()), InputError);
}

// --- Vertex order ------------------------------------------------------------

// Vertex i is the file's i-th vertex even when faces list them out of order
// and one vertex is referenced by no face.
TEST(ReadMesh, KeepsVertexOrderAndIsolatedVertices) {
  TempDir dir;
  const std::string obj =
      "v 0 0 0\n"
      "v 9 9 9\n"  // isolated
      "v 1 0 0\n"
      "v 1 1 0\n"
      "v 0 1 0\n"
      "f 5 1 3 4\n";
  const Mesh mesh = ReadMesh(dir.Write("order.obj", obj));
  EXPECT_EQ(PointsOf(mesh),
            (std::vector<Point>{{0, 0, 0}, {9, 9, 9}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
  EXPECT_EQ(FacesOf(mesh), (Faces{{0, 2, 3, 4}}));
  EXPECT_TRUE(mesh.is_isolated(VertexIndex(1)));
}

// Syntax the shared data and common writers use: CRLF, tabs, `o`/`s`/`g`/
// `usemtl`/`mtllib`/`vn`/`vt` lines, `v/vt/vn` and negative (relative) indices.
TEST(ReadMesh, ObjSyntaxVariants) {
  TempDir dir;
  const std::string obj =
      "mtllib roof.mtl\r\no roof\r\nv 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nvn 0 0 1\r\nvt 0 0\r\n"
      "g panels\r\nusemtl glass\r\ns off\r\nf\t1/1/1\t2/1/1\t3/1/1\r\nv 0 1 0\r\nf -4//1 -2//1 "
      "-1//1\r\n";
  const Mesh mesh = ReadMesh(dir.Write("variants.obj", obj));
  EXPECT_EQ(mesh.number_of_vertices(), 4u);
  EXPECT_EQ(FacesOf(mesh), (Faces{{0, 1, 2}, {0, 2, 3}}));
}

// Comments, counts on the keyword line, a face colour, and face index lists
// wrapped over several lines (as in libigl's *_quads_*.off).
TEST(ReadMesh, OffSyntaxVariants) {
  TempDir dir;
  const std::string off =
      "OFF 5 2 0\n# vertices\n0 0 0\n1 0 0 # first edge\n1 1 0\n0 1 0\n\n0.5 2 0\n"
      "4 0 1 2 3 255 0 0\n3\n\n3 2\n4\n";
  const Mesh mesh = ReadMesh(dir.Write("variants.OFF", off));
  EXPECT_EQ(mesh.number_of_vertices(), 5u);
  EXPECT_EQ(FacesOf(mesh), (Faces{{0, 1, 2, 3}, {2, 4, 3}}));
}

// --- Real meshes ---------------------------------------------------------------

struct RealMesh {
  std::string file;
  std::size_t vertices, faces;
  Point first_vertex;
};

void PrintTo(const RealMesh& m, std::ostream* os) { *os << m.file; }

class RealData : public ::testing::TestWithParam<RealMesh> {};

TEST_P(RealData, LoadsWithTheReadmeCounts) {
  const RealMesh& expected = GetParam();
  ReadInfo info;
  const Mesh mesh = ReadMesh(std::string(ARCHGEO_DATA_DIR) + "/" + expected.file, &info);
  EXPECT_EQ(info.reoriented_faces, 0);  // all are consistently oriented
  EXPECT_EQ(mesh.number_of_vertices(), expected.vertices);
  EXPECT_EQ(mesh.number_of_faces(), expected.faces);
  EXPECT_EQ(mesh.point(VertexIndex(0)), expected.first_vertex);
  EXPECT_TRUE(mesh.is_valid(false));
}

// Counts from ../shared/data/README.md; first vertices copied from the files.
INSTANTIATE_TEST_SUITE_P(
    SharedData, RealData,
    ::testing::Values(
        RealMesh{"libigl_inspired_mesh_quads_Conjugate.off",
                 1749,
                 1633,
                 {41.854476928700002, 25.5624408722, 0.83620864152899999}},
        RealMesh{"libigl_inspired_mesh_quads_Smooth.off",
                 1963,
                 1838,
                 {41.846923828100003, 25.575593948400002, 0.83369135856599996}},
        RealMesh{"libigl_inspired_mesh.obj", 2244, 4288, {43.5118, 26.1886, 0.851145}},
        RealMesh{"dos_free_negshell_marc_anet.obj",
                 2520,
                 2304,
                 {16.407798767089844, 15.912223815917969, 0.102791428565979}},
        RealMesh{"dos_M2_eq_quad2.obj", 920, 871, {-4.410178, -1.988742, 3.477618}},
        RealMesh{"dos_pillow_1.obj",
                 1369,
                 1296,
                 {1.9148775672927743, 1.9148775672927725, -0.60433442195796683}},
        RealMesh{"dos_botanic-garden-bubble-0.obj", 1121, 1076, {-11.5432, -5.1914, 2.09683}},
        RealMesh{"directional_Concerthall.off", 6897, 13535, {-2.94233, 2.46142, -11.1482}},
        RealMesh{"directional_train-station.off", 1753, 3330, {56.68495, -11.18195, 3.59618}}),
    [](const auto& info) {
      std::string name = info.param.file.substr(0, info.param.file.find('.'));
      std::replace_if(
          name.begin(), name.end(), [](char c) { return !std::isalnum(c); }, '_');
      return name;
    });

// --- Bad input: one test per class ------------------------------------------

const char kSquare[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(ReadMeshErrors, MissingFile) {
  TempDir dir;
  try {
    ReadMesh(dir.Path("absent.obj"));
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_TRUE(Contains(error.what(), "cannot open")) << error.what();
    EXPECT_TRUE(Contains(error.what(), "absent.obj")) << error.what();
  }
}

TEST(ReadMeshErrors, UnknownExtensionListsTheSupportedOnes) {
  TempDir dir;
  const std::string message = ReadError(dir, "mesh.stl", kSquare);
  EXPECT_TRUE(Contains(message, ".obj, .off, .ply")) << message;
  EXPECT_TRUE(Contains(ReadError(dir, "mesh", kSquare), "no file extension"));
}

TEST(ReadMeshErrors, GarbageTokenNamesLineAndToken) {
  TempDir dir;
  int line = 0;
  std::string message = ReadError(dir, "a.obj", "v 0 0 0\nv 1 zero 0\nv 1 1 0\nf 1 2 3\n", &line);
  EXPECT_EQ(line, 2);
  EXPECT_TRUE(Contains(message, "'zero'") && Contains(message, "vertex 1")) << message;

  message = ReadError(dir, "b.obj", std::string(kSquare) + "f 1 2 x\n", &line);
  EXPECT_EQ(line, 5);
  EXPECT_TRUE(Contains(message, "'x'") && Contains(message, "face 0")) << message;

  message = ReadError(dir, "c.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 two\n", &line);
  EXPECT_EQ(line, 6);
  EXPECT_TRUE(Contains(message, "'two'")) << message;

  message =
      ReadError(dir, "d.ply",
                "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                "property double z\nelement face 1\nproperty list uchar int vertex_indices\n"
                "end_header\n0 0 0\n1 ? 0\n0 1 0\n3 0 1 2\n",
                &line);
  EXPECT_EQ(line, 11);
  EXPECT_TRUE(Contains(message, "'?'")) << message;

  message = ReadError(dir, "e.obj", std::string(kSquare) + "l 1 2\nf 1 2 3\n", &line);
  EXPECT_EQ(line, 5);
  EXPECT_TRUE(Contains(message, "unsupported OBJ statement 'l'")) << message;
}

TEST(ReadMeshErrors, NonFiniteCoordinateNamesTheLine) {
  TempDir dir;
  int line = 0;
  std::string message =
      ReadError(dir, "nan.obj", "# roof\nv 0 0 0\nv 1 nan 0\nv 1 1 0\nf 1 2 3\n", &line);
  EXPECT_EQ(line, 3);
  EXPECT_TRUE(Contains(message, "nan.obj:3: non-finite coordinate 'nan' in vertex 1")) << message;

  message = ReadError(dir, "inf.off", "OFF\n3 1 0\n0 0 0\n1 0 -inf\n0 1 0\n3 0 1 2\n", &line);
  EXPECT_EQ(line, 4);
  EXPECT_TRUE(Contains(message, "non-finite coordinate '-inf'")) << message;

  message = ReadError(dir, "overflow.obj", "v 0 0 0\nv 1 0 1e999\nv 1 1 0\nf 1 2 3\n", &line);
  EXPECT_EQ(line, 2);
  EXPECT_TRUE(Contains(message, "non-finite coordinate '1e999'")) << message;

  // Binary PLY: no lines, the vertex is named. WriteMesh refuses NaN, so
  // write a marker value and overwrite its 8 bytes with a NaN.
  Mesh mesh = PolygonalMesh();
  const double marker = 12345.678, nan = std::numeric_limits<double>::quiet_NaN();
  mesh.point(VertexIndex(7)) = Point(0, marker, 0);
  const std::string path = dir.Path("nan.ply");
  WriteMesh(path, mesh);
  std::string bytes = FileText(path);
  const std::size_t at = bytes.find(std::string(reinterpret_cast<const char*>(&marker), 8));
  ASSERT_NE(at, std::string::npos);
  bytes.replace(at, 8, std::string(reinterpret_cast<const char*>(&nan), 8));
  dir.Write("nan.ply", bytes);
  try {
    ReadMesh(path);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_TRUE(Contains(error.what(), "non-finite coordinate in vertex 7")) << error.what();
  }
}

TEST(ReadMeshErrors, IndexOutOfRangeNamesTheFace) {
  TempDir dir;
  int line = 0;
  // 5 = n + 1 passes CGAL's own OBJ range check.
  std::string message = ReadError(dir, "a.obj", std::string(kSquare) + "f 1 2 3\nf 1 3 5\n", &line);
  EXPECT_EQ(line, 6);
  EXPECT_TRUE(Contains(message, "face 1 refers to a vertex index out of range")) << message;

  EXPECT_TRUE(Contains(ReadError(dir, "b.obj", std::string(kSquare) + "f 1 2 0\n"), "face 0"));

  message = ReadError(dir, "c.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", &line);
  EXPECT_EQ(line, 6);
  EXPECT_TRUE(Contains(message, "face 0 refers to a vertex index out of range")) << message;

  message =
      ReadError(dir, "d.ply",
                "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                "property double z\nelement face 1\nproperty list uchar int vertex_indices\n"
                "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n",
                &line);
  EXPECT_EQ(line, 13);
  EXPECT_TRUE(Contains(message, "face 0 refers to a vertex index out of range")) << message;
}

TEST(ReadMeshErrors, RepeatedIndexInAFace) {
  TempDir dir;
  int line = 0;
  std::string message = ReadError(dir, "a.obj", std::string(kSquare) + "f 1 2 3 2\n", &line);
  EXPECT_EQ(line, 5);
  EXPECT_TRUE(Contains(message, "face 0 uses vertex 1 more than once")) << message;
  message = ReadError(dir, "b.obj", std::string(kSquare) + "f 1 2 3\nf 4 4\n");
  EXPECT_TRUE(Contains(message, "face 1 has 2 vertices")) << message;
}

TEST(ReadMeshErrors, DegenerateFaces) {
  TempDir dir;
  int line = 0;
  std::string message = ReadError(dir, "collinear.obj",
                                  "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 4\nf 1 2 3\n", &line);
  EXPECT_EQ(line, 6);
  EXPECT_TRUE(Contains(message, "face 1 is degenerate: zero area")) << message;
  message = ReadError(dir, "coincident.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 0 0\n0 1 0\n4 0 1 2 3\n",
                      &line);
  EXPECT_EQ(line, 7);
  EXPECT_TRUE(Contains(message, "face 0 is degenerate: its vertices 1 and 2 coincide")) << message;
}

TEST(ReadMeshErrors, EmptyMesh) {
  TempDir dir;
  EXPECT_TRUE(Contains(ReadError(dir, "a.obj", kSquare), "no faces"));
  EXPECT_TRUE(Contains(ReadError(dir, "b.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"), "no faces"));
  EXPECT_TRUE(Contains(
      ReadError(dir, "c.ply",
                "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty double y\n"
                "property double z\nelement face 0\nproperty list uchar int vertex_indices\n"
                "end_header\n0 0 0\n"),
      "no faces"));
  for (const char* name : {"empty.obj", "empty.off", "empty.ply"}) {
    EXPECT_TRUE(Contains(ReadError(dir, name, ""), "the file is empty")) << name;
  }
}

TEST(ReadMeshErrors, TruncatedFiles) {
  TempDir dir;
  EXPECT_TRUE(Contains(ReadError(dir, "a.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n"),
                       "declares 2 faces, but the file has only 1"));
  TempDir out;
  const std::string path = out.Path("full.ply");
  WriteMesh(path, PolygonalMesh());
  const std::string binary = FileText(path);
  EXPECT_TRUE(Contains(ReadError(dir, "cut.ply", binary.substr(0, binary.size() - 10)),
                       "the file ends inside face 2"));
}

TEST(ReadMeshErrors, NonManifold) {
  TempDir dir;
  // Three triangles on the edge (0, 1).
  std::string message = ReadError(
      dir, "fin.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n");
  EXPECT_TRUE(Contains(message, "non-manifold edge between vertices")) << message;
  EXPECT_TRUE(Contains(message, "3 faces share it")) << message;
  // Bowtie: two triangle fans touching at vertex 2.
  int line = 0;
  message = ReadError(dir, "bowtie.obj",
                      "v 0 0 0\nv 1 0 0\nv 1 1 1\nv 2 2 2\nv 1 2 2\nf 1 2 3\nf 3 4 5\n", &line);
  EXPECT_TRUE(Contains(message, "non-manifold vertex 2")) << message;
  EXPECT_EQ(line, 3);
  // A Moebius strip of three quads cannot be oriented.
  message = ReadError(dir, "moebius.obj",
                      "v 0 0 0\nv 0 1 0\nv 2 0 0\nv 2 1 1\nv 1 3 0\nv 2 3 1\n"
                      "f 1 3 4 2\nf 3 5 6 4\nf 5 2 1 6\n");
  EXPECT_TRUE(Contains(message, "non-manifold")) << message;
}

TEST(ReadMesh, RepairsInconsistentOrientation) {
  TempDir dir;
  // A strip of three quads; the middle one is listed with the opposite orientation.
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nv 3 1 0\n"
      "f 1 2 6 5\nf 2 6 7 3\nf 3 4 8 7\n";
  ReadInfo info;
  const Mesh mesh = ReadMesh(dir.Write("strip.obj", obj), &info);
  EXPECT_EQ(info.reoriented_faces, 1);
  EXPECT_EQ(info.format, "obj");
  EXPECT_EQ(mesh.number_of_faces(), 3u);
  EXPECT_EQ(mesh.number_of_vertices(), 8u);
  EXPECT_TRUE(mesh.is_valid(false));
  EXPECT_EQ(FacesOf(mesh), (Faces{{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}}));
}

// --- StagedOutputs -------------------------------------------------------------

TEST(StagedOutputs, CommitRenamesIntoPlace) {
  TempDir dir;
  const std::string target = dir.Path("out/deep/result.json");
  StagedOutputs outputs;
  const std::string temporary = outputs.Stage(target);
  EXPECT_NE(temporary, target);
  EXPECT_EQ(fs::path(temporary).parent_path(), fs::path(target).parent_path());
  EXPECT_TRUE(fs::is_directory(dir.Path("out/deep")));
  std::ofstream(temporary) << "done";
  EXPECT_FALSE(fs::exists(target));
  outputs.Commit();
  EXPECT_FALSE(fs::exists(temporary));
  EXPECT_EQ(FileText(target), "done");
}

TEST(StagedOutputs, NoCommitLeavesNothing) {
  TempDir dir;
  const std::string target = dir.Path("mesh.ply");
  {
    StagedOutputs outputs;
    WriteMesh(outputs.Stage(target), PolygonalMesh());
    outputs.Stage(dir.Path("never_written.json"));
    EXPECT_FALSE(fs::exists(target));
  }
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(StagedOutputs, NoCommitRemovesTheDirectoriesItCreated) {
  TempDir dir;
  fs::create_directories(dir.Path("kept"));
  {
    StagedOutputs outputs;
    std::ofstream(outputs.Stage(dir.Path("new/deeper/mesh.obj"))) << "partial";
    outputs.Stage(dir.Path("kept/report.json"));
    outputs.Stage(dir.Path("new/other.json"));
    EXPECT_TRUE(fs::is_directory(dir.Path("new/deeper")));
  }
  EXPECT_FALSE(fs::exists(dir.Path("new")));
  EXPECT_TRUE(fs::is_directory(dir.Path("kept")));  // existed before: kept
  EXPECT_TRUE(fs::is_empty(dir.Path("kept")));
}

TEST(StagedOutputs, CommitReplacesAnExistingOutput) {
  TempDir dir;
  const std::string target = dir.Write("report.json", "old");
  StagedOutputs outputs;
  std::ofstream(outputs.Stage(target)) << "new";
  EXPECT_EQ(FileText(target), "old");
  outputs.Commit();
  EXPECT_EQ(FileText(target), "new");
}

TEST(StagedOutputs, ProtectedPathsAreNeverStaged) {
  TempDir dir;
  const std::string input = dir.Write("roof.obj", "original");
  fs::create_directories(dir.Path("sub"));
  fs::create_symlink(input, dir.Path("link.obj"));
  StagedOutputs outputs({input});
  for (const std::string& alias :
       {input, dir.Path("sub/../roof.obj"), dir.Path("./roof.obj"), dir.Path("link.obj")}) {
    EXPECT_THROW(outputs.Stage(alias), InputError) << alias;
  }
  EXPECT_EQ(FileText(input), "original");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 3);
}

TEST(StagedOutputs, SameTargetTwiceThrows) {
  TempDir dir;
  StagedOutputs outputs;
  outputs.Stage(dir.Path("a.ply"));
  EXPECT_THROW(outputs.Stage(dir.Path("./a.ply")), InputError);
}

}  // namespace
}  // namespace archgeo
