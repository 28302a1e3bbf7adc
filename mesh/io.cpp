// archgeo — mesh files through CGAL's polygon-soup IO.
//
// ReadMesh runs four steps:
//  1. ScanObj / ScanOff / ScanPly (ASCII files only). CGAL's soup readers answer only true/false,
//     and std::istream cannot parse "nan" or "inf". The scan records the line
//     of every vertex and face record, rejects garbage and non-finite numbers
//     with their line, and joins OFF face lists wrapped over several lines
//     (CGAL's OFF reader reads one face per line; libigl's *_quads_*.off
//     files wrap them).
//  2. CGAL::IO::read_OBJ / read_OFF / read_PLY into a polygon soup. These
//     readers fill a soup, never a partial mesh.
//  3. CheckSoup: non-finite points (binary files), faces with fewer than 3
//     vertices, out-of-range or repeated indices, degenerate faces.
//  4. PMP::orient_polygon_soup, refused if it had to duplicate a vertex, and
//     PMP::polygon_soup_to_polygon_mesh, which inserts every point (isolated
//     ones included) in file order, so vertex i is the file's i-th vertex.
// PMP::IO::read_polygon_mesh is not used: its soup repair merges duplicate
// points and drops isolated ones, renumbering the vertices.
// Messages number vertices and faces from 0, in file order.
#include "mesh/io.h"

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <glog/logging.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string_view>

#include "mesh/input_error.h"

namespace archgeo {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

enum class Format { kObj, kOff, kPly };

// A mesh as CGAL's soup readers and writers see it.
struct Soup {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
};

// 1-based lines of the vertex and face records of an ASCII file (empty for
// binary files); used only to point messages at the file.
struct LineMap {
  std::vector<int> vertex, face;
  int Vertex(std::size_t i) const { return i < vertex.size() ? vertex[i] : 0; }
  int Face(std::size_t i) const { return i < face.size() ? face[i] : 0; }
};

[[noreturn]] void Fail(const std::string& path, int line, const std::string& message) {
  throw InputError(path, line, "", message);
}

std::string Quote(std::string_view token) { return "'" + std::string(token) + "'"; }

Format FormatOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".obj") return Format::kObj;
  if (ext == ".off") return Format::kOff;
  if (ext == ".ply") return Format::kPly;
  Fail(path, 0,
       (ext.empty() ? std::string("no file extension") : "unknown extension " + Quote(ext)) +
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

std::string NoFaces(std::size_t vertices) {
  return "empty mesh: the file has " + std::to_string(vertices) + " vertices but no faces";
}

std::string OutOfRange(std::size_t face, std::size_t vertices) {
  return "face " + std::to_string(face) + " refers to a vertex index out of range (the file has " +
         std::to_string(vertices) + " vertices)";
}

// Walks a text line by line (lines numbered from 1), dropping '#' comments
// and splitting the rest into whitespace-separated tokens ('\r' included).
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}

  // Advances to the next line with at least one token; false at the end.
  bool Next() {
    while (pos_ < text_.size()) {
      std::size_t end = std::min(text_.find('\n', pos_), text_.size());
      std::string_view line = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++line_;
      line = line.substr(0, line.find('#'));
      tokens_.clear();
      for (std::size_t i = 0; i < line.size();) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i > start) tokens_.push_back(line.substr(start, i - start));
      }
      if (!tokens_.empty()) return true;
    }
    return false;
  }
  int line() const { return line_; }
  const std::vector<std::string_view>& tokens() const { return tokens_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 0;
  std::vector<std::string_view> tokens_;
};

// The whole token as a decimal integer, or nothing.
std::optional<long long> ParseInteger(std::string_view token) {
  long long value = 0;
  const char* end = token.data() + token.size();
  auto [ptr, error] = std::from_chars(token.data(), end, value);
  if (error != std::errc() || ptr != end) return std::nullopt;
  return value;
}

// Checks the values tokens[first..] of vertex `index` (at `line`): at least
// three, each a finite number.
void CheckVertexTokens(const std::string& path, int line, std::size_t index,
                       const std::vector<std::string_view>& tokens, std::size_t first) {
  const std::string vertex = "vertex " + std::to_string(index);
  if (tokens.size() < first + 3) {
    Fail(path, line,
         vertex + " has " + std::to_string(tokens.size() - first) + " coordinates; expected 3");
  }
  for (std::size_t k = first; k < tokens.size(); ++k) {
    const std::string token(tokens[k]);
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0') {
      Fail(path, line, "cannot parse " + Quote(token) + " as a number in " + vertex);
    }
    if (!std::isfinite(value))
      Fail(path, line, "non-finite coordinate " + Quote(token) + " in " + vertex);
  }
}

