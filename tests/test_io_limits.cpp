// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for the mesh readers' bounds (io/io.h, io/soup_readers.h,
// io/input_file.h): no silent misreading (OBJ indices beyond 2^31, relative
// indices, files holding more or fewer records than their header declares),
// declared counts checked against the file size and ReadLimits before any
// allocation (each case names the check that caught it, which only exists
// before allocating), special files refused without blocking, and WriteMesh
// refusing non-finite coordinates.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "io/input_file.h"
#include "io/io.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

namespace fs = std::filesystem;

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Appends `value` in big-endian (binary OFF) or little-endian byte order.
template <typename T>
void Append(std::string* out, T value, bool big_endian) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (big_endian) std::reverse(bytes, bytes + sizeof(T));  // the test host is little-endian
  out->append(reinterpret_cast<const char*>(bytes), sizeof(T));
}

const char kSquareObj[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
const char kSquareOffVertices[] = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";

// ASCII PLY header for `vertices` float vertices and `faces` faces whose
// vertex list is `list` ("uchar int", "int int", "uint int", ...).
std::string PlyHeader(const std::string& format, int vertices, long long faces,
                      const std::string& list = "uchar int") {
  return "ply\nformat " + format + " 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
         std::to_string(faces) + "\nproperty list " + list + " vertex_indices\nend_header\n";
}

// Binary little-endian PLY of the unit square as one quad (list uchar int),
// with `extra` appended.
std::string BinarySquarePly(const std::string& extra = "") {
  std::string ply = PlyHeader("binary_little_endian", 4, 1);
  const float xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const auto& p : xy) {
    Append(&ply, p[0], false);
    Append(&ply, p[1], false);
    Append(&ply, 0.0f, false);
  }
  Append(&ply, std::uint8_t{4}, false);
  for (std::int32_t i = 0; i < 4; ++i) Append(&ply, i, false);
  return ply + extra;
}

// Binary OFF ("OFF BINARY", big-endian) of the unit square as one quad.
std::string BinarySquareOff(const std::string& extra = "") {
  std::string off = "OFF BINARY\n";
  for (std::int32_t c : {4, 1, 0}) Append(&off, c, true);
  const float xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const auto& p : xy) {
    Append(&off, p[0], true);
    Append(&off, p[1], true);
    Append(&off, 0.0f, true);
  }
  for (std::int32_t i : {4, 0, 1, 2, 3, 0}) Append(&off, i, true);  // n, indices, no colour
  return off + extra;
}

class ReadLimitsTest : public ScratchDirTest {
 protected:
  // The InputError of reading `content` as `name` (with `limits`); checks
  // that it names the file.
  InputError Error(const std::string& name, const std::string& content,
                   const ReadLimits& limits = ReadLimits()) const {
    const std::string path = WriteBytes(name, content);
    try {
      ReadMesh(path, nullptr, limits);
    } catch (const InputError& error) {
      EXPECT_EQ(error.file(), path);
      return error;
    }
    ADD_FAILURE() << "no InputError for " << name;
    return InputError(path, 0, "", "");
  }
  std::string WriteBytes(const std::string& name, const std::string& content) const {
    std::ofstream(Path(name), std::ios::binary) << content;
    return Path(name);
  }
};

std::vector<std::vector<std::size_t>> FacesOf(const Mesh& mesh) {
  std::vector<std::vector<std::size_t>> faces;
  for (FaceIndex f : mesh.faces()) {
    std::vector<std::size_t> face;
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      face.push_back(v.idx());
    std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
    faces.push_back(face);
  }
  return faces;
}

// --- OBJ indices ---------------------------------------------------------------

