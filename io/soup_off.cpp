// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — OFF (ASCII and binary) into a polygon soup (see soup_readers.h).
#include <cmath>
#include <cstdint>
#include <string>

#include "io/soup_readers.h"

namespace archgeo {
namespace {

// What the keyword's prefixes announce: [ST][C][N][4]OFF.
struct OffKeyword {
  bool textures = false, colors = false, normals = false, homogeneous = false;
  bool Plain() const { return !textures && !colors && !normals && !homogeneous; }
};

OffKeyword ParseKeyword(const std::string& path, int line, std::string_view keyword) {
  OffKeyword k;
  std::string_view rest = keyword;
  const auto take = [&](std::string_view prefix) {
    if (rest.substr(0, prefix.size()) != prefix) return false;
    rest.remove_prefix(prefix.size());
    return true;
  };
  k.textures = take("ST");
  k.colors = take("C");
  k.normals = take("N");
  k.homogeneous = take("4");
  if (rest.substr(0, 1) == "n") {
    FailInput(path, line, "n-dimensional OFF (" + std::string(keyword) + ") is not supported");
  }
  if (rest != "OFF") {
    FailInput(path, line,
              "not an OFF file: expected the keyword 'OFF' (or STOFF, COFF, NOFF, 4OFF, ...), "
              "found " + QuoteToken(keyword));
  }
  return k;
}

// Declared counts, checked against what `available` bytes can hold (at
// `vertex_bytes` and `face_bytes` each, at the least), then against `limits`.
void CheckCounts(const std::string& path, int line, const char* kind, long long vertices,
                 long long faces, std::uint64_t vertex_bytes, std::uint64_t face_bytes,
                 std::uint64_t available, const ReadLimits& limits) {
  if (vertices < 0 || faces < 0) {
    FailInput(path, line,
              "negative count in the OFF header (" + std::to_string(vertices) + " vertices, " +
                  std::to_string(faces) + " faces)");
  }
  const std::uint64_t needed =
      SaturatingAdd(SaturatingMul(static_cast<std::uint64_t>(vertices), vertex_bytes),
                    SaturatingMul(static_cast<std::uint64_t>(faces), face_bytes));
  if (needed > available) {
    FailInput(path, line,
              "the header declares " + std::to_string(vertices) + " vertices and " +
                  std::to_string(faces) + " faces; " + kind + " OFF needs at least " +
                  std::to_string(vertex_bytes) + " bytes per vertex and " +
                  std::to_string(face_bytes) + " per face, but the file holds only " +
                  std::to_string(available) +
                  " bytes after the header: it is truncated or the header is wrong");
  }
  if (static_cast<std::uint64_t>(vertices) > limits.max_vertices) {
    FailInput(path, line,
              LimitMessage("the header declares " + std::to_string(vertices) + " vertices",
                           limits.max_vertices, "limits.max_vertices"));
  }
  if (static_cast<std::uint64_t>(faces) > limits.max_faces) {
    FailInput(path, line,
              LimitMessage("the header declares " + std::to_string(faces) + " faces",
                           limits.max_faces, "limits.max_faces"));
  }
}

std::string ExtraMessage(std::size_t vertices, std::size_t faces) {
  return "the file holds more than its header declares (" + std::to_string(vertices) +
         " vertices, " + std::to_string(faces) +
         " faces): the count is wrong or another mesh follows";
}

void FailFaceDegree(const std::string& path, int line, std::size_t face, long long size,
                    const ReadLimits& limits) {
  FailInput(path, line,
            LimitMessage("face " + std::to_string(face) + " declares " + std::to_string(size) +
                             " vertices",
                         limits.max_face_degree, "limits.max_face_degree"));
}

// Binary OFF (Geomview): after the "OFF BINARY" line, big-endian int32 counts
// (vertices, faces, edges), float32 x y z per vertex, and per face an int32
// n, n int32 indices, an int32 colour count (0..4) and that many float32.
PolygonSoup ParseBinaryOff(const std::string& path, std::string_view data, std::size_t offset,
                           const ReadLimits& limits) {
  ByteReader in(data, offset, /*big_endian=*/true);
  std::int32_t counts[3];
  for (std::int32_t& c : counts) {
    if (!in.Read(&c)) FailInput(path, 0, "binary OFF: the file ends inside the counts");
  }
  const long long num_vertices = counts[0], num_faces = counts[1];
  CheckCounts(path, 0, "binary", num_vertices, num_faces, 12, 8, in.remaining(), limits);
  PolygonSoup soup;
  soup.points.reserve(static_cast<std::size_t>(num_vertices));
  soup.polygons.reserve(static_cast<std::size_t>(num_faces));
  for (long long i = 0; i < num_vertices; ++i) {
    std::array<double, 3> p;
    for (double& x : p) {
      float f;
      if (!in.Read(&f)) {
        FailInput(path, 0,
                  "the header declares " + std::to_string(num_vertices) +
                      " vertices, but the file ends inside vertex " + std::to_string(i));
      }
      x = f;
      if (!std::isfinite(x)) {
        FailInput(path, 0, "non-finite coordinate in vertex " + std::to_string(i));
      }
    }
    soup.points.push_back(p);
  }
  const auto truncated = [&](std::size_t face) {
    FailInput(path, 0,
              "the header declares " + std::to_string(num_faces) +
                  " faces, but the file ends inside face " + std::to_string(face));
  };
  for (long long j = 0; j < num_faces; ++j) {
    const std::size_t face = soup.polygons.size();
    std::int32_t size;
    if (!in.Read(&size)) truncated(face);
    if (size < 0) {
      FailInput(path, 0,
                "face " + std::to_string(face) + " declares a negative vertex count (" +
                    std::to_string(size) + ")");
    }
    if (static_cast<std::uint64_t>(size) > limits.max_face_degree) {
      FailFaceDegree(path, 0, face, size, limits);
    }
    std::vector<std::size_t> polygon;
    polygon.reserve(static_cast<std::size_t>(size));
    for (std::int32_t k = 0; k < size; ++k) {
      std::int32_t index;
      if (!in.Read(&index)) truncated(face);
      if (index < 0 || index >= num_vertices) {
        FailInput(path, 0, OutOfRangeMessage(face, soup.points.size()));
      }
      polygon.push_back(static_cast<std::size_t>(index));
    }
    std::int32_t colors;
    if (!in.Read(&colors)) truncated(face);
    if (colors < 0 || colors > 4) {
      FailInput(path, 0,
                "face " + std::to_string(face) + ": the colour count after its indices is " +
                    std::to_string(colors) + "; binary OFF allows 0 to 4");
    }
    if (!in.Skip(4 * static_cast<std::uint64_t>(colors))) truncated(face);
    soup.polygons.push_back(std::move(polygon));
  }
  const std::string_view rest = data.substr(in.offset());
  if (rest.find_first_not_of(" \t\r\n") != std::string_view::npos) {
    FailInput(path, 0,
              ExtraMessage(soup.points.size(), soup.polygons.size()) + " (" +
                  std::to_string(rest.size()) + " bytes after the last face)");
  }
  if (soup.polygons.empty()) FailInput(path, 0, NoFacesMessage(soup.points.size()));
  return soup;
}

}  // namespace

// ASCII: the header, then one vertex per line, then faces "n i1 ... in
// [colour]" whose indices may wrap onto following lines.
PolygonSoup ParseOff(const std::string& path, std::string_view data, const ReadLimits& limits) {
  LineReader reader(data);
  if (!reader.Next()) FailInput(path, 0, "not an OFF file: no header");
  const OffKeyword keyword = ParseKeyword(path, reader.line(), reader.tokens()[0]);
  if (reader.tokens().size() > 1 && reader.tokens()[1] == "BINARY") {
    if (!keyword.Plain()) {
      FailInput(path, reader.line(),
                "binary OFF with per-vertex normals, colours, texture coordinates or "
                "homogeneous coordinates (" + std::string(reader.tokens()[0]) +
                    ") is not supported; use plain 'OFF BINARY', ASCII OFF or PLY");
    }
    return ParseBinaryOff(path, data, reader.end_offset(), limits);
  }
  std::vector<std::string_view> counts(reader.tokens().begin() + 1, reader.tokens().end());
  if (counts.empty() && reader.Next()) counts = reader.tokens();
  const auto num_vertices = counts.size() >= 2 ? ParseInteger(counts[0]) : std::nullopt;
  const auto num_faces = counts.size() >= 2 ? ParseInteger(counts[1]) : std::nullopt;
  if (!num_vertices || !num_faces || counts.size() > 3 ||
      (counts.size() == 3 && !ParseInteger(counts[2]))) {
    FailInput(path, reader.line(),
              "cannot read the counts of the OFF header: expected 'vertices faces [edges]'");
  }
  // The shortest records: "0 0 0\n" (8 bytes with w) and "0\n"; the last
  // line may lack its newline.
  const std::size_t dimension = keyword.homogeneous ? 4 : 3;
  CheckCounts(path, reader.line(), "ASCII", *num_vertices, *num_faces, 2 * dimension, 2,
              data.size() - reader.end_offset() + 1, limits);
  PolygonSoup soup;
  soup.points.reserve(static_cast<std::size_t>(*num_vertices));
  soup.polygons.reserve(static_cast<std::size_t>(*num_faces));
  for (long long i = 0; i < *num_vertices; ++i) {
    if (!reader.Next()) {
      FailInput(path, 0,
                "the header declares " + std::to_string(*num_vertices) +
                    " vertices, but the file has only " + std::to_string(i));
    }
    double values[4] = {0, 0, 0, 1};
    ParseVertexTokens(path, reader.line(), soup.points.size(), reader.tokens(), 0, dimension,
                      values);
    std::array<double, 3> p{values[0] / values[3], values[1] / values[3], values[2] / values[3]};
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      FailInput(path, reader.line(),
                "vertex " + std::to_string(i) + " has w = " + std::string(reader.tokens()[3]) +
                    ": x/w, y/w, z/w are not finite");
    }
    soup.points.push_back(p);
    soup.lines.vertex.push_back(reader.line());
  }
  for (long long j = 0; j < *num_faces; ++j) {
    const std::size_t face = soup.polygons.size();
    if (!reader.Next()) {
      FailInput(path, 0,
                "the header declares " + std::to_string(*num_faces) +
                    " faces, but the file has only " + std::to_string(j));
    }
    const int line = reader.line();
    std::vector<std::string_view> tokens = reader.tokens();
    const auto size = ParseInteger(tokens[0]);
    if (!size || *size < 0) {
      FailInput(path, line,
                "cannot parse " + QuoteToken(tokens[0]) + " as the vertex count of face " +
                    std::to_string(face));
    }
    if (static_cast<unsigned long long>(*size) > limits.max_face_degree) {
      FailFaceDegree(path, line, face, *size, limits);
    }
    while (tokens.size() < static_cast<std::size_t>(*size) + 1) {
      if (!reader.Next()) {
        FailInput(path, line,
                  "face " + std::to_string(face) + " declares " + std::to_string(*size) +
                      " vertices, but the file ends first");
      }
      tokens.insert(tokens.end(), reader.tokens().begin(), reader.tokens().end());
    }
    std::vector<std::size_t> polygon;
    polygon.reserve(static_cast<std::size_t>(*size));
    for (long long k = 1; k <= *size; ++k) {
      const auto index = ParseInteger(tokens[k]);
      if (!index || *index < 0) {
        FailInput(path, line,
                  "cannot parse " + QuoteToken(tokens[k]) + " as a vertex index in face " +
                      std::to_string(face));
      }
      if (*index >= *num_vertices) FailInput(path, line, OutOfRangeMessage(face, *num_vertices));
      polygon.push_back(static_cast<std::size_t>(*index));
    }
    for (std::size_t k = static_cast<std::size_t>(*size) + 1; k < tokens.size(); ++k) {
      double ignored;
      if (ParseDouble(tokens[k], &ignored) == NumberParse::kNotANumber) {
        FailInput(path, line,
                  "cannot parse " + QuoteToken(tokens[k]) + " as a colour value of face " +
                      std::to_string(face));
      }
    }
    soup.polygons.push_back(std::move(polygon));
    soup.lines.face.push_back(line);
  }
  if (reader.Next()) {
    FailInput(path, reader.line(), ExtraMessage(soup.points.size(), soup.polygons.size()));
  }
  if (soup.polygons.empty()) FailInput(path, 0, NoFacesMessage(soup.points.size()));
  return soup;
}

}  // namespace archgeo
