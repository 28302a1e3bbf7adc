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
#include <cmath>
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

// A box of pixels and how many there are.
struct Region {
  int count = 0, x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  void Add(int x, int y) {
    ++count;
    x0 = std::min(x0, x);
    y0 = std::min(y0, y);
    x1 = std::max(x1, x);
    y1 = std::max(y1, y);
  }
};

struct Pixel {
  int r, g, b;
};

Pixel At(cairo_surface_t* s, int x, int y) {
  const unsigned char* data = cairo_image_surface_get_data(s);
  const uint32_t v =
      *reinterpret_cast<const uint32_t*>(data + y * cairo_image_surface_get_stride(s) + 4 * x);
  return {int((v >> 16) & 255), int((v >> 8) & 255), int(v & 255)};
}

bool Red(Pixel p) { return p.r > p.g + 60 && p.r > p.b + 60; }
bool Green(Pixel p) { return p.g > p.r + 60 && p.g > p.b + 60; }
bool Yellow(Pixel p) { return p.r > 200 && p.g > 200 && p.b < 90; }
bool Dark(Pixel p) { return p.r < 80 && p.g < 80 && p.b < 80; }

class RenderHtml : public ScratchDirTest {
 protected:
  // `archgeo render` of a twisted grid (red) beside a planar one (green).
  void Render() {
    std::ofstream(Path("twisted.obj")) << GridObj(8, 0.05);
    std::ofstream(Path("flat.obj")) << GridObj(8, 0.0);
    std::string output;
    ASSERT_EQ(Shell(std::string(ARCHGEO_BINARY) + " render " + Path("twisted.obj") + " " +
                        Path("flat.obj") + " --out " + Path("view.html"), &output), 0)
        << output;
  }
  // Headless Chromium on the page with `flags` (a window size, a screenshot
  // or --dump-dom); its standard output.
  std::string Chromium(const std::string& flags, const std::string& url_suffix = "") {
    std::string output;
    const int code = Shell("timeout 120 " + std::string(kChromium) +
                               " --headless=new --no-sandbox --disable-gpu --hide-scrollbars "
                               "--user-data-dir=" + Path("profile") + " " + flags +
                               " 'file://" + Path("view.html") + url_suffix + "' 2>/dev/null",
                           &output);
    EXPECT_EQ(code, 0) << output;
    return output;
  }
  // At a window of width × height: both meshes and the whole colour bar
  // inside the window, the meshes filling it, the bar beside them.
  void ExpectFilledWindow(int width, int height) {
    const std::string shot = Path("shot.png");
    Chromium("--window-size=" + std::to_string(width) + "," + std::to_string(height) +
             " --screenshot=" + shot);
    cairo_surface_t* s = cairo_image_surface_create_from_png(shot.c_str());
    ASSERT_EQ(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
    ASSERT_EQ(cairo_image_surface_get_width(s), width);
    ASSERT_EQ(cairo_image_surface_get_height(s), height);
    Region red, green, yellow;
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const Pixel p = At(s, x, y);
        if (Yellow(p)) yellow.Add(x, y);
        else if (Red(p)) red.Add(x, y);
        else if (Green(p)) green.Add(x, y);
      }
    }
    // The bar: the yellow middle of its gradient, then up through red and
    // down through green to its black border, both ends in the window.
    ASSERT_GT(yellow.count, 20) << "no colour bar at " << width << "x" << height;
    const int bar_x = (yellow.x0 + yellow.x1) / 2, mid = (yellow.y0 + yellow.y1) / 2;
    int top = mid, bottom = mid;
    while (top > 0 && !Dark(At(s, bar_x, top))) --top;
    while (bottom < height - 1 && !Dark(At(s, bar_x, bottom))) ++bottom;
    EXPECT_TRUE(Dark(At(s, bar_x, top)) && Red(At(s, bar_x, top + 3))) << "bar top cut";
    EXPECT_TRUE(Dark(At(s, bar_x, bottom)) && Green(At(s, bar_x, bottom - 3))) << "bar bottom cut";
    EXPECT_GT(bottom - top, height / 2) << "the bar does not use the window's height";
    // The meshes: red left of green, left of the bar, inside the window
    // (the bar's own red and green are right of bar_x - 20), each spanning
    // at least 40% of the window's width.
    Region twisted, flat;
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < bar_x - 20; ++x) {
        const Pixel p = At(s, x, y);
        if (Red(p)) twisted.Add(x, y);
        if (Green(p)) flat.Add(x, y);
      }
    }
    cairo_surface_destroy(s);
    EXPECT_GT(twisted.x0, 0);
    EXPECT_GT(twisted.y0, 0);
    EXPECT_LT(twisted.y1, height - 1);
    EXPECT_LT(twisted.x1, flat.x0) << "the panels overlap";
    EXPECT_LT(flat.x1, bar_x - 30) << "the right panel runs into the bar";
    EXPECT_GT(flat.y0, 0);
    EXPECT_LT(flat.y1, height - 1);
    EXPECT_GT(twisted.x1 - twisted.x0, 2 * width / 5) << "the left mesh does not fill its half";
    EXPECT_GT(flat.x1 - flat.x0, 2 * width / 5) << "the right mesh does not fill its half";
  }
};

