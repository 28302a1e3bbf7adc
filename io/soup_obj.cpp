// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — OBJ into a polygon soup (see soup_readers.h).
#include <algorithm>
#include <array>
#include <string>

#include "io/soup_readers.h"

namespace archgeo {
namespace {

// Statements that carry no geometry archgeo reads: texture coordinates,
// normals, parameter-space vertices, grouping, materials, render attributes.
bool IsIgnoredStatement(std::string_view keyword) {
  static constexpr std::array<std::string_view, 18> kIgnored = {
      "vt", "vn", "vp", "o", "g", "s", "mg", "usemtl", "mtllib", "maplib", "usemap", "bevel",
      "c_interp", "d_interp", "lod", "shadow_obj", "trace_obj", "ctech"};
  return keyword == "stech" ||
         std::find(kIgnored.begin(), kIgnored.end(), keyword) != kIgnored.end();
}

void FailIndex(const std::string& path, int line, std::string_view token, std::size_t face) {
  FailInput(
      path, line,
      "cannot parse " + QuoteToken(token) + " as a vertex index in face " + std::to_string(face));
}

}  // namespace

PolygonSoup ParseObj(const std::string& path, std::string_view data, const ReadLimits& limits) {
  PolygonSoup soup;
  // Positive indices may refer to vertices listed later; they are checked at
  // the end (largest_index holds each face's largest positive index).
  std::vector<std::size_t> largest_index;
  for (LineReader reader(data); reader.Next();) {
    const auto& tokens = reader.tokens();
    const std::string_view keyword = tokens[0];
    if (keyword == "v") {
      if (soup.points.size() >= limits.max_vertices) {
        FailInput(path, reader.line(),
                  LimitMessage("the file has at least " +
                                   std::to_string(limits.max_vertices + 1) + " vertices",
                               limits.max_vertices, "limits.max_vertices"));
      }
      std::array<double, 3> p;
      ParseVertexTokens(path, reader.line(), soup.points.size(), tokens, 1, 3, p.data());
      soup.points.push_back(p);
      soup.lines.vertex.push_back(reader.line());
    } else if (keyword == "f") {
      const std::size_t face = soup.polygons.size();
      if (face >= limits.max_faces) {
        FailInput(path, reader.line(),
                  LimitMessage("the file has at least " + std::to_string(limits.max_faces + 1) +
                                   " faces",
                               limits.max_faces, "limits.max_faces"));
      }
      const std::size_t degree = tokens.size() - 1;
      if (degree > limits.max_face_degree) {
        FailInput(path, reader.line(),
                  LimitMessage("face " + std::to_string(face) + " has " + std::to_string(degree) +
                                   " vertices",
                               limits.max_face_degree, "limits.max_face_degree"));
      }
      std::vector<std::size_t> polygon;
      polygon.reserve(degree);
      std::size_t largest = 0;
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        const std::string_view token = tokens[k];
        const auto value = ParseInteger(token.substr(0, token.find('/')));
        if (!value || *value == 0) FailIndex(path, reader.line(), token, face);
        if (*value > 0) {
          // 1-based; values beyond any possible vertex count are out of range.
          if (static_cast<unsigned long long>(*value) > limits.max_vertices) {
            FailInput(path, reader.line(), OutOfRangeMessage(face, soup.points.size()));
          }
          polygon.push_back(static_cast<std::size_t>(*value - 1));
          largest = std::max(largest, static_cast<std::size_t>(*value));
        } else {
          // Relative: -1 is the last vertex read so far.
          const unsigned long long back = 0ULL - static_cast<unsigned long long>(*value);
          if (back > soup.points.size()) {
            FailInput(path, reader.line(),
                      "face " + std::to_string(face) + " refers to vertex " + std::string(token) +
                          " (relative), but only " + std::to_string(soup.points.size()) +
                          " vertices precede it");
          }
          polygon.push_back(soup.points.size() - static_cast<std::size_t>(back));
        }
      }
      soup.polygons.push_back(std::move(polygon));
      soup.lines.face.push_back(reader.line());
      largest_index.push_back(largest);
    } else if (!IsIgnoredStatement(keyword)) {
      FailInput(path, reader.line(),
                "unsupported OBJ statement " + QuoteToken(keyword) +
                    ": archgeo reads vertices ('v') and polygonal faces ('f'); lines ('l'), "
                    "points ('p'), curves and surfaces are not part of a polygon mesh");
    }
  }
  if (soup.polygons.empty()) FailInput(path, 0, NoFacesMessage(soup.points.size()));
  for (std::size_t j = 0; j < soup.polygons.size(); ++j) {
    if (largest_index[j] > soup.points.size()) {
      FailInput(path, soup.lines.Face(j), OutOfRangeMessage(j, soup.points.size()));
    }
  }
  return soup;
}

}  // namespace archgeo
