// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — pictures of meshes (render/picture.h) with a solve's per-face
// values (problems/report/colors.h): output.image and `archgeo render`.
#pragma once

#include <string>
#include <vector>

#include "mesh/surface_mesh.h"
#include "problems/report/colors.h"
#include "render/picture.h"

namespace archgeo {

// `mesh` (file units) with one value per face (indexed by face index; empty:
// grey) as a picture panel titled `title`.
PicturePanel PanelOf(const Mesh& mesh, const std::vector<double>& face_values, std::string title);

// The colour bar of `values`.
PictureScale ScaleOf(const FaceValues& values);

// The polylines of an OBJ file (`v` and `l` records; `g` sets the colour as
// RenderRequest::lines says). Throws InputError(path, line, key, ...) for a
// file that cannot be read, a bad record or an index out of range.
std::vector<PictureLine> ReadPolylines(const std::string& path, const std::string& key);

// `archgeo render MESH... --out OUT.png`.
struct RenderRequest {
  std::vector<std::string> meshes;  // drawn side by side, the first sets camera and scale
  std::string out;                  // .png (a picture) or .html (a page to rotate)
  std::string value = "auto";       // a FaceValueNames() entry, "none", or "auto": planarity
                                    // when the first mesh has a face of 4+ sides, else bending
  double color_max = 0;             // > 0: the value drawn red; else the value's default
  std::vector<std::string> titles;  // one per mesh; default: the file names
  // OBJ polylines (`v`, `l`; e.g. output.streamlines), the i-th drawn over the
  // i-th mesh (PNG): group v red, w blue, separatrices black, others green.
  std::vector<std::string> lines;
  PictureOptions options;
};

// Reads the meshes, draws them and writes `out` (all-or-nothing, as every
// output). Returns the summary line(s). Throws InputError for unreadable
// meshes, a wrong number of titles, an unknown value or an output name not
// ending in .png or .html.
std::string RenderFiles(const RenderRequest& request);

}  // namespace archgeo
