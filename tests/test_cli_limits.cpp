// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// End to end through the `archgeo` binary (issue 17, input side): every bad
// input below ends with exit 2 at once, a message naming the file or option,
// and nothing written: non-finite or huge `generate` options, sizes beyond the
// documented bounds, a Darboux map that overflows, special files given as
// meshes, tiny files declaring huge counts; and `measure --reference` with a
// far-away vertex gives the exact distance (bounded Hausdorff sampling).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "io/io.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

namespace fs = std::filesystem;

struct Outcome {
  int code;
  std::string output;  // stdout + stderr
};

// Runs archgeo; with `hang_guard`, under coreutils' timeout, so that a run
// that blocks (a FIFO opened for reading) ends with 124 after 60 s instead of
// hanging the suite (a guard, not a speed check: the refusals take
// milliseconds).
Outcome Archgeo(const std::string& args, bool hang_guard = false) {
  const std::string cmd = (hang_guard ? "timeout 60 " : "") + std::string(ARCHGEO_BINARY) + " " +
                          args + " 2>&1";
  Outcome o{0, ""};
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) o.output.append(buf.data(), n);
  const int status = pclose(pipe);
  o.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return o;
}

template <typename T>
void AppendBigEndian(std::string* out, T value) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  std::reverse(bytes, bytes + sizeof(T));
  out->append(reinterpret_cast<const char*>(bytes), sizeof(T));
}

template <typename T>
void AppendLittleEndian(std::string* out, T value) {
  out->append(reinterpret_cast<const char*>(&value), sizeof(T));
}

class CliLimitsTest : public ScratchDirTest {
 protected:
  std::string WriteBytes(const std::string& name, const std::string& bytes) const {
    std::ofstream(Path(name), std::ios::binary) << bytes;
    return Path(name);
  }
  // Exit 2, `needle` in the message, and the folder holds exactly `kept`
  // (no output, no temporary file).
  void ExpectBadInput(const std::string& args, const std::string& needle,
                      const std::set<std::string>& kept = {}) const {
    const Outcome o = Archgeo(args, /*hang_guard=*/true);
    EXPECT_EQ(o.code, 2) << args << "\n" << o.output;
    EXPECT_NE(o.output.find(needle), std::string::npos)
        << args << ": missing '" << needle << "' in\n" << o.output;
    std::set<std::string> present;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      present.insert(entry.path().filename().string());
    }
    EXPECT_EQ(present, kept) << args;
  }
};

TEST_F(CliLimitsTest, GenerateRefusesNonFiniteAndOutOfRangeScaleAndNoise) {
  const std::string out = "generate " + Path("out.obj");
  for (const char* scale : {"inf", "1e308", "nan", "0", "-1", "1e7", "1e-7"}) {
    ExpectBadInput(out + " --scale " + scale, "--scale: key 'scale': must be in [1e-06, 1e+06]");
  }
  for (const char* noise : {"inf", "1e308", "nan", "-0.1", "11"}) {
    ExpectBadInput(out + " --noise " + noise, "--noise: key 'noise': must be in [0, 10]");
  }
  // The bounds themselves are accepted.
  EXPECT_EQ(Archgeo(out + " --nu 2 --nv 2 --scale 1e6 --noise 10").code, 0);
  const Mesh mesh = ReadMesh(Path("out.obj"));
  EXPECT_EQ(mesh.number_of_faces(), 4u);
}

TEST_F(CliLimitsTest, GenerateRefusesSizesBeyondTheLimit) {
  const std::string out = "generate " + Path("out.obj");
  ExpectBadInput(out + " --nu 100000 --nv 100000",
                 "10000000000 faces, more than the limit of 4000000");
  ExpectBadInput(out + " --surface cone_start --nu 2000 --nv 1001",
                 "4004000 faces, more than the limit of 4000000");
  ExpectBadInput(out + " --nu 0 --nv 5", "grid sizes must be >= 1");
  ExpectBadInput(out + " --surface scherk --refinement 30",
                 "--refinement: key 'refinement': must be in [1, 16], got 30");
  ExpectBadInput(out + " --surface scherk --refinement 0", "must be in [1, 16], got 0");
  ExpectBadInput(out + " --surface scherk --reference " + Path("ref.obj") + " --refinement 17",
                 "must be in [1, 16]");
}

// c = 1e308: eq. 12 overflows; the images were written as infinities while
// the summary reported no sample left out.
TEST_F(CliLimitsTest, DarbouxRefusesAMapThatOverflows) {
  ASSERT_EQ(Archgeo("generate " + Path("hp.obj") + " --surface hyperbolic_paraboloid").code, 0);
  for (const char* c : {"1e308", "-1e308", "1e200"}) {
    ExpectBadInput("darboux " + Path("hp.obj") + " " + Path("out.ply") + " --c " + c +
                       " --rulings " + Path("r.obj"),
                   "overflows double precision", {"hp.obj"});
  }
  // A large c that does not overflow still works, and every vertex written
  // is finite (ReadMesh refuses non-finite coordinates).
  const Outcome o = Archgeo("darboux " + Path("hp.obj") + " " + Path("d.ply") + " --c 1e6");
  ASSERT_EQ(o.code, 0) << o.output;
}

