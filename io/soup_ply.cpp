// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — PLY (ASCII, binary little- and big-endian) into a polygon soup
// (see soup_readers.h).
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>

#include "io/soup_readers.h"

namespace archgeo {
namespace {

enum class PlyType { kInt8, kUInt8, kInt16, kUInt16, kInt32, kUInt32, kFloat32, kFloat64 };

std::optional<PlyType> TypeNamed(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType::kInt8;
  if (name == "uchar" || name == "uint8") return PlyType::kUInt8;
  if (name == "short" || name == "int16") return PlyType::kInt16;
  if (name == "ushort" || name == "uint16") return PlyType::kUInt16;
  if (name == "int" || name == "int32") return PlyType::kInt32;
  if (name == "uint" || name == "uint32") return PlyType::kUInt32;
  if (name == "float" || name == "float32") return PlyType::kFloat32;
  if (name == "double" || name == "float64") return PlyType::kFloat64;
  return std::nullopt;
}

std::uint64_t SizeOf(PlyType type) {
  switch (type) {
    case PlyType::kInt8:
    case PlyType::kUInt8:
      return 1;
    case PlyType::kInt16:
    case PlyType::kUInt16:
      return 2;
    case PlyType::kInt32:
    case PlyType::kUInt32:
    case PlyType::kFloat32:
      return 4;
    case PlyType::kFloat64:
      return 8;
  }
  return 1;
}

bool IsInteger(PlyType type) { return type != PlyType::kFloat32 && type != PlyType::kFloat64; }

// The range of an integer type.
std::pair<long long, long long> RangeOf(PlyType type) {
  switch (type) {
    case PlyType::kInt8:
      return {-128, 127};
    case PlyType::kUInt8:
      return {0, 255};
    case PlyType::kInt16:
      return {-32768, 32767};
    case PlyType::kUInt16:
      return {0, 65535};
    case PlyType::kInt32:
      return {std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()};
    case PlyType::kUInt32:
      return {0, std::numeric_limits<std::uint32_t>::max()};
    default:
      return {0, 0};
  }
}

// One value as read: integers exactly, every type also as a double.
struct PlyValue {
  long long integer = 0;
  double real = 0;
};

bool ReadBinary(ByteReader& in, PlyType type, PlyValue* value) {
  const auto take = [&](auto v) {
    if (!in.Read(&v)) return false;
    value->real = static_cast<double>(v);
    if constexpr (std::is_integral_v<decltype(v)>) value->integer = static_cast<long long>(v);
    return true;
  };
  switch (type) {
    case PlyType::kInt8:
      return take(std::int8_t{});
    case PlyType::kUInt8:
      return take(std::uint8_t{});
    case PlyType::kInt16:
      return take(std::int16_t{});
    case PlyType::kUInt16:
      return take(std::uint16_t{});
    case PlyType::kInt32:
      return take(std::int32_t{});
    case PlyType::kUInt32:
      return take(std::uint32_t{});
    case PlyType::kFloat32:
      return take(float{});
    case PlyType::kFloat64:
      return take(double{});
  }
  return false;
}

struct PlyProperty {
  std::string name;
  bool is_list = false;
  PlyType count_type = PlyType::kUInt8;  // lists only
  PlyType type = PlyType::kFloat32;      // the value (list entry) type
};

enum class Role { kOther, kVertex, kFace };

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  int line = 0;
  std::vector<PlyProperty> properties;
  Role role = Role::kOther;
  int coordinate[3] = {-1, -1, -1};  // vertex: property index of x, y, z
  int indices = -1;                  // face: property index of vertex_indices
};

enum class PlyFormat { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

struct PlyHeader {
  PlyFormat format = PlyFormat::kAscii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;
  std::uint64_t num_vertices = 0;  // the vertex element's count (0 if none)
};

int FindProperty(const PlyElement& element, std::string_view name) {
  for (std::size_t k = 0; k < element.properties.size(); ++k) {
    if (element.properties[k].name == name) return static_cast<int>(k);
  }
  return -1;
}

// Parses the header (up to "end_header") and checks what the body must hold.
PlyHeader ParseHeader(const std::string& path, LineReader* reader) {
  if (!reader->Next() || reader->line() != 1 || reader->tokens()[0] != "ply" ||
      reader->tokens().size() != 1) {
    FailInput(path, 1, "not a PLY file: the first line must be 'ply'");
  }
  PlyHeader header;
  bool has_format = false;
  while (true) {
    if (!reader->Next()) FailInput(path, 0, "the PLY header has no 'end_header' line");
    const auto& tokens = reader->tokens();
    const int line = reader->line();
    const std::string_view keyword = tokens[0];
    if (keyword == "end_header" && tokens.size() == 1) break;
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "format") {
      if (has_format || !header.elements.empty() || tokens.size() != 3) {
        FailInput(path, line, "expected one 'format <type> 1.0' line before the elements");
      }
      has_format = true;
      if (tokens[1] == "ascii") {
        header.format = PlyFormat::kAscii;
      } else if (tokens[1] == "binary_little_endian") {
        header.format = PlyFormat::kBinaryLittleEndian;
      } else if (tokens[1] == "binary_big_endian") {
        header.format = PlyFormat::kBinaryBigEndian;
      } else {
        FailInput(path, line,
                  "unknown PLY format " + QuoteToken(tokens[1]) +
                      "; expected ascii, binary_little_endian or binary_big_endian");
      }
    } else if (keyword == "element") {
      const auto count = tokens.size() == 3 ? ParseInteger(tokens[2]) : std::nullopt;
      if (!count || *count < 0) {
        FailInput(path, line, "expected 'element <name> <count>' with a count >= 0");
      }
      PlyElement element;
      element.name = std::string(tokens[1]);
      element.count = static_cast<std::uint64_t>(*count);
      element.line = line;
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) FailInput(path, line, "a PLY property before any element");
      PlyProperty property;
      std::optional<PlyType> type, count_type;
      if (tokens.size() == 5 && tokens[1] == "list") {
        property.is_list = true;
        count_type = TypeNamed(tokens[2]);
        type = TypeNamed(tokens[3]);
        property.name = std::string(tokens[4]);
        if (count_type && !IsInteger(*count_type)) {
          FailInput(path, line, "the count type of a PLY list must be an integer type");
        }
      } else if (tokens.size() == 3 && tokens[1] != "list") {
        count_type = PlyType::kUInt8;
        type = TypeNamed(tokens[1]);
        property.name = std::string(tokens[2]);
      } else {
        FailInput(path, line,
                  "expected 'property <type> <name>' or 'property list <count type> <type> "
                  "<name>'");
      }
      if (!type || !count_type) {
        FailInput(path, line,
                  "unknown PLY property type; expected char, uchar, short, ushort, int, uint, "
                  "float, double (or int8 ... float64)");
      }
      property.type = *type;
      property.count_type = *count_type;
      PlyElement& element = header.elements.back();
      if (FindProperty(element, property.name) >= 0) {
        FailInput(path, line,
                  "property " + QuoteToken(property.name) + " appears twice in element " +
                      QuoteToken(element.name));
      }
      element.properties.push_back(property);
    } else {
      FailInput(path, line, "unknown PLY header line " + QuoteToken(keyword));
    }
  }
  if (!has_format) FailInput(path, 0, "the PLY header has no 'format' line");
  header.body_offset = reader->end_offset();

