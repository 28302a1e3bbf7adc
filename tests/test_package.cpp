// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The installed C++ package (issue 15): `cmake --install` of this build into
// a scratch prefix puts libarchgeo, <archgeo/archgeo.h> (no CGAL, Ceres or
// YAML include in any installed header) and archgeoConfig.cmake there; a
// consumer project written here finds it with find_package(archgeo), links
// archgeo::archgeo, generates a roof in millimetres, solves planar quads and
// checks the result in file units against the same solve done through the
// CLI (same vertices to 1e-9 of the diagonal).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/io.h"
#include "tests/scratch_dir.h"
#include "tests/shell.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

namespace fs = std::filesystem;


const char* kConsumerCMake = R"(cmake_minimum_required(VERSION 3.16)
project(consumer LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 17)
find_package(archgeo 0.1 REQUIRED)
add_executable(consumer main.cpp)
target_link_libraries(consumer PRIVATE archgeo::archgeo)
)";

// Millimetres: the API handles the canonical frame itself.
const char* kConsumerMain = R"(#include <archgeo/archgeo.h>
#include <cstdio>
#include <fstream>
int main(int argc, char** argv) {
  archgeo::SurfaceOptions roof;
  roof.nu = 8; roof.nv = 6; roof.scale = 1000;
  const archgeo::MeshData mesh = archgeo::Generate(roof);
  const archgeo::SolveResult r = archgeo::Solve(
      "problem: planar_quads\nsolver: {num_threads: 1}\n", mesh);
  std::ofstream out(argv[1]);
  out.precision(17);
  for (const auto& p : r.mesh.vertices) out << p[0] << " " << p[1] << " " << p[2] << "\n";
  try {
    archgeo::Solve("problem: planar_quads\nnot_a_key: 1\n", mesh);
  } catch (const archgeo::Error& e) {
    std::printf("error: %s\n", e.what());
  }
  std::printf("version %s status %d vertices %zu\n", archgeo::Version().c_str(), r.status,
              r.mesh.vertices.size());
  return r.status == 0 || r.status == 4 ? 0 : 1;
}
)";

class Package : public ScratchDirTest {};

TEST_F(Package, ConsumerFindsLinksAndSolves) {
  const fs::path build = fs::path(ARCHGEO_BINARY).parent_path();
  const std::string prefix = Path("prefix");
  const Outcome install =
      Shell("cmake --install " + build.string() + " --prefix " + prefix);
  ASSERT_EQ(install.code, 0) << install.output;
  ASSERT_TRUE(fs::exists(prefix + "/include/archgeo/archgeo.h"));
  ASSERT_TRUE(fs::exists(prefix + "/lib/cmake/archgeo/archgeoConfig.cmake"));
  // The public headers are CGAL-free (and Ceres- and YAML-free).
  for (const auto& entry : fs::recursive_directory_iterator(prefix + "/include")) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    for (const char* forbidden : {"CGAL/", "ceres/", "yaml-cpp/", "\"mesh/", "\"problems/"}) {
      EXPECT_EQ(text.str().find(forbidden), std::string::npos)
          << entry.path() << " includes " << forbidden;
    }
  }

  fs::create_directories(Path("consumer"));
  std::ofstream(Path("consumer/CMakeLists.txt")) << kConsumerCMake;
  std::ofstream(Path("consumer/main.cpp")) << kConsumerMain;
  // A consumer links the way this build links its own programs: a sanitizer
  // build (tools/sanitize.sh) installs instrumented static libraries, which
  // need the sanitizer runtimes at link time.
  const Outcome configure =
      Shell("cmake -S " + Path("consumer") + " -B " + Path("consumer/build") +
            " -DCMAKE_PREFIX_PATH=" + prefix + " '-DCMAKE_EXE_LINKER_FLAGS=" +
            ARCHGEO_EXE_LINKER_FLAGS + "'");
  ASSERT_EQ(configure.code, 0) << configure.output;
  const Outcome compile = Shell("cmake --build " + Path("consumer/build"));
  ASSERT_EQ(compile.code, 0) << compile.output;
  const Outcome run = Shell(Path("consumer/build/consumer") + " " + Path("api.txt"));
  ASSERT_EQ(run.code, 0) << run.output;
  EXPECT_NE(run.output.find("version 0.1.0 status"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("vertices 63"), std::string::npos) << run.output;  // (8+1)·(6+1)
  // The same message as the CLI's input error about the key.
  EXPECT_NE(run.output.find("error: <spec>:2: key 'not_a_key'"), std::string::npos) << run.output;

  // The CLI on the same roof and spec: the same vertices.
  const std::string archgeo = ARCHGEO_BINARY;
  ASSERT_EQ(Shell(archgeo + " generate " + Path("roof.obj") + " --nu 8 --nv 6 --scale 1000").code,
            0);
  std::ofstream(Path("spec.yaml")) << "problem: planar_quads\nmesh: roof.obj\nsolver: "
                                      "{num_threads: 1}\noutput: {mesh: out.obj}\n";
  const Outcome cli = Shell(archgeo + " solve " + Path("spec.yaml") + " --quiet");
  ASSERT_TRUE(cli.code == 0 || cli.code == 4) << cli.output;
  const Mesh out = ReadMesh(Path("out.obj"));
  std::ifstream api(Path("api.txt"));
  double worst = 0;
  for (VertexIndex v : out.vertices()) {
    double x, y, z;
    ASSERT_TRUE(api >> x >> y >> z);
    const Point& p = out.point(v);
    worst = std::max({worst, std::abs(p.x() - x), std::abs(p.y() - y), std::abs(p.z() - z)});
  }
  EXPECT_LT(worst, 1e-9 * 2500) << "API and CLI results differ";  // diagonal ≈ 2500 mm
}

}  // namespace
}  // namespace archgeo