// CGAL's reader read indices as int: 2^32 + 4 stopped the face after three
// indices (a quad became a triangle). Every large index is out of range now.
TEST_F(ReadLimitsTest, ObjIndexBeyond2To31IsOutOfRange) {
  for (const std::string index : {"2147483648", "4294967300", "9223372036854775807"}) {
    const InputError e = Error("big.obj", std::string(kSquareObj) + "f 1 2 3 " + index + "\n");
    EXPECT_EQ(e.line(), 5) << index;
    EXPECT_TRUE(Contains(e.message(), "face 0 refers to a vertex index out of range")) << e.what();
  }
  // Beyond the range of a 64-bit integer: not an index at all.
  const InputError e = Error("huge.obj", std::string(kSquareObj) + "f 1 2 3 99999999999999999999\n");
  EXPECT_EQ(e.line(), 5);
  EXPECT_TRUE(Contains(e.message(), "cannot parse '99999999999999999999' as a vertex index"))
      << e.what();
}

// OBJ: a negative index counts back from the last vertex read so far.
TEST_F(ReadLimitsTest, ObjRelativeIndicesFollowTheVerticesReadSoFar) {
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\n"
      "f -3 -2 -1\n"  // (0, 1, 2)
      "v 0 1 0\n"
      "f -4 -2 -1\n";  // (0, 2, 3): -1 is now vertex 3
  const Mesh mesh = ReadMesh(WriteBytes("relative.obj", obj));
  EXPECT_EQ(FacesOf(mesh), (std::vector<std::vector<std::size_t>>{{0, 1, 2}, {0, 2, 3}}));

  const InputError e = Error("before.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_TRUE(Contains(e.message(), "refers to vertex -3 (relative), but only 2 vertices precede"))
      << e.what();
}

TEST_F(ReadLimitsTest, ObjStatementsThatAreNotFacesAreRefusedWithTheirLine) {
  const InputError e = Error("lines.obj", std::string(kSquareObj) + "f 1 2 3\nl 1 2\n");
  EXPECT_EQ(e.line(), 6);
  EXPECT_TRUE(Contains(e.message(), "unsupported OBJ statement 'l'")) << e.what();
}

// --- Files holding more or fewer records than their header declares ---------------

TEST_F(ReadLimitsTest, OffWithMoreFacesThanDeclaredIsRefused) {
  const InputError e =
      Error("more.off", "OFF\n4 1 0\n" + std::string(kSquareOffVertices) + "3 0 1 2\n3 0 2 3\n");
  EXPECT_EQ(e.line(), 8);
  EXPECT_TRUE(Contains(e.message(), "holds more than its header declares (4 vertices, 1 faces)"))
      << e.what();
  // One vertex more than declared: its line is read as a face, the real face
  // is then one too many.
  EXPECT_TRUE(Contains(Error("morev.off", "OFF\n3 1 0\n" + std::string(kSquareOffVertices) +
                                              "3 0 1 2\n")
                           .message(),
                       "holds more than its header declares"));
}

TEST_F(ReadLimitsTest, BinaryOffWithMoreThanDeclaredIsRefused) {
  EXPECT_EQ(FacesOf(ReadMesh(WriteBytes("square.off", BinarySquareOff()))),
            (std::vector<std::vector<std::size_t>>{{0, 1, 2, 3}}));
  EXPECT_EQ(FacesOf(ReadMesh(WriteBytes("newline.off", BinarySquareOff("\n")))).size(), 1u);
  std::string extra;
  for (std::int32_t i : {3, 0, 1, 2, 0}) Append(&extra, i, true);
  const InputError e = Error("more.off", BinarySquareOff(extra));
  EXPECT_TRUE(Contains(e.message(), "holds more than its header declares (4 vertices, 1 faces)"))
      << e.what();
  EXPECT_TRUE(Contains(e.message(), "20 bytes after the last face")) << e.what();
}

TEST_F(ReadLimitsTest, PlyWithMoreThanDeclaredIsRefused) {
  const std::string ascii = PlyHeader("ascii", 4, 1) + kSquareOffVertices + "3 0 1 2\n3 0 2 3\n";
  InputError e = Error("more.ply", ascii);
  EXPECT_EQ(e.line(), 15);
  EXPECT_TRUE(Contains(e.message(), "holds more than its header declares (4 vertices, 1 faces)"))
      << e.what();

  EXPECT_EQ(FacesOf(ReadMesh(WriteBytes("square.ply", BinarySquarePly()))).size(), 1u);
  std::string face;
  Append(&face, std::uint8_t{3}, false);
  for (std::int32_t i : {0, 2, 3}) Append(&face, i, false);
  e = Error("moreb.ply", BinarySquarePly(face));
  EXPECT_TRUE(Contains(e.message(), "holds more than its header declares")) << e.what();
  EXPECT_TRUE(Contains(e.message(), "(13 bytes more)")) << e.what();
}

TEST_F(ReadLimitsTest, FilesWithFewerRecordsThanDeclaredAreTruncated) {
  InputError e = Error("few.ply", PlyHeader("ascii", 4, 2) + kSquareOffVertices + "3 0 1 2\n");
  EXPECT_TRUE(Contains(e.message(), "declares 2 face elements, but the file has only 1"))
      << e.what();
  const std::string full = BinarySquarePly();
  e = Error("cut.ply", full.substr(0, full.size() - 3));
  EXPECT_TRUE(Contains(e.message(), "the file ends inside face 0")) << e.what();
  const std::string off = BinarySquareOff();
  e = Error("cut.off", off.substr(0, off.size() - 6));
  EXPECT_TRUE(Contains(e.message(), "the file ends inside face 0")) << e.what();
}

// --- Declared counts against the file size, before allocating -------------------

// The 59-byte binary OFF of issue 17 declared 200M vertices (98 s, 4.7 GB).
TEST_F(ReadLimitsTest, BinaryOffCountsBeyondTheFileSize) {
  std::string off = "OFF BINARY\n";
  for (std::int32_t c : {200000000, 1, 0}) Append(&off, c, true);
  off.resize(59, '\0');
  InputError e = Error("200M.off", off);
  EXPECT_TRUE(Contains(e.message(), "declares 200000000 vertices and 1 faces")) << e.what();
  EXPECT_TRUE(Contains(e.message(), "holds only 36 bytes after the header")) << e.what();
  // Negative counts.
  std::string negative = "OFF BINARY\n";
  for (std::int32_t c : {-4, 1, 0}) Append(&negative, c, true);
  e = Error("negative.off", negative + std::string(64, '\0'));
  EXPECT_TRUE(Contains(e.message(), "negative count")) << e.what();
}

TEST_F(ReadLimitsTest, AsciiOffCountsBeyondTheFileSize) {
  const InputError e = Error("huge.off", "OFF\n2000000000 2000000000 0\n0 0 0\n1 0 0\n0 1 0\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_TRUE(Contains(e.message(), "needs at least 6 bytes per vertex")) << e.what();
  EXPECT_TRUE(Contains(e.message(), "truncated or the header is wrong")) << e.what();
}

// The 1,248-byte binary PLY of issue 17 had a face list count of 2e9 (3 min,
// 7.8 GB): refused by the face-degree limit, and with that limit raised, as
// a truncated file, without allocating the list.
TEST_F(ReadLimitsTest, PlyListCountBeyondTheLimitAndTheFileSize) {
  std::string ply = PlyHeader("binary_little_endian", 4, 1, "uint int");
  for (int k = 0; k < 12; ++k) Append(&ply, static_cast<float>(k % 3 == 0 ? k : k % 2), false);
  Append(&ply, std::uint32_t{2000000000}, false);
  ply.resize(1248, '\0');
  InputError e = Error("list.ply", ply);
  EXPECT_TRUE(Contains(e.message(), "face 0 declares 2000000000 vertices, more than the limit of "
                                    "1000 (limits.max_face_degree"))
      << e.what();
  ReadLimits raised;
  raised.max_face_degree = 3'000'000'000ULL;
  e = Error("list.ply", ply, raised);
  EXPECT_TRUE(Contains(e.message(), "the file ends inside face 0")) << e.what();
}

// A negative list count made CGAL's reader throw vector::_M_default_append.
TEST_F(ReadLimitsTest, PlyNegativeListCount) {
  std::string ply = PlyHeader("binary_little_endian", 4, 1, "int int");
  for (int k = 0; k < 12; ++k) Append(&ply, static_cast<float>(k % 2), false);
  Append(&ply, std::int32_t{-5}, false);
  ply += std::string(64, '\0');
  InputError e = Error("negative.ply", ply);
  EXPECT_TRUE(Contains(e.message(), "face 0: negative list count -5")) << e.what();
  e = Error("negative_ascii.ply", PlyHeader("ascii", 4, 1, "int int") + kSquareOffVertices +
                                      "-5 0 1 2 3 4\n");
  EXPECT_EQ(e.line(), 14);
  EXPECT_TRUE(Contains(e.message(), "negative list count -5")) << e.what();
}

TEST_F(ReadLimitsTest, PlyElementCountsBeyondTheFileSize) {
  const InputError e = Error("counts.ply", PlyHeader("binary_big_endian", 4, 2000000000) +
                                               std::string(100, '\0'));
  EXPECT_TRUE(Contains(e.message(), "declares 4 vertex, 2000000000 face, which need at least "
                                    "2000000048 bytes, but the file holds only 100"))
      << e.what();
}

// Random bytes under each extension: an InputError, never another exception.
TEST_F(ReadLimitsTest, BinaryGarbageIsBadInput) {
  std::mt19937 random(17);
  for (int trial = 0; trial < 20; ++trial) {
    std::string bytes(64 + trial * 97, '\0');
    for (char& c : bytes) c = static_cast<char>(random());
    for (const char* name : {"garbage.obj", "garbage.off", "garbage.ply"}) {
      EXPECT_THROW(ReadMesh(WriteBytes(name, bytes)), InputError) << name << " " << trial;
    }
    // Behind a valid-looking header.
    EXPECT_THROW(ReadMesh(WriteBytes("g.off", "OFF BINARY\n" + bytes)), InputError) << trial;
    EXPECT_THROW(ReadMesh(WriteBytes("g.ply", PlyHeader("binary_little_endian", 3, 1) + bytes)),
                 InputError)
        << trial;
  }
}

// --- ReadLimits ----------------------------------------------------------------

TEST_F(ReadLimitsTest, EachLimitIsNamedAndCanBeRaised) {
  const std::string obj = std::string(kSquareObj) + "f 1 2 3 4\n";
  const std::string off = "OFF\n4 1 0\n" + std::string(kSquareOffVertices) + "4 0 1 2 3\n";
  const std::string ply = PlyHeader("ascii", 4, 1) + kSquareOffVertices + "4 0 1 2 3\n";
  const struct {
    std::size_t ReadLimits::*limit;
    const char* key;
  } cases[] = {{&ReadLimits::max_vertices, "limits.max_vertices"},
               {&ReadLimits::max_faces, "limits.max_faces"},
               {&ReadLimits::max_face_degree, "limits.max_face_degree"}};
  for (const auto& c : cases) {
    ReadLimits tight;
    tight.*(c.limit) = c.limit == &ReadLimits::max_faces ? 0 : 3;
    for (const auto& [name, content] :
         {std::pair{"a.obj", obj}, std::pair{"a.off", off}, std::pair{"a.ply", ply}}) {
      const InputError e = Error(name, content, tight);
      EXPECT_TRUE(Contains(e.message(), c.key)) << name << ": " << e.what();
      ReadLimits exact = tight;
      exact.*(c.limit) = c.limit == &ReadLimits::max_faces ? 1 : 4;
      EXPECT_EQ(ReadMesh(WriteBytes(name, content), nullptr, exact).number_of_faces(), 1u) << name;
    }
  }
  ReadLimits bytes;
  bytes.max_file_bytes = obj.size() - 1;
  EXPECT_TRUE(Contains(Error("a.obj", obj, bytes).message(), "limits.max_file_bytes"));
  bytes.max_file_bytes = obj.size();
  EXPECT_EQ(ReadMesh(WriteBytes("a.obj", obj), nullptr, bytes).number_of_faces(), 1u);
}

// The defaults hold far more than a 1M-quad mesh (1002001 vertices).
TEST(ReadLimitsDefaults, HoldAMillionQuadMesh) {
  const ReadLimits limits;
  EXPECT_GE(limits.max_vertices, 50'000'000u);
  EXPECT_GE(limits.max_faces, 50'000'000u);
  EXPECT_GE(limits.max_face_degree, 255u);  // any PLY face with a uchar count
}

// --- Special files ---------------------------------------------------------------

TEST_F(ReadLimitsTest, SpecialFilesAreRefusedWithoutBlocking) {
  // Opening a FIFO without a writer blocks: a regression hangs here until
  // ctest's timeout.
  ASSERT_EQ(mkfifo(Path("fifo.obj").c_str(), 0600), 0);
  try {
    ReadMesh(Path("fifo.obj"));
    ADD_FAILURE() << "no InputError for a FIFO";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), Path("fifo.obj"));
    EXPECT_TRUE(Contains(e.message(), "a FIFO (named pipe)")) << e.what();
  }

  fs::create_symlink("/dev/zero", Path("zero.off"));
  try {
    ReadMesh(Path("zero.off"));
    ADD_FAILURE() << "no InputError for /dev/zero";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.message(), "a character device")) << e.what();
  }
  fs::create_directories(Path("folder.ply"));
  try {
    ReadMesh(Path("folder.ply"));
    ADD_FAILURE() << "no InputError for a directory";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.message(), "a directory")) << e.what();
  }
  const int fd = socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  const std::string socket_path = Path("socket.obj");
  ASSERT_LT(socket_path.size(), sizeof(address.sun_path));
  std::strcpy(address.sun_path, socket_path.c_str());
  ASSERT_EQ(bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)), 0);
  try {
    ReadMesh(socket_path);
    ADD_FAILURE() << "no InputError for a socket";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.message(), "a socket")) << e.what();
  }
  close(fd);
}

