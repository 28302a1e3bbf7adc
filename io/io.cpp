// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — mesh files: parsing (io/soup_readers.h), CGAL's soup repair,
// and CGAL's writers.
//
// ReadMesh runs four steps:
//  1. ReadInputFile (io/input_file.h): regular files only, at most
//     limits.max_file_bytes, read whole.
//  2. ParseObj / ParseOff / ParsePly (io/soup_readers.h): the bytes into a
//     polygon soup, every count checked against the file size and `limits`
//     before anything is allocated, the line of every record kept. (CGAL's
//     own soup readers are not used: soup_readers.h says why.)
//  3. CheckSoup: non-finite points, coordinates beyond core/magnitude.h's
//     bounds, faces with fewer than 3 vertices,
//     out-of-range or repeated indices, degenerate faces.
//  3b. WeldCoincidentVertices (io/weld.h) when limits.weld_distance > 0:
//     a per-face-vertices export becomes one surface; the weld's result is
//     checked again (step 3 and 4), and a face it collapses or a
//     non-manifold vertex it makes is bad input.
//  4. PMP::orient_polygon_soup, refused if it had to duplicate a vertex or
//     left an edge with one direction in both its faces
//     (io/soup_halfedges.h); then PMP::polygon_soup_to_polygon_mesh
//     builds the mesh (every point, isolated ones included, in file order,
//     so vertex i is the file's i-th vertex), its precondition
//     is_polygon_soup_a_polygon_mesh off in release: step 4 established it.
// PMP::IO::read_polygon_mesh is not used: its soup repair merges duplicate
// points and drops isolated ones, renumbering the vertices.
// Messages number vertices and faces from 0, in file order.
#include "io/io.h"
#include "io/weld.h"

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <glog/logging.h>

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <type_traits>

#include "core/input_error.h"
#include "core/magnitude.h"
#include "io/input_file.h"
#include "io/output_stream.h"
#include "io/soup_halfedges.h"
#include "io/soup_readers.h"
#include "io/text_scan.h"

namespace archgeo {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

enum class Format { kObj, kOff, kPly };

// A mesh as CGAL's soup functions (orientation, mesh building, writers) see it.
struct Soup {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
};

Format FormatOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".obj") return Format::kObj;
  if (ext == ".off") return Format::kOff;
  if (ext == ".ply") return Format::kPly;
  FailInput(
      path, 0,
      (ext.empty() ? std::string("no file extension") : "unknown extension " + QuoteToken(ext)) +
          "; supported mesh formats: .obj, .off, .ply");
}

const char* FormatName(Format format) {
  switch (format) {
    case Format::kObj:
      return "obj";
    case Format::kOff:
      return "off";
    case Format::kPly:
      return "ply";
  }
  return "";
}

// The file's content as a soup of CGAL points.
Soup ParseSoup(const std::string& name, Format format, std::string_view data,
               const ReadLimits& limits, LineMap* lines) {
  PolygonSoup parsed;
  switch (format) {
    case Format::kObj:
      parsed = ParseObj(name, data, limits);
      break;
    case Format::kOff:
      parsed = ParseOff(name, data, limits);
      break;
    case Format::kPly:
      parsed = ParsePly(name, data, limits);
      break;
  }
  Soup soup;
  soup.points.reserve(parsed.points.size());
  for (const auto& p : parsed.points) soup.points.emplace_back(p[0], p[1], p[2]);
  soup.polygons = std::move(parsed.polygons);
  *lines = std::move(parsed.lines);
  return soup;
}