void FailIndex(const std::string& path, int line, std::string_view token, std::size_t face) {
  Fail(path, line,
       "cannot parse " + Quote(token) + " as a vertex index in face " + std::to_string(face));
}

// OBJ: `v` and `f` records. Tabs become spaces in `text`: CGAL's OBJ reader
// skips from one face index to the next by looking for a space.
LineMap ScanObj(const std::string& path, std::string* text) {
  LineMap lines;
  for (LineReader reader(*text); reader.Next();) {
    const auto& tokens = reader.tokens();
    if (tokens[0] == "v") {
      CheckVertexTokens(path, reader.line(), lines.vertex.size(), tokens, 1);
      lines.vertex.push_back(reader.line());
    } else if (tokens[0] == "f") {
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        const std::string_view index = tokens[k].substr(0, tokens[k].find('/'));
        const auto value = ParseInteger(index);
        if (!value || *value == 0) FailIndex(path, reader.line(), tokens[k], lines.face.size());
      }
      lines.face.push_back(reader.line());
    }
  }
  if (lines.face.empty()) Fail(path, 0, NoFaces(lines.vertex.size()));
  std::replace(text->begin(), text->end(), '\t', ' ');
  return lines;
}

void AppendLine(const std::vector<std::string_view>& tokens, std::string* out) {
  for (std::string_view token : tokens) {
    out->append(token);
    out->push_back(' ');
  }
  out->back() = '\n';
}

// OFF: the header, then one vertex per line, then faces "n i1 ... in [colour]"
// whose indices may wrap onto following lines. ASCII `text` is rewritten with
// one record per line and no comments; binary OFF is left to CGAL.
LineMap ScanOff(const std::string& path, std::string* text) {
  LineMap lines;
  LineReader reader(*text);
  if (!reader.Next()) Fail(path, 0, "not an OFF file: no header");
  const std::string keyword(reader.tokens()[0]);
  if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0) {
    Fail(path, reader.line(),
         "not an OFF file: expected the keyword 'OFF', found " + Quote(keyword));
  }
  if (reader.tokens().size() > 1 && reader.tokens()[1] == "BINARY") return lines;
  if (keyword.find('n') != std::string::npos) {
    Fail(path, reader.line(), "n-dimensional OFF (" + keyword + ") is not supported");
  }
  std::vector<std::string_view> counts(reader.tokens().begin() + 1, reader.tokens().end());
  if (counts.empty() && reader.Next()) counts = reader.tokens();
  const auto num_vertices = counts.size() >= 2 ? ParseInteger(counts[0]) : std::nullopt;
  const auto num_faces = counts.size() >= 2 ? ParseInteger(counts[1]) : std::nullopt;
  if (!num_vertices || !num_faces || *num_vertices < 0 || *num_faces < 0) {
    Fail(path, reader.line(), "cannot read the vertex and face counts of the OFF header");
  }
  std::string normalized =
      keyword + "\n" + std::to_string(*num_vertices) + " " + std::to_string(*num_faces) + " 0\n";
  for (long long i = 0; i < *num_vertices; ++i) {
    if (!reader.Next()) {
      Fail(path, 0,
           "the header declares " + std::to_string(*num_vertices) +
               " vertices, but the file has only " + std::to_string(i));
    }
    CheckVertexTokens(path, reader.line(), lines.vertex.size(), reader.tokens(), 0);
    lines.vertex.push_back(reader.line());
    AppendLine(reader.tokens(), &normalized);
  }
  for (long long j = 0; j < *num_faces; ++j) {
    if (!reader.Next()) {
      Fail(path, 0,
           "the header declares " + std::to_string(*num_faces) + " faces, but the file has only " +
               std::to_string(j));
    }
    const int line = reader.line();
    std::vector<std::string_view> tokens = reader.tokens();
    const auto size = ParseInteger(tokens[0]);
    if (!size || *size < 0) {
      Fail(
          path, line,
          "cannot parse " + Quote(tokens[0]) + " as the vertex count of face " + std::to_string(j));
    }
    while (tokens.size() < static_cast<std::size_t>(*size) + 1) {
      if (!reader.Next()) {
        Fail(path, line,
             "face " + std::to_string(j) + " declares " + std::to_string(*size) +
                 " vertices, but the file ends first");
      }
      tokens.insert(tokens.end(), reader.tokens().begin(), reader.tokens().end());
    }
    for (long long k = 1; k <= *size; ++k) {
      const auto index = ParseInteger(tokens[k]);
      if (!index || *index < 0) FailIndex(path, line, tokens[k], lines.face.size());
      if (*index >= *num_vertices) Fail(path, line, OutOfRange(lines.face.size(), *num_vertices));
    }
    lines.face.push_back(line);
    AppendLine(tokens, &normalized);
  }
  *text = std::move(normalized);
  return lines;
}

