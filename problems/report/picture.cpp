// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/report/picture.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/input_error.h"
#include "io/io.h"
#include "io/output_files.h"
#include "mesh/similarity.h"

namespace archgeo {

PicturePanel PanelOf(const Mesh& mesh, const std::vector<double>& face_values, std::string title) {
  PicturePanel panel;
  panel.title = std::move(title);
  std::vector<int> index(mesh.num_vertices(), -1);
  for (VertexIndex v : mesh.vertices()) {
    index[v.idx()] = int(panel.points.size());
    const Point& p = mesh.point(v);
    panel.points.push_back({p.x(), p.y(), p.z()});
  }
  for (FaceIndex f : mesh.faces()) {
    std::vector<int>& face = panel.faces.emplace_back();
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      face.push_back(index[v.idx()]);
    }
    if (!face_values.empty()) panel.face_values.push_back(face_values[f.idx()]);
  }
  return panel;
}

PictureScale ScaleOf(const FaceValues& values) {
  return {values.label, values.units, values.red_at, values.red_from, values.name != "none"};
}

std::vector<PictureLine> ReadPolylines(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, key, "cannot open the OBJ file of polylines");
  std::vector<std::array<double, 3>> points;
  std::vector<PictureLine> lines;
  PictureLine style;
  style.rgb = {30, 140, 60};
  std::string text;
  int number = 0;
  while (std::getline(in, text)) {
    ++number;
    std::istringstream row(text);
    std::string tag;
    if (!(row >> tag) || tag[0] == '#') continue;
    if (tag == "v") {
      std::array<double, 3> p{};
      if (!(row >> p[0] >> p[1] >> p[2]) || !std::isfinite(p[0]) || !std::isfinite(p[1]) ||
          !std::isfinite(p[2])) {
        throw InputError(path, number, key, "expected `v x y z` with finite numbers");
      }
      points.push_back(p);
    } else if (tag == "g") {
      std::string group;
      row >> group;
      style.rgb = group == "v"              ? std::array<unsigned char, 3>{210, 40, 30}
                  : group == "w"            ? std::array<unsigned char, 3>{30, 80, 210}
                  : group == "separatrices" ? std::array<unsigned char, 3>{0, 0, 0}
                                            : std::array<unsigned char, 3>{30, 140, 60};
      style.width = group == "separatrices" ? 2.0 : 1.0;
    } else if (tag == "l") {
      PictureLine line = style;
      std::string token;
      while (row >> token) {
        const std::string index = token.substr(0, token.find('/'));
        char* end = nullptr;
        const long i = std::strtol(index.c_str(), &end, 10);
        const long n = long(points.size());
        const long k = i > 0 ? i - 1 : n + i;  // negative: relative to the end
        if (end == index.c_str() || *end != '\0' || i == 0 || k < 0 || k >= n) {
          throw InputError(path, number, key,
                           "'" + token + "' is not the index of a vertex given before it");
        }
        line.points.push_back(points[size_t(k)]);
      }
      lines.push_back(std::move(line));
    }
  }
  return lines;
}

std::string RenderFiles(const RenderRequest& r) {
  if (r.meshes.empty()) throw InputError("", 0, "MESH", "no mesh to draw");
  std::string extension = std::filesystem::path(r.out).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension != ".png" && extension != ".html") {
    throw InputError(r.out, 0, "--out",
                     "views are written as PNG pictures or HTML pages: use a .png or .html name");
  }
  if (!r.titles.empty() && r.titles.size() != r.meshes.size()) {
    throw InputError("", 0, "--titles",
                     std::to_string(r.titles.size()) + " titles for " +
                         std::to_string(r.meshes.size()) + " meshes");
  }
  const auto& names = FaceValueNames();
  if (r.value != "auto" && r.value != "none" &&
      std::find(names.begin(), names.end(), r.value) == names.end()) {
    std::string list = "auto, none";
    for (const std::string& n : names) list += ", " + n;
    throw InputError("", 0, "--value", "'" + r.value + "' is not a value (" + list + ")");
  }
  if (r.lines.size() > r.meshes.size()) {
    throw InputError("", 0, "--lines",
                     std::to_string(r.lines.size()) + " files of lines for " +
                         std::to_string(r.meshes.size()) + " meshes (at most one per mesh)");
  }
  std::vector<Mesh> meshes;
  for (const std::string& path : r.meshes) meshes.push_back(ReadMesh(path));
  std::vector<std::vector<PictureLine>> lines;
  for (const std::string& path : r.lines) lines.push_back(ReadPolylines(path, "--lines"));
  // Drawn and measured in the first mesh's local frame: the picture is the
  // same for a mesh far from the origin or at any scale.
  const Similarity local = LocalFrame(meshes.front());
  for (Mesh& mesh : meshes) mesh = InFrame(local, std::move(mesh));
  for (auto& list : lines) {
    for (PictureLine& line : list) {
      for (auto& p : line.points) {
        const Vec3 q = local.ToCanonical(Vec3{p[0], p[1], p[2]});
        p = {q[0], q[1], q[2]};
      }
    }
  }
  std::string value = r.value;
  if (value == "auto") {
    value = "bending";
    for (FaceIndex f : meshes.front().faces()) {
      if (meshes.front().degree(f) >= 4) value = "planarity";
    }
  }
  std::vector<PicturePanel> panels;
  PictureScale scale{"no per-face value (--value none)", "", 1, "", false};
  for (size_t i = 0; i < meshes.size(); ++i) {
    const std::string title =
        r.titles.empty() ? std::filesystem::path(r.meshes[i]).filename().string() : r.titles[i];
    if (value == "none") {
      panels.push_back(PanelOf(meshes[i], {}, title));
      if (i < lines.size()) panels.back().lines = lines[i];
      continue;
    }
    // The first mesh is the "before": it sets the scale of every panel.
    FaceValues v;
    try {
      v = ComputeFaceValues(value, meshes[i], &meshes.front(), nullptr, r.color_max);
    } catch (const InputError& e) {
      if (!e.file().empty()) throw;
      throw InputError(r.meshes[i], 0, e.key(), e.message());  // the value does not fit this mesh
    }
    if (i == 0) scale = ScaleOf(v);
    panels.push_back(PanelOf(meshes[i], v.values, title));
    if (i < lines.size()) panels.back().lines = lines[i];
  }
  std::vector<std::string> inputs = r.meshes;
  inputs.insert(inputs.end(), r.lines.begin(), r.lines.end());
  StagedOutputs staged(inputs);
  staged.Write(r.out, "--out", [&](const std::string& temporary) {
    WriteView(temporary, panels, scale, r.options, "--out");
  });
  staged.Commit();
  return "wrote " + r.out + ": " + std::to_string(panels.size()) + " panel(s), colour: " +
         scale.label + (scale.units.empty() ? "" : " [" + scale.units + "]") + ", red at " +
         std::to_string(scale.red_at) + "\n";
}

}  // namespace archgeo
