// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Pictures and coloured outputs (issue 15): the per-face value of every
// problem and its red value (problems/report/colors.h), the PLY's named float face
// property read back by Debian's meshio (python3-meshio) and by archgeo's own
// reader, and `archgeo render` / output.image PNGs decoded with cairo and
// checked pixel by pixel (a planar grid is drawn green, a twisted one red).
#include <cairo.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "io/io.h"
#include "analysis/metrics.h"
#include "problems/report/colors.h"
#include "problems/spec/spec.h"
#include "tests/scratch_dir.h"
#include "tests/grid_obj.h"
#include "tests/shell.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

namespace fs = std::filesystem;

constexpr const char* kPython = "/usr/bin/python3";  // Debian's, with python3-meshio


std::string Source(const std::string& path) { return std::string(ARCHGEO_SOURCE_DIR) + "/" + path; }
std::string Archgeo() { return ARCHGEO_BINARY; }


struct Pixels {
  int width = 0, height = 0;
  int red = 0, green = 0, drawn = 0;  // mesh pixels by dominant channel; drawn = not white
};

// Counts the pixels of the rectangle [x0, x1) × [y0, y1) of a PNG.
Pixels CountPixels(const std::string& png, int x0, int y0, int x1, int y1) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(png.c_str());
  Pixels p;
  if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(s);
    return p;
  }
  p.width = cairo_image_surface_get_width(s);
  p.height = cairo_image_surface_get_height(s);
  const unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int y = y0; y < std::min(y1, p.height); ++y) {
    for (int x = x0; x < std::min(x1, p.width); ++x) {
      const uint32_t v = *reinterpret_cast<const uint32_t*>(data + y * stride + 4 * x);
      const int r = (v >> 16) & 255, g = (v >> 8) & 255, b = v & 255;
      if (r > 245 && g > 245 && b > 245) continue;
      ++p.drawn;
      if (r > g + 60 && r > b + 60) ++p.red;
      if (g > r + 60 && g > b + 60) ++p.green;
    }
  }
  cairo_surface_destroy(s);
  return p;
}

class Render : public ScratchDirTest {};

TEST_F(Render, OneMeshExactlyAsDocumented) {
  const std::string flat = WriteFile("flat.obj", GridObj(8, 0.0));
  const Outcome o = Shell(Archgeo() + " render " + flat + " --out " + Path("view.png"));
  ASSERT_EQ(o.code, 0) << o.output;
  // One panel (720 × 560 by default) + the colour-bar column (180) and caption (34).
  const Pixels p = CountPixels(Path("view.png"), 0, 60, 720, 560);
  EXPECT_EQ(p.width, 720 + 180);
  EXPECT_EQ(p.height, 560 + 34);
  // Planar quads: the mesh covers a good part of the panel, all green, no red.
  EXPECT_GT(p.drawn, 720 * 500 / 10);
  EXPECT_GT(p.green, p.drawn / 2);
  EXPECT_EQ(p.red, 0);
}

TEST_F(Render, BeforeAfterSideBySideOnOneScale) {
  // δ_PQ,n of the twisted grid is far above the default red value 1e-3.
  const std::string flat = WriteFile("flat.obj", GridObj(8, 0.0));
  const std::string twisted = WriteFile("twisted.obj", GridObj(8, 0.05));
  const Outcome o = Shell(Archgeo() + " render " + twisted + " " + flat + " --titles before,after" +
                          " --out " + Path("pair.png"));
  ASSERT_EQ(o.code, 0) << o.output;
  const Pixels before = CountPixels(Path("pair.png"), 0, 60, 720, 560);
  const Pixels after = CountPixels(Path("pair.png"), 720, 60, 1440, 560);
  EXPECT_EQ(before.width, 2 * 720 + 180);
  EXPECT_GT(before.red, before.drawn / 2);
  EXPECT_EQ(before.green, 0);
  EXPECT_GT(after.green, after.drawn / 2);
  EXPECT_EQ(after.red, 0);
}

// --value none: grey faces and no colour bar (the picture is one panel wide).
TEST_F(Render, ValueNoneDrawsGreyFacesAndNoBar) {
  const std::string twisted = WriteFile("twisted.obj", GridObj(8, 0.05));
  const Outcome o =
      Shell(Archgeo() + " render " + twisted + " --value none --out " + Path("grey.png"));
  ASSERT_EQ(o.code, 0) << o.output;
  const Pixels p = CountPixels(Path("grey.png"), 0, 60, 720, 560);
  EXPECT_EQ(p.width, 720);
  EXPECT_GT(p.drawn, 720 * 500 / 10);
  EXPECT_EQ(p.red, 0);
  EXPECT_EQ(p.green, 0);
}