// PLY: a header up to "end_header"; in ASCII PLY each element is one line, in
// the header's element order. Binary PLY is left to CGAL.
LineMap ScanPly(const std::string& path, const std::string& text) {
  LineReader reader(text);
  if (!reader.Next() || reader.tokens()[0] != "ply") {
    Fail(path, 1, "not a PLY file: the first line must be 'ply'");
  }
  std::string format;
  std::vector<std::pair<std::string, long long>> elements;
  while (true) {
    if (!reader.Next()) Fail(path, 0, "the PLY header has no 'end_header' line");
    const auto& tokens = reader.tokens();
    if (tokens[0] == "end_header") break;
    if (tokens[0] == "format" && tokens.size() > 1) format = tokens[1];
    if (tokens[0] == "element") {
      const auto count = tokens.size() > 2 ? ParseInteger(tokens[2]) : std::nullopt;
      if (!count || *count < 0) Fail(path, reader.line(), "cannot read the PLY element count");
      elements.emplace_back(tokens[1], *count);
    }
  }
  LineMap lines;
  if (format != "ascii") return lines;
  for (const auto& [name, count] : elements) {
    const bool is_vertex = name == "vertex" || name == "vertices";
    const bool is_face = name == "face" || name == "faces";
    for (long long k = 0; k < count; ++k) {
      if (!reader.Next()) {
        Fail(path, 0,
             "the header declares " + std::to_string(count) + " " + name +
                 " elements, but the file has only " + std::to_string(k));
      }
      if (is_vertex) {
        CheckVertexTokens(path, reader.line(), lines.vertex.size(), reader.tokens(), 0);
        lines.vertex.push_back(reader.line());
      }
      if (is_face) lines.face.push_back(reader.line());
    }
  }
  return lines;
}

std::string ReadFile(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) Fail(path, 0, "cannot open: it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) Fail(path, 0, std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) Fail(path, 0, "cannot read the file");
  return buffer.str();
}

// Reads the (pre-scanned) `text` with CGAL's soup reader for `format`.
Soup ReadSoup(const std::string& path, Format format, const std::string& text) {
  Soup soup;
  std::istringstream in(text);
  const auto quiet = CGAL::parameters::verbose(false);
  bool ok = false;
  switch (format) {
    case Format::kObj:
      ok = CGAL::IO::read_OBJ(in, soup.points, soup.polygons, quiet);
      break;
    case Format::kOff:
      ok = CGAL::IO::read_OFF(in, soup.points, soup.polygons, quiet);
      break;
    case Format::kPly:
      CGAL::IO::set_mode(in, CGAL::IO::BINARY);
      ok = CGAL::IO::read_PLY(in, soup.points, soup.polygons, quiet);
      break;
  }
  if (!ok) {
    Fail(path, 0,
         std::string("cannot parse the file as ") + FormatName(format) +
             ": CGAL's reader rejected it (unsupported content or a truncated file)");
  }
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
    Fail(path, line,
         face + " has " + std::to_string(polygon.size()) + " vertices; a face needs at least 3");
  }
  for (std::size_t v : polygon) {
    if (v >= soup.points.size()) {
      Fail(path, line, OutOfRange(j, soup.points.size()));
    }
  }
  std::vector<std::size_t> sorted = polygon;
  std::sort(sorted.begin(), sorted.end());
  const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
  if (repeated != sorted.end()) {
    Fail(path, line, face + " uses vertex " + std::to_string(*repeated) + " more than once");
  }
}

// Face `j` has no coincident consecutive vertices and a non-zero (vector)
// area, relative to the squared bounding-box diagonal.
void CheckFaceShape(const std::string& path, const Soup& soup, std::size_t j, int line,
                    double diagonal) {
  constexpr double kRelativeArea = 1e-14;
  const double tiny = kRelativeArea * diagonal * diagonal;
  const auto& polygon = soup.polygons[j];
  const std::string face = "face " + std::to_string(j);
  const Point& origin = soup.points[polygon[0]];
  Vector twice_area(0, 0, 0);
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const std::size_t a = polygon[k], b = polygon[(k + 1) % polygon.size()];
    if ((soup.points[b] - soup.points[a]).squared_length() <= tiny) {
      Fail(path, line,
           face + " is degenerate: its vertices " + std::to_string(a) + " and " +
               std::to_string(b) + " coincide");
    }
    twice_area = twice_area + CGAL::cross_product(soup.points[a] - origin, soup.points[b] - origin);
  }
  if (0.5 * std::sqrt(twice_area.squared_length()) <= tiny) {
    Fail(path, line, face + " is degenerate: zero area (collinear vertices)");
  }
}