// The one check the spec and principal-edges readers call too: the key is kept.
TEST_F(ReadLimitsTest, CheckRegularInputFileNamesTheKey) {
  ASSERT_EQ(mkfifo(Path("edges.txt").c_str(), 0600), 0);
  try {
    CheckRegularInputFile(Path("edges.txt"), "principal_edges");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "principal_edges");
    EXPECT_EQ(e.file(), Path("edges.txt"));
    EXPECT_TRUE(Contains(e.message(), "FIFO")) << e.what();
  }
  EXPECT_THROW(CheckRegularInputFile("/dev/null", "mesh"), InputError);
  EXPECT_THROW(CheckRegularInputFile(Path("absent.yaml")), InputError);
  const std::string file = WriteBytes("spec.yaml", "mesh: a.obj\n");
  EXPECT_NO_THROW(CheckRegularInputFile(file));
  EXPECT_EQ(ReadInputFile(file), "mesh: a.obj\n");
  try {
    ReadInputFile(file, "spec", 4, "limits.max_spec_bytes");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.message(), "the file has 12 bytes, more than the limit of 4 "
                                      "(limits.max_spec_bytes"))
        << e.what();
  }
}

// --- In memory ---------------------------------------------------------------------

TEST_F(ReadLimitsTest, InMemoryReaderIsTheFileReader) {
  const std::string ply = BinarySquarePly();
  ReadInfo info;
  const Mesh mesh = ReadMeshFromMemory("memory.ply", ply, &info);
  EXPECT_EQ(info.format, "ply");
  EXPECT_EQ(FacesOf(mesh), FacesOf(ReadMesh(WriteBytes("file.ply", ply))));
  try {
    ReadMeshFromMemory("memory.obj", "v 0 0 0\nf 1 1 1\n");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "memory.obj");
    EXPECT_EQ(e.line(), 2);
  }
}