// --lines: OBJ polylines (output.streamlines) drawn over the mesh, group v
// red; a bad vertex index is refused with the file and line (exit 2).
TEST_F(Render, LinesAreDrawnOverTheMeshAndBadOnesRefused) {
  const std::string flat = WriteFile("flat.obj", GridObj(8, 0.0));
  const std::string lines = WriteFile(
      "lines.obj", "g v\nv -3 -3 0\nv 3 3 0\nv 3 -3 0\nl 1 2 3\ng w\nv -3 3 0\nl 3 4\n");
  const Outcome o = Shell(Archgeo() + " render " + flat + " --value none --lines " + lines +
                          " --out " + Path("lines.png"));
  ASSERT_EQ(o.code, 0) << o.output;
  const Pixels with = CountPixels(Path("lines.png"), 0, 60, 720, 560);
  EXPECT_GT(with.red, 300);  // two red strokes across the grey grid (~ 700 pixels long)
  ASSERT_EQ(Shell(Archgeo() + " render " + flat + " --value none --out " + Path("none.png")).code, 0);
  EXPECT_EQ(CountPixels(Path("none.png"), 0, 60, 720, 560).red, 0);
  const std::string bad = WriteFile("bad.obj", "v 0 0 0\nv 1 0 0\nl 1 3\n");
  const Outcome refused = Shell(Archgeo() + " render " + flat + " --lines " + bad + " --out " +
                                Path("bad.png"));
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.output.find(bad + ":3"), std::string::npos) << refused.output;
  EXPECT_FALSE(fs::exists(Path("bad.png")));
}

TEST_F(Render, RefusesANameThatIsNotPngAndNamesIt) {
  const std::string flat = WriteFile("flat.obj", GridObj(2, 0.0));
  const Outcome o = Shell(Archgeo() + " render " + flat + " --out " + Path("view.jpg"));
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.output.find(Path("view.jpg")), std::string::npos) << o.output;
  EXPECT_FALSE(fs::exists(Path("view.jpg")));
}

// Kinks belong to an H-net (all quads): a mesh with a triangle is refused
// naming the mesh and the option, nothing written.
TEST_F(Render, KinksOfAMeshWithATriangleNameTheMeshAndTheOption) {
  const std::string mixed = WriteFile("mixed.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\n"
                                                   "f 1 2 3 4\nf 2 5 3\n");
  const Outcome o = Shell(Archgeo() + " render " + mixed + " --value kinks --out " + Path("kinks.png"));
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find(mixed + ": key '--value': kinks"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("face 1 has 3 sides"), std::string::npos) << o.output;
  EXPECT_FALSE(fs::exists(Path("kinks.png")));
}

TEST_F(Render, SolveWritesImageAndPlyValuesThatMeshioReads) {
  const Outcome o = Shell(Archgeo() + " solve " + Source("examples/planar_quads_gentle.yaml") +
                          " --quiet --set output.mesh=" + Path("out.ply") +
                          " --set output.report=" + Path("out.json") +
                          " --set output.image=" + Path("out.png"));
  ASSERT_TRUE(o.code == 0 || o.code == 4) << o.output;
  const Pixels input = CountPixels(Path("out.png"), 0, 60, 720, 560);
  EXPECT_EQ(input.width, 2 * 720 + 180);
  EXPECT_GT(input.drawn, 720 * 500 / 10);

  // The PLY property equals δ_PQ,n recomputed from the written vertices.
  const Mesh written = ReadMesh(Path("out.ply"));
  const PlanarityMeasure planarity = MeasureFacePlanarity(written);
  const Outcome m = Shell(std::string(kPython) + " -W ignore -c \"import meshio, json; m = "
                          "meshio.read('" + Path("out.ply") + "'); print(json.dumps({'points': "
                          "len(m.points), 'pq': [float(x) for b in m.cell_data['pq_normalized'] "
                          "for x in b], 'red': [int(x) for b in m.cell_data['red'] for x in b], "
                          "'displacement': [float(x) for x in m.point_data['displacement']]}))\"");
  ASSERT_EQ(m.code, 0) << m.output;
  const nlohmann::json read = nlohmann::json::parse(m.output);
  EXPECT_EQ(read["points"], written.number_of_vertices());
  // Per vertex: the displacement from the input, as the report's maximum.
  ASSERT_EQ(read["displacement"].size(), written.number_of_vertices());
  double largest = 0;
  for (double d : read["displacement"]) largest = std::max(largest, d);
  ASSERT_EQ(read["pq"].size(), written.number_of_faces());
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(Path("out.json")));
  const double red_at = report["colors"]["red_at"];
  EXPECT_EQ(report["colors"]["red_from"], "tolerance.pq_normalized_max");
  EXPECT_EQ(red_at, report["settings"]["tolerance"]["pq_normalized_max"].get<double>());
  EXPECT_NEAR(largest, report["after"]["displacement_max"].get<double>(), 1e-6 * (1 + largest));
  EXPECT_GT(largest, 0);
  for (FaceIndex f : written.faces()) {  // faces are read in file order: index = file order
    const double value = read["pq"][f.idx()];
    EXPECT_NEAR(value, planarity.normalized[f.idx()], 1e-6 * (1 + planarity.normalized[f.idx()]));
    EXPECT_EQ(read["red"][f.idx()].get<int>(), ScaleColor(value, red_at)[0]);
  }
}