  bool has_vertex = false, has_face = false;
  for (PlyElement& element : header.elements) {
    if (element.count > 0 && element.properties.empty()) {
      FailInput(path, element.line,
                "element " + QuoteToken(element.name) + " declares " +
                    std::to_string(element.count) + " items but no properties");
    }
    if (element.name == "vertex" || element.name == "vertices") {
      if (has_vertex) FailInput(path, element.line, "a second vertex element");
      has_vertex = true;
      element.role = Role::kVertex;
      header.num_vertices = element.count;
      const char* names[3] = {"x", "y", "z"};
      for (int c = 0; c < 3; ++c) {
        element.coordinate[c] = FindProperty(element, names[c]);
        if (element.coordinate[c] < 0 || element.properties[element.coordinate[c]].is_list) {
          FailInput(path, element.line,
                    std::string("the vertex element has no (scalar) property '") + names[c] + "'");
        }
      }
    } else if (element.name == "face" || element.name == "faces") {
      if (has_face) FailInput(path, element.line, "a second face element");
      has_face = true;
      element.role = Role::kFace;
      element.indices = FindProperty(element, "vertex_indices");
      if (element.indices < 0) element.indices = FindProperty(element, "vertex_index");
      if (element.indices < 0 || !element.properties[element.indices].is_list ||
          !IsInteger(element.properties[element.indices].type)) {
        FailInput(path, element.line,
                  "the face element has no integer list property 'vertex_indices'");
      }
    }
  }
  return header;
}