double BoundingBoxDiagonal(const std::vector<Point>& points) {
  CGAL::Bbox_3 box;
  for (const Point& p : points) box += p.bbox();
  const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin(),
               dz = box.zmax() - box.zmin();
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// Face `j` has at least 3 vertices, each index in range and used once.
void CheckFaceIndices(const std::string& path, const Soup& soup, std::size_t j, int line) {
  const auto& polygon = soup.polygons[j];
  const std::string face = "face " + std::to_string(j);
  if (polygon.size() < 3) {
    FailInput(
        path, line,
        face + " has " + std::to_string(polygon.size()) + " vertices; a face needs at least 3");
  }
  for (std::size_t v : polygon) {
    if (v >= soup.points.size()) {
      FailInput(path, line, OutOfRangeMessage(j, soup.points.size()));
    }
  }
  std::vector<std::size_t> sorted = polygon;
  std::sort(sorted.begin(), sorted.end());
  const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
  if (repeated != sorted.end()) {
    FailInput(path, line, face + " uses vertex " + std::to_string(*repeated) + " more than once");
  }
}

// Face `j` has no coincident consecutive vertices and a non-zero (vector)
// area, relative to the squared bounding-box diagonal. Its corners are
// taken relative to its first one in units of the diagonal, so a mesh
// scaled by 1e±100 is judged as the original (an area's squared length is
// a length to the fourth power: it would underflow or overflow).
void CheckFaceShape(const std::string& path, const Soup& soup, std::size_t j, int line,
                    double diagonal) {
  constexpr double kRelativeArea = 1e-14;
  const auto& polygon = soup.polygons[j];
  const std::string face = "face " + std::to_string(j);
  const Point& origin = soup.points[polygon[0]];
  const auto corner = [&](std::size_t k) { return (soup.points[polygon[k]] - origin) / diagonal; };
  Vector twice_area(0, 0, 0);
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const std::size_t next = (k + 1) % polygon.size();
    if ((corner(next) - corner(k)).squared_length() <= kRelativeArea) {
      FailInput(path, line,
                face + " is degenerate: its vertices " + std::to_string(polygon[k]) + " and " +
                    std::to_string(polygon[next]) + " coincide");
    }
    twice_area = twice_area + CGAL::cross_product(corner(k), corner(next));
  }
  if (0.5 * std::sqrt(twice_area.squared_length()) <= kRelativeArea) {
    FailInput(path, line, face + " is degenerate: zero area (collinear vertices)");
  }
}

// Coordinates whose squares stay normal doubles: every length, area and
// distance is computed from differences and squares of them.
void CheckMagnitude(const std::string& path, const Soup& soup, const LineMap& lines,
                    double diagonal) {
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const Point& p = soup.points[i];
    for (int k = 0; k < 3; ++k) {
      if (std::abs(p[k]) >= kMaxCoordinate) {
        char value[32];
        std::snprintf(value, sizeof value, "%g", p[k]);
        FailInput(path, lines.Vertex(i),
                  "vertex " + std::to_string(i) + " has the coordinate " + value +
                      ": coordinates must lie within ±1e150 (their squares would overflow); "
                      "scale the mesh down");
      }
    }
  }
  if (diagonal > 0 && diagonal < kMinDiagonal) {
    char value[32];
    std::snprintf(value, sizeof value, "%g", diagonal);
    FailInput(path, 0,
              std::string("the mesh is ") + value +
                  " across (bounding-box diagonal): at least 1e-150 is needed (squared lengths "
                  "would underflow); scale the mesh up");
  }
}

// Checks what CGAL's readers accept but a mesh cannot have.
void CheckSoup(const std::string& path, const Soup& soup, const LineMap& lines) {
  if (soup.polygons.empty()) FailInput(path, 0, NoFacesMessage(soup.points.size()));
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const Point& p = soup.points[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
      FailInput(path, lines.Vertex(i), "non-finite coordinate in vertex " + std::to_string(i));
    }
  }
  const double diagonal = BoundingBoxDiagonal(soup.points);
  CheckMagnitude(path, soup, lines, diagonal);
  for (std::size_t j = 0; j < soup.polygons.size(); ++j) {
    CheckFaceIndices(path, soup, j, lines.Face(j));
    CheckFaceShape(path, soup, j, lines.Face(j), diagonal);
  }
}