TEST_F(Render, SolveRefusesAnImageNameThatIsNotPngOrHtml) {
  const Outcome o = Shell(Archgeo() + " solve " + Source("examples/planar_quads_gentle.yaml") +
                          " --quiet --set output.mesh=" + Path("out.ply") +
                          " --set output.report= --set output.image=" + Path("out.stl"));
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.output.find("'" + Path("out.stl") + "'"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find(".tmp-"), std::string::npos) << o.output;  // never a temporary
  EXPECT_FALSE(fs::exists(Path("out.stl")));
  EXPECT_FALSE(fs::exists(Path("out.ply")));  // refused before any work
}

TEST_F(Render, BinaryPlyCarriesTheNamedFloatProperty) {
  const std::string twisted = WriteFile("twisted.obj", GridObj(3, 0.05));
  const Mesh mesh = ReadMesh(twisted);
  const PlanarityMeasure planarity = MeasureFacePlanarity(mesh);
  const std::vector<PlyValues> properties = {{"pq_normalized", planarity.normalized}};
  const std::vector<Rgb> colors(mesh.number_of_faces(), Rgb{255, 0, 0});
  WriteMesh(Path("b.ply"), mesh, &colors, false, &properties);
  std::ifstream in(Path("b.ply"), std::ios::binary);
  std::string header, line;
  while (std::getline(in, line) && line != "end_header") header += line + "\n";
  EXPECT_NE(header.find("format binary_little_endian 1.0"), std::string::npos);
  EXPECT_NE(header.find("property uchar blue\nproperty float pq_normalized\n"), std::string::npos)
      << header;
  // Each face: uchar 4, 4 int indices, 3 uchar colours, 1 float.
  const auto data_start = in.tellg();
  in.seekg(0, std::ios::end);
  EXPECT_EQ(size_t(in.tellg() - data_start),
            mesh.number_of_vertices() * 24 + mesh.number_of_faces() * (1 + 16 + 3 + 4));
  EXPECT_EQ(ReadMesh(Path("b.ply")).number_of_faces(), mesh.number_of_faces());
}

// Every problem's colours honour output.color_max; planar_quads' default is
// its tolerance.
TEST_F(Render, EveryProblemHonoursColorMax) {
  const Mesh grid = ReadMesh(Source("examples/roof_grid.obj"));
  for (const char* example : {"planar_quads", "smooth_mesh", "total_absolute_curvature",
                              "principal_symmetric", "hnet"}) {
    const ProblemSpec spec =
        ReadSpec(Source(std::string("examples/") + example + ".yaml"), {"output.color_max=0.123"});
    const FaceValues v = ComputeFaceValues(spec.declaration->colors, grid, &grid, &spec.settings);
    EXPECT_EQ(v.red_at, 0.123) << example;
    EXPECT_EQ(v.red_from, "output.color_max") << example;
    EXPECT_EQ(v.values.size(), grid.number_of_faces()) << example;
  }
  const ProblemSpec pq = ReadSpec(Source("examples/planar_quads.yaml"),
                                  {"tolerance.pq_normalized_max=0.004"});
  EXPECT_EQ(ComputeFaceValues("planarity", grid, &grid, &pq.settings).red_at, 0.004);
}

}  // namespace
}  // namespace archgeo
