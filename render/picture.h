// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — PNG pictures of meshes with a per-face scalar as colours
// (`archgeo render`, output.image). Drawn with cairo (Debian libcairo2):
// orthographic view, painter's algorithm (faces sorted back to front), flat
// shading, one colour bar with the scale's label, units and red value.
// No CGAL: meshes come as plain arrays (problems/report/picture.h converts).
//
// Camera (shared by every panel, so before/after line up): the principal
// axes of the first panel's vertices; the view looks along the axis of least
// spread (the "normal" of a roof-like surface), tilted by `tilt_degrees`
// about the axis of largest spread (drawn horizontal) so that relief shows;
// screen-up is the side with the larger world z. All panels share one scale
// (the union of their projected extents fits a panel).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace archgeo {

// A polyline drawn over a panel's faces (e.g. streamlines, `archgeo render
// --lines`), in the panel's coordinates.
struct PictureLine {
  std::vector<std::array<double, 3>> points;
  std::array<unsigned char, 3> rgb{0, 0, 0};
  double width = 1;  // pixels
};

struct PicturePanel {
  std::string title;                        // drawn above the panel
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<int>> faces;      // indices into points (≥ 3 each)
  std::vector<double> face_values;          // one per face; empty: all drawn grey
  // Drawn after the faces (over them, without hidden-line removal: meant for
  // lines on the surface seen from its outside, as the default camera does).
  std::vector<PictureLine> lines;
};

struct PictureScale {
  std::string label;     // what the colours show
  std::string units;     // e.g. "rad", "degrees", "1"
  double red_at = 1;     // the value drawn pure red (colour bar top)
  std::string red_from;  // where red_at comes from, e.g. "tolerance.pq_normalized_max"
  bool bar = true;       // false: faces grey, no colour bar (no per-face quantity)
};

struct PictureOptions {
  int panel_width = 720;    // pixels per panel
  int panel_height = 560;
  double tilt_degrees = 35;  // view tilt from the surface's normal
  bool edges = true;         // draw face edges when faces are large enough
};

// Draws the panels side by side with one colour bar and writes a PNG.
// Throws InputError(path, 0, key, ...) if the file cannot be written, and for
// no panel or a panel without faces.
void WritePicture(const std::string& path, const std::vector<PicturePanel>& panels,
                  const PictureScale& scale, const PictureOptions& options = {},
                  const std::string& key = "");

// The camera described above for `panel`: screen right, screen up and the
// direction towards the viewer (unit vectors, right-handed).
std::array<std::array<double, 3>, 3> DefaultCamera(const PicturePanel& panel,
                                                   double tilt_degrees);

// The title line of a panel's colours: its largest finite value and the share
// of faces at or above `red_at` ("max 0.00123, 4.2% of faces at red"); empty
// for a panel without values.
std::string PanelSummary(const PicturePanel& panel, double red_at);

// The same view as a self-contained HTML page (no server, no network: data
// and script inline): one canvas per panel, drag to rotate, the colour bar
// with the scale's label, units and red value. Throws InputError(path, 0,
// key, ...) as WritePicture.
void WriteHtmlView(const std::string& path, const std::vector<PicturePanel>& panels,
                   const PictureScale& scale, const PictureOptions& options = {},
                   const std::string& key = "");

// WritePicture or WriteHtmlView by the extension of `path` (.png, .html).
void WriteView(const std::string& path, const std::vector<PicturePanel>& panels,
               const PictureScale& scale, const PictureOptions& options = {},
               const std::string& key = "");

}  // namespace archgeo