// What orient_polygon_soup reports through its visitor.
struct OrientationReport {
  std::vector<bool> flipped;                               // per polygon
  std::vector<std::array<std::size_t, 3>> singular_edges;  // (a, b, number of faces)
  std::vector<std::size_t> singular_vertices;
};

// CGAL copies the visitor, so it writes through a pointer.
struct OrientationVisitor : PMP::Default_orientation_visitor {
  OrientationReport* report = nullptr;
  void non_manifold_edge(std::size_t a, std::size_t b, std::size_t faces) {
    report->singular_edges.push_back({a, b, faces});
  }
  void non_manifold_vertex(std::size_t v, std::size_t) { report->singular_vertices.push_back(v); }
  void polygon_orientation_reversed(std::size_t p) { report->flipped[p] = !report->flipped[p]; }
};

// Welds the soup's coincident vertices (io/weld.h); the number welded away.
std::size_t Weld(Soup* soup, double distance) {
  if (!(distance > 0)) return 0;
  std::vector<std::array<double, 3>> points;
  points.reserve(soup->points.size());
  for (const Point& p : soup->points) points.push_back({p.x(), p.y(), p.z()});
  const std::size_t welded = WeldCoincidentVertices(&points, &soup->polygons, distance);
  if (welded == 0) return 0;
  soup->points.clear();
  for (const auto& p : points) soup->points.emplace_back(p[0], p[1], p[2]);
  return welded;
}

// Orients the soup consistently and returns the number of faces flipped.
// Fails if that needs duplicated vertices (non-manifold or non-orientable).
int Orient(const std::string& path, Soup* soup, const LineMap& lines) {
  OrientationReport report;
  report.flipped.assign(soup->polygons.size(), false);
  OrientationVisitor visitor;
  visitor.report = &report;
  const bool no_duplicates =
      PMP::orient_polygon_soup(soup->points, soup->polygons, CGAL::parameters::visitor(visitor));
  if (!report.singular_edges.empty()) {
    const auto [a, b, faces] = report.singular_edges.front();
    FailInput(path, 0,
              "non-manifold edge between vertices " + std::to_string(a) + " and " +
                  std::to_string(b) + ": " + std::to_string(faces) + " faces share it");
  }
  if (!report.singular_vertices.empty()) {
    const std::size_t v = report.singular_vertices.front();
    FailInput(path, lines.Vertex(v),
              "non-manifold vertex " + std::to_string(v) +
                  ": its faces do not form one consistently oriented fan"
                  " (two fans touch there, or the surface is not orientable)");
  }
  if (!no_duplicates || !EachOrderedEdgeOnce(soup->polygons, soup->points.size())) {
    FailInput(path, 0,
              "non-manifold or non-orientable mesh: the faces cannot be oriented consistently");
  }
  return static_cast<int>(std::count(report.flipped.begin(), report.flipped.end(), true));
}

// The mesh's vertices (index order, removed ones skipped) and faces.
Soup ToSoup(const Mesh& mesh) {
  Soup soup;
  std::vector<std::size_t> index(mesh.num_vertices());
  for (VertexIndex v : mesh.vertices()) {
    index[v.idx()] = soup.points.size();
    soup.points.push_back(mesh.point(v));
  }
  for (FaceIndex f : mesh.faces()) {
    auto& polygon = soup.polygons.emplace_back();
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      polygon.push_back(index[v.idx()]);
  }
  return soup;
}