TEST_F(CliLimitsTest, SpecialFilesAreRefusedAtOnce) {
  ASSERT_EQ(mkfifo(Path("fifo.obj").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", Path("zero.off"));
  fs::create_directories(Path("folder.ply"));
  const std::set<std::string> inputs = {"fifo.obj", "zero.off", "folder.ply"};
  ExpectBadInput("measure " + Path("fifo.obj"), "fifo.obj: cannot read it: it is a FIFO", inputs);
  ExpectBadInput("measure " + Path("zero.off"), "it is a character device", inputs);
  ExpectBadInput("measure " + Path("folder.ply"), "it is a directory", inputs);
  ASSERT_EQ(Archgeo("generate " + Path("grid.obj") + " --nu 3 --nv 3").code, 0);
  std::set<std::string> with_grid = inputs;
  with_grid.insert("grid.obj");
  ExpectBadInput("measure " + Path("grid.obj") + " --reference " + Path("fifo.obj"), "FIFO",
                 with_grid);
  ExpectBadInput("darboux " + Path("fifo.obj") + " " + Path("out.ply"), "FIFO", with_grid);
}

// The two tiny files of issue 17 (98 s and 4.7 GB; 3 min and 7.8 GB).
TEST_F(CliLimitsTest, TinyFilesDeclaringHugeCountsAreRefusedAtOnce) {
  std::string off = "OFF BINARY\n";
  for (std::int32_t c : {200000000, 1, 0}) AppendBigEndian(&off, c);
  off.resize(59, '\0');
  WriteBytes("200M.off", off);
  ExpectBadInput("measure " + Path("200M.off"), "declares 200000000 vertices and 1 faces",
                 {"200M.off"});

  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list int int vertex_indices\nend_header\n";
  for (float x : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) AppendLittleEndian(&ply, x);
  AppendLittleEndian(&ply, std::int32_t{2000000000});
  ply.resize(1248, '\0');
  WriteBytes("list.ply", ply);
  ExpectBadInput("measure " + Path("list.ply"), "limits.max_face_degree",
                 {"200M.off", "list.ply"});
  // A negative count (was std::length_error from vector::_M_default_append).
  ply.replace(ply.find("end_header\n") + 11 + 36, 4, std::string("\xfb\xff\xff\xff", 4));
  WriteBytes("list.ply", ply);
  ExpectBadInput("measure " + Path("list.ply"), "negative list count -5",
                 {"200M.off", "list.ply"});
  // Random bytes.
  std::string garbage;
  for (int i = 0; i < 5000; ++i) garbage.push_back(static_cast<char>((i * 7919 + 13) % 251));
  WriteBytes("garbage.off", garbage);
  ExpectBadInput("measure " + Path("garbage.off"), "garbage.off",
                 {"200M.off", "list.ply", "garbage.off"});
}

// One vertex moved 300 units on a 2,025-vertex grid took 147 s (unbounded
// Hausdorff sampling). The moved vertex is a sample: the distance is exact.
TEST_F(CliLimitsTest, MeasureReferenceWithAFarVertex) {
  ASSERT_EQ(Archgeo("generate " + Path("grid.obj") + " --nu 44 --nv 44 --noise 0").code, 0);
  Mesh mesh = ReadMesh(Path("grid.obj"));
  ASSERT_EQ(mesh.number_of_vertices(), 2025u);
  const VertexIndex v(22 * 45 + 22);
  const Point p = mesh.point(v);
  mesh.point(v) = Point(p.x(), p.y(), p.z() + 300);
  WriteMesh(Path("moved.obj"), mesh);
  const Outcome o = Archgeo("measure " + Path("moved.obj") + " --reference " + Path("grid.obj") +
                            " --json");
  ASSERT_EQ(o.code, 0) << o.output;
  const nlohmann::json m = nlohmann::json::parse(o.output)["metrics"];
  // The roof's z stays within [-0.55, 0.55], so the moved vertex is between
  // 300 - 1.1 and 300 units from it.
  EXPECT_GT(m["hausdorff"].get<double>(), 298.9);
  EXPECT_LE(m["hausdorff"].get<double>(), 300.0 + 1e-9);
  EXPECT_NEAR(m["hausdorff"].get<double>(), m["surface_distance_max"].get<double>(), 1e-9);
}

}  // namespace
}  // namespace archgeo