// Declared counts against what the body can hold (each item at least its
// fixed-size values and list counts in binary; one character and a separator
// per property in ASCII), then against `limits`.
void CheckCounts(const std::string& path, const PlyHeader& header, std::uint64_t available,
                 const ReadLimits& limits) {
  std::uint64_t needed = 0;
  for (const PlyElement& element : header.elements) {
    std::uint64_t item = 0;
    for (const PlyProperty& p : element.properties) {
      item += header.format == PlyFormat::kAscii ? 2 : SizeOf(p.is_list ? p.count_type : p.type);
    }
    needed = SaturatingAdd(needed, SaturatingMul(element.count, item));
  }
  if (header.format == PlyFormat::kAscii) ++available;  // the last line may lack its newline
  if (needed > available) {
    std::string counts;
    for (const PlyElement& element : header.elements) {
      counts += (counts.empty() ? "" : ", ") + std::to_string(element.count) + " " + element.name;
    }
    FailInput(path, 0,
              "the header declares " + counts + ", which need at least " + std::to_string(needed) +
                  " bytes, but the file holds only " + std::to_string(available) +
                  " bytes after the header: it is truncated or the header is wrong");
  }
  for (const PlyElement& element : header.elements) {
    if (element.role == Role::kVertex && element.count > limits.max_vertices) {
      FailInput(path, element.line,
                LimitMessage("the header declares " + std::to_string(element.count) + " vertices",
                             limits.max_vertices, "limits.max_vertices"));
    }
    if (element.role == Role::kFace && element.count > limits.max_faces) {
      FailInput(path, element.line,
                LimitMessage("the header declares " + std::to_string(element.count) + " faces",
                             limits.max_faces, "limits.max_faces"));
    }
  }
}

// Walks the body, one value at a time, for both encodings.
class BodyReader {
 public:
  BodyReader(const std::string& path, std::string_view data, const PlyHeader& header,
             LineReader* lines, const ReadLimits& limits)
      : path_(path),
        header_(header),
        ascii_(header.format == PlyFormat::kAscii),
        lines_(lines),
        bytes_(data, header.body_offset, header.format == PlyFormat::kBinaryBigEndian),
        limits_(limits),
        num_vertices_(header.num_vertices) {}

  PolygonSoup Read() {
    PolygonSoup soup;
    for (const PlyElement& element : header_.elements) {
      if (element.role == Role::kVertex) soup.points.reserve(element.count);
      if (element.role == Role::kFace) soup.polygons.reserve(element.count);
    }
    for (const PlyElement& element : header_.elements) {
      for (std::uint64_t item = 0; item < element.count; ++item) ReadItem(element, item, &soup);
    }
    if (ascii_ ? lines_->Next() : bytes_.remaining() > 0) {
      FailInput(path_, ascii_ ? lines_->line() : 0,
                "the file holds more than its header declares (" +
                    std::to_string(soup.points.size()) + " vertices, " +
                    std::to_string(soup.polygons.size()) +
                    " faces): a count is wrong or other data follows" +
                    (ascii_ ? std::string()
                            : " (" + std::to_string(bytes_.remaining()) + " bytes more)"));
    }
    if (soup.polygons.empty()) FailInput(path_, 0, NoFacesMessage(soup.points.size()));
    return soup;
  }

 private:
  // "face 12" / "vertex 3" / "edge item 4", for messages.
  static std::string ItemName(const PlyElement& element, std::uint64_t item) {
    if (element.role == Role::kVertex) return "vertex " + std::to_string(item);
    if (element.role == Role::kFace) return "face " + std::to_string(item);
    return QuoteToken(element.name) + " element " + std::to_string(item);
  }

  int Line() const { return ascii_ ? lines_->line() : 0; }

  [[noreturn]] void Truncated(const PlyElement& element, std::uint64_t item) const {
    FailInput(path_, 0,
              "the header declares " + std::to_string(element.count) + " " + element.name +
                  " elements, but the file ends inside " + ItemName(element, item));
  }

  // The next value of `type` (for property `what` of the item).
  PlyValue Next(PlyType type, const PlyElement& element, std::uint64_t item,
                const std::string& what) {
    PlyValue value;
    if (!ascii_) {
      if (!ReadBinary(bytes_, type, &value)) Truncated(element, item);
      return value;
    }
    if (token_ >= lines_->tokens().size()) {
      FailInput(path_, Line(),
                "the line of " + ItemName(element, item) + " ends before its " + what +
                    " (ASCII PLY: one item per line)");
    }
    const std::string_view token = lines_->tokens()[token_++];
    if (IsInteger(type)) {
      const auto integer = ParseInteger(token);
      const auto [low, high] = RangeOf(type);
      if (!integer || *integer < low || *integer > high) {
        FailInput(path_, Line(),
                  "cannot parse " + QuoteToken(token) + " as the " + what + " of " +
                      ItemName(element, item) + " (an integer in [" + std::to_string(low) + ", " +
                      std::to_string(high) + "])");
      }
      value.integer = *integer;
      value.real = static_cast<double>(*integer);
    } else if (ParseDouble(token, &value.real) == NumberParse::kNotANumber) {
      FailInput(path_, Line(),
                "cannot parse " + QuoteToken(token) + " as a number in " + ItemName(element, item));
    }
    return value;
  }