// PLY written directly (CGAL's writer has no float face properties): the
// header, then the vertices and the faces in soup order. `colors` and each
// property's values are in soup (mesh.faces()) order.
bool WritePly(std::ostream& out, const Soup& soup, const std::vector<Rgb>* colors,
              const std::vector<PlyValues>& properties,
              const std::vector<PlyValues>& vertex_properties, bool ascii) {
  out << "ply\nformat " << (ascii ? "ascii" : "binary_little_endian") << " 1.0\n"
      << "comment archgeo\n"
      << "element vertex " << soup.points.size() << "\n"
      << "property double x\nproperty double y\nproperty double z\n";
  for (const PlyValues& p : vertex_properties) out << "property float " << p.name << "\n";
  out << "element face " << soup.polygons.size() << "\n"
      << "property list uchar int vertex_indices\n";
  if (colors) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  for (const PlyValues& p : properties) out << "property float " << p.name << "\n";
  out << "end_header\n";
  const auto raw = [&](const auto& value) {  // little-endian hosts only (x86-64, arm64)
    out.write(reinterpret_cast<const char*>(&value), sizeof value);
  };
  // ASCII: each number by std::to_chars, as printf's %.17g (coordinates),
  // %.9g (float properties) and %d (the same text as std::ostream, without
  // its per-number locale work), into blocks.
  std::string text;
  const auto number = [&](auto value, int digits) {
    char buffer[64];
    std::to_chars_result r;
    if constexpr (std::is_floating_point_v<decltype(value)>) {
      r = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, digits);
    } else {
      r = std::to_chars(buffer, buffer + sizeof buffer, value);
    }
    text.append(buffer, r.ptr);
  };
  const auto line = [&] {
    text += '\n';
    if (text.size() >= (1u << 16)) out.write(text.data(), std::streamsize(text.size())), text.clear();
  };
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const Point& p = soup.points[i];
    if (ascii) {
      number(p.x(), 17), text += ' ', number(p.y(), 17), text += ' ', number(p.z(), 17);
      for (const PlyValues& v : vertex_properties) text += ' ', number(float(v.values[i]), 9);
      line();
    } else {
      for (double x : {p.x(), p.y(), p.z()}) raw(x);
      for (const PlyValues& v : vertex_properties) raw(float(v.values[i]));
    }
  }
  for (std::size_t j = 0; j < soup.polygons.size(); ++j) {
    const auto& polygon = soup.polygons[j];
    if (ascii) {
      number(polygon.size(), 0);
      for (std::size_t v : polygon) text += ' ', number(v, 0);
      if (colors) {
        for (int c = 0; c < 3; ++c) text += ' ', number(int((*colors)[j][c]), 0);
      }
      for (const PlyValues& p : properties) text += ' ', number(float(p.values[j]), 9);
      line();
    } else {
      raw(std::uint8_t(polygon.size()));
      for (std::size_t v : polygon) raw(std::int32_t(v));
      if (colors) {
        for (int c = 0; c < 3; ++c) raw(std::uint8_t((*colors)[j][c]));
      }
      for (const PlyValues& p : properties) raw(float(p.values[j]));
    }
  }
  out.write(text.data(), std::streamsize(text.size()));
  return bool(out);
}

}  // namespace

void CheckMeshExtension(const std::string& path) { FormatOf(path); }

Mesh ReadMesh(const std::string& path, ReadInfo* info, const ReadLimits& limits) {
  FormatOf(path);  // an unknown extension is refused before the file is opened
  const std::string data = ReadInputFile(path, "", limits.max_file_bytes);
  return ReadMeshFromMemory(path, data, info, limits);
}