// --- PLY headers -------------------------------------------------------------------

// CGAL's reader gave missing coordinates the value 0 (a flat mesh).
TEST_F(ReadLimitsTest, PlyVertexNeedsXYZ) {
  std::string ply = PlyHeader("ascii", 4, 1);
  ply.replace(ply.find("property float z"), 16, "property float w");
  const InputError e = Error("noz.ply", ply + kSquareOffVertices + "4 0 1 2 3\n");
  EXPECT_TRUE(Contains(e.message(), "the vertex element has no (scalar) property 'z'")) << e.what();
  // Integer coordinates are read (CGAL's reader asserted on them).
  std::string ints = PlyHeader("ascii", 4, 1);
  for (const char* c : {"x", "y", "z"}) {
    ints.replace(ints.find(std::string("property float ") + c), 16,
                 std::string("property int   ") + c);
  }
  EXPECT_EQ(ReadMesh(WriteBytes("ints.ply", ints + kSquareOffVertices + "4 0 1 2 3\n"))
                .number_of_faces(),
            1u);
}

TEST_F(ReadLimitsTest, PlyBigEndianAndOtherElements) {
  std::string ply =
      "ply\nformat binary_big_endian 1.0\ncomment made by hand\nelement vertex 4\n"
      "property double x\nproperty double y\nproperty double z\nproperty uchar red\n"
      "element face 1\nproperty list ushort uint vertex_index\nproperty list uchar float "
      "texcoord\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  const double xy[4][2] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  for (const auto& p : xy) {
    Append(&ply, p[0], true);
    Append(&ply, p[1], true);
    Append(&ply, 0.5, true);
    Append(&ply, std::uint8_t{200}, true);
  }
  Append(&ply, std::uint16_t{4}, true);
  for (std::uint32_t i : {0u, 1u, 2u, 3u}) Append(&ply, i, true);
  Append(&ply, std::uint8_t{2}, true);
  Append(&ply, 0.25f, true);
  Append(&ply, 0.75f, true);
  Append(&ply, std::int32_t{0}, true);
  Append(&ply, std::int32_t{1}, true);
  const Mesh mesh = ReadMesh(WriteBytes("big.ply", ply));
  ASSERT_EQ(mesh.number_of_vertices(), 4u);
  EXPECT_EQ(mesh.point(VertexIndex(2)), Point(2, 2, 0.5));
  EXPECT_EQ(FacesOf(mesh), (std::vector<std::vector<std::size_t>>{{0, 1, 2, 3}}));
}

// --- Writing -------------------------------------------------------------------------

TEST_F(ReadLimitsTest, WriteMeshRefusesNonFiniteCoordinates) {
  Mesh mesh = ReadMesh(WriteBytes("square.obj", std::string(kSquareObj) + "f 1 2 3 4\n"));
  for (const double bad : {std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN()}) {
    mesh.point(VertexIndex(2)) = Point(1, bad, 0);
    for (const char* name : {"out.obj", "out.off", "out.ply"}) {
      try {
        WriteMesh(Path(name), mesh);
        ADD_FAILURE() << "no InputError for " << name;
      } catch (const InputError& e) {
        EXPECT_EQ(e.file(), Path(name));
        EXPECT_TRUE(Contains(e.message(), "vertex 2 has a non-finite coordinate")) << e.what();
      }
      EXPECT_FALSE(fs::exists(Path(name))) << name;
    }
  }
}

}  // namespace
}  // namespace archgeo