  void ReadItem(const PlyElement& element, std::uint64_t item, PolygonSoup* soup) {
    if (ascii_) {
      if (!lines_->Next()) {
        FailInput(path_, 0,
                  "the header declares " + std::to_string(element.count) + " " + element.name +
                      " elements, but the file has only " + std::to_string(item));
      }
      token_ = 0;
    }
    std::array<double, 3> point{0, 0, 0};
    std::vector<std::size_t> polygon;
    for (std::size_t k = 0; k < element.properties.size(); ++k) {
      const PlyProperty& property = element.properties[k];
      const std::string what = "property " + QuoteToken(property.name);
      if (!property.is_list) {
        const PlyValue value = Next(property.type, element, item, what);
        for (int c = 0; c < 3; ++c) {
          if (element.role != Role::kVertex || element.coordinate[c] != static_cast<int>(k)) {
            continue;
          }
          if (!std::isfinite(value.real)) {
            FailInput(path_, Line(),
                      "non-finite coordinate in vertex " + std::to_string(item) +
                          (ascii_ ? " ('" + std::string(lines_->tokens()[token_ - 1]) + "')"
                                  : std::string()));
          }
          point[c] = value.real;
        }
        continue;
      }
      const PlyValue count = Next(property.count_type, element, item, what + " (list count)");
      const bool is_polygon = element.role == Role::kFace && element.indices == static_cast<int>(k);
      if (count.integer < 0) {
        FailInput(path_, Line(),
                  ItemName(element, item) + ": negative list count " +
                      std::to_string(count.integer) + " for " + what);
      }
      const auto size = static_cast<std::uint64_t>(count.integer);
      if (is_polygon && size > limits_.max_face_degree) {
        FailInput(path_, Line(),
                  LimitMessage("face " + std::to_string(item) + " declares " +
                                   std::to_string(size) + " vertices",
                               limits_.max_face_degree, "limits.max_face_degree"));
      }
      if (!ascii_ && SaturatingMul(size, SizeOf(property.type)) > bytes_.remaining()) {
        Truncated(element, item);
      }
      if (ascii_ && size > lines_->tokens().size() - token_) {
        FailInput(path_, Line(),
                  ItemName(element, item) + ": the list " + QuoteToken(property.name) +
                      " declares " + std::to_string(size) + " values, but the line holds only " +
                      std::to_string(lines_->tokens().size() - token_));
      }
      if (is_polygon) polygon.reserve(static_cast<std::size_t>(size));
      for (std::uint64_t e = 0; e < size; ++e) {
        const PlyValue entry = Next(property.type, element, item, what);
        if (!is_polygon) continue;
        if (entry.integer < 0 || static_cast<std::uint64_t>(entry.integer) >= num_vertices_) {
          FailInput(path_, Line(), OutOfRangeMessage(item, num_vertices_));
        }
        polygon.push_back(static_cast<std::size_t>(entry.integer));
      }
    }
    if (ascii_ && token_ < lines_->tokens().size()) {
      FailInput(path_, Line(),
                "the line of " + ItemName(element, item) + " holds " +
                    std::to_string(lines_->tokens().size()) + " values, more than the " +
                    std::to_string(token_) + " its properties need (ASCII PLY: one item per line)");
    }
    if (element.role == Role::kVertex) {
      soup->points.push_back(point);
      if (ascii_) soup->lines.vertex.push_back(Line());
    } else if (element.role == Role::kFace) {
      soup->polygons.push_back(std::move(polygon));
      if (ascii_) soup->lines.face.push_back(Line());
    }
  }

  const std::string& path_;
  const PlyHeader& header_;
  const bool ascii_;
  LineReader* lines_;
  ByteReader bytes_;
  const ReadLimits& limits_;
  const std::uint64_t num_vertices_;
  std::size_t token_ = 0;  // ASCII: the next token of the current line
};

}  // namespace

PolygonSoup ParsePly(const std::string& path, std::string_view data, const ReadLimits& limits) {
  LineReader reader(data, /*hash_comments=*/false);
  const PlyHeader header = ParseHeader(path, &reader);
  CheckCounts(path, header, data.size() - header.body_offset, limits);
  return BodyReader(path, data, header, &reader, limits).Read();
}

}  // namespace archgeo