TEST_F(RenderHtml, HeadlessChromiumDrawsTheMesh) {
  ASSERT_TRUE(fs::exists(kChromium)) << "no " << kChromium << " (tools/install_deps.sh installs it)";
  Render();
  // The page is self-contained: no http(s) resource.
  const std::string html = ReadFile(Path("view.html"));
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  Chromium("--window-size=1000,560 --screenshot=" + Path("shot.png"));
  cairo_surface_t* shot = cairo_image_surface_create_from_png(Path("shot.png").c_str());
  ASSERT_EQ(cairo_surface_status(shot), CAIRO_STATUS_SUCCESS);
  // The panels share the width left of the colour bar (120 px).
  const Count left = CountPixels(shot, 0, 440, 60, 500);
  const Count right = CountPixels(shot, 440, 880, 60, 500);
  cairo_surface_destroy(shot);
  EXPECT_GT(left.red, 400 * 400 / 10) << "the twisted grid is not drawn red";
  EXPECT_EQ(left.green, 0);
  EXPECT_GT(right.green, 400 * 400 / 10) << "the planar grid is not drawn green";
  EXPECT_EQ(right.red, 0);
}

TEST_F(RenderHtml, TheViewFillsTheWindowWithItsLegendInside) {
  Render();
  ExpectFilledWindow(1200, 800);
  ExpectFilledWindow(1920, 1080);
}

// #face=ID pins that face as a click does: its id and value in every panel.
TEST_F(RenderHtml, AFaceIdInTheAddressIsPinnedWithItsValue) {
  Render();
  const std::string dom = Chromium("--dump-dom", "#face=5");
  const std::string twisted = "<span id=\"pinned\">pinned twisted.obj \u2014 face 5: planarity "
                              "\u03b4_PQ,n: diagonal distance ";
  const size_t at = dom.find(twisted);
  ASSERT_NE(at, std::string::npos) << dom;
  // A twisted quad of tests/grid_obj.h: δ_PQ,n between 0.01 and twist / √2.
  const double value = std::stod(dom.substr(at + twisted.size(), 12));
  EXPECT_GT(value, 0.01);
  EXPECT_LT(value, 0.05 / std::sqrt(2.0));
  EXPECT_NE(dom.find("flat.obj \u2014 face 5: planarity \u03b4_PQ,n: diagonal distance 0 ["),
            std::string::npos) << dom;
  const std::string none = Chromium("--dump-dom", "#face=64");  // 8 × 8 faces: 0..63
  EXPECT_NE(none.find("<span id=\"pinned\"></span>"), std::string::npos) << none;
}

// Hovering and clicking in a real browser: a page that holds the view in a
// frame sends pointer events to the middle of a quad near the left canvas's
// centre and to its empty corner, and writes what the view then shows.
TEST_F(RenderHtml, HoverShowsAndAClickPinsTheFaceUnderThePointer) {
  Render();
  WriteFile("frame.html", R"(<!DOCTYPE html><html><body>
<iframe id="f" src="view.html" width="1200" height="800"></iframe><pre id="out"></pre><script>
document.getElementById("f").addEventListener("load", () => {
  const w = document.getElementById("f").contentWindow, d = w.document;
  const c = d.getElementById("c0"), r = c.getBoundingClientRect();
  const at = (x, y) => ({clientX: r.left + x, clientY: r.top + y, bubbles: true, button: 0});
  const click = (x, y) => {
    c.dispatchEvent(new w.PointerEvent("pointermove", at(x, y)));
    const tip = d.getElementById("tip").style.display == "none" ? "" :
                d.getElementById("tip").textContent;
    c.dispatchEvent(new w.PointerEvent("pointerdown", at(x, y)));
    c.dispatchEvent(new w.PointerEvent("pointerup", at(x, y)));
    return "tip[" + tip + "] pinned[" + d.getElementById("pinned").textContent + "] hash[" +
           w.location.hash + "]\n";
  };
  document.getElementById("out").textContent =
      click(r.width / 2 + 7, r.height / 2 + 5) + click(3, 3);
});
</script></body></html>)");
  std::string output;
  ASSERT_EQ(Shell("timeout 120 " + std::string(kChromium) +
                      " --headless=new --no-sandbox --disable-gpu --allow-file-access-from-files"
                      " --virtual-time-budget=5000 --user-data-dir=" + Path("profile") +
                      " --dump-dom 'file://" + Path("frame.html") + "' 2>/dev/null", &output),
            0);
  const size_t first = output.find("tip[face ");
  ASSERT_NE(first, std::string::npos) << output;
  const int face = std::stoi(output.substr(first + 9));
  EXPECT_GE(face, 0);
  EXPECT_LT(face, 64);
  const std::string id = "face " + std::to_string(face) + ": planarity";
  EXPECT_NE(output.find("pinned[pinned twisted.obj \u2014 " + id), std::string::npos) << output;
  EXPECT_NE(output.find("hash[#face=" + std::to_string(face) + "]"), std::string::npos) << output;
  // The corner holds no face: no tip, and the click there unpins.
  EXPECT_NE(output.find("tip[] pinned[] hash[]"), std::string::npos) << output;
}

}  // namespace
}  // namespace archgeo
