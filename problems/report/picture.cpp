// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/report/picture.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

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
  std::vector<Mesh> meshes;
  for (const std::string& path : r.meshes) meshes.push_back(ReadMesh(path));
  // Drawn and measured in the first mesh's local frame: the picture is the
  // same for a mesh far from the origin or at any scale.
  const Similarity local = LocalFrame(meshes.front());
  for (Mesh& mesh : meshes) mesh = InFrame(local, std::move(mesh));
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
      continue;
    }
    // The first mesh is the "before": it sets the scale of every panel.
    const FaceValues v =
        ComputeFaceValues(value, meshes[i], &meshes.front(), nullptr, r.color_max);
    if (i == 0) scale = ScaleOf(v);
    panels.push_back(PanelOf(meshes[i], v.values, title));
  }
  std::vector<std::string> inputs = r.meshes;
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