// Checks what CGAL's readers accept but a mesh cannot have.
void CheckSoup(const std::string& path, const Soup& soup, const LineMap& lines) {
  if (soup.polygons.empty()) Fail(path, 0, NoFaces(soup.points.size()));
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const Point& p = soup.points[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
      Fail(path, lines.Vertex(i), "non-finite coordinate in vertex " + std::to_string(i));
    }
  }
  const double diagonal = BoundingBoxDiagonal(soup.points);
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
    Fail(path, 0,
         "non-manifold edge between vertices " + std::to_string(a) + " and " + std::to_string(b) +
             ": " + std::to_string(faces) + " faces share it");
  }
  if (!report.singular_vertices.empty()) {
    const std::size_t v = report.singular_vertices.front();
    Fail(path, lines.Vertex(v),
         "non-manifold vertex " + std::to_string(v) +
             ": its faces do not form one consistently oriented fan"
             " (two fans touch there, or the surface is not orientable)");
  }
  if (!no_duplicates || !PMP::is_polygon_soup_a_polygon_mesh(soup->polygons)) {
    Fail(path, 0, "non-manifold or non-orientable mesh: the faces cannot be oriented consistently");
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

// PLY through a fresh Surface_mesh holding only points, faces and, if given,
// uchar face properties red/green/blue (`colors` in soup order): CGAL's
// Surface_mesh writer writes every property map it finds (its "f:color"
// would add alpha), and the soup writer has no colours.
bool WritePly(std::ostream& out, const Soup& soup, const std::vector<Rgb>* colors, bool ascii) {
  Mesh clean;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, clean);
  if (colors != nullptr) {
    const char* names[3] = {"f:red", "f:green", "f:blue"};
    for (int c = 0; c < 3; ++c) {
      auto channel = clean.add_property_map<FaceIndex, std::uint8_t>(names[c]).first;
      for (FaceIndex f : clean.faces()) channel[f] = (*colors)[f.idx()][c];
    }
  }
  CGAL::IO::set_mode(out, ascii ? CGAL::IO::ASCII : CGAL::IO::BINARY);
  return CGAL::IO::write_PLY(out, clean, CGAL::parameters::stream_precision(17));
}

}  // namespace

Mesh ReadMesh(const std::string& path, ReadInfo* info) {
  const Format format = FormatOf(path);
  std::string text = ReadFile(path);
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) Fail(path, 0, "the file is empty");
  LineMap lines;
  switch (format) {
    case Format::kObj:
      lines = ScanObj(path, &text);
      break;
    case Format::kOff:
      lines = ScanOff(path, &text);
      break;
    case Format::kPly:
      lines = ScanPly(path, text);
      break;
  }
  Soup soup = ReadSoup(path, format, text);
  CheckSoup(path, soup, lines);
  const int flipped = Orient(path, &soup, lines);
  if (info != nullptr) *info = {FormatName(format), flipped};

  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
  CHECK_EQ(mesh.number_of_vertices(), soup.points.size());
  return mesh;
}

void WriteMesh(const std::string& path, const Mesh& mesh, const std::vector<Rgb>* face_colors,
               bool ascii_ply) {
  const Format format = FormatOf(path);
  const Soup soup = ToSoup(mesh);
  for (std::size_t j = 0; format == Format::kPly && j < soup.polygons.size(); ++j) {
    if (soup.polygons[j].size() > 255) {
      Fail(path, 0,
           "face " + std::to_string(j) + " has more than 255 vertices, more than PLY" +
               " (a uchar vertex count) can store");
    }
  }
  std::ofstream out(path, std::ios::binary);
  if (!out) Fail(path, 0, std::string("cannot open for writing: ") + std::strerror(errno));
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
      ok = WritePly(out, soup, face_colors != nullptr ? &colors : nullptr, ascii_ply);
      break;
    }
  }
  out.close();
  if (!ok || out.fail()) Fail(path, 0, "cannot write the mesh file");
}

}  // namespace archgeo
