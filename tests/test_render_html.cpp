// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The HTML view (`archgeo render ... --out view.html`, render/html_view.cpp)
// in a real browser: Debian's headless Chromium loads the self-contained
// page from a file (no server) and takes a screenshot, decoded with cairo: a
// twisted grid (every quad far from planar) is drawn red in the left panel,
// a planar grid green in the right one.
#include <cairo.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/scratch_dir.h"
#include "tests/grid_obj.h"
#include "tests/shell.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

namespace fs = std::filesystem;

constexpr const char* kChromium = "/usr/bin/chromium";  // Debian's chromium (install_deps)

int Shell(const std::string& command, std::string* output) {
  const Outcome o = archgeo::Shell(command);
  output->append(o.output);
  return o.code;
}


struct Count {
  int red = 0, green = 0;
};

Count CountPixels(cairo_surface_t* s, int x0, int x1, int y0, int y1) {
  Count c;
  const unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int y = y0; y < std::min(y1, cairo_image_surface_get_height(s)); ++y) {
    for (int x = x0; x < std::min(x1, cairo_image_surface_get_width(s)); ++x) {
      const uint32_t v = *reinterpret_cast<const uint32_t*>(data + y * stride + 4 * x);
      const int r = (v >> 16) & 255, g = (v >> 8) & 255, b = v & 255;
      c.red += r > g + 60 && r > b + 60;
      c.green += g > r + 60 && g > b + 60;
    }
  }
  return c;
}

class RenderHtml : public ScratchDirTest {};

TEST_F(RenderHtml, HeadlessChromiumDrawsTheMesh) {
  ASSERT_TRUE(fs::exists(kChromium)) << "no " << kChromium << " (tools/install_deps.sh installs it)";
  std::ofstream(Path("twisted.obj")) << GridObj(8, 0.05);
  std::ofstream(Path("flat.obj")) << GridObj(8, 0.0);
  std::string output;
  ASSERT_EQ(Shell(std::string(ARCHGEO_BINARY) + " render " + Path("twisted.obj") + " " +
                      Path("flat.obj") + " --width 400 --height 400 --out " + Path("view.html"),
                  &output),
            0)
      << output;
  // The page is self-contained: no http(s) resource.
  std::ifstream page(Path("view.html"));
  const std::string html((std::istreambuf_iterator<char>(page)), std::istreambuf_iterator<char>());
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  output.clear();
  const int code = Shell("timeout 120 " + std::string(kChromium) +
                             " --headless=new --no-sandbox --disable-gpu --hide-scrollbars "
                             "--user-data-dir=" + Path("profile") +
                             " --window-size=1000,560 --screenshot=" + Path("shot.png") +
                             " file://" + Path("view.html"),
                         &output);
  ASSERT_EQ(code, 0) << output;
  cairo_surface_t* shot = cairo_image_surface_create_from_png(Path("shot.png").c_str());
  ASSERT_EQ(cairo_surface_status(shot), CAIRO_STATUS_SUCCESS);
  // Panels: 400 px canvases side by side below a title; the bar to the right.
  const Count left = CountPixels(shot, 0, 400, 60, 480);
  const Count right = CountPixels(shot, 400, 800, 60, 480);
  cairo_surface_destroy(shot);
  EXPECT_GT(left.red, 400 * 400 / 10) << "the twisted grid is not drawn red";
  EXPECT_EQ(left.green, 0);
  EXPECT_GT(right.green, 400 * 400 / 10) << "the planar grid is not drawn green";
  EXPECT_EQ(right.red, 0);
}

}  // namespace
}  // namespace archgeo