Mesh ReadMeshFromMemory(const std::string& name, std::string_view data, ReadInfo* info,
                        const ReadLimits& limits) {
  const Format format = FormatOf(name);
  if (data.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    FailInput(name, 0, "the file is empty");
  }
  LineMap lines;
  Soup soup = ParseSoup(name, format, data, limits, &lines);
  CheckSoup(name, soup, lines);
  const std::size_t welded = Weld(&soup, limits.weld_distance);
  int flipped = 0;
  if (welded == 0) {
    flipped = Orient(name, &soup, lines);
  } else {
    try {
      LineMap faces_only;  // vertex numbers changed: no vertex lines
      faces_only.face = lines.face;
      CheckSoup(name, soup, faces_only);
      flipped = Orient(name, &soup, faces_only);
    } catch (const InputError& e) {
      throw InputError(e.file(), e.line(), "limits.weld_distance",
                       e.message() + " (after welding " + std::to_string(welded) +
                           " coincident vertices; limits.weld_distance: 0 reads the file unwelded)");
    }
  }
  if (info != nullptr) *info = {FormatName(format), flipped, int(welded)};

  // Every point (isolated ones included) in file order, then every face.
  // CGAL's precondition here, is_polygon_soup_a_polygon_mesh, is off in
  // release builds (NDEBUG): CheckSoup and Orient have established it.
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
  CHECK_EQ(mesh.number_of_vertices(), soup.points.size());
  CHECK_EQ(mesh.number_of_faces(), soup.polygons.size());
  return mesh;
}

void WriteMesh(const std::string& path, const Mesh& mesh, const std::vector<Rgb>* face_colors,
               bool ascii_ply, const std::vector<PlyValues>* face_values,
               const std::vector<PlyValues>* vertex_values) {
  const Format format = FormatOf(path);
  std::size_t written = 0;  // the vertex's number in the file
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
      std::ostringstream message;
      message << "vertex " << written << " has a non-finite coordinate (" << p.x() << ", "
              << p.y() << ", " << p.z() << "); refusing to write a mesh that cannot be read back";
      FailInput(path, 0, message.str());
    }
    ++written;
  }
  const Soup soup = ToSoup(mesh);
  for (std::size_t j = 0; format == Format::kPly && j < soup.polygons.size(); ++j) {
    if (soup.polygons[j].size() > 255) {
      FailInput(path, 0,
                "face " + std::to_string(j) + " has more than 255 vertices, more than PLY" +
                    " (a uchar vertex count) can store");
    }
  }
  NoFollowOfstream out(path);
  if (!out) FailInput(path, 0, std::string("cannot open for writing: ") + std::strerror(errno));
  const auto precision = CGAL::parameters::stream_precision(17);
  bool ok = false;
  switch (format) {
    case Format::kObj:
      ok = CGAL::IO::write_OBJ(out, soup.points, soup.polygons, precision);
      break;
    case Format::kOff:
      ok = CGAL::IO::write_OFF(out, soup.points, soup.polygons, precision);
      break;
    case Format::kPly: {
      std::vector<Rgb> colors;  // in soup (mesh.faces()) order
      if (face_colors != nullptr) {
        for (FaceIndex f : mesh.faces()) {
          CHECK_LT(f.idx(), face_colors->size()) << "one colour per face";
          colors.push_back((*face_colors)[f.idx()]);
        }
      }
      // In soup order: mesh.faces() and mesh.vertices() order.
      const auto in_soup_order = [&](const std::vector<PlyValues>* given, auto range) {
        std::vector<PlyValues> out;
        for (std::size_t i = 0; given && i < given->size(); ++i) {
          const PlyValues& p = (*given)[i];
          CHECK(!p.name.empty() && p.name.find_first_not_of(
                                       "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                       "0123456789_") == std::string::npos)
              << "PLY property name '" << p.name << "'";
          PlyValues& q = out.emplace_back();
          q.name = p.name;
          for (auto element : range) {
            CHECK_LT(element.idx(), p.values.size()) << "one value per element";
            q.values.push_back(p.values[element.idx()]);
          }
        }
        return out;
      };
      const std::vector<PlyValues> properties = in_soup_order(face_values, mesh.faces());
      const std::vector<PlyValues> vertex_properties =
          in_soup_order(vertex_values, mesh.vertices());
      ok = WritePly(out, soup, face_colors != nullptr ? &colors : nullptr, properties,
                    vertex_properties, ascii_ply);
      break;
    }
  }
  out.close();
  if (!ok || out.fail()) FailInput(path, 0, "cannot write the mesh file");
}

}  // namespace archgeo
